package diffract.optics.numerics;

import org.apache.commons.math3.special.Erf;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** ErrorFunction against Apache Commons Math's erf and erfc, and the A and S approximation's stated bound. */
class ErrorFunctionTest {
    @Test
    void erfAndErfcAgreeWithCommonsMathToDoublePrecision() {
        for (double x = -7; x <= 7; x += 0.00731) {
            assertEquals(Erf.erf(x), ErrorFunction.erf(x), 2e-16 + 1e-15 * Math.abs(Erf.erf(x)), "erf " + x);
            double expected = Erf.erfc(x);
            assertEquals(expected, ErrorFunction.erfc(x), 1e-14 * expected + 1e-300, "erfc " + x);
        }
        assertEquals(0.0, ErrorFunction.erf(0.0));
        assertEquals(Erf.erfc(12.3), ErrorFunction.erfc(12.3), 1e-14 * Erf.erfc(12.3));
    }

    @Test
    void massInIntervalDoesNotCancelFarOut() {
        // both ends at 5.0 and 5.001: erf(b) - erf(a) would cancel to zero in double
        double expected = 0.5 * (Erf.erfc(5.0) - Erf.erfc(5.001));
        assertEquals(expected, ErrorFunction.massInInterval(5.0, 5.001), 1e-9 * expected);
        assertEquals(expected, ErrorFunction.massInInterval(-5.001, -5.0), 1e-9 * expected);
        assertEquals(0.5 * Erf.erf(-0.3, 0.7), ErrorFunction.massInInterval(-0.3, 0.7), 1e-15);
    }

    @Test
    void fastErfcStaysWithinAbramowitzAndStegunsBound() {
        double worst = 0;
        for (double x = -5; x <= 5; x += 0.001) {
            worst = Math.max(worst, Math.abs(ErrorFunction.fastErfc(x) - Erf.erfc(x)));
        }
        assertTrue(worst <= 1.5e-7, "largest error " + worst);
        assertTrue(worst > 1e-9, "the approximation is not exact: " + worst);
    }
}
