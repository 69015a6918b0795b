package diffract.colour;

/**
 * The CIE 1931 2-degree standard colorimetric observer: colour-matching functions xbar, ybar, zbar
 * tabulated at 1 nm from 360 to 830 nm (CIE 015:2018 Table / ISO/CIE 11664-1, formerly CIE S 014-1),
 * read from {@code /assets/colour/cie1931_2deg_cmf_1nm.csv} (extracted from colour-science 0.4.7, see the
 * README there). Linear interpolation between the 1 nm nodes, 0 outside 360..830 nm.
 */
public final class Cie1931 {
    static final String RESOURCE = "/assets/colour/cie1931_2deg_cmf_1nm.csv";

    private Cie1931() {
    }

    // Holder idiom: the table is parsed once, on first use, thread-safely.
    private static final class Tables {
        static final SpectralTable X_BAR = SpectralTable.fromCsvResource(RESOURCE, "xbar");
        static final SpectralTable Y_BAR = SpectralTable.fromCsvResource(RESOURCE, "ybar");
        static final SpectralTable Z_BAR = SpectralTable.fromCsvResource(RESOURCE, "zbar");
    }

    public static double xBar(double lambdaNm) {
        return Tables.X_BAR.at(lambdaNm);
    }

    public static double yBar(double lambdaNm) {
        return Tables.Y_BAR.at(lambdaNm);
    }

    public static double zBar(double lambdaNm) {
        return Tables.Z_BAR.at(lambdaNm);
    }

    /** 360 nm, the first tabulated wavelength. */
    public static double firstNm() {
        return Tables.Y_BAR.firstNm();
    }

    /** 830 nm, the last tabulated wavelength. */
    public static double lastNm() {
        return Tables.Y_BAR.lastNm();
    }
}
