package diffract.colour;

/**
 * CIE standard illuminant D65, relative spectral power distribution normalised to 100 at 560 nm
 * (CIE 015:2018 / ISO/CIE 11664-2, formerly CIE S 014-2).
 *
 * <p>Data: {@code /assets/colour/cie_d65_relative_spd_1nm.csv}, 1 nm from 300 to 830 nm, extracted from
 * colour-science 0.4.7 by {@code assets/colour/extract_tables.py}: the CIE 5 nm table it ships (300..780 nm),
 * extended to 830 nm by the CIE D-series formula at D65's chromaticity, interpolated linearly to 1 nm as
 * CIE 015:2018 prescribes for the D illuminants. Between nodes we interpolate linearly; outside, the power is 0.
 */
public final class D65 {
    static final String RESOURCE = "/assets/colour/cie_d65_relative_spd_1nm.csv";

    private D65() {
    }

    private static final class Table {
        static final SpectralTable POWER = SpectralTable.fromCsvResource(RESOURCE, "relative_power");
    }

    private static final class White {
        static final Xyz XYZ = perfectReflector(Trapezoid.uniformNodes(Cie1931.firstNm(), Cie1931.lastNm(), 1.0));

        private static Xyz perfectReflector(double[] nodesNm) {
            double[] ones = new double[nodesNm.length];
            java.util.Arrays.fill(ones, 1.0);
            return SpectralIntegrator.reflectedXyz(nodesNm, Trapezoid.weights(nodesNm), ones);
        }
    }

    /** Relative power at {@code lambdaNm} (100 at 560 nm), linear between 1 nm nodes, 0 outside 300..830 nm. */
    public static double relativePower(double lambdaNm) {
        return Table.POWER.at(lambdaNm);
    }

    public static double firstNm() {
        return Table.POWER.firstNm();
    }

    public static double lastNm() {
        return Table.POWER.lastNm();
    }

    /**
     * The white point: XYZ of a perfect reflector under D65, integrated by the trapezoid rule on the 1 nm
     * grid 360..830 nm and normalised to Y = 1. About (0.950470, 1, 1.088827), i.e. CIE 015:2018's
     * (95.047, 100, 108.883) / 100.
     */
    public static Xyz whiteXyz() {
        return White.XYZ;
    }
}
