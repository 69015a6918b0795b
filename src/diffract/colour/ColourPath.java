package diffract.colour;

/**
 * How an XYZ colour (white at Y = 1) becomes display RGB in [0, 1].
 *
 * <ul>
 *   <li>{@link #SRGB}, the default and the correct one: XYZ -&gt; linear sRGB ({@link Srgb#linearFromXyz}),
 *       clip each channel to [0, 1], sRGB transfer curve ({@link Srgb#encode}).</li>
 *   <li>{@link #THESIS}, for comparison with M. Single's 2014 thesis only: its shader's path (eq. 1.11-1.13):
 *       divide X, Y, Z by the D65 white's components, map to "CIE RGB" with the matrix M of eq. 1.12, clip
 *       to [0, 1] and apply gamma 2.5, i.e. c^(1/2.5).</li>
 * </ul>
 *
 * <p>Which way round M goes: eq. 1.12's numbers (0.41847, -0.15866, ...) are the CIE 1931 XYZ -&gt; CIE RGB
 * matrix, the inverse of the familiar CIE RGB -&gt; XYZ matrix (1/0.17697) [[0.49, 0.31, 0.20],
 * [0.17697, 0.81240, 0.01063], [0, 0.01, 0.99]] with which the CIE defined XYZ in 1931 (reproduced e.g.
 * in the Wikipedia article "CIE 1931 color space"). The thesis says "multiply by the inverse of M", which
 * is ambiguous. Checking numerically does not settle it: because CIE RGB is normalised to equal-energy
 * white, both M and M^-1 have equal row sums (0.17697 and 1/0.17697 = 5.6506), so both map the
 * white-normalised (1, 1, 1) to a neutral grey. We apply M itself, RGB = M (X/Xw, Y/Yw, Z/Zw), since it
 * is the direction that turns XYZ into RGB; M^-1 would turn RGB into XYZ. Consequence, faithful to that
 * reading: a perfect white reflector maps to linear 0.17697 in each channel, displayed as
 * 0.17697^(1/2.5) = 0.50, a mid grey (with M^-1 it would be 5.65, clipped to white); the thesis' overall
 * brightness scale, if any, is not part of this path.
 */
public enum ColourPath {
    SRGB {
        @Override
        public float[] displayRgb(Xyz xyz) {
            double[] linear = Srgb.linearFromXyz(xyz);
            return new float[] {
                (float) Srgb.encode(linear[0]), (float) Srgb.encode(linear[1]), (float) Srgb.encode(linear[2]),
            };
        }
    },
    THESIS {
        @Override
        public float[] displayRgb(Xyz xyz) {
            double[] rgb = thesisLinearRgb(xyz);
            return new float[] {thesisGamma(rgb[0]), thesisGamma(rgb[1]), thesisGamma(rgb[2])};
        }
    };

    // Thesis eq. 1.12 (Single 2014), as printed: the CIE XYZ -> CIE RGB matrix, row-major.
    private static final double[][] THESIS_M = {
        {0.41847, -0.15866, -0.082835},
        {-0.091169, 0.25243, 0.015708},
        {0.00092090, -0.0025498, 0.17860},
    };
    // Thesis eq. 1.13: display gamma 2.5.
    private static final double THESIS_GAMMA = 2.5;

    /** Display RGB in [0, 1] for {@code xyz}, scaled so that the D65 white has Y = 1. */
    public abstract float[] displayRgb(Xyz xyz);

    /** THESIS before clipping and gamma: M (X/Xw, Y/Yw, Z/Zw) with the white {@link D65#whiteXyz()}. */
    static double[] thesisLinearRgb(Xyz xyz) {
        Xyz white = D65.whiteXyz();
        return Mat3.times(THESIS_M, new double[] {xyz.x() / white.x(), xyz.y() / white.y(), xyz.z() / white.z()});
    }

    static double[][] thesisMatrix() {
        return Mat3.copy(THESIS_M);
    }

    private static float thesisGamma(double linear) {
        double clipped = Math.min(1, Math.max(0, linear));
        return (float) Math.pow(clipped, 1 / THESIS_GAMMA);
    }
}
