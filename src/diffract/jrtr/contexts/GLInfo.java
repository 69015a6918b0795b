package diffract.jrtr.contexts;

import com.jogamp.nativewindow.NativeWindowFactory;
import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL3;

import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * What the driver says about itself, and which platform gave the context: for logs, reports and error messages.
 * Every {@code GLRenderContext} hands its info to the listener set with {@link #reportTo} (the command
 * line prints it once per renderer); nothing is reported without one.
 */
public record GLInfo(String version, String renderer, String vendor, String glslVersion, boolean coreProfile,
                     String platform) {
    private static final Pattern VERSION = Pattern.compile("(\\d+)\\.(\\d+)");
    private static volatile Consumer<GLInfo> listener = info -> { };

    /** Queries the current context. */
    public static GLInfo of(GL gl) {
        String version = gl.glGetString(GL.GL_VERSION);
        boolean core;
        String platform;
        if (gl.getContext() != null) {
            core = gl.getContext().isGLCoreProfile();
            platform = joglPlatform();
        } else {
            int[] v = parseVersion(version);
            int[] mask = {0};
            if (v[0] > 3 || (v[0] == 3 && v[1] >= 2)) {
                gl.glGetIntegerv(GL3.GL_CONTEXT_PROFILE_MASK, mask, 0);
            }
            core = (mask[0] & GL3.GL_CONTEXT_CORE_PROFILE_BIT) != 0;
            platform = gl instanceof LwjglGL3.GLPlatform p ? p.platformDescription() : "unknown platform";
        }
        return new GLInfo(version, gl.glGetString(GL.GL_RENDERER), gl.glGetString(GL.GL_VENDOR),
                gl.glGetString(GL2ES2.GL_SHADING_LANGUAGE_VERSION), core, platform);
    }

    /** JOGL's window system, as a user would name it. */
    private static String joglPlatform() {
        String type = NativeWindowFactory.getNativeWindowType(true);
        if (NativeWindowFactory.TYPE_X11.equals(type)) {
            String display = System.getenv("DISPLAY");
            return "GLX" + (display == null ? "" : " on X display " + display);
        }
        if (NativeWindowFactory.TYPE_WINDOWS.equals(type)) {
            return "WGL";
        }
        if (NativeWindowFactory.TYPE_MACOSX.equals(type)) {
            return "CGL";
        }
        return "JOGL " + type;
    }

    /** {major, minor} from a GL_VERSION string ("4.5 (Core Profile) Mesa 22.3.6", "4.6.0 NVIDIA 550.54"); 0.0 if none. */
    public static int[] parseVersion(String glVersion) {
        Matcher m = VERSION.matcher(glVersion == null ? "" : glVersion);
        return m.find() ? new int[] {Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2))} : new int[] {0, 0};
    }

    /**
     * Sets who hears of each render context's GL (the command line: a line on standard error per renderer). One
     * listener per process; null silences.
     */
    public static void reportTo(Consumer<GLInfo> newListener) {
        listener = newListener == null ? info -> { } : newListener;
    }

    /** Hands {@code info} to the listener ({@code GLRenderContext} calls it for every new context). */
    public static void report(GLInfo info) {
        listener.accept(info);
    }

    /**
     * "OpenGL 4.5 (Core Profile) Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits) (Mesa/X.org), GLSL 4.50, EGL
     * surfaceless": version, renderer, vendor, GLSL and platform ("core profile" is added where the version string
     * does not say it).
     */
    @Override
    public String toString() {
        boolean saysCore = version != null && version.toLowerCase(java.util.Locale.ROOT).contains("core");
        return "OpenGL " + version + (coreProfile && !saysCore ? " core profile" : "") + ", " + renderer + " ("
                + vendor + "), GLSL " + glslVersion + ", " + platform;
    }
}
