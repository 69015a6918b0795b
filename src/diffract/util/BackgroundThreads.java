package diffract.util;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

/** Stopping background work that nobody waits for any more (a viewer's bake or precompute when it closes). */
public final class BackgroundThreads {
    /** How long a stop waits for the work to notice its interruption. */
    static final long GRACE_MS = 100;

    private BackgroundThreads() {
    }

    /**
     * One background thread of this name for work queued one task at a time; a daemon, so that work nobody waits
     * for (a bake, a precompute) never keeps the JVM alive after the window closed.
     */
    public static ExecutorService single(String name) {
        return Executors.newSingleThreadExecutor(runnable -> {
            Thread thread = new Thread(runnable, name);
            thread.setDaemon(true);
            return thread;
        });
    }

    /** Interrupts the executor's work and waits briefly for it; keeps this thread's interrupt. */
    public static void stop(ExecutorService executor) {
        executor.shutdownNow();
        try {
            executor.awaitTermination(GRACE_MS, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
