package diffract.colour;

/**
 * A CIE 1931 XYZ tristimulus value (CIE 015:2018), scaled so that the reference white has
 * Y = 1 (not 100). Immutable; components may be any double, including negative ones from an out-of-gamut
 * transform.
 */
public record Xyz(double x, double y, double z) {

    /**
     * The XYZ with chromaticity (x, y) and luminance Y (the chromaticity definition inverted:
     * X = x Y / y, Z = (1 - x - y) Y / y).
     *
     * @throws IllegalArgumentException if chromaticity y is not positive
     */
    public static Xyz fromChromaticity(double chromaticityX, double chromaticityY, double luminanceY) {
        if (!(chromaticityY > 0)) {
            throw new IllegalArgumentException("chromaticity y must be positive, was " + chromaticityY);
        }
        double scale = luminanceY / chromaticityY;
        return new Xyz(chromaticityX * scale, luminanceY, (1 - chromaticityX - chromaticityY) * scale);
    }

    /** Chromaticity x = X / (X + Y + Z) (CIE 015:2018); NaN for black. */
    public double chromaticityX() {
        return x / (x + y + z);
    }

    /** Chromaticity y = Y / (X + Y + Z) (CIE 015:2018); NaN for black. */
    public double chromaticityY() {
        return y / (x + y + z);
    }

    public Xyz scaled(double factor) {
        return new Xyz(x * factor, y * factor, z * factor);
    }

    double[] toArray() {
        return new double[] {x, y, z};
    }
}
