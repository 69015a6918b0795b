package diffract.optics.rigorous;

import java.util.function.DoubleUnaryOperator;

/**
 * A 1-D periodic surface relief: the height above the lowest point as a function of the position across the
 * grooves, over one period. The grooves run along the other axis; the structure is uniform along them.
 *
 * @param periodUm    the period, um
 * @param depthUm     the peak-to-valley height, um: the largest value of h, whose smallest is 0
 * @param heightUm    the height at a fraction t in [0, 1) of the period, um; continuous and periodic (h(0) = h(1^-)),
 *                    within [0, depthUm]
 * @param description what it is, for reports ("sinusoid, period 1 um, 0.3 um deep")
 */
public record Profile(double periodUm, double depthUm, DoubleUnaryOperator heightUm, String description) {
    public Profile {
        if (!(periodUm > 0) || !Double.isFinite(periodUm)) {
            throw new IllegalArgumentException("a profile's period must be > 0 um, got " + periodUm);
        }
        if (!(depthUm >= 0) || !Double.isFinite(depthUm)) {
            throw new IllegalArgumentException("a profile's depth must be >= 0 um, got " + depthUm);
        }
    }

    /** h(t) in um at the fraction t of the period (wrapped into [0, 1)). */
    public double at(double t) {
        return heightUm.applyAsDouble(t - Math.floor(t));
    }

    /** A sinusoid of peak-to-valley {@code depthUm}: h = depth (1 + sin 2 pi t) / 2. */
    public static Profile sinusoid(double periodUm, double depthUm) {
        return new Profile(periodUm, depthUm, t -> 0.5 * depthUm * (1 + Math.sin(2 * Math.PI * t)),
                String.format(java.util.Locale.ROOT, "sinusoid, period %.4g um, %.4g um deep", periodUm, depthUm));
    }

    /**
     * A triangle of peak-to-valley {@code depthUm} that rises over the fraction {@code rise} of the period and falls
     * over the rest (0.5: symmetric; near 1: a blazed sawtooth with a steep back).
     */
    public static Profile triangle(double periodUm, double depthUm, double rise) {
        if (!(rise > 0 && rise < 1)) {
            throw new IllegalArgumentException("a triangle's rise is a fraction in (0, 1), got " + rise);
        }
        return new Profile(periodUm, depthUm, t -> t < rise ? depthUm * t / rise : depthUm * (1 - t) / (1 - rise),
                String.format(java.util.Locale.ROOT, "triangle, period %.4g um, %.4g um deep, rising over %.0f %%",
                        periodUm, depthUm, 100 * rise));
    }

    /**
     * The polyline through {@code heightsUm}, equally spaced samples of one period starting at t = 0 (the last joins
     * the first), shifted so its lowest sample is 0: a measured cross-section.
     */
    public static Profile sampled(double periodUm, double[] heightsUm, String description) {
        int n = heightsUm.length;
        if (n < 2) {
            throw new IllegalArgumentException("a sampled profile needs at least 2 samples, got " + n);
        }
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (double h : heightsUm) {
            if (!Double.isFinite(h)) {
                throw new IllegalArgumentException("a sampled profile's heights must be finite");
            }
            min = Math.min(min, h);
            max = Math.max(max, h);
        }
        double[] h = new double[n];
        for (int i = 0; i < n; i++) {
            h[i] = heightsUm[i] - min;
        }
        return new Profile(periodUm, max - min, t -> {
            double x = t * n;
            int i = Math.min(n - 1, (int) Math.floor(x));
            double f = x - i;
            return h[i] + f * (h[(i + 1) % n] - h[i]);
        }, description);
    }
}
