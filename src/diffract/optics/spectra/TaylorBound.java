package diffract.optics.spectra;

/**
 * How many Taylor terms the expansion of exp(i k w h) needs (thesis 001 section 3.3.3).
 *
 * <p>With x = k_max * |w|_max * max|h| = (2 pi / lambda_min) * 2 * max|h|, the Lagrange remainder of the n-th
 * Taylor polynomial of e^t on [0, x] is at most x^(n+1) e^x / (n+1)! (001, "Part 2: Find such an N"). For the
 * purely imaginary argument the sharper bound x^(n+1) / (n+1)! holds (|d^k/dt^k e^(it)| = 1); we keep the
 * thesis' bound, which is conservative, so the chosen N is never too small.
 */
public final class TaylorBound {
    /** |w| = cos(theta_i) + cos(theta_r) is at most 2 (004, appendix on the component w). */
    public static final double MAX_ABS_W = 2.0;

    private TaylorBound() {
    }

    /** x = (2 pi / lambda_min) * 2 * max|h|, dimensionless (lambda and h in the same unit). */
    public static double maxPhase(double lambdaMinNm, double maxAbsHeightUm) {
        double lambdaMinUm = lambdaMinNm * 1e-3;
        return 2.0 * Math.PI / lambdaMinUm * MAX_ABS_W * maxAbsHeightUm;
    }

    /** The thesis' Lagrange bound x^(n+1) e^x / (n+1)!, evaluated in log space so large n never overflows. */
    public static double lagrangeRemainder(double x, int n) {
        if (n < 0) {
            throw new IllegalArgumentException("n must be >= 0");
        }
        if (x == 0) {
            return 0;
        }
        double log = (n + 1) * Math.log(x) + x - logFactorial(n + 1);
        return Math.exp(log);
    }

    /**
     * The smallest n >= 0 whose remainder is at most {@code tolerance} (for x >= 0). The remainder decreases
     * monotonically once n + 2 > x, so the search is a simple scan.
     */
    public static int termsForTolerance(double x, double tolerance) {
        if (!(tolerance > 0)) {
            throw new IllegalArgumentException("tolerance must be > 0, got " + tolerance);
        }
        for (int n = 0; n < 100_000; n++) {
            if (lagrangeRemainder(x, n) <= tolerance) {
                return n;
            }
        }
        throw new IllegalArgumentException("no Taylor order below 100000 reaches tolerance " + tolerance + " at x = " + x);
    }

    /**
     * The order at which a fragment's Taylor loop may stop: the first n in 0..N whose Lagrange bound
     * x^(n+1) e^x / (n+1)! is at most {@code tolerance}, else N; N itself when the tolerance is 0 (the thesis'
     * fixed N). The bound is evaluated by the recurrence b_0 = x e^x, b_n = b_{n-1} x / (n + 1), exactly as the
     * shader does ({@code taylorStopOrder} in diffraction_common.glsl), so CPU and GPU stop at the same order
     * except where float32 rounding puts b_n on the other side of the tolerance.
     *
     * <p>Why stopping there is safe: the terms n+1..N that are dropped are sum_k (k w)^k / k! DFT_k with
     * |DFT_k| <= max|h|^k (DFT_k is the normalised transform of (i h)^k), so they move P by at most
     * sum_{k > n} x^k / k!, the tail of e^x, which the Lagrange bound bounds.
     *
     * @param x k |w| max|h| of the fragment, >= 0
     */
    public static int stopOrder(double x, double tolerance, int highestOrder) {
        if (tolerance == 0) {
            return highestOrder;
        }
        double bound = x * Math.exp(x);
        for (int n = 0; n < highestOrder; n++) {
            if (bound <= tolerance) {
                return n;
            }
            bound *= x / (n + 2);
        }
        return highestOrder;
    }

    static double logFactorial(int n) {
        double sum = 0;
        for (int k = 2; k <= n; k++) {
            sum += Math.log(k);
        }
        return sum;
    }
}
