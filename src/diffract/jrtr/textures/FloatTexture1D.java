package diffract.jrtr.textures;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2GL3;
import com.jogamp.opengl.GL3;

import java.nio.FloatBuffer;

/**
 * A 1-D lookup table of RGBA floats (GL_TEXTURE_1D, RGBA32F, nearest): entry i is {@code rgba[4i .. 4i+3]},
 * read exactly in a shader with {@code texelFetch(sampler1D, i, 0)}.
 */
public final class FloatTexture1D extends Texture {
    private final float[] rgba;

    public FloatTexture1D(float[] rgba) {
        if (rgba.length == 0 || rgba.length % 4 != 0) {
            throw new IllegalArgumentException("need a positive multiple of 4 floats (RGBA entries), got "
                    + rgba.length);
        }
        this.rgba = rgba;
    }

    public int size() {
        return rgba.length / 4;
    }

    @Override
    public int glTarget() {
        return GL2GL3.GL_TEXTURE_1D;
    }

    @Override
    protected void fill(GL3 gl) {
        int[] maxSize = new int[1];
        gl.glGetIntegerv(GL.GL_MAX_TEXTURE_SIZE, maxSize, 0);
        if (size() > maxSize[0]) {
            throw new IllegalArgumentException(size() + " entries exceed GL_MAX_TEXTURE_SIZE = " + maxSize[0]);
        }
        gl.glTexImage1D(GL2GL3.GL_TEXTURE_1D, 0, GL.GL_RGBA32F, size(), 0, GL.GL_RGBA, GL.GL_FLOAT,
                FloatBuffer.wrap(rgba));
        gl.glTexParameteri(GL2GL3.GL_TEXTURE_1D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST);
        gl.glTexParameteri(GL2GL3.GL_TEXTURE_1D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST);
        gl.glTexParameteri(GL2GL3.GL_TEXTURE_1D, GL.GL_TEXTURE_WRAP_S, GL.GL_CLAMP_TO_EDGE);
        gl.glTexParameteri(GL2GL3.GL_TEXTURE_1D, GL3.GL_TEXTURE_MAX_LEVEL, 0);
    }

    @Override
    public String toString() {
        return "FloatTexture1D[" + size() + " RGBA32F]";
    }
}
