package diffract.jrtr.contexts;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GLAutoDrawable;

/**
 * The GL context behind an {@code OffscreenTarget}: headless EGL ({@link EglContext}) or a hidden JOGL
 * drawable ({@link JoglOffscreenContext}, which on Linux needs an X display). {@link HeadlessGL#newContext} chooses.
 */
public interface OffscreenContext {
    /**
     * Makes the context current on this thread and returns its GL; whatever context was current on this thread
     * before is remembered and made current again by {@link #release}. Calls nest.
     */
    GL3 makeCurrent();

    /** Undoes the matching {@link #makeCurrent}. */
    void release();

    /** What {@code GLEventListener} callbacks receive: its GL and the (nominal) surface size. */
    GLAutoDrawable drawable();

    /** Destroys the context; it must not be current. */
    void destroy();
}
