package diffract.colour;

/**
 * sRGB as defined by IEC 61966-2-1:1999: primaries R (0.64, 0.33), G (0.30, 0.60), B (0.15, 0.06), white D65
 * (0.3127, 0.3290), and the piecewise transfer curve.
 *
 * <p>The XYZ &lt;-&gt; linear sRGB matrices are derived here in double precision from those chromaticities
 * (the standard construction of SMPTE RP 177-1993): the columns of RGB-&gt;XYZ are the
 * primaries' XYZ, scaled so that RGB (1, 1, 1) is the white point with Y = 1. IEC 61966-2-1 prints the
 * inverse rounded to 4 digits (3.2406, -1.5372, -0.4986, ...); deriving it avoids that rounding, so that
 * white round-trips exactly.
 *
 * <p>The matrices leave out-of-gamut values (negative, or above 1) as they are; {@link #encode} clips them
 * to [0, 1] per channel. Saturated spectral colours (diffraction peaks) are mostly outside the sRGB gamut,
 * so they are displayed clipped per channel, which shifts their hue slightly towards the gamut's corners.
 */
public final class Srgb {
    // IEC 61966-2-1:1999: primaries and reference white chromaticities.
    private static final double[][] PRIMARIES_XY = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
    private static final double WHITE_X = 0.3127;
    private static final double WHITE_Y = 0.3290;

    // IEC 61966-2-1:1999 transfer curve (encoding and its inverse).
    private static final double LINEAR_BREAK = 0.0031308;
    private static final double LINEAR_SLOPE = 12.92;
    private static final double OFFSET = 0.055;
    private static final double GAMMA = 2.4;
    // The standard decodes with the break at 0.04045, a rounding of 12.92 * 0.0031308 = 0.040449936. Using the
    // unrounded value makes decode an exact inverse of encode: with 0.04045, encoded values in the
    // 6e-8 wide gap (0.040449936, 0.04045] would come back from encode(decode(.)) off by up to 3e-8.
    private static final double ENCODED_BREAK = LINEAR_SLOPE * LINEAR_BREAK;

    private static final double[][] LINEAR_TO_XYZ = deriveLinearToXyz();
    private static final double[][] XYZ_TO_LINEAR = Mat3.inverse(LINEAR_TO_XYZ);

    private Srgb() {
    }

    private static double[][] deriveLinearToXyz() {
        // Columns: each primary's XYZ at Y = 1, to be scaled by s so that P s = white.
        double[][] p = new double[3][3];
        for (int c = 0; c < 3; c++) {
            Xyz primary = Xyz.fromChromaticity(PRIMARIES_XY[c][0], PRIMARIES_XY[c][1], 1.0);
            p[0][c] = primary.x();
            p[1][c] = primary.y();
            p[2][c] = primary.z();
        }
        double[] s = Mat3.times(Mat3.inverse(p), whiteXyz().toArray());
        double[][] m = new double[3][3];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                m[r][c] = p[r][c] * s[c];
            }
        }
        return m;
    }

    /**
     * The sRGB white, XYZ of chromaticity (0.3127, 0.3290) at Y = 1: (0.950456, 1, 1.089058). Note that this
     * differs in the 4th digit from the spectrally integrated {@link D65#whiteXyz()} (0.950470, 1, 1.088827),
     * because IEC rounded the white's chromaticity to 4 digits.
     */
    public static Xyz whiteXyz() {
        return Xyz.fromChromaticity(WHITE_X, WHITE_Y, 1.0);
    }

    /** Linear sRGB {r, g, b} of {@code xyz}, unclipped. */
    public static double[] linearFromXyz(Xyz xyz) {
        return Mat3.times(XYZ_TO_LINEAR, xyz.toArray());
    }

    /** XYZ of linear sRGB {r, g, b}; the exact inverse of {@link #linearFromXyz}. */
    public static Xyz xyzFromLinear(double[] linearRgb) {
        if (linearRgb.length != 3) {
            throw new IllegalArgumentException("need 3 components, got " + linearRgb.length);
        }
        double[] v = Mat3.times(LINEAR_TO_XYZ, linearRgb);
        return new Xyz(v[0], v[1], v[2]);
    }

    /** The derived XYZ -&gt; linear sRGB matrix, row-major (a copy). */
    public static double[][] xyzToLinearMatrix() {
        return Mat3.copy(XYZ_TO_LINEAR);
    }

    /** The derived linear sRGB -&gt; XYZ matrix, row-major (a copy). */
    public static double[][] linearToXyzMatrix() {
        return Mat3.copy(LINEAR_TO_XYZ);
    }

    /**
     * The sRGB transfer curve (IEC 61966-2-1): 12.92 c below 0.0031308, 1.055 c^(1/2.4) - 0.055 above,
     * after clamping c to [0, 1]. NaN stays NaN.
     */
    public static double encode(double linear) {
        if (linear <= 0) {
            return 0;
        }
        if (linear >= 1) {
            return 1;
        }
        if (linear <= LINEAR_BREAK) {
            return LINEAR_SLOPE * linear;
        }
        return (1 + OFFSET) * Math.pow(linear, 1 / GAMMA) - OFFSET;
    }

    /**
     * The inverse curve (IEC 61966-2-1): c / 12.92 up to 12.92 * 0.0031308, ((c + 0.055) / 1.055)^2.4
     * above. Not clamped: values outside [0, 1] follow the formulas (negative input follows the linear part).
     */
    public static double decode(double encoded) {
        if (encoded <= ENCODED_BREAK) {
            return encoded / LINEAR_SLOPE;
        }
        return Math.pow((encoded + OFFSET) / (1 + OFFSET), GAMMA);
    }

    /** XYZ (D65, Y = 1) of interleaved display-encoded sRGB triples, as a picture's pixels are stored. */
    public static float[] xyzOfDisplayRgb(float[] rgb) {
        float[] xyz = new float[rgb.length];
        for (int p = 0; p + 2 < rgb.length; p += 3) {
            Xyz c = xyzFromLinear(new double[] {decode(rgb[p]), decode(rgb[p + 1]), decode(rgb[p + 2])});
            xyz[p] = (float) c.x();
            xyz[p + 1] = (float) c.y();
            xyz[p + 2] = (float) c.z();
        }
        return xyz;
    }
}
