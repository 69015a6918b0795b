package diffract.optics.numerics;

/**
 * The error function, for the box averages of Gaussian lobes (a Gaussian's mass in an interval is a difference of
 * two erf values).
 *
 * <p>{@link #erf} and {@link #erfc} are accurate to double precision (ErrorFunctionTest holds them to Apache Commons
 * Math to 1e-14 relative) and fast: erfc and e^(-x^2) are tabulated every 1/64 up to 6 (from Commons Math's
 * erfc, a regularised incomplete gamma function, too slow for inner loops) and continued from the nearest node x_0
 * by the Taylor series erfc(x_0 + d) = erfc(x_0) + 2/sqrt(pi) e^(-x_0^2) sum_{n&gt;=1} (-1)^n H_{n-1}(x_0) d^n / n!
 * (H the physicists' Hermite polynomials; |d| &lt;= 1/128, nine terms); beyond 6 erfc comes from its continued
 * fraction (modified Lentz). {@link #massInInterval} takes the difference on the side where it does not cancel.
 * {@link #fastErfc} is the five-term rational approximation of Abramowitz and Stegun 7.1.26 (absolute error below
 * 1.5e-7), the formula the GLSL lobes shader evaluates in float32; the CPU mirror of that shader uses it too.
 */
public final class ErrorFunction {
    private static final double TWO_OVER_SQRT_PI = 2.0 / Math.sqrt(Math.PI);
    private static final double ONE_OVER_SQRT_PI = 1.0 / Math.sqrt(Math.PI);

    private ErrorFunction() {
    }

    private static final int NODES_PER_UNIT = 64;
    private static final double TABLE_END = 6.0;
    private static final double[] TABLE_ERFC;
    private static final double[] TABLE_GAUSS;

    static {
        int n = (int) (TABLE_END * NODES_PER_UNIT) + 1;
        TABLE_ERFC = new double[n];
        TABLE_GAUSS = new double[n];
        for (int i = 0; i < n; i++) {
            double x = (double) i / NODES_PER_UNIT;
            TABLE_ERFC[i] = org.apache.commons.math3.special.Erf.erfc(x);
            TABLE_GAUSS[i] = Math.exp(-x * x);
        }
    }

    public static double erf(double x) {
        if (Double.isNaN(x)) {
            return x;
        }
        double a = Math.abs(x);
        // below 1/2 the positive series is exact and short; above, erfc < 0.48 and 1 - erfc loses at most a bit
        double value = a < 0.5 ? series(a) : 1.0 - erfc(a);
        return x < 0 ? -value : value;
    }

    public static double erfc(double x) {
        if (Double.isNaN(x)) {
            return x;
        }
        if (x < 0) {
            return 2.0 - erfc(-x);
        }
        if (x >= TABLE_END) {
            return continuedFractionErfc(x);
        }
        int i = (int) Math.rint(x * NODES_PER_UNIT);
        double x0 = (double) i / NODES_PER_UNIT;
        double d = x - x0;
        // sum_{n>=1} (-1)^n H_{n-1}(x0) d^n / n!, H_0 = 1, H_1 = 2 x0, H_{k+1} = 2 x0 H_k - 2 k H_{k-1}
        double hPrevious = 0;
        double h = 1;
        double power = 1;
        double sum = 0;
        for (int k = 1; k <= 9; k++) {
            power *= -d / k;
            sum += h * power;
            double next = 2 * x0 * h - 2 * (k - 1) * hPrevious;
            hPrevious = h;
            h = next;
        }
        return TABLE_ERFC[i] + TWO_OVER_SQRT_PI * TABLE_GAUSS[i] * sum;
    }

    /**
     * The mass of the density exp(-z^2) / sqrt(pi) in [a, b], (erf(b) - erf(a)) / 2, computed with erfc where both
     * ends lie on the same side of 0 (far out their erf values would cancel).
     */
    public static double massInInterval(double a, double b) {
        if (a >= 0) {
            return 0.5 * (erfc(a) - erfc(b));
        }
        if (b <= 0) {
            return 0.5 * (erfc(-b) - erfc(-a));
        }
        return 0.5 * (erf(b) - erf(a));
    }

    /** Abramowitz and Stegun 7.1.26 for x &gt;= 0: erfc(x) = t (a1 + t (a2 + ...)) e^(-x^2), t = 1 / (1 + p x). */
    public static double fastErfc(double x) {
        if (x < 0) {
            return 2.0 - fastErfc(-x);
        }
        double t = 1.0 / (1.0 + 0.3275911 * x);
        double poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
        return poly * Math.exp(-x * x);
    }

    /** Phi(z) from erfc on whichever side does not cancel, {@link #fastErfc} where {@code fast} (the shader's). */
    public static double normalCdf(double z, boolean fast) {
        double x = Math.abs(z) / Math.sqrt(2);
        double tail = 0.5 * (fast ? fastErfc(x) : erfc(x));
        return z >= 0 ? 1 - tail : tail;
    }

    /** {@link #massInInterval} with {@link #fastErfc}: what the shader computes. */
    public static double fastMassInInterval(double a, double b) {
        if (a >= 0) {
            return 0.5 * (fastErfc(a) - fastErfc(b));
        }
        if (b <= 0) {
            return 0.5 * (fastErfc(-b) - fastErfc(-a));
        }
        return 0.5 * (2.0 - fastErfc(-a) - fastErfc(b));
    }

    private static double series(double x) {
        double x2 = x * x;
        double term = x;
        double sum = x;
        for (int n = 1; n < 200; n++) {
            term *= 2.0 * x2 / (2 * n + 1);
            sum += term;
            if (term < 1e-17 * sum) {
                break;
            }
        }
        return TWO_OVER_SQRT_PI * Math.exp(-x2) * sum;
    }

    /** erfc(x) = e^(-x^2) / sqrt(pi) * 1 / (x + (1/2) / (x + 1 / (x + (3/2) / (x + ...)))), x &gt; 3. */
    private static double continuedFractionErfc(double x) {
        if (x > 27.3) {
            return 0.0; // e^(-x^2) underflows
        }
        double tiny = 1e-300;
        double f = x;
        double c = x;
        double d = 0;
        for (int n = 1; n < 500; n++) {
            double an = n * 0.5;
            d = x + an * d;
            d = Math.abs(d) < tiny ? tiny : d;
            c = x + an / c;
            c = Math.abs(c) < tiny ? tiny : c;
            d = 1.0 / d;
            double delta = c * d;
            f *= delta;
            if (Math.abs(delta - 1.0) < 1e-16) {
                break;
            }
        }
        return ONE_OVER_SQRT_PI * Math.exp(-x * x) / f;
    }
}
