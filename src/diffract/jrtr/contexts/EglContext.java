package diffract.jrtr.contexts;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GLAutoDrawable;
import diffract.util.UserInputException;
import org.lwjgl.PointerBuffer;
import org.lwjgl.egl.EGL10;
import org.lwjgl.egl.EGL12;
import org.lwjgl.egl.EGL14;
import org.lwjgl.egl.EGL15;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GLCapabilities;

import java.lang.reflect.Proxy;
import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Locale;

/**
 * A desktop OpenGL 3.3+ core context without a window or an X server: EGL through LWJGL's bindings, on the display
 * {@link EglDisplay} chooses (a GPU through EGL_EXT_platform_device, or Mesa's surfaceless platform), made current
 * with no surface at all ({@code EGL_KHR_surfaceless_context}; a 1 x 1 pbuffer where that is missing). It draws only
 * into framebuffer objects, which is all {@code OffscreenTarget} needs. Its GL is JOGL's {@link GL3}
 * interface answered by LWJGL ({@link LwjglGL3}), so the engine's code runs on it unchanged.
 */
public final class EglContext implements OffscreenContext {
    private final EglDisplay display;
    private final long context;
    private final long surface;
    private final GL3 gl;
    private final GLCapabilities capabilities;
    private final GLAutoDrawable drawable;
    private final Deque<Previous> previous = new ArrayDeque<>();
    private boolean destroyed;

    /** What was current on the thread before {@link #makeCurrent}: restored by {@link #release}. */
    private record Previous(long display, long draw, long read, long context, GLCapabilities capabilities) {
    }

    /** Creates the context on {@code display}; throws {@link UserInputException} naming the EGL error. */
    public EglContext(EglDisplay display) {
        this.display = display;
        if (!EGL12.eglBindAPI(EGL14.EGL_OPENGL_API)) {
            throw new UserInputException(display.description + " offers no desktop OpenGL ("
                    + errorName(EGL10.eglGetError()) + ")");
        }
        boolean surfaceless = display.has("EGL_KHR_surfaceless_context");
        long config = chooseConfig(surfaceless);
        int[] attributes = {
            EGL15.EGL_CONTEXT_MAJOR_VERSION, 3,
            EGL15.EGL_CONTEXT_MINOR_VERSION, 3,
            EGL15.EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL15.EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
            EGL10.EGL_NONE};
        if (!display.atLeastEgl15() && !display.has("EGL_KHR_create_context")) {
            throw new UserInputException(display.description + ": EGL " + display.eglVersion[0] + "."
                    + display.eglVersion[1] + " without EGL_KHR_create_context cannot ask for a 3.3 core context");
        }
        context = EGL10.eglCreateContext(display.handle, config, EGL10.EGL_NO_CONTEXT, attributes);
        if (context == EGL10.EGL_NO_CONTEXT) {
            throw new UserInputException(display.description + ": no OpenGL 3.3 core context ("
                    + errorName(EGL10.eglGetError()) + ")");
        }
        if (surfaceless) {
            surface = EGL10.EGL_NO_SURFACE;
        } else {
            surface = EGL10.eglCreatePbufferSurface(display.handle, config,
                    new int[] {EGL10.EGL_WIDTH, 1, EGL10.EGL_HEIGHT, 1, EGL10.EGL_NONE});
            if (surface == EGL10.EGL_NO_SURFACE) {
                int error = EGL10.eglGetError();
                EGL10.eglDestroyContext(display.handle, context);
                throw new UserInputException(display.description + ": no pbuffer surface (" + errorName(error) + ")");
            }
        }
        Previous before = current();
        if (!EGL10.eglMakeCurrent(display.handle, surface, surface, context)) {
            int error = EGL10.eglGetError();
            destroyNative();
            throw new UserInputException(display.description + ": cannot make the context current ("
                    + errorName(error) + ")");
        }
        try {
            capabilities = GL.createCapabilities();
            int[] version = GLInfo.parseVersion(org.lwjgl.opengl.GL11C.glGetString(org.lwjgl.opengl.GL11C.GL_VERSION));
            gl = LwjglGL3.create(display.description, version);
        } finally {
            restore(before);
        }
        drawable = headlessDrawable(gl);
    }

    /** Any config of desktop OpenGL; one with pbuffers where the context needs a surface to be current. */
    private long chooseConfig(boolean surfaceless) {
        int[] wanted = {
            EGL10.EGL_SURFACE_TYPE, surfaceless ? 0 : EGL10.EGL_PBUFFER_BIT,
            EGL12.EGL_RENDERABLE_TYPE, EGL14.EGL_OPENGL_BIT,
            EGL10.EGL_NONE};
        PointerBuffer configs = PointerBuffer.allocateDirect(1);
        int[] count = new int[1];
        if (!EGL10.eglChooseConfig(display.handle, wanted, configs, count) || count[0] == 0) {
            throw new UserInputException(display.description + ": no EGL config for desktop OpenGL pbuffers ("
                    + errorName(EGL10.eglGetError()) + ")");
        }
        return configs.get(0);
    }

    @Override
    public GL3 makeCurrent() {
        if (destroyed) {
            throw new IllegalStateException("EGL context already destroyed");
        }
        Previous before = current();
        if (!EGL10.eglMakeCurrent(display.handle, surface, surface, context)) {
            throw new IllegalStateException("cannot make the EGL context current on " + Thread.currentThread().getName()
                    + " (" + errorName(EGL10.eglGetError()) + "; is it current on another thread?)");
        }
        GL.setCapabilities(capabilities);
        previous.push(before);
        return gl;
    }

    @Override
    public void release() {
        restore(previous.pop());
    }

    private static Previous current() {
        GLCapabilities caps;
        try {
            caps = GL.getCapabilities();
        } catch (IllegalStateException none) {
            caps = null;
        }
        return new Previous(EGL10.eglGetCurrentDisplay(), EGL10.eglGetCurrentSurface(EGL10.EGL_DRAW),
                EGL10.eglGetCurrentSurface(EGL10.EGL_READ), EGL14.eglGetCurrentContext(), caps);
    }

    private void restore(Previous before) {
        if (before.context() != EGL10.EGL_NO_CONTEXT) {
            EGL10.eglMakeCurrent(before.display(), before.draw(), before.read(), before.context());
        } else {
            EGL10.eglMakeCurrent(display.handle, EGL10.EGL_NO_SURFACE, EGL10.EGL_NO_SURFACE, EGL10.EGL_NO_CONTEXT);
        }
        GL.setCapabilities(before.capabilities());
    }

    @Override
    public GLAutoDrawable drawable() {
        return drawable;
    }

    @Override
    public void destroy() {
        if (!destroyed) {
            destroyed = true;
            destroyNative();
        }
    }

    private void destroyNative() {
        if (surface != EGL10.EGL_NO_SURFACE) {
            EGL10.eglDestroySurface(display.handle, surface);
        }
        EGL10.eglDestroyContext(display.handle, context);
    }

    /**
     * The drawable handed to {@code GLEventListener}s: its GL, and a nominal 16 x 16 surface (targets draw into their
     * own framebuffer and call {@code reshape} with its size). Nothing else of JOGL's drawable exists here.
     */
    private static GLAutoDrawable headlessDrawable(GL3 gl) {
        return (GLAutoDrawable) Proxy.newProxyInstance(EglContext.class.getClassLoader(),
                new Class<?>[] {GLAutoDrawable.class}, (self, method, args) -> switch (method.getName()) {
                    case "getGL" -> gl;
                    case "getSurfaceWidth", "getSurfaceHeight" -> 16;
                    case "hashCode" -> System.identityHashCode(self);
                    case "equals" -> self == args[0];
                    case "toString" -> "headless EGL drawable";
                    default -> throw new UnsupportedOperationException(method.getName()
                            + " is not offered by the headless EGL drawable");
                });
    }

    /** EGL error codes by name, for messages. */
    static String errorName(int code) {
        return switch (code) {
            case 0x3000 -> "EGL_SUCCESS";
            case 0x3001 -> "EGL_NOT_INITIALIZED";
            case 0x3002 -> "EGL_BAD_ACCESS";
            case 0x3003 -> "EGL_BAD_ALLOC";
            case 0x3004 -> "EGL_BAD_ATTRIBUTE";
            case 0x3005 -> "EGL_BAD_CONFIG";
            case 0x3006 -> "EGL_BAD_CONTEXT";
            case 0x3008 -> "EGL_BAD_DISPLAY";
            case 0x3009 -> "EGL_BAD_MATCH";
            case 0x300C -> "EGL_BAD_PARAMETER";
            default -> String.format(Locale.ROOT, "EGL error 0x%04X", code);
        };
    }
}
