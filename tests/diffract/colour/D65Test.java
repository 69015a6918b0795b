package diffract.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class D65Test {
    @Test
    void tableIs300To830At1Nm() {
        assertEquals(300.0, D65.firstNm());
        assertEquals(830.0, D65.lastNm());
    }

    @Test
    void normalisedTo100At560() {
        assertEquals(100.0, D65.relativePower(560), 0);
        assertEquals(0.0341, D65.relativePower(300), 0);
        assertEquals(63.3828, D65.relativePower(780), 0);
        // CIE D-series nodes beyond colour-science's 780 nm (CIE 015:2018 table values)
        assertEquals(63.8434, D65.relativePower(785), 1e-12);
        assertEquals(60.3125, D65.relativePower(830), 1e-12);
    }

    @Test
    void oneNanometreNodesAreLinearBetweenTheCie5NmNodesAndZeroOutside() {
        assertEquals(0.0341 + 0.5 * (1.6643 - 0.0341), D65.relativePower(302.5), 1e-12);
        double at555 = D65.relativePower(555);
        double at560 = D65.relativePower(560);
        assertEquals(at555 + 0.2 * (at560 - at555), D65.relativePower(556), 1e-12);
        assertEquals(0.0, D65.relativePower(299.9));
        assertEquals(0.0, D65.relativePower(830.1));
    }

    @Test
    void whitePointIsCie015() {
        Xyz white = D65.whiteXyz();
        assertEquals(0.9505, white.x(), 1e-3);
        assertEquals(1.0, white.y(), 1e-12);
        assertEquals(1.0888, white.z(), 1e-3);
        // CIE 015:2018 lists the D65 white (2-degree observer) as X = 95.047, Z = 108.883 (Y = 100).
        assertEquals(0.95047, white.x(), 1e-4);
        assertEquals(1.08883, white.z(), 1e-4);
        // Our exact numbers (trapezoid, 1 nm, 360..830 nm).
        assertEquals(0.95047042, white.x(), 1e-8);
        assertEquals(1.08882713, white.z(), 1e-8);
        assertEquals(0.3127, white.chromaticityX(), 1e-4);
        assertEquals(0.3290, white.chromaticityY(), 1e-4);
    }
}
