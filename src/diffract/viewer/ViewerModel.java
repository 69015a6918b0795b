package diffract.viewer;

import diffract.jrtr.scenegraph.Shape;
import diffract.optics.patches.HeightField;
import diffract.optics.spectra.TaylorTerms;

import diffract.pipeline.DiffractionPipeline;
import diffract.scene.SceneSetup;
import diffract.util.Reporter;

import java.awt.image.BufferedImage;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.UnaryOperator;

/**
 * The viewer's model: the fixed {@link SceneSetup} (the patch's pipeline, which also says where more Taylor terms
 * come from, the shape, the pigmentation image) and the current {@link ViewerState}. Thread-safe: the state is an immutable snapshot behind an atomic
 * reference, replaced by compare-and-set, so the controller (input thread), the precompute worker and the render
 * thread never see half an update.
 */
public final class ViewerModel {
    private final SceneSetup setup;
    private final AtomicReference<ViewerState> state;

    /**
     * @param initialTerms terms 0..N of {@code setup.patch()}; when the setup asks for more, the viewer draws with
     *                     these ({@link ViewerState#drawableSettings}) until more are precomputed
     */
    public ViewerModel(SceneSetup setup, TaylorTerms initialTerms) {
        if (initialTerms.rows() != setup.patch().rows() || initialTerms.cols() != setup.patch().cols()) {
            throw new IllegalArgumentException("terms of a " + initialTerms.cols() + "x" + initialTerms.rows()
                    + " patch for a " + setup.patch().cols() + "x" + setup.patch().rows() + " patch");
        }
        this.setup = setup;
        this.state = new AtomicReference<>(initialState(initialTerms));
    }

    /** Computes (or loads) the terms the setup asks for on this thread, then builds the model. */
    public static ViewerModel load(SceneSetup setup, Reporter reporter) {
        TaylorTerms terms = setup.pipeline().terms(setup.settings().taylor().highestOrder(), reporter);
        return new ViewerModel(setup, terms);
    }

    private ViewerState initialState(TaylorTerms terms) {
        return new ViewerState(setup.settings(), new ViewerState.View(setup.camera(), setup.light(), setup.exposure(),
                setup.mode(), setup.pigmentationOn()), terms, null, null, null);
    }

    public SceneSetup setup() {
        return setup;
    }

    public HeightField patch() {
        return setup.patch();
    }

    public String patchName() {
        return setup.patchName();
    }

    public Shape shape() {
        return setup.shape();
    }

    public Optional<BufferedImage> pigmentationImage() {
        return Optional.ofNullable(setup.pigmentation());
    }

    public DiffractionPipeline pipeline() {
        return setup.pipeline();
    }

    /**
     * Bakes the BAKED table of the current state now, on the calling thread, if the state draws the baked variant
     * (and spreads it by a wide disc light, {@link diffract.render.DiscTable}):
     * the table is then in the pipeline's {@link diffract.render.BakedTables} when an offscreen frame asks for it, and its
     * progress shows on the console (the viewer's window bakes in the background instead, {@link TableBaker}).
     */
    public void bakeIfNeeded(Reporter reporter) {
        ViewerState s = state();
        if (s.drawableSettings().variant().drawsTable()) {
            pipeline().tables().of(s.terms(), s.drawableSettings(), reporter)
                    .prepareSpread(s.drawableSettings(), reporter);
        }
    }

    /** The current snapshot. */
    public ViewerState state() {
        return state.get();
    }

    /** Replaces the snapshot by {@code change(current)}, atomically (retried if another thread got there first). */
    public ViewerState update(UnaryOperator<ViewerState> change) {
        return state.updateAndGet(change);
    }

    /**
     * Back to the setup's settings, camera, light and display choices; the terms at hand (and a precompute under
     * way) are kept, since they cost time and stay valid for the same patch.
     */
    public ViewerState reset(Notice notice) {
        return update(s -> initialState(s.terms()).withPrecompute(s.precompute()).withBake(s.bake()).withNotice(notice));
    }
}
