package diffract.optics.lobes;

import diffract.optics.NaiveDft;
import diffract.optics.patches.HeightField;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.spectra.TexelCoefficients;
import diffract.optics.windows.CoherenceWindow;
import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobe decomposition of the windowed power spectrum (GaussianLobes): with every pair kept it is an identity,
 * |sum_m G(s - m) T_m|^2 = sum_c W_c exp(-|s - c|^2_sigma), here on exact coefficients of a rough patch and on the
 * float32 Taylor series, for windows narrow and wide in texels.
 */
class GaussianLobesTest {
    private static final HeightField ROUGH = NaiveDft.randomPatch(6, 8, 0.4, 0.25, 3);

    @Test
    void lobeSumEqualsTheSquaredWindowedSumWithEveryPairKept() {
        for (double sigmaSpatialUm : new double[] {0.4, 1.2, 4.0}) { // sigma_f = 0.8, 0.26, 0.08 texels along x
            CoherenceWindow window = new CoherenceWindow(sigmaSpatialUm);
            ExactSpectrum exact = new ExactSpectrum(ROUGH, window);
            double sigmaX = exact.sigmaTexelsX();
            double sigmaY = exact.sigmaTexelsY();
            // a threshold of 1e-40 keeps every pair that could matter at 1e-12
            GaussianLobes lobes = new GaussianLobes(exact, sigmaX, sigmaY, 1e-40);
            Random random = new Random(7);
            for (int trial = 0; trial < 25; trial++) {
                double sx = (random.nextDouble() - 0.5) * ROUGH.cols();
                double sy = (random.nextDouble() - 0.5) * ROUGH.rows();
                double a = -random.nextDouble() * 30;
                double direct = directPower(exact, sx, sy, a, sigmaX, sigmaY);
                double viaLobes = lobes.power(sx, sy, a);
                assertEquals(direct, viaLobes, 1e-12 * Math.max(1e-3, direct),
                        "sigma_s " + sigmaSpatialUm + " s = (" + sx + ", " + sy + ")");
            }
        }
    }

    /** |sum_m G(s - m) T_m|^2 over every texel of the band. */
    private static double directPower(TexelCoefficients t, double sx, double sy, double a, double sigmaX, double sigmaY) {
        double re = 0;
        double im = 0;
        double[] c = new double[2];
        for (int my = -ROUGH.rows() / 2; my < ROUGH.rows() - ROUGH.rows() / 2; my++) {
            for (int mx = -ROUGH.cols() / 2; mx < ROUGH.cols() - ROUGH.cols() / 2; mx++) {
                t.texel(mx, my).at(a, c);
                double g = CoherenceWindow.weight(mx - sx, sigmaX) * CoherenceWindow.weight(my - sy, sigmaY);
                re += g * c[0];
                im += g * c[1];
            }
        }
        return re * re + im * im;
    }

    @Test
    void pairRadiusFollowsTheStatedThreshold() {
        // K = floor(2 sigma sqrt(ln(1 / threshold))): the last |m - m'| whose weight exp(-d^2 / (4 sigma^2)) reaches it
        for (double sigma : new double[] {0.05, 0.1, 0.3, 0.64, 1.0, 3.0}) {
            for (double threshold : new double[] {1e-4, 1e-8, 1e-12}) {
                int k = GaussianLobes.pairRadius(sigma, threshold);
                assertTrue(Math.exp(-k * k / (4 * sigma * sigma)) >= threshold * (1 - 1e-12));
                assertTrue(Math.exp(-(k + 1) * (k + 1) / (4 * sigma * sigma)) < threshold);
            }
        }
        // the design note's "pairs beyond ~6 sigma contribute < 1e-8" does not hold: at 6 sigma the weight is 1.2e-4
        assertEquals(Math.exp(-9), Math.exp(-36.0 / 4), 0);
        assertTrue(Math.exp(-9) > 1e-4);
        // at 65 um coherence a 10 um patch has sigma = 0.098 texels: no pair reaches 1e-4 (nearest: 5e-12)
        double sigma = CoherenceWindow.thesis().sigmaTexels(10.0);
        assertEquals(0, GaussianLobes.pairRadius(sigma, 1e-4));
        assertTrue(Math.exp(-1 / (4 * sigma * sigma)) < 1e-11);
    }

    @Test
    void lobeDerivativeMatchesFiniteDifferences() {
        ExactSpectrum exact = new ExactSpectrum(ROUGH, new CoherenceWindow(1.2));
        GaussianLobes lobes = new GaussianLobes(exact, exact.sigmaTexelsX(), exact.sigmaTexelsY(), 1e-6);
        double[] wd = new double[2];
        for (int[] c : new int[][] {{0, 0}, {2, -4}, {3, 1}, {-5, 2}}) {
            GaussianLobes.Lobe lobe = lobes.lobe(c[0], c[1]);
            for (double a : new double[] {-0.5, -7.3, -19.0}) {
                lobe.weightWithDerivative(a, wd);
                double h = 1e-5;
                double numeric = (lobe.weight(a + h) - lobe.weight(a - h)) / (2 * h);
                assertEquals(lobe.weight(a), wd[0], 1e-15);
                assertEquals(numeric, wd[1], 1e-7 * Math.max(1, Math.abs(numeric)), "lobe " + c[0] + "," + c[1]);
            }
        }
    }
}
