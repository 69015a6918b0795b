package diffract.jrtr.textures;

/**
 * Mip levels as box averages, made on the host: texel i of a level of m texels along an axis averages the span
 * [i n / m, (i + 1) n / m) of the level below it (n texels), each texel of that level weighted by its overlap with the
 * span. A level so keeps every texel's share of the total, and a level's texel centre, (i + 0.5) / m in texture
 * coordinates, is its span's centre. {@code glGenerateMipmap} instead leaves the filter to the driver: Mesa's
 * llvmpipe samples a non-power-of-two level bilinearly at the new texel centres, which for 513 texels halved to 256
 * falls on every other texel near the middle and skips the texels between (a narrow line there vanishes from
 * the levels above it).
 */
public final class BoxMipmaps {
    private BoxMipmaps() {
    }

    /** The size of the level above one of {@code n} texels: half, rounded down, at least 1 (GL's rule). */
    public static int halved(int n) {
        return Math.max(1, n / 2);
    }

    /** How many levels a texture of this size has, itself included, down to 1 x 1. */
    public static int levels(int width, int height) {
        int levels = 1;
        for (int w = width, h = height; w > 1 || h > 1; w = halved(w), h = halved(h)) {
            levels++;
        }
        return levels;
    }

    /**
     * The level above {@code level} ({@code channels} values a texel, x fastest, then y, then layer): each layer
     * halved along x and y by the box average, summed in double.
     */
    public static float[] next(float[] level, int width, int height, int layers, int channels) {
        int w2 = halved(width);
        int h2 = halved(height);
        double[] alongX = new double[w2 * height * layers * channels];
        double[] row = new double[width * channels];
        for (int r = 0; r < height * layers; r++) {
            for (int k = 0; k < width * channels; k++) {
                row[k] = level[r * width * channels + k];
            }
            for (int i = 0; i < w2; i++) {
                addSpan(row, width, w2, i, channels, alongX, (r * w2 + i) * channels);
            }
        }
        float[] out = new float[w2 * h2 * layers * channels];
        double[] column = new double[height * channels];
        double[] sum = new double[channels];
        for (int layer = 0; layer < layers; layer++) {
            for (int x = 0; x < w2; x++) {
                for (int y = 0; y < height; y++) {
                    for (int c = 0; c < channels; c++) {
                        column[y * channels + c] = alongX[((layer * height + y) * w2 + x) * channels + c];
                    }
                }
                for (int j = 0; j < h2; j++) {
                    java.util.Arrays.fill(sum, 0);
                    addSpan(column, height, h2, j, channels, sum, 0);
                    for (int c = 0; c < channels; c++) {
                        out[((layer * h2 + j) * w2 + x) * channels + c] = (float) sum[c];
                    }
                }
            }
        }
        return out;
    }

    /** Adds the box average of span i (of m spans over the n texels of {@code values}) into out[at..]. */
    private static void addSpan(double[] values, int n, int m, int i, int channels, double[] out, int at) {
        double width = (double) n / m;
        double lo = i * width;
        double hi = (i + 1) * width;
        for (int t = (int) Math.floor(lo); t < Math.min(n, (int) Math.ceil(hi)); t++) {
            double overlap = Math.min(hi, t + 1) - Math.max(lo, t);
            for (int c = 0; c < channels; c++) {
                out[at + c] += overlap / width * values[t * channels + c];
            }
        }
    }
}
