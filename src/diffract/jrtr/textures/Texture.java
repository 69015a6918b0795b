package diffract.jrtr.textures;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import diffract.jrtr.gl.GLErrors;
import diffract.jrtr.gl.GpuResource;

/**
 * A texture whose data is copied to the GPU once, the first time a material using it is drawn (or on an
 * explicit {@link #upload}), never per frame. The CPU data passed to a constructor is kept (not copied) so the
 * texture can be uploaded again after {@link #dispose}; do not modify it afterwards.
 */
public abstract class Texture extends GpuResource {
    private int texture;

    /** GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, ... */
    public abstract int glTarget();

    /** Fills the bound texture object (glTexImage*, parameters). */
    protected abstract void fill(GL3 gl);

    /** The GL texture name; the texture must have been uploaded. */
    public int glTexture() {
        if (!isUploaded()) {
            throw new IllegalStateException(this + " is not uploaded");
        }
        return texture;
    }

    /** Uploads if needed and binds to texture unit {@code unit}. */
    public void bind(GL3 gl, int unit) {
        upload(gl);
        gl.glActiveTexture(GL.GL_TEXTURE0 + unit);
        gl.glBindTexture(glTarget(), texture);
    }

    @Override
    protected void createOnGpu(GL3 gl) {
        int[] name = new int[1];
        gl.glGenTextures(1, name, 0);
        gl.glActiveTexture(GL.GL_TEXTURE0);
        gl.glBindTexture(glTarget(), name[0]);
        // rows of RG floats or RGBA bytes need no padding; 1 also keeps odd widths of small formats safe
        gl.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 1);
        try {
            fill(gl);
            GLErrors.check(gl, "uploading " + this);
        } catch (RuntimeException e) {
            gl.glDeleteTextures(1, name, 0);
            throw e;
        } finally {
            gl.glBindTexture(glTarget(), 0);
        }
        texture = name[0];
    }

    @Override
    protected void deleteOnGpu(GL3 gl) {
        gl.glDeleteTextures(1, new int[] {texture}, 0);
        texture = 0;
    }

    /** Nearest filtering, no mipmaps, clamp to edge: what exact per-texel table lookups need. */
    static void nearestClamp(GL3 gl, int target) {
        clampWithoutMipmaps(gl, target, GL.GL_NEAREST);
    }

    /** This filter for minification and magnification, no mipmaps, s and t clamped to the edge. */
    static void clampWithoutMipmaps(GL3 gl, int target, int filter) {
        gl.glTexParameteri(target, GL.GL_TEXTURE_MIN_FILTER, filter);
        gl.glTexParameteri(target, GL.GL_TEXTURE_MAG_FILTER, filter);
        gl.glTexParameteri(target, GL.GL_TEXTURE_WRAP_S, GL.GL_CLAMP_TO_EDGE);
        gl.glTexParameteri(target, GL.GL_TEXTURE_WRAP_T, GL.GL_CLAMP_TO_EDGE);
        gl.glTexParameteri(target, GL3.GL_TEXTURE_BASE_LEVEL, 0);
        gl.glTexParameteri(target, GL3.GL_TEXTURE_MAX_LEVEL, 0);
    }
}
