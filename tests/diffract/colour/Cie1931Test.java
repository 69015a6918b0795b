package diffract.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class Cie1931Test {
    private static final double[] NODES_1NM = Trapezoid.uniformNodes(360, 830, 1);

    // Trapezoid integrals of the colour-science 0.4.7 table (numpy.trapezoid over 360..830 nm at 1 nm):
    // xbar 106.8654039140245, ybar 106.856914916767, zbar 106.89194822863601.
    @Test
    void integralsMatchColourScience() {
        assertEquals(106.8654039140245, Trapezoid.integrate(NODES_1NM, Cie1931::xBar), 1e-9);
        assertEquals(106.856914916767, Trapezoid.integrate(NODES_1NM, Cie1931::yBar), 1e-9);
        assertEquals(106.89194822863601, Trapezoid.integrate(NODES_1NM, Cie1931::zBar), 1e-9);
    }

    @Test
    void integralsMatchTheRoundedBriefValues() {
        assertEquals(106.865, Trapezoid.integrate(NODES_1NM, Cie1931::xBar), 1e-3);
        assertEquals(106.857, Trapezoid.integrate(NODES_1NM, Cie1931::yBar), 1e-3);
        assertEquals(106.892, Trapezoid.integrate(NODES_1NM, Cie1931::zBar), 1e-3);
    }

    @Test
    void rangeIs360To830() {
        assertEquals(360.0, Cie1931.firstNm());
        assertEquals(830.0, Cie1931.lastNm());
    }

    @Test
    void nodeValuesAreTheCieTable() {
        // CIE table values (CVRL's digits): ybar(555) = 1 (photopic peak), xbar(600) = 1.0622, zbar(450) = 1.77211.
        assertEquals(1.0, Cie1931.yBar(555), 0);
        assertEquals(1.0622, Cie1931.xBar(600), 0);
        assertEquals(1.77211, Cie1931.zBar(450), 0);
        assertEquals(0.0001299, Cie1931.xBar(360), 0);
    }

    @Test
    void interpolatesLinearlyAndIsZeroOutside() {
        assertEquals(0.5 * (Cie1931.yBar(555) + Cie1931.yBar(556)), Cie1931.yBar(555.5), 1e-15);
        assertEquals(0.75 * Cie1931.xBar(600) + 0.25 * Cie1931.xBar(601), Cie1931.xBar(600.25), 1e-15);
        assertEquals(0.0, Cie1931.yBar(359.999));
        assertEquals(0.0, Cie1931.zBar(830.001));
        assertEquals(0.0, Cie1931.xBar(-1));
    }
}
