package diffract.jrtr.textures;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import diffract.jrtr.gl.GLErrors;

import java.nio.FloatBuffer;

/**
 * The smallest and largest depth of a depth map over square blocks of its texels, one level per block size: level
 * p holds, per texel (i, j), the bounds over the map's texels [i 2^p, (i + 1) 2^p) x [j 2^p, (j + 1) 2^p) as
 * (min, max) in an RG32F texel, read with {@code texelFetch(bounds, ivec2(i, j), p)}; level 0 is the map's own
 * depths (min = max), for shaders that need them raw while the map itself is sampled with comparisons. A shader that compares many
 * depths of a region against one value asks the bounds of the blocks covering the region first: when every depth
 * there lies on the same side, the answer is known without the comparisons (a hierarchical depth test, as in
 * N. Greene, M. Kass and G. Miller, "Hierarchical Z-buffer visibility", SIGGRAPH 1993).
 */
public final class DepthBounds extends Texture {
    private final int mapSizePx;
    private final float[][] levels;

    /** Bounds of a square depth map of side {@code mapSizePx}, a power of two of at least 2. */
    public DepthBounds(int mapSizePx) {
        if (mapSizePx < 2 || Integer.bitCount(mapSizePx) != 1) {
            throw new IllegalArgumentException("depth bounds need a power-of-two map of at least 2, got " + mapSizePx);
        }
        this.mapSizePx = mapSizePx;
        int count = Integer.numberOfTrailingZeros(mapSizePx) + 1;
        levels = new float[count][];
        for (int p = 0; p < count; p++) {
            int side = mapSizePx >> p;
            levels[p] = new float[2 * side * side];
        }
    }

    /** Levels: block sizes 1, 2, 4, ..., the whole map. */
    public int levelCount() {
        return levels.length;
    }

    /**
     * Recomputes the bounds of {@code depth} (mapSizePx^2 values, row-major) and, where the texture is uploaded in
     * the context of {@code gl}, replaces its levels.
     */
    public void update(GL3 gl, float[] depth) {
        of(depth, mapSizePx, levels);
        if (isUploaded()) {
            gl.glActiveTexture(GL.GL_TEXTURE0);
            gl.glBindTexture(GL.GL_TEXTURE_2D, glTexture());
            gl.glPixelStorei(GL.GL_UNPACK_ALIGNMENT, 1);
            fill(gl);
            gl.glBindTexture(GL.GL_TEXTURE_2D, 0);
            GLErrors.check(gl, "updating " + this);
        }
    }

    /** (min, max) over block (i, j) of level p, as held on the host. */
    public float[] bounds(int p, int i, int j) {
        int side = mapSizePx >> p;
        int at = 2 * (i + side * j);
        return new float[] {levels[p][at], levels[p][at + 1]};
    }

    /** Fills {@code levels} from {@code depth}: level 0 the depths, each next level from 2 x 2 blocks of the last. */
    static void of(float[] depth, int size, float[][] levels) {
        if (depth.length != size * size) {
            throw new IllegalArgumentException("a " + size + "^2 depth map needs " + size * size + " values, got "
                    + depth.length);
        }
        int side = size;
        float[] first = levels[0];
        for (int t = 0; t < depth.length; t++) {
            first[2 * t] = depth[t];
            first[2 * t + 1] = depth[t];
        }
        for (int p = 1; p < levels.length; p++) {
            int below = side;
            side /= 2;
            float[] fine = levels[p - 1];
            float[] coarse = levels[p];
            for (int j = 0; j < side; j++) {
                for (int i = 0; i < side; i++) {
                    int a = 2 * (2 * i + below * 2 * j);
                    int b = a + 2;
                    int c = a + 2 * below;
                    int d = c + 2;
                    coarse[2 * (i + side * j)] = Math.min(Math.min(fine[a], fine[b]), Math.min(fine[c], fine[d]));
                    coarse[2 * (i + side * j) + 1] = Math.max(Math.max(fine[a + 1], fine[b + 1]),
                            Math.max(fine[c + 1], fine[d + 1]));
                }
            }
        }
    }

    @Override
    public int glTarget() {
        return GL.GL_TEXTURE_2D;
    }

    @Override
    protected void fill(GL3 gl) {
        for (int p = 0; p < levels.length; p++) {
            int side = mapSizePx >> p;
            gl.glTexImage2D(GL.GL_TEXTURE_2D, p, GL3.GL_RG32F, side, side, 0, GL3.GL_RG, GL.GL_FLOAT,
                    FloatBuffer.wrap(levels[p]));
        }
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MIN_FILTER, GL.GL_NEAREST_MIPMAP_NEAREST);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_MAG_FILTER, GL.GL_NEAREST);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_S, GL.GL_CLAMP_TO_EDGE);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL.GL_TEXTURE_WRAP_T, GL.GL_CLAMP_TO_EDGE);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL3.GL_TEXTURE_BASE_LEVEL, 0);
        gl.glTexParameteri(GL.GL_TEXTURE_2D, GL3.GL_TEXTURE_MAX_LEVEL, levels.length - 1);
    }

    @Override
    public String toString() {
        return "DepthBounds[" + mapSizePx + "]";
    }
}
