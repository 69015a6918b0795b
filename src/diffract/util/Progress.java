package diffract.util;

import java.util.Locale;
import java.util.Optional;

/**
 * When a task's progress deserves a line, and what the line says. Short work says nothing: the first line comes
 * only once the task has run {@link #FIRST_LINE_AFTER_S} seconds, later ones at most every
 * {@link #LINE_EVERY_S} seconds, each with the time left, extrapolated linearly from the rate since the first report;
 * a task that printed anything ends with one line that says it is done. Time is passed in (nanoseconds from any
 * fixed origin), so the rule is tested without a clock.
 */
public final class Progress {
    /** Work shorter than this prints no progress at all. */
    public static final double FIRST_LINE_AFTER_S = 2.0;
    /** At most one line per this many seconds. */
    public static final double LINE_EVERY_S = 5.0;

    private final String task;
    private final long startNanos;
    private double startFraction = Double.NaN;
    private long lastLineNanos;
    private boolean printed;
    private boolean finished;

    public Progress(String task, long startNanos) {
        this.task = task;
        this.startNanos = startNanos;
    }

    /**
     * The line to print for {@code fraction} done (in [0, 1]) at time {@code nowNanos}, if one is due.
     */
    public synchronized Optional<String> update(double fraction, long nowNanos) {
        if (finished) {
            return Optional.empty();
        }
        double f = Math.min(1.0, Math.max(0.0, fraction));
        if (Double.isNaN(startFraction)) {
            startFraction = f; // the work before the first report is not timed: leave it out of the rate
        }
        double elapsedS = (nowNanos - startNanos) * 1e-9;
        if (f >= 1.0) {
            finished = true;
            return printed ? Optional.of(String.format(Locale.ROOT, "%s: done in %s", task, duration(elapsedS)))
                    : Optional.empty();
        }
        if (elapsedS < FIRST_LINE_AFTER_S || (printed && (nowNanos - lastLineNanos) * 1e-9 < LINE_EVERY_S)) {
            return Optional.empty();
        }
        printed = true;
        lastLineNanos = nowNanos;
        double done = f - startFraction;
        String left = done > 0 ? ", about " + duration(elapsedS * (1 - f) / done) + " left" : "";
        return Optional.of(String.format(Locale.ROOT, "%s: %.0f %% after %s%s", task, 100 * f, duration(elapsedS),
                left));
    }

    /** True once the task reached 1. */
    public synchronized boolean finished() {
        return finished;
    }

    /** "7 s", "2 min 05 s", "1 h 02 min". */
    public static String duration(double seconds) {
        long s = Math.max(0, Math.round(seconds));
        if (s < 60) {
            return s + " s";
        }
        if (s < 3600) {
            return String.format(Locale.ROOT, "%d min %02d s", s / 60, s % 60);
        }
        return String.format(Locale.ROOT, "%d h %02d min", s / 3600, (s % 3600) / 60);
    }
}
