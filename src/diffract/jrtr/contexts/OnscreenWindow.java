package diffract.jrtr.contexts;

import com.jogamp.newt.awt.NewtCanvasAWT;
import com.jogamp.newt.opengl.GLWindow;
import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import com.jogamp.opengl.GLEventListener;
import diffract.jrtr.textures.FloatFramebuffer;


/**
 * A NEWT window showing a {@link GLEventListener} (usually a {@code Renderer}, the same one
 * {@code OffscreenTarget} drives). Input listeners attach to {@link #glWindow()} ({@code addKeyListener},
 * {@code addMouseListener}); {@link #setTitle} changes the caption, e.g. to show frame times. The caller drives
 * drawing: {@link #display} draws one frame on the calling thread (a render loop of the caller's, which decides
 * between frames what to do).
 */
public final class OnscreenWindow implements AutoCloseable {
    private final GLWindow window;
    /** The AWT component the window is drawn in when it lives inside a frame ({@link #embedded}), else null. */
    private final NewtCanvasAWT canvas;

    /** Creates and shows the window; throws {@link diffract.util.UserInputException} when there is no display. */
    public OnscreenWindow(String title, int width, int height, GLEventListener listener) {
        window = GLWindow.create(GLProfiles.capabilities());
        window.setTitle(title);
        window.setSize(width, height);
        window.addGLEventListener(listener);
        window.setVisible(true);
        canvas = null;
    }

    private OnscreenWindow(GLEventListener listener, int width, int height) {
        window = GLWindow.create(GLProfiles.capabilities());
        window.addGLEventListener(listener);
        canvas = new NewtCanvasAWT(window);
        canvas.setPreferredSize(new java.awt.Dimension(width, height));
        canvas.setMinimumSize(new java.awt.Dimension(64, 64));
    }

    /**
     * A window drawn inside an AWT or Swing frame: add {@link #canvas()} to the frame (the window appears when the frame
     * shows it). Input listeners attach to {@link #glWindow()} as for a window of its own; the caller drives drawing.
     */
    public static OnscreenWindow embedded(GLEventListener listener, int width, int height) {
        return new OnscreenWindow(listener, width, height);
    }

    /** The AWT component of an {@link #embedded} window, else null. */
    public NewtCanvasAWT canvas() {
        return canvas;
    }

    /** The NEWT window, for input listeners and window settings. */
    public GLWindow glWindow() {
        return window;
    }

    public void setTitle(String title) {
        window.setTitle(title);
    }

    /** Draws one frame now, on this thread (the listener's display, then the buffer swap). */
    public void display() {
        window.display();
    }

    /**
     * Draws one frame on this thread and reads what it drew: RGBA floats, rows top-down, {@code surfaceWidth() x
     * surfaceHeight()} pixels (window pixels are 8-bit, so values are multiples of 1/255). Not while another
     * thread's render loop draws the window: that loop reads its own frames.
     */
    public float[] renderRgba() {
        int width = window.getSurfaceWidth();
        int height = window.getSurfaceHeight();
        float[][] result = new float[1][];
        // runs after the listeners' display and before the buffer swap, so the back buffer holds this frame
        window.invoke(true, drawable -> {
            GL3 gl = drawable.getGL().getGL3();
            gl.glReadBuffer(GL.GL_BACK);
            result[0] = FloatFramebuffer.readBoundRgbaTopDown(gl, width, height);
            return true;
        });
        if (result[0] == null) {
            throw new IllegalStateException("window did not draw (not visible or already closed?)");
        }
        return result[0];
    }

    public int surfaceWidth() {
        return window.getSurfaceWidth();
    }

    public int surfaceHeight() {
        return window.getSurfaceHeight();
    }

    /** Destroys the window; the listener's dispose frees its GPU objects. */
    @Override
    public void close() {
        if (canvas != null) {
            canvas.destroy(); // detaches the NEWT window from the frame and destroys it
        } else {
            window.destroy();
        }
    }
}
