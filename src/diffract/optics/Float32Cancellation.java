package diffract.optics;

/**
 * When the thesis' Taylor sum stops being trustworthy in float32 (issue #6). The series
 * sum_n (k w)^n / n! DFT_n converges for every phase, but with x = k |w| max|h| its terms grow to about
 * e^x / sqrt(2 pi x) before they cancel down to |P| <= 1; float32 keeps 24 bits, so each term carries an absolute
 * rounding error of about 2^-24 of its size and the sum an error of order 2^-24 e^x. A float32 evaluation (the GPU)
 * is therefore accurate to about {@link #expectedAbsoluteError(double)} in P, whatever N is; beyond
 * x = ln(tolerance / 2^-24) the result is rounding noise that still looks plausible. The CPU variants sum the same
 * float32 terms in double and are limited only by the terms' own rounding (2^-24 |DFT_n| each, the same order).
 * Tests measure the actual error of a float32 sum against the exact transform and hold it to this estimate.
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

    /** The phase beyond which a float32 Taylor sum errs by more than {@code toleranceInP}: ln(tolerance / 2^-24). */
    public static double reliablePhaseLimit(double toleranceInP) {
        return Math.log(toleranceInP / FLOAT32_UNIT_ROUNDOFF);
    }
}
