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

    /** Progress of a named task, {@code fraction} in [0, 1]. Implementations throttle their output. */
    void progress(String task, double fraction);

    /** Prints to standard error; progress at most every 10 %. */
    Reporter STDERR = new Reporter() {
        private String lastTask = "";
        private int lastDecile = -1;

        @Override
        public void warn(String message) {
            System.err.println("warning: " + message);
        }

        @Override
        public void info(String message) {
            System.err.println(message);
        }

        @Override
        public synchronized void progress(String task, double fraction) {
            int decile = (int) Math.floor(Math.min(1.0, Math.max(0.0, fraction)) * 10.0);
            if (!task.equals(lastTask)) {
                lastTask = task;
                lastDecile = -1;
            }
            if (decile > lastDecile) {
                lastDecile = decile;
                System.err.printf("%s: %d%%%n", task, decile * 10);
            }
        }
    };

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
