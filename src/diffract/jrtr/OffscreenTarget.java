package diffract.jrtr;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GLAutoDrawable;
import com.jogamp.opengl.GLEventListener;
import diffract.jrtr.contexts.GLInfo;
import diffract.jrtr.contexts.HeadlessGL;
import diffract.jrtr.contexts.OffscreenContext;
import diffract.jrtr.gl.GLVersionException;
import diffract.jrtr.gl.GpuTimer;
import diffract.jrtr.textures.FloatFramebuffer;

import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Function;

/**
 * Renders a {@link GLEventListener} (usually a {@link Renderer}) without a window: a GL context of its own
 * ({@link HeadlessGL} chooses: headless EGL, needing no X server, or a hidden JOGL context on the X display) plus
 * our own RGBA32F framebuffer, so results are read back as floats. The listener gets the same
 * init/reshape/display/dispose calls as in a window. The context is made current on the calling thread for each
 * call; use one target from one thread at a time.
 *
 * <pre>{@code
 * try (OffscreenTarget target = new OffscreenTarget(new Renderer(scene, camera, frustum))) {
 *     float[] rgba = target.renderRgba(128, 128);       // top-down rows, 4 floats per pixel
 *     target.writePng(Path.of("out/frame.png"), 128, 128);
 * }
 * }</pre>
 */
public final class OffscreenTarget implements AutoCloseable {
    private final GLEventListener listener;
    private final OffscreenContext context;
    private final GLAutoDrawable drawable;
    private FloatFramebuffer framebuffer;
    private boolean listenerInitialized;
    private boolean closed;

    /**
     * Creates the GL context; throws {@link diffract.util.UserInputException} with the reason when none can be
     * made (no EGL and no X display), {@link GLVersionException} when it is older than OpenGL 3.3.
     */
    public OffscreenTarget(GLEventListener listener) {
        this(listener, HeadlessGL.newContext());
    }

    /** On a given context (tests compare the EGL and JOGL contexts this way). */
    OffscreenTarget(GLEventListener listener, OffscreenContext context) {
        this.listener = listener;
        this.context = context;
        this.drawable = context.drawable();
        try {
            withContext(gl -> {
                GLRenderContext.requireVersion(gl);
                return null;
            });
        } catch (RuntimeException e) {
            context.destroy();
            throw e;
        }
    }

    /**
     * Runs {@code work} with this target's GL context current on this thread and returns its result. A context
     * that was current on this thread before (e.g. a window's, when a table is rendered offscreen from inside its
     * display callback) is made current again afterwards.
     */
    public <T> T withContext(Function<GL3, T> work) {
        if (closed) {
            throw new IllegalStateException("offscreen target already closed");
        }
        GL3 gl = context.makeCurrent();
        try {
            return work.apply(gl);
        } finally {
            context.release();
        }
    }

    /** The driver's version and renderer strings. */
    public GLInfo info() {
        return withContext(GLInfo::of);
    }

    /** Renders one frame of {@code width} x {@code height} pixels; RGBA floats, rows top-down. */
    public float[] renderRgba(int width, int height) {
        return withContext(gl -> {
            drawFrame(gl, width, height);
            return framebuffer.readRgbaTopDown(gl);
        });
    }

    /** Renders one frame and drops alpha: RGB floats, rows top-down (what {@code ImageFiles} takes). */
    public float[] renderRgb(int width, int height) {
        return dropAlpha(renderRgba(width, height));
    }

    /** Renders one frame and writes it as an 8-bit PNG (values clamped to [0, 1], alpha dropped). */
    public void writePng(Path file, int width, int height) throws IOException {
        diffract.util.ImageFiles.writePng(file, renderRgb(width, height), width, height, 3);
    }

    /** Renders one frame and writes the raw float RGB values as PFM. */
    public void writePfm(Path file, int width, int height) throws IOException {
        diffract.util.ImageFiles.writePfm(file, renderRgb(width, height), width, height, 3);
    }

    /**
     * Median GPU time of one frame at the given size, in milliseconds, over {@code frames} (at least 10)
     * frames after {@code warmupFrames} unmeasured ones (shader compilation and uploads happen in warm-up).
     */
    public double measureMedianMs(int width, int height, int warmupFrames, int frames) {
        return withContext(gl -> {
            prepare(gl, width, height);
            return new GpuTimer(gl).measureMedianMs(() -> listener.display(drawable), warmupFrames, frames);
        });
    }

    private void drawFrame(GL3 gl, int width, int height) {
        prepare(gl, width, height);
        listener.display(drawable);
        gl.glFinish();
    }

    /** Initialises the listener once, (re)creates the float framebuffer when the size changes, binds it. */
    private void prepare(GL3 gl, int width, int height) {
        if (!listenerInitialized) {
            listener.init(drawable);
            listenerInitialized = true;
        }
        if (framebuffer == null || framebuffer.width() != width || framebuffer.height() != height) {
            if (framebuffer != null) {
                framebuffer.delete(gl);
            }
            framebuffer = new FloatFramebuffer(gl, width, height);
            framebuffer.bind(gl);
            listener.reshape(drawable, 0, 0, width, height);
        }
        framebuffer.bind(gl);
    }

    /** The RGB of {@code rgba}, 4 floats a pixel, in its order. */
    public static float[] dropAlpha(float[] rgba) {
        float[] rgb = new float[rgba.length / 4 * 3];
        for (int i = 0, j = 0; i < rgba.length; i += 4, j += 3) {
            rgb[j] = rgba[i];
            rgb[j + 1] = rgba[i + 1];
            rgb[j + 2] = rgba[i + 2];
        }
        return rgb;
    }

    /** Disposes the listener's GPU objects and the framebuffer, then destroys the context. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        try {
            withContext(gl -> {
                if (listenerInitialized) {
                    listener.dispose(drawable);
                }
                if (framebuffer != null) {
                    framebuffer.delete(gl);
                    framebuffer = null;
                }
                return null;
            });
        } finally {
            closed = true;
            context.destroy();
        }
    }
}
