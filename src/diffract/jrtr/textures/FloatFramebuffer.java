package diffract.jrtr.textures;

import com.jogamp.opengl.GL2ES3;
import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import diffract.jrtr.gl.GLErrors;
import diffract.jrtr.gl.PixelRect;

import java.nio.FloatBuffer;

/**
 * A framebuffer object with an RGBA32F colour renderbuffer and a 24-bit depth renderbuffer, so renders keep
 * full float precision (no clamping to [0, 1], no 8-bit rounding) and can be read back as floats, or copied
 * (scaled) into another framebuffer, e.g. a window's. Lives in the GL context it was made in.
 */
public final class FloatFramebuffer {
    private final int width;
    private final int height;
    private final int framebuffer;
    private final int[] renderbuffers;

    public FloatFramebuffer(GL3 gl, int width, int height) {
        int[] maxSize = new int[1];
        gl.glGetIntegerv(GL.GL_MAX_RENDERBUFFER_SIZE, maxSize, 0);
        if (width <= 0 || height <= 0 || width > maxSize[0] || height > maxSize[0]) {
            throw new IllegalArgumentException("framebuffer size " + width + "x" + height + " outside 1.."
                    + maxSize[0]);
        }
        this.width = width;
        this.height = height;
        int[] fbo = new int[1];
        gl.glGenFramebuffers(1, fbo, 0);
        framebuffer = fbo[0];
        renderbuffers = new int[2];
        gl.glGenRenderbuffers(2, renderbuffers, 0);
        gl.glBindRenderbuffer(GL.GL_RENDERBUFFER, renderbuffers[0]);
        gl.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_RGBA32F, width, height);
        gl.glBindRenderbuffer(GL.GL_RENDERBUFFER, renderbuffers[1]);
        gl.glRenderbufferStorage(GL.GL_RENDERBUFFER, GL.GL_DEPTH_COMPONENT24, width, height);
        gl.glBindRenderbuffer(GL.GL_RENDERBUFFER, 0);
        gl.glBindFramebuffer(GL.GL_FRAMEBUFFER, framebuffer);
        gl.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_COLOR_ATTACHMENT0, GL.GL_RENDERBUFFER,
                renderbuffers[0]);
        gl.glFramebufferRenderbuffer(GL.GL_FRAMEBUFFER, GL.GL_DEPTH_ATTACHMENT, GL.GL_RENDERBUFFER,
                renderbuffers[1]);
        int status = gl.glCheckFramebufferStatus(GL.GL_FRAMEBUFFER);
        if (status != GL.GL_FRAMEBUFFER_COMPLETE) {
            delete(gl);
            throw new IllegalStateException("float framebuffer " + width + "x" + height + " incomplete: status 0x"
                    + Integer.toHexString(status));
        }
        GLErrors.check(gl, "creating a " + width + "x" + height + " float framebuffer");
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Makes this the draw and read framebuffer, drawing into colour attachment 0. */
    public void bind(GL3 gl) {
        gl.glBindFramebuffer(GL.GL_FRAMEBUFFER, framebuffer);
        gl.glDrawBuffers(1, new int[] {GL.GL_COLOR_ATTACHMENT0}, 0);
        gl.glReadBuffer(GL.GL_COLOR_ATTACHMENT0);
    }

    /** RGBA floats, rows top-down (OpenGL's row 0 is the bottom one, images start at the top). */
    public float[] readRgbaTopDown(GL3 gl) {
        bind(gl);
        float[] topDown = readBoundRgbaTopDown(gl, width, height);
        GLErrors.check(gl, "reading back the float framebuffer");
        return topDown;
    }

    /**
     * RGBA floats of the read buffer bound now (a framebuffer's attachment or a window's back buffer), {@code width}
     * x {@code height} from the corner, rows top-down.
     */
    public static float[] readBoundRgbaTopDown(GL3 gl, int width, int height) {
        gl.glPixelStorei(GL.GL_PACK_ALIGNMENT, 4);
        gl.glPixelStorei(GL2ES3.GL_PACK_ROW_LENGTH, 0);
        FloatBuffer buffer = FloatBuffer.allocate(width * height * 4);
        gl.glReadPixels(0, 0, width, height, GL.GL_RGBA, GL.GL_FLOAT, buffer);
        float[] bottomUp = buffer.array();
        float[] topDown = new float[bottomUp.length];
        int row = width * 4;
        for (int y = 0; y < height; y++) {
            System.arraycopy(bottomUp, y * row, topDown, (height - 1 - y) * row, row);
        }
        return topDown;
    }

    /**
     * Copies {@code from} (pixels of this framebuffer) onto {@code to} of the framebuffer {@code target} (0 or a
     * drawable's default framebuffer for a window), scaled with linear filtering; leaves {@code target} bound.
     * The scissor test must be off (it clips blits too).
     */
    public void blitTo(GL3 gl, PixelRect from, int target, PixelRect to) {
        if (from.isEmpty() || to.isEmpty()) {
            return;
        }
        gl.glBindFramebuffer(GL.GL_READ_FRAMEBUFFER, framebuffer);
        gl.glReadBuffer(GL.GL_COLOR_ATTACHMENT0);
        gl.glBindFramebuffer(GL.GL_DRAW_FRAMEBUFFER, target);
        gl.glBlitFramebuffer(from.x(), from.y(), from.x() + from.width(), from.y() + from.height(),
                to.x(), to.y(), to.x() + to.width(), to.y() + to.height(), GL.GL_COLOR_BUFFER_BIT, GL.GL_LINEAR);
        gl.glBindFramebuffer(GL.GL_FRAMEBUFFER, target);
        GLErrors.check(gl, "copying a " + width + "x" + height + " float framebuffer");
    }

    public void delete(GL3 gl) {
        gl.glBindFramebuffer(GL.GL_FRAMEBUFFER, 0);
        gl.glDeleteFramebuffers(1, new int[] {framebuffer}, 0);
        gl.glDeleteRenderbuffers(2, renderbuffers, 0);
    }
}
