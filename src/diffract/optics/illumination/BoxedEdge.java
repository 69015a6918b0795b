package diffract.optics.illumination;

import diffract.optics.numerics.ErrorFunction;

/**
 * A blurred straight edge seen through a map pixel's box: the average of Phi((d + n . t) / s) over t uniform in the
 * box [-h_x, h_x] x [-h_y, h_y], n the edge's unit normal (DiscFootprint's rim, lobes_footprint.glsl's
 * boxedNormalCdf). n . t is the sum of two uniform variables of half-widths A = h_x |n_x| and B = h_y |n_y| (a
 * trapezoid), so with Psi_1(z) = z Phi(z) + phi(z) and Psi_2(z) = ((z^2 + 1) Phi(z) + z phi(z)) / 2, the first and
 * second antiderivatives of Phi,
 * <pre>
 *     E = s^2 / (4 A B) [Psi_2(z + a + b) - Psi_2(z - a + b) - Psi_2(z + a - b) + Psi_2(z - a - b)],
 * </pre>
 * z = d / s, a = A / s, b = B / s; with b much smaller than a the box is one uniform, E = [Psi_1(z + a) - Psi_1(z - a)]
 * / (2 a), and with a much smaller than 1 a point, E = Phi(z). The box is exact here, where the Gaussian of its
 * variance (h^2 / 3 per axis) puts a tail of Phi(-sqrt 3) = 4 % of the plateau beyond the box's reach.
 *
 * <p>Numerics: E is evaluated for d at most 0 (E(d) = 1 - E(-d) otherwise), so that every Psi_2 is at most of size
 * (a + b)^2 / 2 and the second difference loses at most a factor (a + b)^2 / (2 a b) of precision; below
 * {@link #UNIFORM_BELOW} (b / a) that factor would pass 50 and the uniform's formula takes over (it leaves out a
 * variance b^2 / 3 against a^2 / 3, 1e-4 of it); below {@link #POINT_BELOW} (a) the box is left out (an error of order
 * a^2 / 6 of the edge's slope).
 */
public final class BoxedEdge {
    /** b / a below which the trapezoid is taken as the uniform of half-width A. */
    public static final double UNIFORM_BELOW = 1e-2;
    /** a = A / s below which the box is left out. */
    public static final double POINT_BELOW = 1e-3;

    private static final double INV_SQRT_TWO_PI = 1 / Math.sqrt(2 * Math.PI);

    private BoxedEdge() {
    }

    /**
     * The average of Phi((d + n . t) / s) over the box's projection, half-widths {@code a} and {@code b} (in the units
     * of d and s, in any order).
     *
     * @param fast the shader's erfc ({@link ErrorFunction#fastErfc}) instead of the accurate one
     */
    public static double average(double d, double halfWidthA, double halfWidthB, double s, boolean fast) {
        double a = Math.max(halfWidthA, halfWidthB) / s;
        double b = Math.min(halfWidthA, halfWidthB) / s;
        return d <= 0 ? lower(d / s, a, b, fast) : 1 - lower(-d / s, a, b, fast);
    }

    /** E for z at most 0. */
    private static double lower(double z, double a, double b, boolean fast) {
        if (a < POINT_BELOW) {
            return ErrorFunction.normalCdf(z, fast);
        }
        if (b < UNIFORM_BELOW * a) {
            return Math.max(0, (psi1(z + a, fast) - psi1(z - a, fast)) / (2 * a));
        }
        return Math.max(0, (psi2(z + a + b, fast) - psi2(z - a + b, fast) - psi2(z + a - b, fast)
                + psi2(z - a - b, fast)) / (4 * a * b));
    }

    /** Psi_1(z) = z Phi(z) + phi(z), the antiderivative of Phi. */
    static double psi1(double z, boolean fast) {
        return z * ErrorFunction.normalCdf(z, fast) + INV_SQRT_TWO_PI * Math.exp(-0.5 * z * z);
    }

    /** Psi_2(z) = ((z^2 + 1) Phi(z) + z phi(z)) / 2, the antiderivative of Psi_1. */
    static double psi2(double z, boolean fast) {
        return 0.5 * ((z * z + 1) * ErrorFunction.normalCdf(z, fast) + z * INV_SQRT_TWO_PI * Math.exp(-0.5 * z * z));
    }
}
