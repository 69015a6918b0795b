package diffract.optics;

import diffract.optics.patches.HeightField;
import diffract.optics.spectra.TaylorBound;
import diffract.precompute.TaylorTermComputer;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** 004 eq. {@code taylorseriesapproximationofp} and 001 section 3.3.3: sum_n (a^n / n!) DFT_n -> DFT(exp(i a h)). */
class TaylorSeriesTest {

    @Test
    void theSeriesOfStoredTermsConvergesToTheExactTransformWithinTheLagrangeBound() {
        HeightField h = NaiveDft.randomPatch(8, 10, 0.3, 0.1, 11);
        double maxAbs = h.maxAbsHeightUm();
        double lambdaUm = 0.4;
        double a = 2 * Math.PI / lambdaUm * -1.7; // k w with w = -1.7
        double x = Math.abs(a) * maxAbs;
        double[][] termsInDouble = new double[31][];
        for (int n = 0; n <= 30; n++) {
            termsInDouble[n] = TaylorTermComputer.termInDouble(h, n);
        }
        double[] exp = NaiveDft.expIAH(h, a);
        double previousError = Double.POSITIVE_INFINITY;
        for (int order = 0; order <= 30; order++) {
            double worst = 0;
            for (int r = 0; r < 8; r++) {
                for (int c = 0; c < 10; c++) {
                    double[] exact = NaiveDft.inverseAt(exp, 8, 10, c - 5, r - 4);
                    double re = 0;
                    double im = 0;
                    double coefficient = 1;
                    for (int n = 0; n <= order; n++) {
                        if (n > 0) {
                            coefficient *= a / n;
                        }
                        re += coefficient * termsInDouble[n][2 * (r * 10 + c)];
                        im += coefficient * termsInDouble[n][2 * (r * 10 + c) + 1];
                    }
                    worst = Math.max(worst, Math.hypot(re - exact[0], im - exact[1]));
                }
            }
            double bound = TaylorBound.lagrangeRemainder(x, order);
            assertTrue(worst <= bound + 1e-13, "order " + order + ": error " + worst + " > bound " + bound);
            if (order > x + 1) {
                assertTrue(worst <= previousError + 1e-14, "the error must shrink once n > x: order " + order);
            }
            previousError = worst;
        }
        assertTrue(previousError < 1e-12, "30 terms at x = " + x + " reach double precision, got " + previousError);
    }

    @Test
    void thesisNumbersForTheBound() {
        // 001 section 3.3.3: lambda_min = 400 nm, max|h| = 0.15 um, |w| <= 2  ->  x = 1.5 pi
        double x = TaylorBound.maxPhase(400, 0.15);
        assertEquals(1.5 * Math.PI, x, 1e-12);
        // the thesis prints 2.9950e-4, 8.8150e-8, 1.0050e-11 (rounded to about 3 digits)
        assertEquals(2.9950e-4, TaylorBound.lagrangeRemainder(x, 20), 1e-3 * 2.9950e-4);
        assertEquals(8.8150e-8, TaylorBound.lagrangeRemainder(x, 25), 1e-3 * 8.8150e-8);
        assertEquals(1.0050e-11, TaylorBound.lagrangeRemainder(x, 30), 1e-3 * 1.0050e-11);
        // "N = 25 for 8.8e-8": the thesis' figure is the bound at N = 25 rounded, 8.815e-8
        assertEquals(25, TaylorBound.termsForTolerance(x, 8.8150e-8 * (1 + 1e-9)));
        assertEquals(26, TaylorBound.termsForTolerance(x, 8.80e-8));
        assertEquals(20, TaylorBound.termsForTolerance(x, 3e-4));
    }

    @Test
    void boundNeverOverflowsForLargeOrders() {
        double r = TaylorBound.lagrangeRemainder(60, 300);
        assertTrue(Double.isFinite(r) && r < 1e-20);
        assertEquals(0, TaylorBound.termsForTolerance(0, 1e-9));
    }
}
