package diffract.colour;

/**
 * The spectral weights of the lobes method's wavelength rule: the tristimulus density f = S (xbar, ybar, zbar) / N
 * (D65 times CIE 1931, interpolated linearly between whole nanometres as the product S xbar etc., truncated to the
 * band [lambda_min, lambda_max] and normalised to N = integral of S ybar over the band), and its averages over hat
 * functions of half-width h = 1, 2, 4, 8 and 16 nm,
 * <pre>
 *   f_h(lambda) = (1 / h) integral f(l) max(0, 1 - |l - lambda| / h) dl,
 * </pre>
 * both tabulated every nanometre from lambda_min. A rule with nodes lambda_j = lambda_min + j h and weights
 * h f_h(lambda_j) is the trapezoid rule for the smooth factor g of integral f g: exact for the spectral structure of
 * f (its kinks every nanometre) and for any g that is linear between the nodes, and exactly D65 white with Y = 1
 * for g = 1 (the hats of a grid starting at lambda_min sum to 1 on the band). For node spacings below 1 nm the
 * weight is h f(lambda_j). The GPU receives the same table (level 0 = f, level l = f_{2^(l-1)}).
 *
 * <p>With {@link MirrorNormalisation#ENERGY} f carries the mirror's factor (lambda_0 / lambda)^2 (N does not), taken
 * at whole nanometres like S and the CMFs; white then means a flat mirror's lobe integrated over its directions.
 */
public final class HatFilteredSpectrum {
    /** Hat half-widths 2^0 .. 2^(LEVELS - 2) nm: 1, 2, 4, 8, 16. */
    public static final int LEVELS = 6;
    /** The widest hat, nm: the largest node spacing the rule takes. */
    public static final int WIDEST_HAT_NM = 1 << (LEVELS - 2);

    private final double lambdaMinNm;
    private final double lambdaMaxNm;
    private final int positions;
    /** [level][position][channel], normalised by N. */
    private final double[][][] table;
    private final double normaliser;
    private final MirrorNormalisation normalisation;
    /** Range maxima of the node weights per nanometre ({@link #maxDensity(double, double)}). */
    private final double[][] rangeMax;

    /** The thesis' weighting ({@link MirrorNormalisation#PEAK}). */
    public HatFilteredSpectrum(double lambdaMinNm, double lambdaMaxNm) {
        this(lambdaMinNm, lambdaMaxNm, MirrorNormalisation.PEAK);
    }

    public HatFilteredSpectrum(double lambdaMinNm, double lambdaMaxNm, MirrorNormalisation normalisation) {
        this.normalisation = normalisation;
        if (!(lambdaMinNm > 0) || !(lambdaMaxNm > lambdaMinNm)) {
            throw new IllegalArgumentException("need 0 < lambda_min < lambda_max, got " + lambdaMinNm + ", " + lambdaMaxNm);
        }
        this.lambdaMinNm = lambdaMinNm;
        this.lambdaMaxNm = lambdaMaxNm;
        // nodes up to lambda_max + 16 nm: hats beyond lambda_max still overlap the band
        this.positions = (int) Math.ceil(lambdaMaxNm - lambdaMinNm) + WIDEST_HAT_NM + 1;
        double n = 0;
        for (double lo = lambdaMinNm; lo < lambdaMaxNm; ) {
            double hi = Math.min(lambdaMaxNm, Math.floor(lo) + 1);
            n += 0.5 * (hi - lo) * (luminance(lo) + luminance(hi)); // linear between whole nm: exact
            lo = hi;
        }
        if (!(n > 0)) {
            throw new IllegalArgumentException("the band " + lambdaMinNm + ".." + lambdaMaxNm + " nm sees no D65 luminance");
        }
        this.normaliser = n;
        this.table = new double[LEVELS][positions][3];
        for (int p = 0; p < positions; p++) {
            double lambda = lambdaMinNm + p;
            table[0][p] = truncated(lambda);
            for (int c = 0; c < 3; c++) {
                table[0][p][c] /= n;
            }
            for (int level = 1; level < LEVELS; level++) {
                double h = 1 << (level - 1);
                table[level][p] = hatAverage(lambda, h);
                for (int c = 0; c < 3; c++) {
                    table[level][p][c] /= n;
                }
            }
        }
        this.rangeMax = rangeMaxima(table, positions);
    }

    /** S ybar at whole nanometres, linear in between: the normaliser's integrand, without the mirror's factor. */
    private static double luminance(double lambdaNm) {
        double lo = Math.floor(lambdaNm);
        double t = lambdaNm - lo;
        double a = D65.relativePower(lo) * Cie1931.yBar(lo);
        if (t == 0) {
            return a;
        }
        double b = D65.relativePower(lo + 1) * Cie1931.yBar(lo + 1);
        return a + t * (b - a);
    }

    /**
     * S (xbar, ybar, zbar) times the mirror's factor, each at whole nanometres and multiplied there, linear in
     * between.
     */
    private double[] product(double lambdaNm) {
        double lo = Math.floor(lambdaNm);
        double t = lambdaNm - lo;
        double[] a = atWholeNm(lo);
        if (t == 0) {
            return a;
        }
        double[] b = atWholeNm(lo + 1);
        return new double[] {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    }

    private double[] atWholeNm(double lambdaNm) {
        double s = D65.relativePower(lambdaNm) * normalisation.factor(lambdaNm);
        return new double[] {s * Cie1931.xBar(lambdaNm), s * Cie1931.yBar(lambdaNm), s * Cie1931.zBar(lambdaNm)};
    }

    private double[] truncated(double lambdaNm) {
        return lambdaNm < lambdaMinNm || lambdaNm > lambdaMaxNm ? new double[3] : product(lambdaNm);
    }

    /** (1 / h) integral of f times the hat of half-width h at lambda: Simpson's rule between breakpoints (exact). */
    private double[] hatAverage(double lambda, double h) {
        double from = Math.max(lambda - h, lambdaMinNm);
        double to = Math.min(lambda + h, lambdaMaxNm);
        double[] sum = new double[3];
        if (!(to > from)) {
            return sum;
        }
        // breakpoints: whole nanometres (f's kinks), the hat's apex, the ends
        java.util.TreeSet<Double> cuts = new java.util.TreeSet<>();
        cuts.add(from);
        cuts.add(to);
        if (lambda > from && lambda < to) {
            cuts.add(lambda);
        }
        for (double k = Math.ceil(from); k < to; k++) {
            if (k > from) {
                cuts.add(k);
            }
        }
        Double previous = null;
        for (double cut : cuts) {
            if (previous != null) {
                double a = previous;
                double b = cut;
                double m = 0.5 * (a + b);
                double[] fa = product(a);
                double[] fm = product(m);
                double[] fb = product(b);
                double ha = hat(a, lambda, h);
                double hm = hat(m, lambda, h);
                double hb = hat(b, lambda, h);
                for (int c = 0; c < 3; c++) {
                    sum[c] += (b - a) / 6 * (fa[c] * ha + 4 * fm[c] * hm + fb[c] * hb);
                }
            }
            previous = cut;
        }
        for (int c = 0; c < 3; c++) {
            sum[c] /= h;
        }
        return sum;
    }

    private static double hat(double l, double centre, double h) {
        return Math.max(0, 1 - Math.abs(l - centre) / h);
    }

    /**
     * The weight {X, Y, Z} of node lambda_j for node spacing h into out: h f_h(lambda_j) for h = 1, 2, 4, 8, 16 nm
     * (lambda_j = lambda_min + j h, a whole number of nanometres from lambda_min), h f(lambda_j) below 1 nm (f
     * interpolated linearly between the table's nanometres).
     */
    public void weight(double lambdaNm, double spacingNm, double[] out) {
        double position = lambdaNm - lambdaMinNm;
        if (spacingNm >= 1) {
            int level = levelOf(spacingNm);
            int p = (int) Math.rint(position);
            double[] v = p >= 0 && p < positions ? table[level][p] : ZERO;
            out[0] = spacingNm * v[0];
            out[1] = spacingNm * v[1];
            out[2] = spacingNm * v[2];
            return;
        }
        int p = (int) Math.floor(position);
        double t = position - p;
        double[] a = p >= 0 && p < positions ? table[0][p] : ZERO;
        double[] b = p + 1 >= 0 && p + 1 < positions ? table[0][p + 1] : ZERO;
        for (int c = 0; c < 3; c++) {
            out[c] = spacingNm * (a[c] + t * (b[c] - a[c]));
        }
    }

    private static final double[] ZERO = new double[3];

    /** The table level of a spacing of 1, 2, 4, 8 or 16 nm. */
    public static int levelOf(double spacingNm) {
        int level = 1 + (int) Math.round(Math.log(spacingNm) / Math.log(2));
        if (level < 1 || level >= LEVELS || (1 << (level - 1)) != spacingNm) {
            throw new IllegalArgumentException("hat spacings are 1, 2, 4, 8 or 16 nm, got " + spacingNm);
        }
        return level;
    }

    /**
     * The largest weight per nanometre of any channel at any level over the band's nodes: a node's weight is at most
     * its spacing times this, so that a lobe's weighted sum over a passage is bounded before its weights are read.
     */
    public double maxDensity() {
        return maxDensity(lambdaMinNm, lambdaMaxNm);
    }

    /**
     * As {@link #maxDensity()} for the nodes of a passage [fromNm, toNm]: every node a passage takes lies within it,
     * or is the first at or beyond lambda_max (one hat more), and below 1 nm interpolates the next nanometre. One
     * range-maximum query (the largest of two overlapping power-of-two windows).
     */
    public double maxDensity(double fromNm, double toNm) {
        int a = Math.max(0, Math.min(positions - 1, (int) Math.floor(fromNm - lambdaMinNm) - 1));
        int b = Math.max(a, Math.min(positions - 1, (int) Math.ceil(toNm - lambdaMinNm) + WIDEST_HAT_NM + 1));
        int k = 31 - Integer.numberOfLeadingZeros(b - a + 1);
        return Math.max(rangeMax[k][a], rangeMax[k][b - (1 << k) + 1]);
    }

    /**
     * A bound on the sum of any set of one spacing's node weights in any channel: the hats of a spacing sum to one on
     * the band, so a whole grid's weights sum to the density's integral, and a passage's nodes are part of a grid.
     * The largest channel's integral (1 nm trapezoids of the table) with 2 % to spare for spacings below 1 nm, whose
     * trapezoids on the interpolated density differ from it by less.
     */
    public double bandWeight() {
        double max = 0;
        for (int c = 0; c < 3; c++) {
            double sum = 0;
            for (int p = 0; p < positions; p++) {
                sum += table[0][p][c];
            }
            max = Math.max(max, sum);
        }
        return 1.02 * max;
    }

    /** The levels of {@link #rangeMaxRgba}: windows of 1, 2, 4, ... positions up to the whole table. */
    public int rangeMaxLevels() {
        return rangeMax.length;
    }

    /**
     * The range maxima for the GPU: RGBA32F texels, level-major ({@link #positions} per level), the largest weight of
     * any channel and hat level over positions p .. p + 2^level - 1 in R.
     */
    public float[] rangeMaxRgba() {
        float[] out = new float[4 * rangeMax.length * positions];
        for (int level = 0; level < rangeMax.length; level++) {
            for (int p = 0; p < positions; p++) {
                out[4 * (level * positions + p)] = (float) rangeMax[level][p];
            }
        }
        return out;
    }

    /** rangeMax[k][p]: the largest entry of any channel and level at positions p .. p + 2^k - 1 (clipped). */
    private static double[][] rangeMaxima(double[][][] table, int positions) {
        int levels = 32 - Integer.numberOfLeadingZeros(positions);
        double[][] max = new double[levels][positions];
        for (int p = 0; p < positions; p++) {
            for (double[][] level : table) {
                for (double v : level[p]) {
                    max[0][p] = Math.max(max[0][p], v);
                }
            }
        }
        for (int k = 1; k < levels; k++) {
            int half = 1 << (k - 1);
            for (int p = 0; p < positions; p++) {
                max[k][p] = Math.max(max[k - 1][p], p + half < positions ? max[k - 1][p + half] : 0);
            }
        }
        return max;
    }

    /** Table entries per level (every nanometre from lambda_min to lambda_max + 16 nm). */
    public int positions() {
        return positions;
    }

    /** The table for the GPU: RGBA32F texels, level-major, (X, Y, Z, 0) per position, normalised. */
    public float[] rgba() {
        float[] out = new float[4 * LEVELS * positions];
        for (int level = 0; level < LEVELS; level++) {
            for (int p = 0; p < positions; p++) {
                int i = 4 * (level * positions + p);
                out[i] = (float) table[level][p][0];
                out[i + 1] = (float) table[level][p][1];
                out[i + 2] = (float) table[level][p][2];
            }
        }
        return out;
    }


}
