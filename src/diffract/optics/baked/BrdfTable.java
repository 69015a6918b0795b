package diffract.optics.baked;

import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.optics.BakedGrid;
import diffract.optics.DiffractionBrdf;
import diffract.optics.LobeSpectrum;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.Footprint;
import diffract.optics.illumination.GainFactor;
import diffract.optics.numerics.Covariance2;
import diffract.optics.settings.GainModel;
import diffract.util.Reporter;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;

/**
 * The lobes method's spectral factor of a patch, tabulated on the CPU over the baked table's grid ({@link BakedGrid}:
 * (u, v, w) = -omega_i - omega_r) in linear sRGB, for renderers outside diffract (Mitsuba 3, docs/guide/mitsuba.md). The
 * factor depends on the two directions only through (u, v, w), so one table serves every incident direction; the
 * gain factor and shadowing, which vary fast near the horizon, stay analytic ({@link #relative}).
 *
 * <p>Each node holds the average over its cell's box in (u, v) (side 4 / (n - 1)) under a point light: an order
 * narrower than a cell keeps its energy instead of falling between nodes, and a renderer brings the light's own size.
 * Nodes that no pair of directions above the horizon reaches, nor any neighbour of theirs, hold 0 without being
 * computed: there |(u, v)| &gt; 2 or |w| &gt; 2 sqrt(1 - |(u, v)|^2 / 4).
 */
public final class BrdfTable {
    private final BakedGrid grid;
    private final float[] rgb;
    private final double refractiveIndex;
    private final GainModel gainModel;

    /**
     * @param rgb linear sRGB, 3 floats per node at {@code 3 (i + n (j + n k))} (i along u, j along v, k along w)
     */
    public BrdfTable(BakedGrid grid, float[] rgb, double refractiveIndex, GainModel gain) {
        if (rgb.length != 3 * grid.texels()) {
            throw new IllegalArgumentException("table of " + grid + " needs " + 3 * grid.texels() + " floats, got "
                    + rgb.length);
        }
        this.grid = grid;
        this.rgb = rgb;
        this.refractiveIndex = refractiveIndex;
        this.gainModel = gain;
    }

    /** Tabulates a lobes-method BRDF (point light) over {@code grid}, rows in parallel. */
    public static BrdfTable of(DiffractionBrdf brdf, BakedGrid grid, Reporter reporter) {
        LobeSpectrum lobes = brdf.lobes();
        if (lobes == null) {
            throw new IllegalArgumentException("the table holds the lobes method; build the BRDF with Variant.LOBES");
        }
        int n = grid.uvSamples();
        int rows = n * grid.wSamples();
        float[] rgb = new float[(int) (3 * grid.texels())];
        Footprint cell = cellFootprint(grid);
        AtomicInteger done = new AtomicInteger();
        String task = String.format(java.util.Locale.ROOT, "tabulating %d x %d x %d nodes", n, n, grid.wSamples());
        IntStream.range(0, rows).parallel().forEach(row -> {
            int j = row % n;
            int k = row / n;
            double v = grid.uv(j);
            double w = grid.w(k);
            for (int i = 0; i < n; i++) {
                double u = grid.uv(i);
                if (!nearReachable(grid, u, v, w)) {
                    continue;
                }
                double[] xyz = lobes.xyz(u, v, w, cell);
                double[] lin = Srgb.linearFromXyz(new Xyz(xyz[0], xyz[1], xyz[2]));
                int p = 3 * (i + n * (j + n * k));
                rgb[p] = (float) lin[0];
                rgb[p + 1] = (float) lin[1];
                rgb[p + 2] = (float) lin[2];
            }
            int finished = done.incrementAndGet();
            if (finished % n == 0 || finished == rows) {
                reporter.progress(task, finished / (double) rows);
            }
        });
        return new BrdfTable(grid, rgb, brdf.illumination().refractiveIndex(), brdf.illumination().gain());
    }

    /** A node's cell: a box of one node spacing in u and v. */
    public static Footprint cellFootprint(BakedGrid grid) {
        double half = 0.5 * (BakedGrid.U_MAX - BakedGrid.U_MIN) / (grid.uvSamples() - 1);
        return new Footprint(half, half, Covariance2.ZERO);
    }

    /**
     * Whether a point within one node spacing of (u, v, w) (along each axis) is reached by directions above the
     * horizon: |(u, v)| &lt;= 2 and -w &lt;= 2 sqrt(1 - |(u, v)|^2 / 4), the sum of two cosines whose sines add up to
     * |(u, v)| being largest when both are equal.
     */
    static boolean nearReachable(BakedGrid grid, double u, double v, double w) {
        double huv = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (grid.uvSamples() - 1);
        double hw = (BakedGrid.W_MAX - BakedGrid.W_MIN) / (grid.wSamples() - 1);
        double r = Math.max(0, Math.hypot(u, v) - Math.sqrt(2) * huv);
        if (r > 2) {
            return false;
        }
        return -(w + hw) <= 2 * Math.sqrt(Math.max(0, 1 - r * r / 4));
    }

    public BakedGrid grid() {
        return grid;
    }

    /** The floats, 3 per node, i (u) fastest, then j (v), then k (w): a (w, v, u, rgb) array in C order. */
    public float[] rgb() {
        return rgb;
    }

    public double refractiveIndex() {
        return refractiveIndex;
    }

    public GainModel gain() {
        return gainModel;
    }

    /** Linear sRGB of node (i, j, k). */
    public double[] node(int i, int j, int k) {
        int p = 3 * (i + grid.uvSamples() * (j + grid.uvSamples() * k));
        return new double[] {rgb[p], rgb[p + 1], rgb[p + 2]};
    }

    /** The table trilinearly interpolated at (u, v, w), clamped to the grid (the plugin's texture lookup). */
    public double[] at(double u, double v, double w) {
        int n = grid.uvSamples();
        double fu = clamp((u - BakedGrid.U_MIN) / (BakedGrid.U_MAX - BakedGrid.U_MIN) * (n - 1), n - 1);
        double fv = clamp((v - BakedGrid.U_MIN) / (BakedGrid.U_MAX - BakedGrid.U_MIN) * (n - 1), n - 1);
        double fw = clamp((w - BakedGrid.W_MIN) / (BakedGrid.W_MAX - BakedGrid.W_MIN) * (grid.wSamples() - 1),
                grid.wSamples() - 1);
        int i0 = Math.min((int) fu, n - 2);
        int j0 = Math.min((int) fv, n - 2);
        int k0 = Math.min((int) fw, grid.wSamples() - 2);
        double tu = fu - i0;
        double tv = fv - j0;
        double tw = fw - k0;
        double[] out = new double[3];
        for (int c = 0; c < 8; c++) {
            int di = c & 1;
            int dj = (c >> 1) & 1;
            int dk = (c >> 2) & 1;
            double weight = (di == 1 ? tu : 1 - tu) * (dj == 1 ? tv : 1 - tv) * (dk == 1 ? tw : 1 - tw);
            double[] value = node(i0 + di, j0 + dj, k0 + dk);
            for (int ch = 0; ch < 3; ch++) {
                out[ch] += weight * value[ch];
            }
        }
        return out;
    }

    private static double clamp(double x, int max) {
        return Math.max(0, Math.min(max, x));
    }

    /**
     * The relative BRDF in linear sRGB (what {@code brdfmap --pfm} writes per direction): the gain factor and
     * shadowing times the interpolated table. omega_i towards the light, omega_r towards the viewer.
     */
    public double[] relative(Direction wi, Direction wr) {
        double gain = GainFactor.gainTimesShadowing(wi, wr, refractiveIndex, gainModel);
        if (gain == 0) {
            return new double[3];
        }
        double[] t = at(-wi.x() - wr.x(), -wi.y() - wr.y(), -wi.z() - wr.z());
        return new double[] {gain * t[0], gain * t[1], gain * t[2]};
    }
}
