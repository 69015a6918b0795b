package diffract.util;

import java.io.PrintStream;
import java.util.HashMap;
import java.util.Map;
import java.util.function.LongSupplier;
import java.util.function.Supplier;

/**
 * The command line's {@link Reporter}: warnings and notes on standard error, progress only for work that lasts
 * (the {@link Progress} rule: nothing in the first seconds, then a line every few seconds with the time left).
 * Quiet, it keeps warnings and drops notes and progress. The stream is looked up at each line, so a caller that
 * redirects {@code System.err} (tests) sees what is printed after the redirection.
 */
public final class ConsoleReporter implements Reporter {
    private final boolean quiet;
    private final LongSupplier nanoClock;
    private final Supplier<PrintStream> err;
    private final Map<String, Progress> tasks = new HashMap<>();

    public ConsoleReporter(boolean quiet) {
        this(quiet, System::nanoTime, () -> System.err);
    }

    /** With another clock and stream (tests). */
    public ConsoleReporter(boolean quiet, LongSupplier nanoClock, Supplier<PrintStream> err) {
        this.quiet = quiet;
        this.nanoClock = nanoClock;
        this.err = err;
    }

    public boolean quiet() {
        return quiet;
    }

    @Override
    public void warn(String message) {
        err.get().println("warning: " + message);
    }

    @Override
    public void info(String message) {
        if (!quiet) {
            err.get().println(message);
        }
    }

    /** A task is known by its name: the first call starts its clock, a fraction of 1 ends it. */
    @Override
    public void progress(String task, double fraction) {
        if (quiet) {
            return;
        }
        long now = nanoClock.getAsLong();
        String line;
        synchronized (tasks) {
            Progress p = tasks.computeIfAbsent(task, t -> new Progress(t, now));
            line = p.update(fraction, now).orElse(null);
            if (p.finished()) {
                tasks.remove(task);
            }
        }
        if (line != null) {
            err.get().println(line);
        }
    }
}
