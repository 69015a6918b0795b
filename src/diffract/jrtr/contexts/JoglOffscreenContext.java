package diffract.jrtr.contexts;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GLAutoDrawable;
import com.jogamp.opengl.GLCapabilities;
import com.jogamp.opengl.GLContext;
import com.jogamp.opengl.GLDrawableFactory;
import com.jogamp.opengl.GLOffscreenAutoDrawable;

import java.util.ArrayDeque;
import java.util.Deque;
import java.util.Optional;

/**
 * A hidden JOGL context ({@link GLDrawableFactory#createOffscreenAutoDrawable}): the window system's own GL (GLX
 * on an X display, WGL, CGL). Used where a JOGL window's context is current on the thread (the two must come from
 * the same window system) and where headless EGL is unavailable or not wanted.
 */
public final class JoglOffscreenContext implements OffscreenContext {
    private final GLOffscreenAutoDrawable drawable;
    private final Deque<Optional<GLContext>> previous = new ArrayDeque<>();

    /** Throws {@link diffract.util.UserInputException} when there is no display. */
    public JoglOffscreenContext() {
        GLContext before = GLContext.getCurrent();
        GLCapabilities caps = GLProfiles.capabilities();
        caps.setOnscreen(false);
        caps.setDoubleBuffered(false);
        // the drawable's own (tiny) framebuffer is never drawn into; targets render into their FloatFramebuffer
        drawable = GLDrawableFactory.getFactory(caps.getGLProfile())
                .createOffscreenAutoDrawable(null, caps, null, 16, 16);
        drawable.display(); // realises the context; no listener is attached, so nothing is drawn
        restore(before);
    }

    @Override
    public GL3 makeCurrent() {
        GLContext context = drawable.getContext();
        GLContext before = GLContext.getCurrent();
        if (context.makeCurrent() == GLContext.CONTEXT_NOT_CURRENT) {
            throw new IllegalStateException("cannot make the offscreen GL context current");
        }
        previous.push(Optional.ofNullable(before));
        return context.getGL().getGL3();
    }

    @Override
    public void release() {
        Optional<GLContext> before = previous.pop();
        drawable.getContext().release();
        restore(before.orElse(null));
    }

    /** Makes {@code before} (a context current on this thread before we took it over, or null) current again. */
    private void restore(GLContext before) {
        if (before != null && before != drawable.getContext() && GLContext.getCurrent() != before) {
            before.makeCurrent();
        }
    }

    @Override
    public GLAutoDrawable drawable() {
        return drawable;
    }

    @Override
    public void destroy() {
        GLContext before = GLContext.getCurrent();
        drawable.destroy();
        restore(before);
    }
}
