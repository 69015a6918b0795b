package diffract.optics.spectra;

import diffract.optics.NaiveDft;
import diffract.optics.patches.HeightField;
import diffract.optics.windows.CoherenceWindow;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;

import java.util.Locale;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The phase-centred expansion against the exact spectrum, from 10 nm to 2 um high patches, where the
 * thesis' series around 0 (summed in double over the same kind of float32 terms) falls apart.
 */
class PhaseCentredSpectrumTest {
    /** Wide in texels (sigma_f ~ 2 texels on a 1.6 um patch), so many texels and their phases take part. */
    private static final CoherenceWindow WINDOW = new CoherenceWindow(0.12);
    /** A window radius that covers the whole 12 x 16 band, so the Taylor spectra sum what the exact one sums. */
    private static final int ALL_TEXELS = 16;

    @Test
    void planCoversEveryReachablePhaseWithinTheHalfWidth() {
        PhaseCentres c = PhaseCentres.forPatch(2.0, 380);
        // x = 2 k max|h| = 66.1 at 380 nm: round(66.1 / 4) + 1 = 18 centres, 15 orders each
        assertEquals(18, c.centreCount());
        assertEquals(14, c.highestOrder());
        assertEquals(270, c.layerCount());
        double kMax = 2 * Math.PI / 0.38;
        for (double a = 0; a >= -2 * kMax; a -= 0.01) {
            double offset = Math.abs(a - c.centrePerUm(c.nearestCentre(a))) * 2.0;
            assertTrue(offset <= c.halfWidth() + 1e-9, "a = " + a + ": |a - a_j| max|h| = " + offset);
        }
        assertEquals(1, PhaseCentres.forPatch(0, 380).centreCount(), "a flat patch needs the centre 0 only");
    }

    @Test
    void centreZeroIsTheThesisTermsBitForBit() {
        HeightField patch = NaiveDft.randomPatch(7, 10, 0.6, 0.1, 3);
        PhaseCentres c = PhaseCentres.forPatch(patch.maxAbsHeightUm(), 380);
        PhaseCentredTerms centred = TaylorTermComputer.computeCentred(patch, c, Reporter.SILENT);
        TaylorTerms plain = TaylorTermComputer.compute(patch, c.highestOrder(), Reporter.SILENT);
        for (int n = 0; n <= c.highestOrder(); n++) {
            assertArrayEquals(plain.termData(n), centred.aroundCentre(0).termData(n), "term " + n);
        }
    }

    @Test
    void centredTermsAreTheTransformsOfTheShiftedExponential() {
        HeightField patch = NaiveDft.randomPatch(6, 5, 1.5, 0.1, 8);
        PhaseCentres c = PhaseCentres.forPatch(patch.maxAbsHeightUm(), 380);
        PhaseCentredTerms centred = TaylorTermComputer.computeCentred(patch, c, Reporter.SILENT);
        int j = c.centreCount() - 1;
        double[] f = NaiveDft.expIAH(patch, c.centrePerUm(j));
        double[] powers = NaiveDft.powerIH(patch, 3);
        double[] product = new double[f.length]; // exp(i a_j h) (i h)^3
        for (int p = 0; p < f.length; p += 2) {
            product[p] = f[p] * powers[p] - f[p + 1] * powers[p + 1];
            product[p + 1] = f[p] * powers[p + 1] + f[p + 1] * powers[p];
        }
        TaylorTerms t = centred.aroundCentre(j);
        for (int r = 0; r < 6; r++) {
            for (int col = 0; col < 5; col++) {
                double[] d = NaiveDft.inverseAt(product, 6, 5, col - t.centreCol(), r - t.centreRow());
                // float32 storage of values up to max|h|^3 = 3.4: a few 1e-7
                assertEquals(d[0], t.re(3, r, col), 1e-6);
                assertEquals(d[1], t.im(3, r, col), 1e-6);
            }
        }
    }

    @Test
    void centredSeriesMeetsTheExactSpectrumAtEveryHeightWhereThePlainSeriesFails() {
        StringBuilder table = new StringBuilder("maxH um, x, worst |P|^2 error: plain N = 30, centred\n");
        double plainAtTwoMicrometres = 0;
        for (double maxH : new double[] {0.01, 0.25, 0.5, 1.0, 2.0}) {
            HeightField patch = NaiveDft.randomPatch(12, 16, 2 * maxH, 0.1, 21);
            ExactSpectrum exact = new ExactSpectrum(patch, WINDOW);
            PhaseCentres c = PhaseCentres.forPatch(patch.maxAbsHeightUm(), 380);
            PhaseCentredTerms centredTerms = TaylorTermComputer.computeCentred(patch, c, Reporter.SILENT);
            PatchSpectrum centred = new PhaseCentredSpectrum(centredTerms,
                    t -> new TaylorGaussianSpectrum(t, c.highestOrder(), ALL_TEXELS, WINDOW));
            TaylorTerms plainTerms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
            PatchSpectrum plain = new TaylorGaussianSpectrum(plainTerms, 30, ALL_TEXELS, WINDOW);
            Random random = new Random(4);
            double worstCentred = 0;
            double worstPlain = 0;
            for (int trial = 0; trial < 200; trial++) {
                double u = random.nextDouble() * 2 - 1;
                double v = random.nextDouble() * 2 - 1;
                double w = trial == 0 ? -2 : -2 * random.nextDouble(); // include the largest phase
                double lambdaUm = trial == 0 ? 0.38 : 0.38 + 0.4 * random.nextDouble();
                double reference = exact.power(u, v, w, lambdaUm);
                worstCentred = Math.max(worstCentred, Math.abs(centred.power(u, v, w, lambdaUm) - reference));
                worstPlain = Math.max(worstPlain, Math.abs(plain.power(u, v, w, lambdaUm) - reference));
            }
            double x = TaylorBound.maxPhase(380, patch.maxAbsHeightUm());
            table.append(String.format(Locale.ROOT, "%.2f, %.1f, %.3g, %.3g%n", patch.maxAbsHeightUm(), x,
                    worstPlain, worstCentred));
            // float32 terms (2^-24 relative) around a centre at most b = 2 away: 2^-24 e^2 = 4.4e-7 in P, plus the
            // truncation bound 1.9e-7; |P|^2 <= 1 doubles it. Measured: at most 1.3e-8 (see the printed table).
            assertTrue(worstCentred < 2e-6, "centred at maxH " + maxH + ": " + worstCentred);
            if (maxH == 2.0) {
                plainAtTwoMicrometres = worstPlain;
            }
        }
        TestReport.line(PhaseCentredSpectrumTest.class, table);
        assertTrue(plainAtTwoMicrometres > 1e-2, "the plain series should fail at 2 um:\n" + table);
    }
}
