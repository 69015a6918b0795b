package diffract.viewer;

import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;

import java.util.concurrent.ExecutorService;

/**
 * Computes more Taylor terms in the background when the model asks for more than it holds. Progress goes into the
 * model (the title shows it); the new terms replace the old ones in one state update when complete, so the render
 * thread draws with the old terms until then. Requests that arrive while a run is under way are not queued one by
 * one: when the run ends, one follow-up run computes what the state asks for then (if it still needs more).
 */
public final class TermPrecomputer implements AutoCloseable {
    private final ViewerModel model;
    private final ExecutorService executor = diffract.util.BackgroundThreads.single("diffract-viewer-precompute");
    private int runningOrder = -1;

    public TermPrecomputer(ViewerModel model) {
        this.model = model;
    }

    /** Starts (or schedules) a precompute when the state asks for more terms than it holds; returns at once. */
    public synchronized void ensureTermsFor(ViewerState state) {
        int wanted = state.settings().taylor().highestOrder();
        if (wanted <= state.terms().highestOrder() || runningOrder >= 0) {
            return; // enough terms, or a run under way: finished() looks at the state again
        }
        start(wanted);
    }

    /** Whether a precompute is running or scheduled. */
    public synchronized boolean isBusy() {
        return runningOrder >= 0;
    }

    private void start(int order) {
        runningOrder = order;
        model.update(s -> s.withPrecompute(new PrecomputeProgress(order, 0)));
        executor.execute(() -> run(order));
    }

    private void run(int order) {
        try {
            TaylorTerms terms = model.pipeline().terms(order, new ProgressToModel(order));
            model.update(s -> (terms.highestOrder() > s.terms().highestOrder() ? s.withTerms(terms) : s)
                    .withPrecompute(null));
        } catch (RuntimeException e) {
            // back to the N at hand, so finished() does not start the same failing run again
            model.update(s -> s.withPrecompute(null)
                    .withSettings(s.settings().with(b -> b.highestOrder(Math.min(s.settings().taylor().highestOrder(),
                            s.terms().highestOrder()))))
                    .withNotice(Notice.forSeconds("precompute of N = " + order + " failed: " + e.getMessage(), 10)));
        } finally {
            finished();
        }
    }

    private synchronized void finished() {
        runningOrder = -1;
        ensureTermsFor(model.state());
    }

    /** Stops waiting runs; a run under way finishes on its daemon thread and is discarded with the JVM. */
    @Override
    public void close() {
        diffract.util.BackgroundThreads.stop(executor);
    }

    /** Turns the precompute's progress into model updates, only when the whole percent changes. */
    private final class ProgressToModel implements Reporter {
        private final int order;
        private int lastPercent = -1;

        ProgressToModel(int order) {
            this.order = order;
        }

        @Override
        public void warn(String message) {
            model.update(s -> s.withNotice(Notice.forSeconds(message, 5)));
        }

        @Override
        public void info(String message) {
            System.out.println(message);
        }

        @Override
        public void progress(String task, double fraction) {
            PrecomputeProgress progress = new PrecomputeProgress(order, fraction);
            if (progress.percent() != lastPercent) {
                lastPercent = progress.percent();
                model.update(s -> s.withPrecompute(progress));
            }
        }
    }
}
