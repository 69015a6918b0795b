package diffract.jrtr.textures;

import com.jogamp.opengl.GL2ES2;
import com.jogamp.opengl.GL2ES3;
import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import diffract.jrtr.gl.GLErrors;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.util.List;

/**
 * A GL_TEXTURE_2D_ARRAY of two-channel floats: width x height texels per layer, one layer per {@code float[]}
 * slice of width * height * 2 values (RG interleaved, row 0 first, row 0 = texel y 0). Nearest filtering by default,
 * so shaders read exact values with {@code texelFetch(sampler, ivec3(x, y, layer), 0)}; linear filtering within a
 * layer on request ({@link #linear}), for tables a shader interpolates with {@code texture}.
 */
public final class FloatTextureArray extends Texture {
    /** Storage precision on the GPU. */
    public enum Precision {
        /** RG32F: values round-trip bit-exactly. */
        FLOAT32(GL.GL_RG32F),
        /** RG16F: half the memory; values rounded to half precision (11 significant bits). */
        FLOAT16(GL.GL_RG16F),
        /**
         * RG8 (unsigned normalised): a quarter of the memory; every value must lie in [0, 1] and is stored as the
         * byte {@link #toUnorm8 round(255 v)}, which a shader reads back as byte / 255. The caller normalises.
         */
        UNORM8(GL.GL_RG8);

        private final int internalFormat;

        Precision(int internalFormat) {
            this.internalFormat = internalFormat;
        }

        public int internalFormat() {
            return internalFormat;
        }

        /** Bytes per texel of the two channels. */
        public int bytesPerTexel() {
            return this == FLOAT32 ? 8 : this == FLOAT16 ? 4 : 2;
        }
    }

    private final int width;
    private final int height;
    private final List<float[]> layers;
    private final Precision precision;
    /** 2 (RG) or 4 (RGBA, float32 only). */
    private final int channels;
    private boolean linear;

    public FloatTextureArray(int width, int height, List<float[]> layers, Precision precision) {
        this(width, height, layers, precision, 2);
    }

    /** Four float32 channels per texel (RGBA interleaved), for tables a shader reads four values of at once. */
    public static FloatTextureArray rgba(int width, int height, List<float[]> layers) {
        return new FloatTextureArray(width, height, layers, Precision.FLOAT32, 4);
    }

    private FloatTextureArray(int width, int height, List<float[]> layers, Precision precision, int channels) {
        if (width <= 0 || height <= 0 || layers.isEmpty()) {
            throw new IllegalArgumentException("need width, height and layer count > 0, got " + width + "x" + height
                    + "x" + layers.size());
        }
        for (int i = 0; i < layers.size(); i++) {
            if (layers.get(i).length != width * height * channels) {
                throw new IllegalArgumentException("layer " + i + ": expected " + width * height * channels
                        + " floats (" + width + "x" + height + " x " + channels + " channels), got "
                        + layers.get(i).length);
            }
        }
        this.width = width;
        this.height = height;
        this.layers = List.copyOf(layers);
        this.precision = precision;
        this.channels = channels;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    public int layerCount() {
        return layers.size();
    }

    public Precision precision() {
        return precision;
    }

    /** Linear filtering between the texels of a layer (s and t clamped to the edge), set before the first upload. */
    public FloatTextureArray linear() {
        this.linear = true;
        return this;
    }

    @Override
    public int glTarget() {
        return GL2ES3.GL_TEXTURE_2D_ARRAY;
    }

    @Override
    protected void fill(GL3 gl) {
        int target = glTarget();
        int[] maxLayers = new int[1];
        gl.glGetIntegerv(GL2ES3.GL_MAX_ARRAY_TEXTURE_LAYERS, maxLayers, 0);
        if (layers.size() > maxLayers[0]) {
            throw new IllegalArgumentException(layers.size() + " layers exceed GL_MAX_ARRAY_TEXTURE_LAYERS = "
                    + maxLayers[0]);
        }
        // allocate once, then copy layer by layer, so no buffer of the whole array is ever needed
        GLErrors.check(gl, "before allocating " + this);
        int format = channels == 4 ? GL.GL_RGBA : GL2ES2.GL_RG;
        gl.glTexImage3D(target, 0, channels == 4 ? GL.GL_RGBA32F : precision.internalFormat(), width, height,
                layers.size(), 0, format, GL.GL_FLOAT, null);
        int error = gl.glGetError();
        if (error != GL.GL_NO_ERROR) {
            // a driver may cap one texture's size (Mesa's llvmpipe at 1 GiB): a texture it did not allocate would
            // read as zeros or garbage, so the draw stops here
            throw new diffract.util.UserInputException(String.format(java.util.Locale.ROOT, "the GPU refused a %d x %d"
                    + " x %d texture of %s (%s): the data is too large for this GL; use a smaller or coarser height "
                    + "field, fewer layers or half precision", width, height, layers.size(),
                    diffract.util.MemoryEstimate.size((long) width * height * layers.size() * precision.bytesPerTexel()
                            * channels / 2),
                    GLErrors.name(error)));
        }
        if (precision == Precision.UNORM8) {
            fillBytes(gl, target);
        } else {
            for (int layer = 0; layer < layers.size(); layer++) {
                gl.glTexSubImage3D(target, 0, 0, 0, layer, width, height, 1, format, GL.GL_FLOAT,
                        FloatBuffer.wrap(layers.get(layer)));
            }
        }
        clampWithoutMipmaps(gl, target, linear ? GL.GL_LINEAR : GL.GL_NEAREST);
    }

    /**
     * UNORM8 layers are quantised here, not by the driver, so the stored byte is {@link #toUnorm8} on every GL
     * (the spec allows either rounding of float-to-normalised conversions). Rows of 2 * width bytes need not be
     * 4-byte aligned: unpack alignment 1 while uploading.
     */
    private void fillBytes(GL3 gl, int target) {
        ByteBuffer bytes = ByteBuffer.allocateDirect(width * height * 2);
        gl.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 1);
        for (int layer = 0; layer < layers.size(); layer++) {
            float[] values = layers.get(layer);
            bytes.clear();
            for (float v : values) {
                bytes.put((byte) toUnorm8(v));
            }
            bytes.flip();
            gl.glTexSubImage3D(target, 0, 0, 0, layer, width, height, 1, GL2ES2.GL_RG, GL.GL_UNSIGNED_BYTE, bytes);
        }
        gl.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 4);
    }

    /** The byte UNORM8 stores for v in [0, 1]: round(255 v), clamped (GL reads it back as byte / 255). */
    public static int toUnorm8(float v) {
        return (int) Math.max(0, Math.min(255, Math.round(v * 255.0)));
    }

    @Override
    public String toString() {
        return "FloatTextureArray[" + width + "x" + height + "x" + layers.size() + " " + (channels == 4 ? "RGBA "
                : "") + precision + "]";
    }
}
