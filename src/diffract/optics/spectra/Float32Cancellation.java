package diffract.optics.spectra;

/**
 * When the thesis' Taylor sum stops being trustworthy in float32. The series
 * sum_n (k w)^n / n! DFT_n converges for every phase, but with x = k |w| max|h| its terms grow to about
 * e^x / sqrt(2 pi x) before they cancel down to |P| <= 1; float32 keeps 24 bits, so each term carries an absolute
 * rounding error of about 2^-24 of its size and the sum an error of order 2^-24 e^x. A float32 evaluation (the GPU)
 * is therefore accurate to about {@link #expectedAbsoluteError(double)} in P, whatever N is; beyond
 * x = ln(tolerance / 2^-24) the result is rounding noise that still looks plausible. The CPU variants sum the same
 * float32 terms in double and are limited only by the terms' own rounding (2^-24 |DFT_n| each, the same order).
 * Tests measure the actual error of a float32 sum against the exact transform and hold it to this estimate.
 * {@code TaylorEvaluation} uses {@link #plainSeriesError} to switch a scene to the phase-centred
 * expansion ({@link PhaseCentres}), whose float32 error stays near 2^-24 e^2 at every height.
 */
public final class Float32Cancellation {
    /** Unit roundoff of IEEE float32, 2^-24. */
    public static final double FLOAT32_UNIT_ROUNDOFF = 0x1p-24;

    private Float32Cancellation() {
    }

    /** The largest phase x = k |w| max|h| a scene reaches: k at lambda_min, |w| = 2 (grazing or normal, back-lit). */
    public static double maxPhase(double lambdaMinNm, double maxAbsHeightUm) {
        return TaylorBound.maxPhase(lambdaMinNm, maxAbsHeightUm);
    }

    /** About 2^-24 e^x: the absolute error in P of a float32 Taylor sum at phase x. */
    public static double expectedAbsoluteError(double x) {
        return FLOAT32_UNIT_ROUNDOFF * Math.exp(x);
    }

    /**
     * The patch's own estimate, sharper than 2^-24 e^x: 2^-24 sum_n |a|^n / n! max_m |DFT_n(m)|, the rounding of
     * the largest term products the sum carries. The terms of real patches are far smaller than max|h|^n (most
     * heights lie well below the maximum), so this is what a scene should be judged by.
     *
     * @param a the phase factor k w (per micrometre)
     */
    public static double expectedAbsoluteError(TaylorTerms terms, double a) {
        double sum = 0;
        double coefficient = 1;
        for (int n = 0; n <= terms.highestOrder(); n++) {
            if (n > 0) {
                coefficient *= Math.abs(a) / n;
            }
            sum += coefficient * maxAbs(terms, n);
        }
        return FLOAT32_UNIT_ROUNDOFF * sum;
    }

    /** max over texels of |DFT_n|. */
    static double maxAbs(TaylorTerms terms, int n) {
        double max = 0;
        for (int r = 0; r < terms.rows(); r++) {
            for (int c = 0; c < terms.cols(); c++) {
                max = Math.max(max, Math.hypot(terms.re(n, r, c), terms.im(n, r, c)));
            }
        }
        return max;
    }

    /**
     * Whether the thesis' series around 0, truncated at {@code highestOrder} and summed in float32, can reach
     * {@link #TOLERANCE_IN_P} for this patch at every phase the scene reaches (|a| up to 2 k_max): the estimate of
     * {@link #plainSeriesError}.
     */
    public static boolean plainSeriesSuffices(TaylorTerms terms, int highestOrder, double shortestLambdaNm) {
        return plainSeriesError(terms, highestOrder, 2 * 2 * Math.PI / (shortestLambdaNm * 1e-3)) <= TOLERANCE_IN_P;
    }

    /**
     * The patch's estimate of the error in P of the plain series at phase factor a: the float32 rounding of the
     * terms it sums ({@link #expectedAbsoluteError(TaylorTerms, double)} over orders 0..N) plus the truncated
     * tail. The tail is estimated from the last term, t_N = |a|^N / N! max|DFT_N|: the terms beyond it shrink at
     * least by r = x / (N + 2) per order (x = |a| max|h|, |DFT_{n+1}| <= max|h| |DFT_n| on average), so the tail
     * is about t_N r / (1 - r); with r >= 1 the series has not begun to converge at order N (infinite).
     */
    public static double plainSeriesError(TaylorTerms terms, int highestOrder, double a) {
        double rounding = 0;
        double coefficient = 1;
        double lastTerm = 0;
        for (int n = 0; n <= highestOrder; n++) {
            if (n > 0) {
                coefficient *= Math.abs(a) / n;
            }
            lastTerm = coefficient * maxAbs(terms, n);
            rounding += lastTerm;
        }
        double r = Math.abs(a) * terms.maxAbsHeightUm() / (highestOrder + 2);
        double tail = r < 1 ? lastTerm * r / (1 - r) : Double.POSITIVE_INFINITY;
        return FLOAT32_UNIT_ROUNDOFF * rounding + tail;
    }

    /** Errors in P below this stay below one 8-bit display step at the exposures BRDF maps are shown with. */
    public static final double TOLERANCE_IN_P = 1e-3;

    /** The phase beyond which a float32 Taylor sum errs by more than {@code toleranceInP}: ln(tolerance / 2^-24). */
    public static double reliablePhaseLimit(double toleranceInP) {
        return Math.log(toleranceInP / FLOAT32_UNIT_ROUNDOFF);
    }
}
