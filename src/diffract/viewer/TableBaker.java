package diffract.viewer;

import diffract.optics.BrdfSettings;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Methods;
import diffract.optics.Variant;
import diffract.render.BakedTables;
import diffract.util.Reporter;

import java.util.concurrent.ExecutorService;

/**
 * Bakes the baked variant's table in the background when the window needs one it has not got (a bake takes
 * minutes on a software rasteriser), and spreads it by a wide disc light where the surface reads that
 * ({@link diffract.render.DiscTable}, a second or two): the window shows the preview meanwhile, the title the
 * progress. The
 * table goes into the pipeline's {@link BakedTables}, where the render thread finds it. One bake at a time; a request
 * during a bake is dropped, and the window asks again when the bake ends if it still needs another table. A table
 * in the disk cache is loaded on the asking thread instead ({@link #loadStored}): that takes a fraction of a second,
 * so the window draws it at full quality at once.
 */
public final class TableBaker implements AutoCloseable {
    /** What the viewer draws when a bake fails: a method whose textures need no bake. */
    private static final Variant FALLBACK = Methods.Role.FALLBACK.method();

    private final ViewerModel model;
    private final ExecutorService executor = diffract.util.BackgroundThreads.single("diffract-viewer-bake");
    private boolean busy;

    public TableBaker(ViewerModel model) {
        this.model = model;
    }

    /** Starts baking the table of these terms and settings unless a bake is under way; returns at once. */
    public synchronized void ensureBaked(TaylorTerms terms, BrdfSettings settings) {
        if (busy || model.pipeline().tables().isReady(terms, settings)) {
            return;
        }
        busy = true;
        model.update(s -> s.withBake(new BakeProgress(0)));
        executor.execute(() -> bake(terms, settings));
    }

    /**
     * Whether the table of these terms and settings is at hand without a bake: in memory, or loaded now from the disk
     * cache (a damaged entry is said as a notice, and then baked by {@link #ensureBaked}).
     */
    public boolean loadStored(TaylorTerms terms, BrdfSettings settings) {
        return model.pipeline().tables().ofStored(terms, settings, new ProgressToModel()).isPresent()
                && model.pipeline().tables().isReady(terms, settings);
    }

    /** Whether a bake is under way. */
    public synchronized boolean isBusy() {
        return busy;
    }

    private void bake(TaylorTerms terms, BrdfSettings settings) {
        try {
            model.pipeline().tables().of(terms, settings, new ProgressToModel())
                    .prepareSpread(settings, new ProgressToModel());
            model.update(s -> s.withBake(null));
        } catch (RuntimeException e) {
            // back to the fallback method, whose textures need no bake, so the window does not ask for the failing
            // table again
            model.update(s -> s.withBake(null)
                    .withSettings(s.settings().variant().drawsTable() ? s.settings().with(b -> b.drawnBy(FALLBACK))
                            : s.settings())
                    .withNotice(Notice.forSeconds("baking the table failed: " + e.getMessage() + "; drawing "
                            + FALLBACK.spec(), 10)));
        } finally {
            synchronized (this) {
                busy = false;
            }
        }
    }

    /** Stops waiting bakes; a bake under way finishes on its daemon thread and is discarded with the JVM. */
    @Override
    public void close() {
        diffract.util.BackgroundThreads.stop(executor);
    }

    /** The bake's progress into the model, only when the whole percent changes. */
    private final class ProgressToModel implements Reporter {
        private int lastPercent = -1;

        @Override
        public void warn(String message) {
            model.update(s -> s.withNotice(Notice.forSeconds(message, 5)));
        }

        @Override
        public void info(String message) {
        }

        @Override
        public void progress(String task, double fraction) {
            BakeProgress progress = new BakeProgress(fraction);
            if (progress.percent() != lastPercent) {
                lastPercent = progress.percent();
                model.update(s -> s.withBake(progress));
            }
        }
    }
}
