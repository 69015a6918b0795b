package diffract.jrtr.contexts;

import com.jogamp.opengl.GLContext;
import diffract.util.UserInputException;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * Where offscreen GL contexts come from. By default headless EGL ({@link EglContext}: no X server, and the only way
 * to a GPU on a server); a hidden JOGL context on the X display (GLX under Xvfb, say) is the fallback where EGL does
 * not initialise, and is always used where a JOGL window's context is current on the thread (a picture rendered
 * offscreen from inside the viewer's frame).
 *
 * <p>Settings, read when the first context is made:
 * <ul>
 *   <li>{@value #GPU_VARIABLE}{@code =N} or {@link #useGpu(int)} ({@code --gpu N}): EGL device N (see
 *       {@link EglDisplay}); without it, the first hardware device, else Mesa's surfaceless platform.</li>
 *   <li>{@value #PLATFORM_VARIABLE}{@code =egl|x11}: only EGL, or only the JOGL context on the X display.</li>
 * </ul>
 */
public final class HeadlessGL {
    /** Environment variable: the EGL device index to render on. */
    public static final String GPU_VARIABLE = "DIFFRACT_GPU";
    /** Environment variable: {@code egl} or {@code x11} instead of the automatic choice. */
    public static final String PLATFORM_VARIABLE = "DIFFRACT_GL";

    private static Integer gpu;
    /** Opened EGL displays by choice ("auto" or the device index): each is opened once per process. */
    private static final Map<String, EglDisplay> DISPLAYS = new HashMap<>();
    /** Why a choice has no display, by choice. */
    private static final Map<String, String> PROBLEMS = new HashMap<>();

    private HeadlessGL() {
    }

    /**
     * Later offscreen contexts render on EGL device {@code index} ({@code --gpu N}); null goes back to
     * {@value #GPU_VARIABLE} or the automatic choice.
     */
    public static synchronized void useGpu(Integer index) {
        if (index != null && index < 0) {
            throw new UserInputException("a GPU index is 0 or more, got " + index);
        }
        gpu = index;
    }

    /**
     * Empty when an offscreen context can be made in this process (EGL initialises, or there is an X display for
     * the fallback); otherwise the one-line reason with what to install.
     */
    public static Optional<String> problem() {
        return problem(System.getenv());
    }

    static synchronized Optional<String> problem(Map<String, String> environment) {
        String platform = platform(environment);
        if (!platform.equals("x11") && eglDisplay(environment) != null) {
            return Optional.empty();
        }
        if (!platform.equals("egl") && DisplayCheck.problem(environment, osName()).isEmpty()) {
            return Optional.empty();
        }
        return Optional.of(platform.equals("x11") ? DisplayCheck.NO_DISPLAY_MESSAGE
                : "no headless OpenGL: " + PROBLEMS.get(choice(environment)) + (platform.equals("egl") ? ""
                : "; and no X display for the fallback (" + DisplayCheck.NO_DISPLAY_MESSAGE + ")"));
    }

    /** Throws {@link UserInputException} with {@link #problem()}'s reason when no offscreen context can be made. */
    public static void require() {
        problem().ifPresent(reason -> {
            throw new UserInputException(reason);
        });
    }

    /**
     * What identifies the GL context current on this thread: JOGL's context object, the EGL context handle of a
     * headless one, or null when none is current.
     */
    public static Object currentContext() {
        GLContext jogl = GLContext.getCurrent();
        if (jogl != null) {
            return jogl;
        }
        synchronized (HeadlessGL.class) {
            if (DISPLAYS.isEmpty()) {
                return null; // no EGL context was ever made in this process
            }
        }
        long egl = org.lwjgl.egl.EGL14.eglGetCurrentContext();
        return egl == 0L ? null : egl;
    }

    /** A new offscreen context, from the source the rules above choose. */
    public static synchronized OffscreenContext newContext() {
        Map<String, String> environment = System.getenv();
        if (GLContext.getCurrent() != null) {
            return new JoglOffscreenContext(); // beside a window's context: the same window system
        }
        String platform = platform(environment);
        if (!platform.equals("x11")) {
            EglDisplay egl = eglDisplay(environment);
            if (egl != null) {
                return new EglContext(egl);
            }
            if (platform.equals("egl") || DisplayCheck.problem(environment, osName()).isPresent()) {
                require();
            }
        }
        return new JoglOffscreenContext();
    }

    /** The EGL display of the current choice (opened on first use), or null with the reason in {@link #PROBLEMS}. */
    private static EglDisplay eglDisplay(Map<String, String> environment) {
        Integer index = gpuIndex(environment);
        String choice = choice(environment);
        if (!DISPLAYS.containsKey(choice) && !PROBLEMS.containsKey(choice)) {
            try {
                DISPLAYS.put(choice, EglDisplay.open(index));
                terminateAtExit();
            } catch (UserInputException e) {
                if (index != null) {
                    throw e; // a GPU asked for by number is not silently replaced
                }
                PROBLEMS.put(choice, e.getMessage());
            } catch (LinkageError | RuntimeException e) {
                PROBLEMS.put(choice, "EGL unavailable (" + e + "): install libegl1 libegl-mesa0 libgl1-mesa-dri");
            }
        }
        return DISPLAYS.get(choice);
    }

    private static boolean terminatesAtExit;

    /**
     * Terminates the opened EGL displays when the JVM exits. NVIDIA's EGL crashes in its own threads at process exit
     * when a display is left initialised (SIGSEGV in libEGL_nvidia, exit status 134 after a finished command);
     * Mesa's does not mind either way. Contexts still current on another thread live on until released, as EGL
     * defines for eglTerminate.
     */
    private static void terminateAtExit() {
        if (terminatesAtExit) {
            return;
        }
        terminatesAtExit = true;
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            synchronized (HeadlessGL.class) {
                for (EglDisplay display : DISPLAYS.values()) {
                    display.terminate();
                }
            }
        }, "egl-terminate"));
    }

    private static String choice(Map<String, String> environment) {
        Integer index = gpuIndex(environment);
        return index == null ? "auto" : "device " + index;
    }

    private static String osName() {
        return System.getProperty("os.name", "");
    }

    private static Integer gpuIndex(Map<String, String> environment) {
        if (gpu != null) {
            return gpu;
        }
        String value = environment.get(GPU_VARIABLE);
        if (value == null || value.isBlank()) {
            return null;
        }
        try {
            int index = Integer.parseInt(value.trim());
            if (index < 0) {
                throw new NumberFormatException();
            }
            return index;
        } catch (NumberFormatException e) {
            throw new UserInputException(GPU_VARIABLE + "=" + value + " is not a device index (0, 1, ...)");
        }
    }

    private static String platform(Map<String, String> environment) {
        String value = environment.getOrDefault(PLATFORM_VARIABLE, "").trim().toLowerCase(Locale.ROOT);
        return switch (value) {
            case "", "auto" -> "auto";
            case "egl", "x11" -> value;
            default -> throw new UserInputException(PLATFORM_VARIABLE + "=" + value + ": use egl or x11");
        };
    }
}
