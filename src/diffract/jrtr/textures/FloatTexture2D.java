package diffract.jrtr.textures;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL3;

import java.nio.FloatBuffer;

/**
 * A 2-D RGBA texture from floats, stored as RGBA16F, with a full mipmap chain filtered trilinearly (and
 * anisotropically where the driver offers it), so maps of directions or radiance can be minified without aliasing.
 * Row 0 of the data is texture row 0 (texcoord t near 0). Wrapping: repeat along s, clamp along t, or clamp both.
 */
public final class FloatTexture2D extends Texture {
    /** GL_TEXTURE_MAX_ANISOTROPY_EXT: not in GL3's interface, the value from EXT_texture_filter_anisotropic. */
    private static final int TEXTURE_MAX_ANISOTROPY = 0x84FE;
    private static final int MAX_TEXTURE_MAX_ANISOTROPY = 0x84FF;

    private final int width;
    private final int height;
    private final float[] rgba;
    private final boolean repeatS;

    /** @param rgba width x height RGBA floats, row-major from texture row 0; kept, not copied */
    public FloatTexture2D(int width, int height, float[] rgba, boolean repeatS) {
        if (width < 1 || height < 1 || rgba.length != 4 * width * height) {
            throw new IllegalArgumentException("a " + width + " x " + height + " RGBA texture needs "
                    + 4 * width * height + " floats, got " + rgba.length);
        }
        this.width = width;
        this.height = height;
        this.rgba = rgba;
        this.repeatS = repeatS;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    @Override
    public int glTarget() {
        return GL.GL_TEXTURE_2D;
    }

    @Override
    protected void fill(GL3 gl) {
        gl.glTexImage2D(GL.GL_TEXTURE_2D, 0, GL.GL_RGBA16F, width, height, 0, GL.GL_RGBA, GL.GL_FLOAT,
                FloatBuffer.wrap(rgba));
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR_MIPMAP_LINEAR);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_S, repeatS ? GL.GL_REPEAT : GL.GL_CLAMP_TO_EDGE);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_T, GL.GL_CLAMP_TO_EDGE);
        if (gl.isExtensionAvailable("GL_EXT_texture_filter_anisotropic")
                || gl.isExtensionAvailable("GL_ARB_texture_filter_anisotropic")) {
            float[] max = new float[1];
            gl.glGetFloatv(MAX_TEXTURE_MAX_ANISOTROPY, max, 0);
            gl.glTexParameterf(GL.GL_TEXTURE_2D, TEXTURE_MAX_ANISOTROPY, Math.min(8f, max[0]));
        }
        gl.glGenerateMipmap(GL.GL_TEXTURE_2D);
    }

    @Override
    public String toString() {
        return "FloatTexture2D[" + width + "x" + height + "]";
    }
}
