package diffract.app.options;

import diffract.util.ConsoleReporter;
import diffract.util.Reporter;
import picocli.CommandLine.Option;

/**
 * {@code -q, --quiet}, shared by every command: no progress and no notes on standard error, only warnings and
 * errors (a command's result on standard output stays). Without it, progress appears only for work that lasts
 * more than a couple of seconds ({@link diffract.util.Progress}).
 */
public final class QuietOption {
    @Option(names = {"-q", "--quiet"}) public boolean quiet;

    /** Where the command's notes, warnings and progress go: a fresh reporter per run. */
    public Reporter reporter() {
        return new ConsoleReporter(quiet);
    }
}
