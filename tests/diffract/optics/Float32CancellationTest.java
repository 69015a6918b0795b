package diffract.optics;

import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;

import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Measures where a float32 Taylor sum, as the GPU computes it, turns into rounding noise, and holds the measured
 * error to {@link Float32Cancellation}'s estimate 2^-24 e^x (issue #6).
 */
class Float32CancellationTest {

    /** sum_n c_n DFT_n(texel) with every operation in float32, coefficients by the shader's recurrence. */
    private static float[] float32Sum(TaylorTerms terms, int row, int col, double a, int highestOrder) {
        float coefficient = 1f;
        float re = 0f;
        float im = 0f;
        for (int n = 0; n <= highestOrder; n++) {
            if (n > 0) {
                coefficient = coefficient * (float) a / n;
            }
            re += coefficient * terms.re(n, row, col);
            im += coefficient * terms.im(n, row, col);
        }
        return new float[] {re, im};
    }

    @Test
    void float32ErrorGrowsLikeExpOfThePhaseAndStaysWithinTheEstimate() {
        StringBuilder table = new StringBuilder("x, worst |P_float32 - P_exact| over all texels, patch estimate,"
                + " worst-case estimate 2^-24 e^x\n");
        double firstUnreliable = Double.NaN;
        for (double maxHeight : new double[] {0.05, 0.2, 0.4, 0.6, 0.8, 1.0}) {
            HeightField patch = NaiveDft.randomPatch(16, 16, 2 * maxHeight, 0.1, 77);
            double h = patch.maxAbsHeightUm();
            double a = -2 * 2 * Math.PI / 0.38; // k w at 380 nm, |w| = 2
            double x = Math.abs(a) * h;
            int order = TaylorBound.termsForTolerance(x, 1e-12);
            TaylorTerms terms = TaylorTermComputer.compute(patch, order, Reporter.SILENT);
            double[] exp = NaiveDft.expIAH(patch, a);
            double worst = 0;
            for (int r = 0; r < 16; r++) {
                for (int c = 0; c < 16; c++) {
                    double[] exact = NaiveDft.inverseAt(exp, 16, 16, c - 8, r - 8);
                    float[] p = float32Sum(terms, r, c, a, order);
                    worst = Math.max(worst, Math.hypot(p[0] - exact[0], p[1] - exact[1]));
                }
            }
            double estimate = Float32Cancellation.expectedAbsoluteError(x);
            double patchEstimate = Float32Cancellation.expectedAbsoluteError(terms, a);
            table.append(String.format(Locale.ROOT, "%.2f, %.3g, %.3g, %.3g%n", x, worst, patchEstimate, estimate));
            // the worst case holds, and the patch's own estimate is within an order of magnitude of what happens
            assertTrue(worst <= estimate + 1e-6, "x = " + x + ": error " + worst + " vs worst case " + estimate);
            assertTrue(worst <= 10 * patchEstimate + 1e-6 && worst >= patchEstimate / 100,
                    "x = " + x + ": error " + worst + " vs patch estimate " + patchEstimate);
            if (worst > 1e-3 && Double.isNaN(firstUnreliable)) {
                firstUnreliable = x;
            }
        }
        System.out.print(table);
        // ... and the breakdown is real: by x ~ 20 the float32 sum errs by more than 1e-3 (P itself is <= 1)
        assertTrue(firstUnreliable <= 21, "float32 stayed accurate to x = 21?\n" + table);
        System.out.printf(Locale.ROOT, "float32 sum first errs by > 1e-3 at x = %.1f (estimate: x > %.1f)%n",
                firstUnreliable, Float32Cancellation.reliablePhaseLimit(1e-3));
    }

    @Test
    void limitFollowsFromTheUnitRoundoff() {
        assertEquals(Math.log(1e-3) + 24 * Math.log(2), Float32Cancellation.reliablePhaseLimit(1e-3), 1e-12);
        assertEquals(9.73, Float32Cancellation.reliablePhaseLimit(1e-3), 0.01);
    }
}
