package diffract.optics;

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

    static double logFactorial(int n) {
        double sum = 0;
        for (int k = 2; k <= n; k++) {
            sum += Math.log(k);
        }
        return sum;
    }
}
