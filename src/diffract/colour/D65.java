package diffract.colour;

/**
 * CIE standard illuminant D65, relative spectral power distribution normalised to 100 at 560 nm
 * (CIE 015:2018 / ISO/CIE 11664-2, formerly CIE S 014-2).
 *
 * <p>Data: {@code /assets/colour/cie_d65_relative_spd_5nm.csv}, extracted from colour-science 0.4.7
 * ({@code colour.SDS_ILLUMINANTS['D65']}), which ships it at <b>5 nm from 300 to 780 nm</b> only (the CIE's
 * official table is 1 nm, 300..830 nm). We keep the data as shipped and interpolate linearly between the
 * 5 nm nodes, as CIE 15:2004 recommends for the D series. Above 780 nm the power is 0; there
 * ybar is below 2e-5 of its peak, so this moves the D65 white point by about 2e-6 in X and Z.
 */
public final class D65 {
    static final String RESOURCE = "/assets/colour/cie_d65_relative_spd_5nm.csv";

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

    /** Relative power at {@code lambdaNm} (100 at 560 nm), linear between 5 nm nodes, 0 outside 300..780 nm. */
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
     * grid 360..830 nm and normalised to Y = 1. About (0.950468, 1, 1.088828), i.e. CIE 015:2018's
     * (95.047, 100, 108.883) / 100.
     */
    public static Xyz whiteXyz() {
        return White.XYZ;
    }
}
