package diffract.util;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.HashSet;
import java.util.Locale;
import java.util.Set;

/**
 * Where tests put what they measure (errors, peak positions, timings of a run): one text file per test class,
 * {@code target/test-reports/<Class>.txt}, started afresh by the first line a test run writes. Tests print nothing.
 */
public final class TestReport {
    /** The folder of the reports. */
    public static final Path DIR = Path.of("target", "test-reports");

    private static final Set<Class<?>> STARTED = new HashSet<>();

    private TestReport() {
    }

    /** Appends one line to the report of {@code test}. */
    public static synchronized void line(Class<?> test, String text) {
        Path file = DIR.resolve(test.getSimpleName() + ".txt");
        try {
            Files.createDirectories(DIR);
            if (STARTED.add(test)) {
                Files.writeString(file, "", StandardCharsets.UTF_8);
            }
            Files.writeString(file, text.endsWith("\n") ? text : text + "\n", StandardCharsets.UTF_8,
                    StandardOpenOption.APPEND);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the test report " + file, e);
        }
    }

    /** {@link #line} of a table or other text being built. */
    public static void line(Class<?> test, CharSequence text) {
        line(test, text.toString());
    }

    /** {@link #line} of a formatted text in the given locale. */
    public static void printf(Class<?> test, Locale locale, String format, Object... args) {
        line(test, String.format(locale, format, args));
    }

    /** {@link #line} of a formatted text ({@link Locale#ROOT}; a trailing %n is one line end). */
    public static void printf(Class<?> test, String format, Object... args) {
        line(test, String.format(Locale.ROOT, format, args));
    }
}
