package diffract.optics.spectra;

/**
 * Where a phase-centred Taylor expansion of exp(i a h), a = k w, puts its centres, and the arithmetic
 * every expansion around a centre shares (the CPU reference {@link ExactSpectrum}, the float32 terms of
 * {@code TaylorTermComputer.computeCentred} and the GPU's {@code taylor_centred.glsl}).
 *
 * <p>The thesis expands around a = 0 (004 eq. {@code finalexpression}): sum_n a^n / n! DFT((i h)^n). Its terms
 * grow to about e^x, x = |a| max|h|, before they cancel, so float32 loses everything beyond x ~ 17
 * ({@link Float32Cancellation}). Around a centre a_j the same function is
 * exp(i a h) = exp(i a_j h) sum_n (a - a_j)^n / n! (i h)^n, and the transforms
 * E_{j,n} = fftshift(ifft2(exp(i a_j h) (i h)^n)) are as cheap to precompute as the thesis' DFT_n (which are
 * E_{0,n}). With the centres a_j = -j * spacing, spacing = 2 b / max|h|, the nearest centre leaves
 * |a - a_j| max|h| <= b, every term is at most b^n / n! of P's scale, and a float32 sum errs by about
 * 2^-24 e^b whatever the patch's height.
 *
 * <p>The reachable phases: w = -(cos theta_i + cos theta_r) lies in [-2, 0] above the horizon, k = 2 pi / lambda
 * in [2 pi / lambda_max, 2 pi / lambda_min], so a lies in [-2 k_max, 0] and needs
 * round(2 k_max max|h| / (2 b)) + 1 centres.
 *
 * @param halfWidth        b, the largest |a - a_j| max|h| a fragment sees
 * @param spacingPerUm     distance between centres in a (1/um)
 * @param centreCount      centres a_0 = 0, a_1 = -spacing, ...
 * @param highestOrder     the last order summed around every centre
 */
public record PhaseCentres(double halfWidth, double spacingPerUm, int centreCount, int highestOrder) {
    /**
     * b = 2: a float32 sum then errs by at most about 2^-24 e^2 = 4.4e-7 of P's scale, and 15 orders
     * (remainder below the thesis' bound 2^15 e^2 / 15! = 1.9e-7) reach 1e-6. A smaller b needs more centres
     * (memory), a larger b more orders per fragment (time) and more rounding (e^b). Measured on a 2 um patch at
     * 380 nm (Float32CancellationTest): b = 1: 350 layers, 10 orders; b = 2: 270, 15; b = 4: 198, 22; all within
     * 4e-7 in P. b = 2 halves the thesis' 31 terms per fragment at a memory between the two.
     */
    public static final double DEFAULT_HALF_WIDTH = 2.0;
    /** The truncation error the orders per centre must reach (the thesis' Lagrange bound, TaylorBound). */
    public static final double TRUNCATION_TOLERANCE = 1e-6;

    public PhaseCentres {
        if (!(halfWidth > 0) || !(spacingPerUm > 0) || centreCount < 1 || highestOrder < 0) {
            throw new IllegalArgumentException("bad phase centres: b " + halfWidth + ", spacing " + spacingPerUm
                    + ", " + centreCount + " centres, order " + highestOrder);
        }
    }

    /** The centres a patch needs for wavelengths from {@code lambdaMinNm} on, with {@link #DEFAULT_HALF_WIDTH}. */
    public static PhaseCentres forPatch(double maxAbsHeightUm, double lambdaMinNm) {
        return forPatch(maxAbsHeightUm, lambdaMinNm, DEFAULT_HALF_WIDTH);
    }

    public static PhaseCentres forPatch(double maxAbsHeightUm, double lambdaMinNm, double halfWidth) {
        // a flat patch needs one centre; any spacing serves, 1/um keeps the arithmetic finite
        double spacing = maxAbsHeightUm > 0 ? 2 * halfWidth / maxAbsHeightUm : 1.0;
        double maxPhase = TaylorBound.maxPhase(lambdaMinNm, maxAbsHeightUm); // 2 k_max max|h|
        int count = (int) Math.floor(maxPhase / (2 * halfWidth) + 0.5) + 1;
        int order = TaylorBound.termsForTolerance(halfWidth, TRUNCATION_TOLERANCE);
        return new PhaseCentres(halfWidth, spacing, count, order);
    }

    /** a_j = -j * spacing (1/um). */
    public double centrePerUm(int j) {
        return -j * spacingPerUm;
    }

    /** The nearest centre to a = k w <= 0: round(-a / spacing), clamped to the centres that exist. */
    public int nearestCentre(double a) {
        int j = (int) Math.floor(-a / spacingPerUm + 0.5);
        return Math.max(0, Math.min(centreCount - 1, j));
    }

    /** Orders per centre, highestOrder + 1. */
    public int ordersPerCentre() {
        return highestOrder + 1;
    }

    /** Texture-array layers: centres x orders. */
    public int layerCount() {
        return centreCount * ordersPerCentre();
    }

    /** GPU memory of the RG32F texture array for a rows x cols patch. */
    public long bytesRg32f(int rows, int cols) {
        return (long) layerCount() * rows * cols * 2 * Float.BYTES;
    }

    /** exp(i a_j h) per sample, interleaved Re/Im: the start of the expansion around a_j (1 + 0i at a_j = 0). */
    public static double[] centreField(double[] heightsUm, double centrePerUm) {
        double[] f = new double[2 * heightsUm.length];
        if (centrePerUm == 0) { // exactly 1 + 0i (no -0 from sin(-0)): the thesis' terms bit for bit
            for (int p = 0; p < heightsUm.length; p++) {
                f[2 * p] = 1.0;
            }
            return f;
        }
        for (int p = 0; p < heightsUm.length; p++) {
            double phase = centrePerUm * heightsUm[p];
            f[2 * p] = Math.cos(phase);
            f[2 * p + 1] = Math.sin(phase);
        }
        return f;
    }

    /** (re + i im) * (i h) = -h im + i h re, in place: one more power of (i h). */
    public static void multiplyByIH(double[] complex, double[] heightsUm) {
        for (int p = 0; p < heightsUm.length; p++) {
            double re = complex[2 * p];
            double im = complex[2 * p + 1];
            complex[2 * p] = -heightsUm[p] * im;
            complex[2 * p + 1] = heightsUm[p] * re;
        }
    }
}
