package diffract.jrtr.textures;

import com.jogamp.opengl.GL;
import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL2ES3;
import com.jogamp.opengl.GL3;

import java.nio.FloatBuffer;

/**
 * A GL_TEXTURE_3D of RGB floats with trilinear filtering: texel (x, y, z) is {@code rgb[3 (x + width (y + height z))
 * .. + 2]}, so x runs fastest, then y, then z (glTexImage3D's order). Texel centres sit at texture coordinates
 * (i + 0.5) / size; coordinates outside [0, 1] clamp to the edge texels. Read with {@code texture(sampler3D, stp)}.
 */
public final class FloatTexture3D extends Texture {
    /** Storage precision on the GPU. */
    public enum Precision {
        /** RGB32F: 12 bytes a texel, exact float32. */
        FLOAT32(GL.GL_RGB32F, 12),
        /** RGB16F: 6 bytes a texel (drivers may pad to 8), 11 significant bits, no normal values below 6.1e-5. */
        FLOAT16(GL.GL_RGB16F, 6);

        private final int internalFormat;
        private final int bytesPerTexel;

        Precision(int internalFormat, int bytesPerTexel) {
            this.internalFormat = internalFormat;
            this.bytesPerTexel = bytesPerTexel;
        }

        /** The nominal size of a texel in this format (what the format asks for, before any driver padding). */
        public int bytesPerTexel() {
            return bytesPerTexel;
        }
    }

    private final int width;
    private final int height;
    private final int depth;
    private final float[] rgb;
    private final Precision precision;
    private final boolean mipmapped;
    private final boolean layered;

    public FloatTexture3D(int width, int height, int depth, float[] rgb, Precision precision) {
        this(width, height, depth, rgb, precision, false);
    }

    /**
     * A GL_TEXTURE_2D_ARRAY of the same data (layer z = the z-th slice) without mip levels, bilinear within a layer:
     * for lookups of one slice at a time, which need neither the third axis' interpolation nor a level choice.
     */
    public static FloatTexture3D layers(int width, int height, int depth, float[] rgb, Precision precision) {
        return new FloatTexture3D(width, height, depth, rgb, precision, false, true);
    }

    /**
     * @param mipmapped a GL_TEXTURE_2D_ARRAY instead (layer z = the z-th slice, same data layout) with mip levels per
     *                  layer (box averages within a slice, {@link BoxMipmaps}) and GL_LINEAR_MIPMAP_LINEAR, for lookups
     *                  with {@code textureLod} that average over a footprint larger than a texel without blurring the
     *                  slices into each other (the shader interpolates between slices itself)
     */
    public FloatTexture3D(int width, int height, int depth, float[] rgb, Precision precision, boolean mipmapped) {
        this(width, height, depth, rgb, precision, mipmapped, mipmapped);
    }

    private FloatTexture3D(int width, int height, int depth, float[] rgb, Precision precision, boolean mipmapped,
                           boolean layered) {
        if (width <= 0 || height <= 0 || depth <= 0) {
            throw new IllegalArgumentException("need a positive size, got " + width + "x" + height + "x" + depth);
        }
        if (rgb.length != 3L * width * height * depth) {
            throw new IllegalArgumentException("expected " + 3L * width * height * depth + " floats (" + width + "x"
                    + height + "x" + depth + " x RGB), got " + rgb.length);
        }
        this.width = width;
        this.height = height;
        this.depth = depth;
        this.rgb = rgb;
        this.precision = precision;
        this.mipmapped = mipmapped;
        this.layered = layered;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public int depth() {
        return depth;
    }

    public Precision precision() {
        return precision;
    }

    /** The nominal GPU memory of the texture: texels x bytes per texel of its format (mip levels add about 1/3). */
    public long gpuBytes() {
        long base = (long) width * height * depth * precision.bytesPerTexel();
        return mipmapped ? base * 4 / 3 : base;
    }

    @Override
    public int glTarget() {
        return layered ? GL2ES3.GL_TEXTURE_2D_ARRAY : GL2ES2.GL_TEXTURE_3D;
    }

    @Override
    protected void fill(GL3 gl) {
        int[] maxSize = new int[1];
        gl.glGetIntegerv(GL2ES2.GL_MAX_3D_TEXTURE_SIZE, maxSize, 0);
        if (Math.max(width, Math.max(height, depth)) > maxSize[0]) {
            throw new IllegalArgumentException(width + "x" + height + "x" + depth
                    + " exceeds GL_MAX_3D_TEXTURE_SIZE = " + maxSize[0]);
        }
        int target = glTarget();
        gl.glTexImage3D(target, 0, precision.internalFormat, width, height, depth, 0, GL.GL_RGB, GL.GL_FLOAT,
                FloatBuffer.wrap(rgb));
        if (mipmapped) {
            // box averages made here, the same on every driver (BoxMipmaps)
            float[] level = rgb;
            int w = width;
            int h = height;
            int levels = BoxMipmaps.levels(width, height);
            for (int k = 1; k < levels; k++) {
                level = BoxMipmaps.next(level, w, h, depth, 3);
                w = BoxMipmaps.halved(w);
                h = BoxMipmaps.halved(h);
                gl.glTexImage3D(target, k, precision.internalFormat, w, h, depth, 0, GL.GL_RGB, GL.GL_FLOAT,
                        FloatBuffer.wrap(level));
            }
            gl.glTexParameteri(target, GL2ES3.GL_TEXTURE_MAX_LEVEL, levels - 1);
            gl.glTexParameteri(target, GL.GL_TEXTURE_MIN_FILTER, GL.GL_LINEAR_MIPMAP_LINEAR);
            gl.glTexParameteri(target, GL.GL_TEXTURE_MAG_FILTER, GL.GL_LINEAR);
            gl.glTexParameteri(target, GL.GL_TEXTURE_WRAP_S, GL.GL_CLAMP_TO_EDGE);
            gl.glTexParameteri(target, GL.GL_TEXTURE_WRAP_T, GL.GL_CLAMP_TO_EDGE);
        } else {
            clampWithoutMipmaps(gl, target, GL.GL_LINEAR); // trilinear (bilinear per layer) between the samples
        }
        gl.glTexParameteri(target, GL2ES2.GL_TEXTURE_WRAP_R, GL.GL_CLAMP_TO_EDGE);
    }

    @Override
    public String toString() {
        return "FloatTexture3D[" + width + "x" + height + "x" + depth + " " + precision + "]";
    }
}
