package diffract.util;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/**
 * Where long-running code sends warnings, notes and progress. The optics and the precompute never print
 * directly, so tests can collect what they say and the CLI can decide where it goes (stderr).
 */
public interface Reporter {
    void warn(String message);

    void info(String message);

    /**
     * Progress of a named task, {@code fraction} in [0, 1]; a task reports 1 once, when it is done. Implementations
     * throttle their output.
     */
    void progress(String task, double fraction);

    /**
     * Prints to standard error; progress only for work that lasts more than a couple of seconds, with the time
     * left ({@link ConsoleReporter}).
     */
    Reporter STDERR = new ConsoleReporter(false);

    /** Says nothing. */
    Reporter SILENT = new Reporter() {
        @Override
        public void warn(String message) {
        }

        @Override
        public void info(String message) {
        }

        @Override
        public void progress(String task, double fraction) {
        }
    };

    /** Keeps warnings and notes for tests to inspect. */
    final class Collecting implements Reporter {
        private final List<String> warnings = Collections.synchronizedList(new ArrayList<>());
        private final List<String> infos = Collections.synchronizedList(new ArrayList<>());

        @Override
        public void warn(String message) {
            warnings.add(message);
        }

        @Override
        public void info(String message) {
            infos.add(message);
        }

        @Override
        public void progress(String task, double fraction) {
        }

        public List<String> warnings() {
            return List.copyOf(warnings);
        }

        public List<String> infos() {
            return List.copyOf(infos);
        }
    }
}
