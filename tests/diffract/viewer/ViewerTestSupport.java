package diffract.viewer;

import diffract.optics.BrdfSettings;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.Variant;
import diffract.pipeline.DiffractionPipeline;
import diffract.pipeline.NamedPatch;
import diffract.pipeline.TermSource;
import diffract.precompute.TaylorTermComputer;
import diffract.render.Stage;
import diffract.scene.DisplayMode;
import diffract.scene.LightDirection;
import diffract.scene.OrbitCamera;
import diffract.scene.PrimitiveShapes;
import diffract.scene.SceneSetup;
import diffract.util.Reporter;

/** Small, fast viewer models for the tests: llvmpipe runs the shaders on the CPU. */
final class ViewerTestSupport {
    /** An Elaphe-like patch of 32 x 32 pixels (2 ridges of 1.144 um): cheap terms, cheap shading. */
    static final HeightField PATCH = SyntheticPatches.elapheLike(32, 2, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, 0.3, 1L)
            .meanSubtracted();

    private ViewerTestSupport() {
    }


    /** 8 terms, 20 nm steps, coherence length 10 um so the orders are wide enough to light many pixels. */
    static BrdfSettings settings() {
        return BrdfSettings.builder(Variant.FLSS).highestOrder(8).windowRadius(1).lambdaRangeNm(380, 780).lambdaStepNm(20).coherenceLengthUm(4 * 2.5).refractiveIndex(1.5).pqReplicas(0).build();
    }

    /** The sphere with the test patch, its terms from {@code source}. */
    static SceneSetup setup(TermSource source) {
        return new SceneSetup(new DiffractionPipeline(new NamedPatch("test-patch", PATCH, null), source),
                PrimitiveShapes.sphere(new double[] {1, 0, 0}), null, 0.2, settings(), new OrbitCamera(0, 20, 3.0, 0, 0, 0),
                new LightDirection(30, 90), 10, DisplayMode.SURFACE, false, SceneSetup.DEFAULT_VERTICAL_FOV_DEG,
                Stage.none());
    }

    static SceneSetup setup() {
        return setup(directTerms());
    }

    static TermSource directTerms() {
        return (n, reporter) -> TaylorTermComputer.compute(PATCH, n, reporter);
    }

    /**
     * Terms computed directly, but those beyond the model's initial N only once {@code gate} opens: the test decides
     * when a background precompute finishes, so what it asserts meanwhile does not depend on the machine's speed.
     */
    static TermSource gatedTerms(java.util.concurrent.CountDownLatch gate) {
        return (n, reporter) -> {
            try {
                if (n > settings().taylor().highestOrder() && !gate.await(600, java.util.concurrent.TimeUnit.SECONDS)) {
                    throw new IllegalStateException("the test never opened the gate");
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted", e);
            }
            return TaylorTermComputer.compute(PATCH, n, reporter);
        };
    }

    static ViewerModel model(TermSource source) {
        return ViewerModel.load(setup(source), Reporter.SILENT);
    }

    /**
     * A model whose configured frame is deliberately expensive: N = 60, 1 nm steps (401 wavelengths), a 9 x 9
     * window, about two million term lookups per pixel; on llvmpipe minutes for a 128 x 128 frame, seconds for its
     * 1/8 pass. The preview ({@link PreviewPolicy}: one texel, 40 nm) stays cheap.
     */
    static ViewerModel expensiveModel() {
        SceneSetup cheap = setup();
        SceneSetup expensive = cheap.withSettings(cheap.settings().with(b -> b.highestOrder(60).lambdaStepNm(1)
                .windowRadius(4)));
        return ViewerModel.load(expensive, Reporter.SILENT);
    }

    /** Waits (a generous ceiling: a busy machine is slow) until the window shows the refined picture of the model's state. */
    static boolean awaitRefined(ViewerWindow viewer, ViewerModel model) throws InterruptedException {
        return waitFor(() -> viewer.refinement().isRefined(model.state()), 300);
    }

    /** Waits up to {@code seconds} for {@code condition}; returns whether it came true. */
    static boolean waitFor(java.util.function.BooleanSupplier condition, double seconds) throws InterruptedException {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < end) {
            if (condition.getAsBoolean()) {
                return true;
            }
            Thread.sleep(20);
        }
        return condition.getAsBoolean();
    }
}
