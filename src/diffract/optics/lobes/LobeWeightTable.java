package diffract.optics.lobes;

import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.TaylorBound;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.spectra.TaylorTexels;
import diffract.optics.spectra.TexelCoefficients;

/**
 * Each texel's lobe weight W_m(a) = |T_m(a)|^2 tabulated over the phase factor a = k w, for the lobes method
 * (docs/design/filtering.md, section 6). T_m depends on the wavelength and on w only through a, and a = k w &lt;= 0 lies in
 * [-p_max, 0] with p_max = 2 k_max = 4 pi / lambda_min (|w| &lt;= 2); the table holds W and p-derivative at K
 * equally spaced magnitudes p = -a, and a lookup interpolates between the two neighbouring samples by the cubic
 * Hermite polynomial. One lookup replaces reading the texel's N + 1 Taylor terms and summing the series.
 *
 * <p><b>Spacing.</b> The exact coefficient T_m(a) = DFT(exp(i a h))(m) is a sum of exp(i a h(x)) over the patch:
 * band-limited in a to |h| &lt;= max|h|, so W is band-limited to 2 max|h| and, by Bernstein's inequality,
 * |W''''| &lt;= (2 max|h|)^4 sup W. The Hermite cubic errs by at most delta^4 / 384 |W''''|, so the spacing
 * delta = (384 tolerance)^(1/4) / (2 max|h|) keeps the interpolation within {@code tolerance} of the texel's largest
 * weight (an estimate for the Taylor series, which is that function to its truncation error).
 *
 * <p><b>Bounds.</b> For each of {@link #BINS} equal bins of p the table also holds the largest value its interpolant
 * takes there (endpoints and the cubic's interior extrema, exactly), so the lobes method can skip a texel whose lobe
 * cannot reach a given size before reading its weight ({@code LobeQuadrature.cutoff}). Blocks of {@link
 * #BLOCK} x {@link #BLOCK} texels hold the largest of their texels' bounds per bin, so that a march over the texels
 * skips a block none of whose lobes can reach the cutoff with one test instead of one per texel: a wide scan's halo is
 * mostly such blocks.
 *
 * <p>Values are rounded to float32 once, here; the CPU ({@link #weight}) and the shader interpolate the same numbers.
 */
public final class LobeWeightTable {
    /** Bound bins over [0, p_max]. */
    public static final int BINS = 8;
    /** The most samples a table may hold (the GPU keeps them as layers of a texture array, 2048 at least). */
    public static final int MAX_SAMPLES = 2048 - BINS / 2;
    /** Texels per side of a block of bounds. */
    public static final int BLOCK = 8;

    private final int rows;
    private final int cols;
    private final double tolerance;
    private final double lambdaMinNm;
    private final int samples;
    private final double maxPhasePerUm;
    private final double stepPerUm;
    /** Per sample k, per texel (row-major): W and delta dW/dp, interleaved (the GPU's RG layers). */
    private final float[][] layers;
    /** Per texel, BINS bounds. */
    private final float[] bounds;
    private final int blockRows;
    private final int blockCols;
    /** Per block (row-major), BINS bounds: the largest of its texels'. */
    private final float[] blockBounds;
    /**
     * Per block, its texels from the largest bound over all bins down ({@link #orderedTexel}): (offset in the block,
     * that bound) in slot j of block (bc, br) at texel (BLOCK bc + j % BLOCK, BLOCK br + j / BLOCK) of a grid of
     * blockCols BLOCK x blockRows BLOCK; (-1, 0) past a block's last texel.
     */
    private final float[] order;

    /** The table of the thesis' series over the float32 terms, orders 0..highestOrder (what the shader reads). */
    public static LobeWeightTable ofTerms(TaylorTerms terms, int highestOrder, double lambdaMinNm, double tolerance) {
        return new LobeWeightTable(new TaylorTexels(terms, highestOrder), lambdaMinNm, tolerance);
    }

    /** The table of the phase-centred expansion's float32 terms. */
    public static LobeWeightTable ofTerms(PhaseCentredTerms terms, double lambdaMinNm, double tolerance) {
        return new LobeWeightTable(new TaylorTexels(terms), lambdaMinNm, tolerance);
    }

    /**
     * The heap a table of a rows x cols term grid takes (its K samples, from the patch's max|h| and the tolerance as
     * the constructor chooses them, and its bounds, as float32 pairs), for the estimates made before the work.
     */
    public static long bytes(int rows, int cols, double maxAbsHeightUm, double lambdaMinNm, double tolerance) {
        return 8L * rows * cols * (samples(maxAbsHeightUm, lambdaMinNm, tolerance) + BINS / 2)
                + 4L * BINS * blocks(rows) * blocks(cols) + 8L * blocks(rows) * blocks(cols) * BLOCK * BLOCK;
    }

    /** K, the samples of the phase a table of a patch of this max|h| takes (as the constructor chooses them). */
    public static long samples(double maxAbsHeightUm, double lambdaMinNm, double tolerance) {
        double maxPhase = maxPhasePerUm(lambdaMinNm);
        double wanted = maxAbsHeightUm > 0 ? Math.pow(384 * tolerance, 0.25) / (2 * maxAbsHeightUm) : maxPhase;
        return Math.max(2, (long) Math.ceil(maxPhase / wanted - 1e-9) + 1);
    }

    /** p_max = 2 k_max = 4 pi / lambda_min, um^-1 (|w| &lt;= 2). */
    static double maxPhasePerUm(double lambdaMinNm) {
        return TaylorBound.MAX_ABS_W * 2 * Math.PI / (lambdaMinNm * 1e-3);
    }

    /**
     * @param lambdaMinNm the shortest wavelength: the table reaches p_max = 4 pi / lambda_min, the largest |k w|
     * @param tolerance   the interpolation error allowed, relative to a texel's largest weight: (0, 1e-2]
     */
    public LobeWeightTable(TexelCoefficients coefficients, double lambdaMinNm, double tolerance) {
        if (!(tolerance > 0 && tolerance <= 1e-2)) {
            throw new IllegalArgumentException("the weight table's tolerance must be in (0, 1e-2], got " + tolerance);
        }
        this.tolerance = tolerance;
        this.rows = coefficients.rows();
        this.cols = coefficients.cols();
        this.lambdaMinNm = lambdaMinNm;
        this.maxPhasePerUm = maxPhasePerUm(lambdaMinNm);
        double maxAbs = coefficients.maxAbsHeightUm();
        double wanted = maxAbs > 0 ? Math.pow(384 * tolerance, 0.25) / (2 * maxAbs) : maxPhasePerUm;
        int k = (int) Math.ceil(maxPhasePerUm / wanted - 1e-9) + 1;
        this.samples = Math.max(2, k);
        if (samples > MAX_SAMPLES) {
            throw new diffract.util.UserInputException(String.format(java.util.Locale.ROOT,
                    "the lobes method's weight table would need %d samples of the phase (max |h| = %.3g um, tolerance "
                            + "%.0e); the most it holds is %d: use a larger tolerance or a lower patch", samples, maxAbs,
                    tolerance, MAX_SAMPLES));
        }
        this.stepPerUm = maxPhasePerUm / (samples - 1);
        this.layers = new float[samples][2 * rows * cols];
        double[] t = new double[4];
        for (int row = 0; row < rows; row++) {
            for (int col = 0; col < cols; col++) {
                TexelCoefficients.Texel texel = coefficients.texel(col - cols / 2, row - rows / 2);
                if (texel == null) {
                    continue; // T_m = 0: a texel the coefficients leave out
                }
                int index = 2 * (row * cols + col);
                for (int s = 0; s < samples; s++) {
                    double a = -s * stepPerUm;
                    texel.withDerivative(a, t);
                    double w = t[0] * t[0] + t[1] * t[1];
                    double dWda = 2 * (t[0] * t[2] + t[1] * t[3]);
                    layers[s][index] = (float) w;
                    layers[s][index + 1] = (float) (-dWda * stepPerUm); // per unit of the sample index, along p
                }
            }
        }
        this.bounds = new float[BINS * rows * cols];
        for (int texel = 0; texel < rows * cols; texel++) {
            for (int s = 0; s + 1 < samples; s++) {
                double max = intervalMax(layers[s][2 * texel], layers[s][2 * texel + 1], layers[s + 1][2 * texel],
                        layers[s + 1][2 * texel + 1]);
                // the bins this interval [s, s + 1] (in samples) overlaps
                int b0 = bin(s * stepPerUm);
                int b1 = bin((s + 1) * stepPerUm);
                for (int b = b0; b <= b1; b++) {
                    int i = BINS * texel + b;
                    bounds[i] = (float) Math.max(bounds[i], Math.nextUp((float) max));
                }
            }
        }
        this.blockRows = blocks(rows);
        this.blockCols = blocks(cols);
        this.blockBounds = new float[BINS * blockRows * blockCols];
        for (int row = 0; row < rows; row++) {
            for (int col = 0; col < cols; col++) {
                int block = BINS * ((row / BLOCK) * blockCols + col / BLOCK);
                int texel = BINS * (row * cols + col);
                for (int b = 0; b < BINS; b++) {
                    blockBounds[block + b] = Math.max(blockBounds[block + b], bounds[texel + b]);
                }
            }
        }
        this.order = new float[2 * blockRows * BLOCK * blockCols * BLOCK];
        for (int br = 0; br < blockRows; br++) {
            for (int bc = 0; bc < blockCols; bc++) {
                java.util.List<float[]> texels = new java.util.ArrayList<>();
                for (int r = br * BLOCK; r < Math.min(rows, (br + 1) * BLOCK); r++) {
                    for (int c = bc * BLOCK; c < Math.min(cols, (bc + 1) * BLOCK); c++) {
                        float largest = 0;
                        for (int b = 0; b < BINS; b++) {
                            largest = Math.max(largest, bounds[BINS * (r * cols + c) + b]);
                        }
                        texels.add(new float[] {(r - br * BLOCK) * BLOCK + (c - bc * BLOCK), largest});
                    }
                }
                // brightest first; ties by offset, so that the order is the table's, not the sort's
                texels.sort((a, b) -> a[1] != b[1] ? Float.compare(b[1], a[1]) : Float.compare(a[0], b[0]));
                for (int slot = 0; slot < BLOCK * BLOCK; slot++) {
                    int at = 2 * ((br * BLOCK + slot / BLOCK) * blockCols * BLOCK + bc * BLOCK + slot % BLOCK);
                    order[at] = slot < texels.size() ? texels.get(slot)[0] : -1;
                    order[at + 1] = slot < texels.size() ? texels.get(slot)[1] : 0;
                }
            }
        }
    }

    /** Blocks along an axis of this many texels. */
    static int blocks(int texels) {
        return (texels + BLOCK - 1) / BLOCK;
    }

    private int bin(double p) {
        return Math.min(BINS - 1, Math.max(0, (int) Math.floor(p / maxPhasePerUm * BINS)));
    }

    /**
     * The largest value of the Hermite cubic with endpoint values w0, w1 and derivatives d0, d1 (per unit t) on
     * t in [0, 1]: at an endpoint or where its derivative, a quadratic, vanishes.
     */
    static double intervalMax(double w0, double d0, double w1, double d1) {
        double max = Math.max(w0, w1);
        // H(t) = w0 h00 + d0 h10 + w1 h01 + d1 h11; H'(t) = A t^2 + B t + C
        double a = 6 * w0 + 3 * d0 - 6 * w1 + 3 * d1;
        double b = -6 * w0 - 4 * d0 + 6 * w1 - 2 * d1;
        double c = d0;
        double[] roots = new double[2];
        int n;
        if (Math.abs(a) < 1e-300) {
            n = 0;
            if (b != 0) {
                roots[n++] = -c / b;
            }
        } else {
            double disc = b * b - 4 * a * c;
            n = 0;
            if (disc >= 0) {
                double q = -0.5 * (b + Math.copySign(Math.sqrt(disc), b));
                roots[n++] = q / a;
                if (q != 0) {
                    roots[n++] = c / q;
                }
            }
        }
        for (int i = 0; i < n; i++) {
            if (roots[i] > 0 && roots[i] < 1) {
                max = Math.max(max, hermite(w0, d0, w1, d1, roots[i]));
            }
        }
        return max;
    }

    /** The cubic Hermite polynomial on [0, 1]. */
    public static double hermite(double w0, double d0, double w1, double d1, double t) {
        double t2 = t * t;
        double t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * w0 + (t3 - 2 * t2 + t) * d0 + (-2 * t3 + 3 * t2) * w1 + (t3 - t2) * d1;
    }

    /** W_m at phase factor a (clamped to [-p_max, 0]) of the texel at (col, row) of the term grid; &gt;= 0. */
    public double weight(int col, int row, double a) {
        double x = Math.min(samples - 1, Math.max(0, -a / stepPerUm));
        int s = Math.min(samples - 2, (int) x);
        double t = x - s;
        int i = 2 * (row * cols + col);
        return Math.max(0, hermite(layers[s][i], layers[s][i + 1], layers[s + 1][i], layers[s + 1][i + 1], t));
    }

    /** The largest weight of the texel at (col, row) for phase magnitudes p = -a in [pLo, pHi] (um^-1). */
    public double bound(int col, int row, double pLo, double pHi) {
        int b0 = bin(pLo);
        int b1 = bin(pHi);
        int texel = row * cols + col;
        double max = 0;
        for (int b = b0; b <= b1; b++) {
            max = Math.max(max, bounds[BINS * texel + b]);
        }
        return max;
    }

    /**
     * The largest weight of any texel of block (blockCol, blockRow) (texels BLOCK blockCol.. and BLOCK blockRow.. of
     * the grid) for p in [pLo, pHi]: at least {@link #bound} of each of them.
     */
    public double blockBound(int blockCol, int blockRow, double pLo, double pHi) {
        int b0 = bin(pLo);
        int b1 = bin(pHi);
        int block = BINS * (blockRow * blockCols + blockCol);
        double max = 0;
        for (int b = b0; b <= b1; b++) {
            max = Math.max(max, blockBounds[block + b]);
        }
        return max;
    }

    /**
     * The texel in slot j (0..BLOCK^2 - 1) of block (blockCol, blockRow)'s order, from the largest bound over all bins
     * down: its offset row * BLOCK + col within the block, or -1 past the block's last texel.
     */
    public int orderedTexel(int blockCol, int blockRow, int slot) {
        return (int) order[orderIndex(blockCol, blockRow, slot)];
    }

    /** The bound over all bins of {@link #orderedTexel}: no later slot of the block has a larger one. */
    public double orderedBound(int blockCol, int blockRow, int slot) {
        return order[orderIndex(blockCol, blockRow, slot) + 1];
    }

    private int orderIndex(int blockCol, int blockRow, int slot) {
        return 2 * ((blockRow * BLOCK + slot / BLOCK) * blockCols * BLOCK + blockCol * BLOCK + slot % BLOCK);
    }

    /** The GPU's RG layer of the blocks' orders, blockCols BLOCK x blockRows BLOCK texels ({@link #orderedTexel}). */
    public float[] orderLayer() {
        return order;
    }

    public int blockRows() {
        return blockRows;
    }

    public int blockCols() {
        return blockCols;
    }

    /** The GPU's RG layers of the block bounds: bins 2 j and 2 j + 1 of every block in layer j, blockCols x blockRows. */
    public java.util.List<float[]> blockLayers() {
        java.util.List<float[]> out = new java.util.ArrayList<>(BINS / 2);
        int blocks = blockRows * blockCols;
        for (int j = 0; j < BINS / 2; j++) {
            float[] layer = new float[2 * blocks];
            for (int block = 0; block < blocks; block++) {
                layer[2 * block] = blockBounds[BINS * block + 2 * j];
                layer[2 * block + 1] = blockBounds[BINS * block + 2 * j + 1];
            }
            out.add(layer);
        }
        return out;
    }

    public int rows() {
        return rows;
    }

    public int cols() {
        return cols;
    }

    /** K, the samples of p from 0 to p_max. */
    public int samples() {
        return samples;
    }

    /** The sample spacing delta in p, um^-1. */
    public double stepPerUm() {
        return stepPerUm;
    }

    public double maxPhasePerUm() {
        return maxPhasePerUm;
    }

    public double tolerance() {
        return tolerance;
    }

    /** The shortest wavelength the table reaches (p_max = 4 pi / lambda_min), nm. */
    public double lambdaMinNm() {
        return lambdaMinNm;
    }

    /**
     * The GPU's RG layers: sample k's (W, delta dW/dp) per texel for k = 0..K-1, then BINS / 2 layers of bounds (bins
     * 2 j and 2 j + 1 in layer K + j).
     */
    public java.util.List<float[]> layers() {
        java.util.List<float[]> out = new java.util.ArrayList<>(samples + BINS / 2);
        for (float[] layer : layers) {
            out.add(layer);
        }
        for (int j = 0; j < BINS / 2; j++) {
            float[] layer = new float[2 * rows * cols];
            for (int texel = 0; texel < rows * cols; texel++) {
                layer[2 * texel] = bounds[BINS * texel + 2 * j];
                layer[2 * texel + 1] = bounds[BINS * texel + 2 * j + 1];
            }
            out.add(layer);
        }
        return out;
    }
}
