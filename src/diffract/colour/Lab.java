package diffract.colour;

/**
 * CIE 1976 L*a*b* (CIELAB) as defined in CIE 015:2018 and ISO/CIE 11664-4, with the exact constants of
 * the current definition: epsilon = (6/29)^3 = 216/24389 and kappa = (29/3)^3 = 24389/27 (the older 0.008856
 * and 903.3 are their roundings, which leave a small kink at the break). Immutable.
 */
public record Lab(double l, double a, double b) {
    private static final double EPSILON = 216.0 / 24389.0;
    private static final double KAPPA = 24389.0 / 27.0;

    /**
     * L*a*b* of {@code xyz} relative to the reference white {@code white} (both at the same scale, e.g.
     * {@link D65#whiteXyz()} for colours from {@link SpectralIntegrator}).
     */
    public static Lab fromXyz(Xyz xyz, Xyz white) {
        double fx = f(xyz.x() / white.x());
        double fy = f(xyz.y() / white.y());
        double fz = f(xyz.z() / white.z());
        return new Lab(116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz));
    }

    // f(t) = t^(1/3) above epsilon, else the linear segment (kappa t + 16) / 116 that meets it there.
    private static double f(double t) {
        return t > EPSILON ? Math.cbrt(t) : (KAPPA * t + 16) / 116;
    }
}
