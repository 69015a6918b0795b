package diffract.optics.spectra;

import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.Variant;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.windows.WindowRadii;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The Taylor loop that stops once the Lagrange remainder of the lookup's own x = |k w| max|h|
 * meets a tolerance, and the window radius that follows sigma_f, held against the fixed-N, fixed-window sums.
 */
class EarlyStopAndWindowTest {
    private static final HeightField PATCH = SyntheticPatches.elapheLike(32, 4, 0.6, 0.3, 7).meanSubtracted();
    private static final TaylorTerms TERMS = TaylorTermComputer.compute(PATCH, 30, Reporter.SILENT);
    /** The thesis' window, fixed at the DFT's origin, as Algorithm 3 sums it (AveragedWindowTest holds the average). */
    private static final CoherenceWindow WINDOW = new CoherenceWindow(2.5, WindowPlacement.FIXED);

    /**
     * Tolerance 0 is the thesis' fixed N, to the last bit: the sum equals a literal restatement of 003 Algorithm 3
     * (coefficients by recurrence, the same loops in the same order) exactly, at lookups all over the band.
     */
    @Test
    void toleranceZeroIsTheFixedSumBitForBit() {
        TaylorGaussianSpectrum spectrum = new TaylorGaussianSpectrum(TERMS, 30, new WindowRadii(1, 1), 0.0, WINDOW);
        double sigmaX = WINDOW.sigmaTexels(spectrum.extentXUm());
        double sigmaY = WINDOW.sigmaTexels(spectrum.extentYUm());
        int checked = 0;
        for (double u = -0.9; u <= 0.9; u += 0.137) {
            for (double v = -0.9; v <= 0.9; v += 0.113) {
                double w = -1.9 + 0.3 * Math.abs(u);
                double lambdaUm = 0.45;
                double sx = u * spectrum.extentXUm() / lambdaUm;
                double sy = v * spectrum.extentYUm() / lambdaUm;
                double a = 2 * Math.PI / lambdaUm * w;
                double expected = literalFixedSum(sx, sy, a, sigmaX, sigmaY);
                assertEquals(expected, spectrum.power(u, v, w, lambdaUm), 0.0, "u " + u + ", v " + v);
                checked++;
            }
        }
        assertTrue(checked > 100);
        assertEquals(0.0, BrdfSettings.thesis(Variant.FLSS).taylor().tolerance());
    }

    /**
     * With tolerance eps every lookup's P moves by at most eps times the window's summed weights: the dropped
     * terms are bounded by the Lagrange remainder per texel (|DFT_n| <= max|h|^n), the window sums them. Measured:
     * the printed largest ratio of the change to that bound (well below 1: the e^x bound is loose), and the mean
     * stop order, which shows the loop really stops early.
     */
    @Test
    void earlyStopStaysWithinTheRemainderBound() {
        for (double tolerance : new double[] {1e-3, 1e-6, 1e-9}) {
            TaylorGaussianSpectrum fixed = new TaylorGaussianSpectrum(TERMS, 30, new WindowRadii(1, 1), 0.0, WINDOW);
            TaylorGaussianSpectrum early = new TaylorGaussianSpectrum(TERMS, 30, new WindowRadii(1, 1), tolerance,
                    WINDOW);
            double sigmaX = WINDOW.sigmaTexels(fixed.extentXUm());
            double sigmaY = WINDOW.sigmaTexels(fixed.extentYUm());
            double worstRatio = 0;
            double orderSum = 0;
            int count = 0;
            for (double u = -1.5; u <= 1.5; u += 0.0731) {
                for (double w = -2.0; w <= -0.05; w += 0.173) {
                    for (double lambdaUm : new double[] {0.38, 0.55, 0.78}) {
                        double v = 0.37 * u + 0.05;
                        double[] pFixed = fixed.amplitude(u, v, w, lambdaUm);
                        double[] pEarly = early.amplitude(u, v, w, lambdaUm);
                        double change = Math.hypot(pEarly[0] - pFixed[0], pEarly[1] - pFixed[1]);
                        double sx = u * fixed.extentXUm() / lambdaUm;
                        double sy = v * fixed.extentYUm() / lambdaUm;
                        double bound = tolerance * windowWeightSum(sx, sy, 1, sigmaX, sigmaY);
                        assertTrue(change <= bound, "tolerance " + tolerance + ": P moved by " + change
                                + " > bound " + bound + " at u " + u + ", w " + w + ", lambda " + lambdaUm);
                        if (bound > 0) {
                            worstRatio = Math.max(worstRatio, change / bound);
                        }
                        orderSum += early.stopOrder(w, lambdaUm);
                        count++;
                    }
                }
            }
            double meanOrder = orderSum / count;
            TestReport.printf(EarlyStopAndWindowTest.class, "early stop, tolerance %.0e: largest change / bound %.3g, mean stop order %.1f of 30%n",
                    tolerance, worstRatio, meanOrder);
            assertTrue(meanOrder < 25, "the loop must stop early on average, got " + meanOrder);
        }
    }

    @Test
    void stopOrderIsTheFirstOrderWhoseLagrangeBoundMeetsTheTolerance() {
        double x = 1.5 * Math.PI; // 001 sec. 3.3.3: N = 25 gives 8.815e-8
        assertEquals(25, TaylorBound.stopOrder(x, 8.815e-8 * 1.0001, 40));
        assertEquals(26, TaylorBound.stopOrder(x, 8.8e-8, 40));
        assertEquals(40, TaylorBound.stopOrder(x, 0.0, 40), "tolerance 0 = the fixed N");
        assertEquals(20, TaylorBound.stopOrder(x, 1e-30, 20), "never beyond N");
        assertEquals(0, TaylorBound.stopOrder(0.0, 1e-12, 30), "a flat patch or w = 0 needs the zeroth term only");
        for (int n = 0; n < 40; n++) {
            for (double tolerance : new double[] {1e-2, 1e-7, 1e-12}) {
                int stop = TaylorBound.stopOrder(x, tolerance, 40);
                assertTrue(TaylorBound.lagrangeRemainder(x, stop) <= tolerance * (1 + 1e-12));
                if (stop > 0) {
                    assertTrue(TaylorBound.lagrangeRemainder(x, stop - 1) > tolerance);
                }
            }
        }
        // only the terms a patch can need are uploaded
        BrdfSettings s = BrdfSettings.thesis(Variant.FLSS).with(b -> b.taylorTolerance(8.8e-8));
        assertEquals(26, s.highestOrderNeeded(0.15 * 380 / 400.0));
        assertEquals(30, BrdfSettings.thesis(Variant.FLSS).highestOrderNeeded(0.15));
    }

    /**
     * The automatic radius R = max(0, ceil(3 sigma - 1/2)) holds every texel within 3 sigma of the lookup. Measured
     * per axis, the share of the window's weight it captures (1 - the largest weight it leaves out, over all
     * lookups, relative to the window's largest total) is printed; asserted
     * >= 99.7 % per axis (99.4 % in 2-D), where the thesis' fixed 3 x 3 captures 97.5 % at sigma = 0.64 (a 65 um
     * patch) per axis. For a wide window the share approaches the continuous Gaussian's mass over the worst
     * placement, Phi(R / sigma) - Phi(-(R + 1) / sigma), which the test also checks (to the midpoint rule's 3e-4).
     */
    @Test
    void automaticRadiusCapturesTheWindow() {
        assertEquals(0, WindowRadii.automatic(0.09), "the 9.2 um Elaphe-like patch: the nearest texel alone");
        assertEquals(2, WindowRadii.automatic(65 / (2 * Math.PI * 16.25)), "a 65 um patch, 4 sigma_s = 65 um");
        assertEquals(WindowRadii.MAX_AUTOMATIC, WindowRadii.automatic(100));
        for (double sigma : new double[] {0.02, 0.09, 0.2, 0.4, 0.637, 1.0, 1.5, 2.0}) {
            int r = WindowRadii.automatic(sigma);
            double captured = WindowRadii.capturedWeight(sigma, r);
            TestReport.printf(EarlyStopAndWindowTest.class, "automatic window: sigma %.3f texels -> R = %d, captures %.5f per axis%n",
                    sigma, r, captured);
            assertTrue(captured >= 0.997, "sigma " + sigma + ", R " + r + ": " + captured);
            assertTrue(captured * captured >= 0.994);
        }
        double thesisCapture = WindowRadii.capturedWeight(0.637, 1);
        assertTrue(thesisCapture < 0.98, "fixed 3 x 3 at sigma 0.637: " + thesisCapture);
        // texel weights are the Gaussian at the cell centres, the continuous mass its integral over the cells: the
        // midpoint rule's error on the tails, ~ G'' / 24 per cell, separates them by 1.6e-4 here
        assertEquals(continuousWorstShare(2.0, 6), WindowRadii.capturedWeight(2.0, 6), 3e-4);
        WindowRadii radii = BrdfSettings.thesis(Variant.FLSS).with(b -> b.automaticWindowRadius(true)).windowRadii(65, 1.6);
        assertEquals(new WindowRadii(2, 0), radii, "the 65 x 1.6 um blazed grating");
    }

    /** The automatic radius changes the FLSS map by at most the weight it adds beyond the fixed window. */
    @Test
    void automaticRadiusIsUsedByTheCpuVariants() {
        BrdfSettings s = BrdfSettings.builder(Variant.FLSS).highestOrder(30).windowRadius(1).lambdaRangeNm(380, 780).lambdaStepNm(5).coherenceLengthUm(4 * 2.5).refractiveIndex(1.5).pqReplicas(0).build()
                .with(b -> b.automaticWindowRadius(true));
        WindowRadii radii = s.windowRadii(TERMS.cols() * TERMS.pixelSizeXUm(), TERMS.rows() * TERMS.pixelSizeYUm());
        TaylorGaussianSpectrum literal = new TaylorGaussianSpectrum(TERMS, 30, radii, 0.0, s.coherenceWindow());
        DiffractionBrdf brdf = DiffractionBrdf.create(s, PATCH, TERMS);
        for (double u = -0.8; u <= 0.8; u += 0.2) {
            assertEquals(literal.power(u, 0.1, -1.5, 0.5), brdf.spectrum().power(u, 0.1, -1.5, 0.5), 0.0);
        }
    }

    /** 003 Algorithm 3 written out: window around round(s), Gaussian weights, sum_{n<=30} (a^n / n!) DFT_n. */
    private static double literalFixedSum(double sx, double sy, double a, double sigmaX, double sigmaY) {
        double[] c = new double[31];
        c[0] = 1;
        for (int n = 1; n <= 30; n++) {
            c[n] = c[n - 1] * a / n;
        }
        int ax = (int) Math.floor(sx + 0.5);
        int ay = (int) Math.floor(sy + 0.5);
        double re = 0;
        double im = 0;
        for (int j = ay - 1; j <= ay + 1; j++) {
            int row = j + TERMS.centreRow();
            if (row < 0 || row >= TERMS.rows()) {
                continue;
            }
            double wy = CoherenceWindow.weight(j - sy, sigmaY);
            for (int i = ax - 1; i <= ax + 1; i++) {
                int col = i + TERMS.centreCol();
                if (col < 0 || col >= TERMS.cols()) {
                    continue;
                }
                double weight = wy * CoherenceWindow.weight(i - sx, sigmaX);
                int index = 2 * (row * TERMS.cols() + col);
                double sumRe = 0;
                double sumIm = 0;
                for (int n = 0; n <= 30; n++) {
                    sumRe += c[n] * TERMS.termUnsafe(n)[index];
                    sumIm += c[n] * TERMS.termUnsafe(n)[index + 1];
                }
                re += weight * sumRe;
                im += weight * sumIm;
            }
        }
        return re * re + im * im;
    }

    private static double windowWeightSum(double sx, double sy, int radius, double sigmaX, double sigmaY) {
        double sum = 0;
        int ax = (int) Math.floor(sx + 0.5);
        int ay = (int) Math.floor(sy + 0.5);
        for (int j = ay - radius; j <= ay + radius; j++) {
            for (int i = ax - radius; i <= ax + radius; i++) {
                sum += CoherenceWindow.weight(j - sy, sigmaY) * CoherenceWindow.weight(i - sx, sigmaX);
            }
        }
        return sum;
    }

    /** Share of a continuous Gaussian's mass over [-R - 1, R] texels, by Simpson's rule on 20000 panels. */
    private static double continuousWorstShare(double sigma, int radius) {
        double inside = simpson(-radius - 1.0, radius, sigma);
        double total = simpson(-radius - 1.0 - 20 * sigma, radius + 20 * sigma, sigma);
        return inside / total;
    }

    private static double simpson(double from, double to, double sigma) {
        int panels = 20000;
        double h = (to - from) / panels;
        double sum = CoherenceWindow.weight(from, sigma) + CoherenceWindow.weight(to, sigma);
        for (int k = 1; k < panels; k++) {
            sum += (k % 2 == 1 ? 4 : 2) * CoherenceWindow.weight(from + k * h, sigma);
        }
        return sum * h / 3;
    }
}
