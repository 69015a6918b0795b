package diffract.render;

import diffract.jrtr.textures.FloatTexture3D;
import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;

import diffract.util.Reporter;

import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;

/**
 * The baked lobes table spread once by a wide disc light, for surfaces ({@code DISC_TABLE} in
 * {@code disc_table.glsl}): a lookup of the spread table costs what a Gaussian light's lookup costs, where
 * integrating the disc per pixel over the rows of the table ({@code baked_disc.glsl}) reads tens of rows.
 *
 * <p>Under a disc of half-angle R about omega_i, a pixel averages the point light's table over an ellipse in (u, v)
 * (disc_ellipse.glsl): semi-axis a = sin R along e (across the plane of incidence) and b = a cos theta_i along r (in
 * it). The ellipse depends on omega_i in the surface's own frame, which turns from scale to scale, so no one spread
 * serves every pixel. The family here does: member k is the table averaged over the round disc of radius
 * a c_k ({@link #MEMBER_COS}), which depends on the light's size only (not on where it is: it is redone when the size
 * changes, never when the light moves). A pixel with cos theta_i = c reads the member of the largest c_k <= c and
 * adds the rest of its ellipse as a Gaussian of the remaining covariance, (a^2 / 4)(1 - c_k^2) along e and
 * (a^2 / 4)(c^2 - c_k^2) along r, through the table's mip-mapped footprint lookup. Member 0 (c_0 = 0) is the point
 * table itself on the spread grid (averaged over a disc of half the grid's step, against aliasing: a variance of a
 * sixteenth of a step squared, left out of the rest): below the smallest disc member a pixel reads it with the disc's
 * whole covariance, as a disc narrow next to the pixel does. It lives in the members' texture rather than being read
 * from the table's own, so that every pixel runs one lookup path: a software rasteriser runs every branch its
 * pixels' lanes take, and two paths cost both everywhere. Between two members the pixel blends them over the upper
 * {@link #BLEND_FRACTION} of the interval, so that the picture does not jump where c crosses a c_k.
 *
 * <p>What it leaves out against the per-pixel rows: the density 1 / (Omega d_z), the gain factor and w vary across the
 * disc and are taken at its centre, and an ellipse narrower than its member's round disc along r is the Gaussian's
 * approximation. The GPU suite measures the staged scenes against the lobes method's still under the same disc
 * (docs/design/viewer.md).
 *
 * <p>Layout: side x side RGB samples over the table's (u, v) range (samples at both ends, as {@link BakedGrid}),
 * member k's w slices at layers k wSamples .. (k + 1) wSamples - 1, the table's own w samples; mip-mapped per layer.
 */
public final class DiscTable {
    /**
     * cos theta_i of the members: each holds the table spread by the round disc of radius sin R times it; member 0's
     * disc is the point light's (the table resampled, {@link #memberRadiusUv}).
     */
    static final double[] MEMBER_COS = {0, 0.55, 0.7, 0.85, 1.0};
    /** The fraction of each interval between two members, at its top, over which a pixel blends the two. */
    public static final double BLEND_FRACTION = 0.25;
    /**
     * A disc whose radius sin R spans fewer of the baked table's samples than this is integrated per pixel over the
     * table's rows instead: a few rows then, and a spread table would be the table itself.
     */
    public static final double MIN_RADIUS_SAMPLES = 4;
    /** The spread table's (u, v) grid keeps this many samples across the radius sin R, up to the table's own. */
    public static final double RADIUS_SAMPLES = 8;

    /** False: every disc is integrated over the table's rows (DiscTableSceneTest compares the two). */
    static volatile boolean enabled = true;

    private final int side;
    private final int wSamples;
    private final double halfAngleRad;
    private final float[] rgb;

    private DiscTable(int side, int wSamples, double halfAngleRad, float[] rgb) {
        this.side = side;
        this.wSamples = wSamples;
        this.halfAngleRad = halfAngleRad;
        this.rgb = rgb;
    }

    /** cos theta_i of each member, ascending. */
    public static double[] memberCos() {
        return MEMBER_COS.clone();
    }

    /**
     * Whether a surface drawn with {@code settings} from a filtered table on {@code grid} reads a spread table for its
     * disc: a disc light whose radius spans at least {@link #MIN_RADIUS_SAMPLES} of the table's samples.
     */
    public static boolean applies(BrdfSettings settings, BakedGrid grid) {
        return enabled && settings.illumination().light().isDisc()
                && radiusSamples(settings.illumination().light().halfAngleRad(), grid.uvSamples())
                >= MIN_RADIUS_SAMPLES;
    }

    /** Samples of a grid of n per axis across the radius sin R. */
    static double radiusSamples(double halfAngleRad, int n) {
        return Math.sin(halfAngleRad) * 0.25 * (n - 1);
    }

    /**
     * The spread grid's samples per axis never go below this (or the table's, where fewer): the point member serves
     * grazing light, whose ellipse is thin along r, at half the resolution of the 512-sample table at least.
     */
    public static final int MIN_SIDE = 257;

    /**
     * The spread grid's samples per axis: {@link #RADIUS_SAMPLES} across sin R and at least {@link #MIN_SIDE}, at most
     * the table's.
     */
    static int side(double halfAngleRad, int tableSamples) {
        int needed = (int) Math.ceil(RADIUS_SAMPLES / (0.25 * Math.sin(halfAngleRad))) + 1;
        return Math.min(Math.max(needed, MIN_SIDE), tableSamples);
    }

    /**
     * The radius in (u, v) of member m's round disc: sin R c_m, and for the point member (c_0 = 0) half the spread
     * grid's step, the resampling's prefilter.
     */
    public static double memberRadiusUv(int m, double halfAngleRad, int side) {
        double radius = Math.sin(halfAngleRad) * MEMBER_COS[m];
        return radius > 0 ? radius : 0.5 * (BakedGrid.U_MAX - BakedGrid.U_MIN) / (side - 1);
    }

    /** The filtered table spread by the disc of half-angle {@code halfAngleRad} for every member. */
    public static DiscTable of(BakedTable table, double halfAngleRad) {
        return of(table, halfAngleRad, Reporter.SILENT);
    }

    /** As {@link #of(BakedTable, double)}, its progress (per w slice) on {@code reporter}. */
    public static DiscTable of(BakedTable table, double halfAngleRad, Reporter reporter) {
        if (!table.filtered()) {
            throw new IllegalArgumentException("only a filtered table (of the lobes method) is spread by a disc");
        }
        BakedGrid grid = table.grid();
        int n = grid.uvSamples();
        int nw = grid.wSamples();
        int side = side(halfAngleRad, n);
        int members = MEMBER_COS.length;
        float[] out = new float[3 * side * side * nw * members];
        float[] values = table.values();
        String task = String.format(Locale.ROOT, "spreading the table by the %.3g-degree disc",
                Math.toDegrees(2 * halfAngleRad));
        AtomicInteger done = new AtomicInteger();
        reporter.progress(task, 0);
        IntStream.range(0, nw).parallel().forEach(k -> {
            Bands bands = Bands.of(values, n, k, Math.max(1, (n - 1) / (side - 1)));
            for (int member = 0; member < members; member++) {
                bands.spread(memberRadiusUv(member, halfAngleRad, side), side, out,
                        3 * side * side * (member * nw + k));
            }
            reporter.progress(task, done.incrementAndGet() / (double) nw);
        });
        return new DiscTable(side, nw, halfAngleRad, out);
    }

    /**
     * One w slice of the table as bands of {@code pool} rows and their running sums along u at the edges of cells
     * {@code pool} samples wide: the table's interpolant held constant on its cells (BakedDisc.rowSums), cell i
     * spanning [u_i - h/2, u_i + h/2), so that band b's running sum at edge e is the table's integral over the band's
     * area up to u = u_min - h/2 + e pool h (the last band and cell may be narrower).
     *
     * @param sums    per channel, band b's sums at index b (edges + 1) + e
     * @param heights each band's height in v
     */
    private record Bands(int pool, int count, int edges, double h, double[][] sums, double[] heights) {
        static Bands of(float[] values, int n, int k, int pool) {
            double h = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (n - 1);
            int count = (n + pool - 1) / pool;
            int edges = count + 1;
            double[][] sums = new double[3][count * edges];
            double[] heights = new double[count];
            for (int b = 0; b < count; b++) {
                int rows = Math.min(n, (b + 1) * pool) - b * pool;
                heights[b] = rows * h;
                for (int c = 0; c < 3; c++) {
                    double[] band = sums[c];
                    double before = 0;
                    for (int e = 1; e < edges; e++) {
                        for (int i = (e - 1) * pool; i < Math.min(n, e * pool); i++) {
                            for (int j = b * pool; j < b * pool + rows; j++) {
                                before += values[3 * (i + n * (j + n * k)) + c];
                            }
                        }
                        band[b * edges + e] = h * h * before;
                    }
                }
            }
            return new Bands(pool, count, edges, h, sums, heights);
        }

        /**
         * The slice averaged over the round disc of radius rho (u, v units) about each of side x side points, into
         * out at offset: the disc's area within a band is exact (a circle's segment), spent as a chord of that mean
         * width across the whole band, whose integral along u is a difference of the band's running sums. Zero beyond
         * the table (unreachable directions), divided by the whole disc's area.
         */
        void spread(double rho, int side, float[] out, int offset) {
            double step = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (side - 1);
            double cell = pool * h;
            double origin = BakedGrid.U_MIN - 0.5 * h; // the first edge
            double area = Math.PI * rho * rho;
            int maxBands = (int) Math.ceil(2 * rho / cell) + 3;
            int[] inDisc = new int[maxBands];
            double[] halfWidths = new double[maxBands];
            double[] sumsR = sums[0];
            double[] sumsG = sums[1];
            double[] sumsB = sums[2];
            for (int y = 0; y < side; y++) {
                double v = BakedGrid.U_MIN + y * step;
                int found = 0;
                int first = Math.max(0, (int) Math.floor((v - rho - origin) / cell));
                int last = Math.min(count - 1, (int) Math.floor((v + rho - origin) / cell));
                for (int b = first; b <= last; b++) {
                    double low = origin + b * cell;
                    double inBand = segmentArea(low + heights[b] - v, rho) - segmentArea(low - v, rho);
                    if (inBand > 0) {
                        inDisc[found] = b;
                        halfWidths[found] = inBand / (2 * heights[b]);
                        found++;
                    }
                }
                for (int x = 0; x < side; x++) {
                    double t = (BakedGrid.U_MIN + x * step - origin) / cell;
                    double r = 0;
                    double g = 0;
                    double bl = 0;
                    for (int q = 0; q < found; q++) {
                        int row = inDisc[q] * edges;
                        double reach = halfWidths[q] / cell;
                        double t1 = Math.min(t + reach, count);
                        double t0 = Math.max(t - reach, 0);
                        if (t1 <= t0) {
                            continue;
                        }
                        int i1 = Math.min((int) t1, count - 1);
                        double f1 = t1 - i1;
                        int i0 = Math.min((int) t0, count - 1);
                        double f0 = t0 - i0;
                        int a1 = row + i1;
                        int a0 = row + i0;
                        r += sumsR[a1] + f1 * (sumsR[a1 + 1] - sumsR[a1]) - sumsR[a0] - f0 * (sumsR[a0 + 1] - sumsR[a0]);
                        g += sumsG[a1] + f1 * (sumsG[a1 + 1] - sumsG[a1]) - sumsG[a0] - f0 * (sumsG[a0 + 1] - sumsG[a0]);
                        bl += sumsB[a1] + f1 * (sumsB[a1 + 1] - sumsB[a1]) - sumsB[a0] - f0 * (sumsB[a0 + 1] - sumsB[a0]);
                    }
                    int to = offset + 3 * (x + side * y);
                    out[to] = (float) (r / area);
                    out[to + 1] = (float) (g / area);
                    out[to + 2] = (float) (bl / area);
                }
            }
        }
    }

    /** The area of the disc of radius rho below the line at height y from its centre (0 below, pi rho^2 above). */
    static double segmentArea(double y, double rho) {
        if (y <= -rho) {
            return 0;
        }
        if (y >= rho) {
            return Math.PI * rho * rho;
        }
        return y * Math.sqrt(rho * rho - y * y) + rho * rho * Math.asin(y / rho) + 0.5 * Math.PI * rho * rho;
    }

    public int side() {
        return side;
    }

    public int wSamples() {
        return wSamples;
    }

    public double halfAngleRad() {
        return halfAngleRad;
    }

    /** XYZ of member m at sample (i, j) of (u, v) and w sample k. */
    public float[] xyzAt(int m, int i, int j, int k) {
        int at = 3 * (i + side * (j + side * (k + wSamples * m)));
        return new float[] {rgb[at], rgb[at + 1], rgb[at + 2]};
    }

    /** A new texture of the members for one GL context: one mip-mapped layer per member and w slice. */
    public FloatTexture3D texture() {
        return new FloatTexture3D(side, side, wSamples * MEMBER_COS.length, rgb, BakedTable.PRECISION, true);
    }

    /** One line: the grid, the members and the memory. */
    public String describe() {
        return String.format(Locale.ROOT, "%d x %d x %d table spread by a %.3g-degree disc for %d members, %.1f MB",
                side, side, wSamples, Math.toDegrees(2 * halfAngleRad), MEMBER_COS.length,
                4.0 / 3 * 6 * rgb.length / 3 / 1e6);
    }
}
