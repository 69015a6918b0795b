package diffract.optics.spectra;

import diffract.optics.NaiveDft;
import diffract.optics.patches.HeightField;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;

import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Measures where a float32 Taylor sum, as the GPU computes it, turns into rounding noise, and holds the measured
 * error to {@link Float32Cancellation}'s estimate 2^-24 e^x.
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
        TestReport.line(Float32CancellationTest.class, table);
        // ... and the breakdown is real: by x ~ 20 the float32 sum errs by more than 1e-3 (P itself is <= 1)
        assertTrue(firstUnreliable <= 21, "float32 stayed accurate to x = 21?\n" + table);
        TestReport.printf(Float32CancellationTest.class, Locale.ROOT, "float32 sum first errs by > 1e-3 at x = %.1f (estimate: x > %.1f)%n",
                firstUnreliable, Float32Cancellation.reliablePhaseLimit(1e-3));
    }

    /**
     * The phase-centred expansion summed exactly as taylor_centred.glsl does, in float32 (coefficients
     * of the offset k w - a_j by the shader's recurrence): its error stays at the float32 level, about
     * 2^-24 e^b (b = 2), at every height, where the plain series' error grows like e^x.
     */
    @Test
    void phaseCentredFloat32SumStaysAccurateAtEveryHeight() {
        StringBuilder table = new StringBuilder("x, plain N = 30: estimated error (plainSeriesError), centred: measured worst |P_float32 - P_exact|\n");
        for (double maxHeight : new double[] {0.2, 0.6, 1.0, 2.0}) {
            HeightField patch = NaiveDft.randomPatch(16, 16, 2 * maxHeight, 0.1, 77);
            double a = -2 * 2 * Math.PI / 0.38; // the largest phase: k w at 380 nm, |w| = 2
            double x = Math.abs(a) * patch.maxAbsHeightUm();
            PhaseCentres centres = PhaseCentres.forPatch(patch.maxAbsHeightUm(), 380);
            PhaseCentredTerms centred = TaylorTermComputer.computeCentred(patch, centres, Reporter.SILENT);
            double worst = 0;
            // the largest phase and phases half-way between centres (the largest offsets b)
            for (double phase : new double[] {a, a / 3 - centres.spacingPerUm() / 2, a / 2}) {
                int j = centres.nearestCentre(phase);
                double[] exp = NaiveDft.expIAH(patch, phase);
                float offset = (float) phase - (float) centres.centrePerUm(j); // as the shader: k w + j spacing
                for (int r = 0; r < 16; r++) {
                    for (int c = 0; c < 16; c++) {
                        double[] exact = NaiveDft.inverseAt(exp, 16, 16, c - 8, r - 8);
                        float[] p = float32Sum(centred.aroundCentre(j), r, c, offset, centres.highestOrder());
                        worst = Math.max(worst, Math.hypot(p[0] - exact[0], p[1] - exact[1]));
                    }
                }
            }
            TaylorTerms plain = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
            table.append(String.format(Locale.ROOT, "%.1f, %.3g, %.3g%n", x,
                    Float32Cancellation.plainSeriesError(plain, 30, a), worst));
            // float32 terms and sum around a centre b <= 2 away: 2^-24 e^2 = 4.4e-7 per unit of |E|, the offset's
            // own float32 rounding (6e-8 |a| max|h| <= 4e-6 in phase at x = 66) and the truncation 1.9e-7;
            // measured at most 2.7e-7 up to x = 67 (printed)
            assertTrue(worst < 1e-5, "x = " + x + ": centred float32 error " + worst + "\n" + table);
        }
        TestReport.line(Float32CancellationTest.class, table);
    }

    /**
     * The choice of the half-width b (PhaseCentres.DEFAULT_HALF_WIDTH): on a 2 um patch at 380 nm (x = 67), the
     * layers (centres x orders for a truncation bound of 1e-6) and the measured float32 error of the centred sum
     * for b = 0.5 .. 4. Every b reaches float32 accuracy on this patch (its terms are far below the worst case
     * 2^-24 e^b); a larger b trades texture memory (layers) for work per fragment (orders). Measured: b = 0.5: 544
     * layers, 8 orders; 1: 350, 10; 2: 270, 15; 3: 228, 19; 4: 198, 22; errors 7e-8 .. 4e-7.
     */
    @Test
    void halfWidthTradesLayersForOrdersAtFloat32Accuracy() {
        HeightField patch = NaiveDft.randomPatch(16, 16, 4.0, 0.1, 77);
        double a = -2 * 2 * Math.PI / 0.38;
        StringBuilder table = new StringBuilder("b, centres, orders, layers, worst float32 error in P\n");
        int previousLayers = Integer.MAX_VALUE;
        int previousOrders = 0;
        for (double b : new double[] {0.5, 1, 2, 3, 4}) {
            PhaseCentres centres = PhaseCentres.forPatch(patch.maxAbsHeightUm(), 380, b);
            PhaseCentredTerms centred = TaylorTermComputer.computeCentred(patch, centres, Reporter.SILENT);
            double worst = 0;
            // half-way between the last two centres: the largest offset b at a large phase
            double phase = centres.centrePerUm(centres.centreCount() - 2) - centres.spacingPerUm() / 2;
            for (double p : new double[] {a, phase}) {
                int j = centres.nearestCentre(p);
                double[] exp = NaiveDft.expIAH(patch, p);
                float offset = (float) p - (float) centres.centrePerUm(j);
                for (int r = 0; r < 16; r++) {
                    for (int c = 0; c < 16; c++) {
                        double[] exact = NaiveDft.inverseAt(exp, 16, 16, c - 8, r - 8);
                        float[] sum = float32Sum(centred.aroundCentre(j), r, c, offset, centres.highestOrder());
                        worst = Math.max(worst, Math.hypot(sum[0] - exact[0], sum[1] - exact[1]));
                    }
                }
            }
            table.append(String.format(Locale.ROOT, "%.1f, %d, %d, %d, %.3g%n", b, centres.centreCount(),
                    centres.ordersPerCentre(), centres.layerCount(), worst));
            assertTrue(worst < 1e-6, "b = " + b + ": " + worst + "\n" + table);
            assertTrue(centres.layerCount() < previousLayers && centres.ordersPerCentre() > previousOrders,
                    "layers fall and orders rise with b\n" + table);
            previousLayers = centres.layerCount();
            previousOrders = centres.ordersPerCentre();
        }
        TestReport.line(Float32CancellationTest.class, table);
    }

    /**
     * The switch's estimate (rounding plus truncated tail of the thesis' N = 30) against the measured error of the
     * float32 sum of 31 terms: never below a tenth of it, so a scene the estimate passes (<= 1e-3) errs by at most
     * 1e-2 in P. Measured: the estimate is 3 to 6 times the error from x = 1.7 to 20 (printed).
     */
    @Test
    void plainSeriesEstimateCoversTheMeasuredErrorOfThirtyOneTerms() {
        StringBuilder table = new StringBuilder("x, measured error of N = 30 in float32, plainSeriesError\n");
        for (double maxHeight : new double[] {0.05, 0.2, 0.3, 0.4, 0.5, 0.6}) {
            HeightField patch = NaiveDft.randomPatch(16, 16, 2 * maxHeight, 0.1, 77);
            double a = -2 * 2 * Math.PI / 0.38;
            TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
            double[] exp = NaiveDft.expIAH(patch, a);
            double worst = 0;
            for (int r = 0; r < 16; r++) {
                for (int c = 0; c < 16; c++) {
                    double[] exact = NaiveDft.inverseAt(exp, 16, 16, c - 8, r - 8);
                    float[] p = float32Sum(terms, r, c, a, 30);
                    worst = Math.max(worst, Math.hypot(p[0] - exact[0], p[1] - exact[1]));
                }
            }
            double estimate = Float32Cancellation.plainSeriesError(terms, 30, a);
            table.append(String.format(Locale.ROOT, "%.1f, %.3g, %.3g%n", Math.abs(a) * patch.maxAbsHeightUm(),
                    worst, estimate));
            assertTrue(worst <= 10 * estimate, "estimate below a tenth of the error\n" + table);
        }
        TestReport.line(Float32CancellationTest.class, table);
    }

    @Test
    void limitFollowsFromTheUnitRoundoff() {
        assertEquals(Math.log(1e-3) + 24 * Math.log(2), Float32Cancellation.reliablePhaseLimit(1e-3), 1e-12);
        assertEquals(9.73, Float32Cancellation.reliablePhaseLimit(1e-3), 0.01);
    }
}
