package diffract.render;

import diffract.jrtr.textures.FloatTexture3D;
import diffract.lighting.ExtendedLight;
import diffract.optics.BakedGrid;
import diffract.optics.illumination.LightSource;

import java.util.List;
import java.util.stream.IntStream;

/**
 * The baked lobes table spread once per environment light, for the staged surface of the baked variant
 * ({@code SKY_TABLE} in {@code surface_stage.glsl}): a light of sigma_a widens every order by the Gaussian of covariance
 * sigma_a^2 (cos^2 theta_i r r^T + e e^T) in (u, v) (LightSource.uvCovariance), and for a sky's lights (tens of degrees
 * wide) that spread is far wider than a pixel's footprint or the table's cells. So each light's share is looked up in a
 * copy of the table spread in advance by an isotropic Gaussian of that light, one lookup per light instead
 * of a footprint's four mip-mapped ones, on the coarser grid that the spread allows (a small texture stays in the
 * cache).
 *
 * <p>The isotropic stand-in: cos^2 theta_i is taken as the light's elevation above the ground plane (y up), where the
 * staged scenes' surfaces face: variance sigma_a^2 (1 + cos^2 theta) / 2 per axis, the mean of the true covariance's
 * two axes. The table's own light (sigma_a of the settings, isotropic), the pooling of table cells and the lookup's
 * bilinear tent are taken off that variance. What this costs against the footprint lookup of the lobes method's
 * still is measured by the GPU suite (docs/design/viewer.md).
 *
 * <p>Layout: a 2-D array of side x side RGB samples per layer, light k's w slices at layers k wSamples ..
 * (k + 1) wSamples - 1, each over the table's (u, v) range at side samples per axis; the w slices are W_OVERSAMPLING
 * times as dense as the table's, linear in between, and the lookup takes the nearest (one bilinear lookup per light:
 * half a trilinear one's work).
 */
public final class SkyTable {
    /**
     * cos^2 theta_i of the isotropic stand-in: its mean over the directions a light reaches a surface from, weighted by
     * the irradiance cos theta_i they bring, int cos^3 / int cos = 1 / 2 over the hemisphere.
     */
    public static final double MEAN_COS2_THETA_I = 0.5;
    /** Most samples per axis of (u, v) of a light's spread table. */
    public static final int MAX_SIDE = 128;
    /** Fewest samples per axis of (u, v). */
    public static final int MIN_SIDE = 16;
    /** Samples per standard deviation of the narrowest light's spread that the (u, v) grid keeps. */
    public static final double SAMPLES_PER_SIGMA = 1.5;
    /** w samples of the spread tables per sample of the baked table (linear in between). */
    public static final int W_OVERSAMPLING = 4;

    private final int side;
    private final int wSamples;
    private final int lights;
    private final float[] rgb;

    private SkyTable(int side, int wSamples, int lights, float[] rgb) {
        this.side = side;
        this.wSamples = wSamples;
        this.lights = lights;
        this.rgb = rgb;
    }

    /**
     * The table spread for each of {@code lights}; {@code tableLightSigmaRad} is the light the table holds already.
     */
    public static SkyTable of(BakedTable table, List<ExtendedLight> lights, double tableLightSigmaRad) {
        BakedGrid grid = table.grid();
        int n = grid.uvSamples();
        int nw = grid.wSamples();
        double[] sigmaUv = new double[lights.size()];
        double narrowest = Double.POSITIVE_INFINITY;
        for (int k = 0; k < lights.size(); k++) {
            ExtendedLight light = lights.get(k);
            double sigma = LightSource.sigmaRadOf(light.angularDiameterDeg());
            sigmaUv[k] = sigma * Math.sqrt((1 + MEAN_COS2_THETA_I) / 2);
            narrowest = Math.min(narrowest, sigmaUv[k]);
        }
        int side = side(narrowest, n);
        int pool = Math.max(1, n / side);
        Pooled pooled = Pooled.of(table.values(), n, nw, pool);
        double step = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (side - 1);
        int slices = W_OVERSAMPLING * (nw - 1) + 1;
        float[] out = new float[3 * side * side * slices * lights.size()];
        float[] one = new float[3 * side * side * nw];
        for (int k = 0; k < lights.size(); k++) {
            double variance = sigmaUv[k] * sigmaUv[k] - tableLightSigmaRad * tableLightSigmaRad
                    - pooled.spacing * pooled.spacing / 12 - step * step / 6;
            spread(pooled, side, Math.sqrt(Math.max(variance, 0)), one);
            oversampleW(one, side * side, nw, out, k * 3 * side * side * slices);
        }
        return new SkyTable(side, slices, lights.size(), out);
    }

    /**
     * The (u, v) samples per axis: SAMPLES_PER_SIGMA across the narrowest light's spread, a power of two from
     * MIN_SIDE to MAX_SIDE and never more than the table's own.
     */
    static int side(double narrowestSigmaUv, int tableSamples) {
        double range = BakedGrid.U_MAX - BakedGrid.U_MIN;
        int needed = (int) Math.ceil(SAMPLES_PER_SIGMA * range / narrowestSigmaUv) + 1;
        int side = MIN_SIDE;
        while (side < needed && side < MAX_SIDE) {
            side *= 2;
        }
        return Math.min(side, tableSamples);
    }

    /** Slices m / W_OVERSAMPLING of the table's nw w slices, linear between them (the lookup takes the nearest). */
    private static void oversampleW(float[] rgb, int perSlice, int nw, float[] out, int offset) {
        int slices = W_OVERSAMPLING * (nw - 1) + 1;
        for (int m = 0; m < slices; m++) {
            int below = Math.min(m / W_OVERSAMPLING, nw - 2);
            float t = (m - below * W_OVERSAMPLING) / (float) W_OVERSAMPLING;
            for (int i = 0; i < 3 * perSlice; i++) {
                out[offset + 3 * perSlice * m + i] = (1 - t) * rgb[3 * perSlice * below + i]
                        + t * rgb[3 * perSlice * (below + 1) + i];
            }
        }
    }

    /** The table's cells averaged over pool x pool blocks, at the blocks' mean (u, v). */
    private record Pooled(float[] rgb, int count, int wSamples, double[] position, double[] weight, double spacing) {
        static Pooled of(float[] values, int n, int nw, int pool) {
            int count = (n + pool - 1) / pool;
            double du = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (n - 1);
            double[] position = new double[count];
            double[] weight = new double[count];
            for (int a = 0; a < count; a++) {
                int first = a * pool;
                int last = Math.min(n, first + pool) - 1;
                position[a] = BakedGrid.U_MIN + du * (first + last) / 2.0;
                weight[a] = (last - first + 1) * du; // the u range the block's mean stands for
            }
            float[] rgb = new float[3 * count * count * nw];
            for (int w = 0; w < nw; w++) {
                for (int j = 0; j < n; j++) {
                    for (int i = 0; i < n; i++) {
                        int from = 3 * (i + n * (j + n * w));
                        int to = 3 * (i / pool + count * (j / pool + count * w));
                        for (int ch = 0; ch < 3; ch++) {
                            rgb[to + ch] += values[from + ch];
                        }
                    }
                }
                for (int b = 0; b < count; b++) {
                    for (int a = 0; a < count; a++) {
                        int cells = (int) Math.round(weight[a] / du) * (int) Math.round(weight[b] / du);
                        int to = 3 * (a + count * (b + count * w));
                        for (int ch = 0; ch < 3; ch++) {
                            rgb[to + ch] /= cells;
                        }
                    }
                }
            }
            return new Pooled(rgb, count, nw, position, weight, pool * du);
        }
    }

    /**
     * The pooled table convolved with an isotropic Gaussian of standard deviation sigmaUv (u and v units), zero beyond
     * the table (unreachable directions), sampled at side x side points over the table's range: separable, u then v,
     * each a Riemann sum over the blocks.
     */
    private static void spread(Pooled p, int side, double sigmaUv, float[] out) {
        double step = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (side - 1);
        double[][] kernel = new double[side][p.count];
        for (int j = 0; j < side; j++) {
            double at = BakedGrid.U_MIN + j * step;
            if (sigmaUv == 0) {
                kernel[j][nearest(p, at)] = 1;
                continue;
            }
            for (int a = 0; a < p.count; a++) {
                kernel[j][a] = p.weight[a] * gaussian(at - p.position[a], sigmaUv);
            }
        }
        int count = p.count;
        IntStream.range(0, p.wSamples).parallel().forEach(w -> {
            double[] alongU = new double[3 * side * count]; // (j, b): spread along u
            for (int b = 0; b < count; b++) {
                for (int j = 0; j < side; j++) {
                    double r = 0, g = 0, bl = 0;
                    double[] kj = kernel[j];
                    for (int a = 0; a < count; a++) {
                        double k = kj[a];
                        if (k == 0) {
                            continue;
                        }
                        int at = 3 * (a + count * (b + count * w));
                        r += k * p.rgb[at];
                        g += k * p.rgb[at + 1];
                        bl += k * p.rgb[at + 2];
                    }
                    int to = 3 * (j + side * b);
                    alongU[to] = r;
                    alongU[to + 1] = g;
                    alongU[to + 2] = bl;
                }
            }
            for (int l = 0; l < side; l++) {
                double[] kl = kernel[l];
                for (int j = 0; j < side; j++) {
                    double r = 0, g = 0, bl = 0;
                    for (int b = 0; b < count; b++) {
                        double k = kl[b];
                        if (k == 0) {
                            continue;
                        }
                        int at = 3 * (j + side * b);
                        r += k * alongU[at];
                        g += k * alongU[at + 1];
                        bl += k * alongU[at + 2];
                    }
                    int to = 3 * (j + side * (l + side * w));
                    out[to] = (float) r;
                    out[to + 1] = (float) g;
                    out[to + 2] = (float) bl;
                }
            }
        });
    }

    /** A Gaussian density, cut at 5 standard deviations (its weight beyond is below 3e-7). */
    private static double gaussian(double x, double sigma) {
        double t = x / sigma;
        return Math.abs(t) > 5 ? 0 : Math.exp(-0.5 * t * t) / (Math.sqrt(2 * Math.PI) * sigma);
    }

    /** Without a spread: the block nearest to {@code at} (the first of two as near), which gets weight 1. */
    private static int nearest(Pooled p, double at) {
        int best = 0;
        for (int b = 1; b < p.count; b++) {
            if (Math.abs(at - p.position[b]) < Math.abs(at - p.position[best])) {
                best = b;
            }
        }
        return best;
    }

    public int side() {
        return side;
    }

    public int wSamples() {
        return wSamples;
    }

    public int lights() {
        return lights;
    }

    /** XYZ of light k's spread table at sample (i, j) of (u, v) and w sample m. */
    public float[] xyzAt(int k, int i, int j, int m) {
        int at = 3 * (i + side * (j + side * (m + wSamples * k)));
        return new float[] {rgb[at], rgb[at + 1], rgb[at + 2]};
    }

    /** A new texture of the spread tables for one GL context: one layer per w slice, bilinear in (u, v). */
    public FloatTexture3D texture() {
        return FloatTexture3D.layers(side, side, wSamples * lights, rgb, BakedTable.PRECISION);
    }
}
