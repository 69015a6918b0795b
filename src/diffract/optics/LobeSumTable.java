package diffract.optics;

import diffract.optics.lobes.LobeWeightTable;
import diffract.optics.windows.CoherenceWindow;

/**
 * The lobes method's texel sums, for scans wider than about two thirds of the coherence length (docs/design/filtering.md,
 * section 6; docs/measurements/scans.md). There a pixel reaches hundreds of lobes, each closer to the next than its own width, and
 * marching over them one by one costs more than the thesis' FLSS; instead the averaged window's |P|^2 =
 * sum_m W_m(a) exp(-|s - m|^2 / sigma_f^2) (docs/design/theory.md, the window averaged over its position) is integrated over
 * the footprint's box in s = (u L_x, v L_y) / lambda with each lobe's mass spread over its texel's cell
 * [m - 1/2, m + 1/2]^2, so that a box's integral is four corners of a summed-area table.
 *
 * <p><b>Spread.</b> A lobe of the averaged window has the variance sigma_f^2 / 2 per axis (in texels), a cell of one
 * texel 1 / 12: the weights are first convolved per axis with a kernel of the variance between, sigma_f^2 / 2 - 1 /
 * 12, so that every lobe's spread has its true mean and variance ({@link #applies}: only where that is not negative,
 * sigma_f &gt;= 1 / sqrt(6) texels). Its shape is the cell's convolved with the kernel's, not a Gaussian: within a
 * footprint at least a cell wide, what counts is the lobe's mass and its centre. Where lobes are wider still the
 * cells are c texels wide ({@link #cellTexels}), each texel's mass split between the two cells nearest its centre
 * (which keeps its mean) and the kernel narrowed by what cells and split add: the spectrum resampled on the lobes'
 * own scale, c^2 times fewer cells.
 *
 * <p><b>Tails.</b> In each quadrant of the texel grid (m_x &gt;= 0 or &lt; 0, m_y &gt;= 0 or &lt; 0) the table holds
 * the sums from each cell corner outwards, T(I, J) = sum over cells i &gt;= I, j &gt;= J, counted from the grid's
 * centre. A box's sum is T(inner corner) - T(two side corners) + T(outer corner); its float32 rounding is relative
 * to what lies beyond the box's inner corner, where the spectrum of a rough surface has decayed, not to the mirror's
 * power, which a summed-area table counted from one corner of the grid would carry into every box.
 *
 * <p><b>Phase.</b> For each of the weight table's K samples of p = -a ({@link LobeWeightTable}), T of W and of
 * delta dW/dp: the cubic Hermite polynomial between two samples is linear in its data, so the sums interpolate as
 * the weights do.
 *
 * <p><b>Layout</b> (the GPU's, {@code lobes_sum.glsl}): one RGBA layer per interval [k, k + 1] of samples, its T of
 * (W, delta dW/dp) at k and at k + 1, 2 (n_x + 2) x 2 (n_y + 2) texels,
 * the quadrant (q_x, q_y) (0: m &gt;= 0, 1: m &lt; 0) at (q_x (n_x + 2), q_y (n_y + 2)); corner I of the quadrant's
 * local coordinate t = +-(s + 1/2) / c (in cells) at texel I, so that linear filtering between corners integrates the cells exactly;
 * T = 0 at I = n_x and n_x + 1 (and along y), where every quadrant's texels end, so that the filter's neighbour of a
 * clamped corner is 0 and never the next quadrant's. Values are rounded to float32 here; the CPU reads the same
 * numbers ({@link #boxSum}).
 */
public final class LobeSumTable {
    /** The narrowest lobe whose variance reaches a cell's: sigma_f^2 / 2 &gt;= 1 / 12, in texels. */
    public static final double MIN_SIGMA_TEXELS = Math.sqrt(1.0 / 6);
    /** The widest variance one pass of the three-tap kernel takes while its centre tap stays at least half. */
    private static final double PASS_VARIANCE = 0.5;

    /** Texels per cell along each axis, c. */
    private final int cell;
    private final int cellsX;
    private final int cellsY;
    private final int width;
    private final int height;
    private final int samples;
    private final double stepPerUm;
    /**
     * Per interval [k, k + 1] of samples: (T of W and of delta dW/dp at k, the same at k + 1) interleaved, width x
     * height, row 0 first: one fetch holds a corner's Hermite data.
     */
    private final float[][] layers;

    /**
     * Whether the lobes method sums these texels from the table: the window averaged over its position (no texel
     * pairs), a tabulated weight, sums asked for ({@link LobeQuadrature#sumNodesPerBox}) and lobes at least as
     * wide as a cell on both axes.
     */
    public static boolean applies(CoherenceWindow window, LobeQuadrature quadrature, double extentXUm,
                                  double extentYUm) {
        return window.averaged() && quadrature.sumNodesPerBox() > 0 && quadrature.weightTolerance() > 0
                && window.sigmaTexels(extentXUm) >= MIN_SIGMA_TEXELS
                && window.sigmaTexels(extentYUm) >= MIN_SIGMA_TEXELS;
    }

    /**
     * The heap the table of a rows x cols grid with K samples and lobes sigma_f texels wide takes, for the estimates
     * made before the work.
     */
    public static long bytes(int rows, int cols, long samples, double sigmaTexelsX, double sigmaTexelsY) {
        int c = cellTexels(Math.min(sigmaTexelsX, sigmaTexelsY));
        return 16L * 2 * (cells(cols, c) + 2) * 2 * (cells(rows, c) + 2) * (samples - 1);
    }

    /** Cells per half of an axis of n texels: the larger half, m &gt;= 0, in cells of c texels. */
    private static int cells(int n, int c) {
        return (n - n / 2 + c - 1) / c;
    }

    /**
     * The texels per cell, c: the most whose spread (the cell's own variance c^2 / 12 and the split of each texel's
     * mass between the two cells nearest its centre) stays within a lobe's variance sigma_f^2 / 2. 1 below sigma_f =
     * 1.47 texels (scans narrower than 150 um at 65 um), 2 for a 200 um scan: the table is c^2 times smaller.
     */
    static int cellTexels(double sigmaTexels) {
        int c = 1;
        while (c < 64 && spreadVariance(c + 1) <= 0.5 * sigmaTexels * sigmaTexels) {
            c++;
        }
        return c;
    }

    /** The variance a texel's mass takes in cells of c texels: the cell's, c^2 / 12, and its split's on average. */
    static double spreadVariance(int c) {
        double split = 0;
        for (int i = 0; i < c; i++) {
            double f = splitFraction(i, c);
            split += f * (1 - f);
        }
        return c * c * (1.0 / 12 + split / c);
    }

    /** The fraction of texel i's mass that goes to the next cell: its centre's offset past its cell's centre. */
    private static double splitFraction(int i, int c) {
        double x = (i + 0.5) / c - 0.5;
        return x - Math.floor(x);
    }

    /**
     * @param weights       the lobe weights over the phase
     * @param sigmaTexelsX  sigma_f in texels along x (at least {@link #MIN_SIGMA_TEXELS})
     * @param sigmaTexelsY  along y
     */
    public LobeSumTable(LobeWeightTable weights, double sigmaTexelsX, double sigmaTexelsY) {
        if (!(sigmaTexelsX >= MIN_SIGMA_TEXELS && sigmaTexelsY >= MIN_SIGMA_TEXELS)) {
            throw new IllegalArgumentException("texel sums need lobes at least as wide as a cell, sigma_f >= "
                    + MIN_SIGMA_TEXELS + " texels, got " + sigmaTexelsX + " x " + sigmaTexelsY);
        }
        int rows = weights.rows();
        int cols = weights.cols();
        this.cell = cellTexels(Math.min(sigmaTexelsX, sigmaTexelsY));
        this.cellsX = cells(cols, cell);
        this.cellsY = cells(rows, cell);
        this.width = 2 * (cellsX + 2);
        this.height = 2 * (cellsY + 2);
        this.samples = weights.samples();
        this.stepPerUm = weights.stepPerUm();
        double[][] kernelX = kernelPasses(0.5 * sigmaTexelsX * sigmaTexelsX - spreadVariance(cell));
        double[][] kernelY = kernelPasses(0.5 * sigmaTexelsY * sigmaTexelsY - spreadVariance(cell));
        java.util.List<float[]> source = weights.layers();
        this.layers = new float[samples - 1][];
        double[] value = new double[rows * cols];
        double[] scratch = new double[rows * cols];
        float[] previous = null;
        for (int k = 0; k < samples; k++) {
            float[] layer = new float[2 * width * height];
            for (int channel = 0; channel < 2; channel++) {
                float[] in = source.get(k);
                for (int i = 0; i < rows * cols; i++) {
                    value[i] = in[2 * i + channel];
                }
                for (double[] pass : kernelX) {
                    convolve(value, scratch, rows, cols, pass, true);
                }
                for (double[] pass : kernelY) {
                    convolve(value, scratch, rows, cols, pass, false);
                }
                tails(value, rows, cols, layer, channel);
            }
            if (previous != null) {
                float[] packed = new float[4 * width * height];
                for (int i = 0; i < width * height; i++) {
                    packed[4 * i] = previous[2 * i];
                    packed[4 * i + 1] = previous[2 * i + 1];
                    packed[4 * i + 2] = layer[2 * i];
                    packed[4 * i + 3] = layer[2 * i + 1];
                }
                layers[k - 1] = packed;
            }
            previous = layer;
        }
    }

    /**
     * Passes of a symmetric three-tap kernel (v / 2, 1 - v, v / 2), whose variances add up to {@code variance}:
     * the binomial-like kernel of many passes tends to the Gaussian of that variance.
     */
    private static double[][] kernelPasses(double variance) {
        if (variance <= 0) {
            return new double[0][];
        }
        int n = (int) Math.ceil(variance / PASS_VARIANCE - 1e-12);
        double v = variance / n;
        double[][] passes = new double[n][];
        for (int i = 0; i < n; i++) {
            passes[i] = new double[] {v / 2, 1 - v, v / 2};
        }
        return passes;
    }

    /** One pass of the three-tap kernel along x (or y), in place; texels beyond the grid are 0. */
    private static void convolve(double[] value, double[] scratch, int rows, int cols, double[] taps, boolean alongX) {
        System.arraycopy(value, 0, scratch, 0, value.length);
        for (int row = 0; row < rows; row++) {
            for (int col = 0; col < cols; col++) {
                double sum = taps[1] * scratch[row * cols + col];
                if (alongX) {
                    sum += col > 0 ? taps[0] * scratch[row * cols + col - 1] : 0;
                    sum += col + 1 < cols ? taps[2] * scratch[row * cols + col + 1] : 0;
                } else {
                    sum += row > 0 ? taps[0] * scratch[(row - 1) * cols + col] : 0;
                    sum += row + 1 < rows ? taps[2] * scratch[(row + 1) * cols + col] : 0;
                }
                value[row * cols + col] = sum;
            }
        }
    }

    /**
     * The quadrants' outward sums of one channel of the term grid, in double, into the layer's channel: each texel's
     * value split between the two cells nearest its centre along each axis, across the axes through the origin too
     * (the cells of both halves lie c texels apart), so that the cells keep its mass and its mean; beyond the last
     * cell of a half it stays in that cell.
     */
    private void tails(double[] value, int rows, int cols, float[] layer, int channel) {
        // cells G = -n..n-1 per axis: G >= 0 is cell G of the half m >= 0, G < 0 cell -1 - G of the other
        int nx = 2 * cellsX;
        double[] mass = new double[nx * 2 * cellsY];
        for (int row = 0; row < rows; row++) {
            double y = (row - rows / 2 - (cell - 1) / 2.0) / cell;
            int y0 = (int) Math.floor(y);
            double fy = y - y0;
            for (int col = 0; col < cols; col++) {
                double w = value[row * cols + col];
                if (w == 0) {
                    continue;
                }
                double x = (col - cols / 2 - (cell - 1) / 2.0) / cell;
                int x0 = (int) Math.floor(x);
                double fx = x - x0;
                for (int b = 0; b < 2; b++) {
                    int gy = Math.min(cellsY - 1, Math.max(-cellsY, y0 + b)) + cellsY;
                    double wy = b == 0 ? 1 - fy : fy;
                    for (int a = 0; a < 2; a++) {
                        int gx = Math.min(cellsX - 1, Math.max(-cellsX, x0 + a)) + cellsX;
                        mass[gy * nx + gx] += w * wy * (a == 0 ? 1 - fx : fx);
                    }
                }
            }
        }
        double[] t = new double[(cellsX + 1) * (cellsY + 1)];
        for (int qy = 0; qy < 2; qy++) {
            for (int qx = 0; qx < 2; qx++) {
                java.util.Arrays.fill(t, 0);
                // outward sums, from the last cell in
                for (int j = cellsY - 1; j >= 0; j--) {
                    int gy = (qy == 0 ? j : -1 - j) + cellsY;
                    for (int i = cellsX - 1; i >= 0; i--) {
                        int gx = (qx == 0 ? i : -1 - i) + cellsX;
                        int at = j * (cellsX + 1) + i;
                        t[at] = mass[gy * nx + gx] + t[at + 1] + t[at + cellsX + 1] - t[at + cellsX + 2];
                    }
                }
                for (int j = 0; j <= cellsY; j++) {
                    for (int i = 0; i <= cellsX; i++) {
                        int x = qx * (cellsX + 2) + i;
                        int y = qy * (cellsY + 2) + j;
                        layer[2 * (y * width + x) + channel] = (float) t[j * (cellsX + 1) + i];
                    }
                }
            }
        }
    }

    /**
     * sum_m W'_m(a) |box &#8745; cell_m|, the weights (spread as above) integrated over the box [x0, x1] x [y0, y1]
     * in texels (cell m = [m - 1/2, m + 1/2]^2), at phase factor a (clamped to [-p_max, 0]); as the shader
     * computes it, in double.
     */
    public double boxSum(double x0, double x1, double y0, double y1, double a) {
        double x = Math.min(samples - 1, Math.max(0, -a / stepPerUm));
        int k = Math.min(samples - 2, (int) x);
        double t = x - k;
        return boxSumPieces(x0, x1, y0, y1, k, t);
    }

    /** The box's sum from its parts in each quadrant, at samples k and k + 1 and the Hermite parameter t. */
    private double boxSumPieces(double x0, double x1, double y0, double y1, int k, double t) {
        double[][] xPieces = axisPieces(x0, x1, cellsX, cell);
        double[][] yPieces = axisPieces(y0, y1, cellsY, cell);
        double sum = 0;
        for (double[] px : xPieces) {
            for (double[] py : yPieces) {
                int ox = (int) px[2] * (cellsX + 2);
                int oy = (int) py[2] * (cellsY + 2);
                sum += corner(ox, oy, px[0], py[0], k, t) - corner(ox, oy, px[1], py[0], k, t)
                        - corner(ox, oy, px[0], py[1], k, t) + corner(ox, oy, px[1], py[1], k, t);
            }
        }
        return sum;
    }

    /**
     * The parts of [lo, hi] (texels) in each half of an axis, in that half's local coordinate t = +-(s + 1/2) / c (in
     * cells) clamped to [0, cells]: {t_inner, t_outer, half} with half 0 for m &gt;= 0 and 1 for m &lt; 0.
     */
    static double[][] axisPieces(double lo, double hi, int cells, int c) {
        java.util.List<double[]> out = new java.util.ArrayList<>(2);
        if (hi > -0.5) {
            out.add(new double[] {clamp((Math.max(lo, -0.5) + 0.5) / c, cells), clamp((hi + 0.5) / c, cells), 0});
        }
        if (lo < -0.5) {
            out.add(new double[] {clamp(-(Math.min(hi, -0.5) + 0.5) / c, cells), clamp(-(lo + 0.5) / c, cells), 1});
        }
        return out.toArray(new double[0][]);
    }

    private static double clamp(double t, int cells) {
        return Math.min(cells, Math.max(0, t));
    }

    /** The Hermite-interpolated tail at local (t, u) of the quadrant at (ox, oy): bilinear between corners. */
    private double corner(int ox, int oy, double tx, double ty, int k, double t) {
        float[] layer = layers[k];
        int i = Math.min((int) Math.floor(tx), cellsX - 1);
        int j = Math.min((int) Math.floor(ty), cellsY - 1);
        double fx = tx - i;
        double fy = ty - j;
        int i00 = 4 * ((oy + j) * width + ox + i);
        int i10 = i00 + 4;
        int i01 = i00 + 4 * width;
        int i11 = i01 + 4;
        double[] v = new double[4];
        for (int c = 0; c < 4; c++) {
            v[c] = (1 - fy) * ((1 - fx) * layer[i00 + c] + fx * layer[i10 + c])
                    + fy * ((1 - fx) * layer[i01 + c] + fx * layer[i11 + c]);
        }
        return LobeWeightTable.hermite(v[0], v[1], v[2], v[3], t);
    }

    /** Texels per cell along each axis, c. */
    public int cellTexels() {
        return cell;
    }

    /** Cells per quadrant along x, n_x. */
    public int cellsX() {
        return cellsX;
    }

    public int cellsY() {
        return cellsY;
    }

    /** The GPU layer's width, 2 (n_x + 2). */
    public int width() {
        return width;
    }

    public int height() {
        return height;
    }



    /** The GPU's RGBA layers, one per interval of samples (see the class comment). */
    public java.util.List<float[]> layers() {
        return java.util.List.of(layers);
    }
}
