package diffract.jrtr.contexts;

import diffract.util.UserInputException;

import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * Tells, before any OpenGL call, whether this process can open a window (or a JOGL context at all). On Linux JOGL
 * needs an X server (a real one or Xvfb); without one its EGL path fails with an opaque EGL_NOT_INITIALIZED. This
 * class turns that into one line a user can act on. Offscreen rendering does not need it ({@link HeadlessGL}).
 *
 * <p>The launcher can call {@code java -cp target/diffract.jar diffract.jrtr.contexts.DisplayCheck}: exit code 0 when a
 * display is available, otherwise it prints {@link #NO_DISPLAY_MESSAGE} to standard error and exits with 3.
 */
public final class DisplayCheck {
    /** What to tell the user when there is no X display. */
    public static final String NO_DISPLAY_MESSAGE =
            "no X display: run under xvfb-run, or install xvfb (apt-get install xvfb xauth libgl1-mesa-dri)";

    /** Exit code of {@link #main} when no display is available. */
    public static final int EXIT_NO_DISPLAY = 3;

    private DisplayCheck() {
    }

    /** Empty when a GL context can be attempted in this process; otherwise the one-line reason. */
    public static Optional<String> problem() {
        return problem(System.getenv(), System.getProperty("os.name", ""));
    }

    /**
     * Same as {@link #problem()} for a given environment and OS name. Only X11 systems need DISPLAY; Windows
     * and macOS open GL contexts without it.
     */
    public static Optional<String> problem(Map<String, String> environment, String osName) {
        String os = osName.toLowerCase(Locale.ROOT);
        if (os.startsWith("windows") || os.startsWith("mac")) {
            return Optional.empty();
        }
        String display = environment.get("DISPLAY");
        if (display == null || display.isBlank()) {
            return Optional.of(NO_DISPLAY_MESSAGE);
        }
        return Optional.empty();
    }

    /**
     * Throws {@link UserInputException} (which the CLI prints as one line, exit code 2) with the reason when no
     * display is available.
     */
    public static void requireDisplay() {
        Optional<String> problem = problem();
        if (problem.isPresent()) {
            throw new UserInputException(problem.get());
        }
    }

    /** Exit 0 when a display is available, else print the reason to standard error and exit 3. */
    public static void main(String[] args) {
        Optional<String> problem = problem();
        if (problem.isPresent()) {
            System.err.println("diffract: " + problem.get());
            System.exit(EXIT_NO_DISPLAY);
        }
    }
}
