package diffract.optics.spectra;

import diffract.optics.NaiveDft;
import diffract.optics.patches.HeightField;
import diffract.optics.windows.CoherenceWindow;
import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** The reference evaluates the windowed DTFT of exp(i k w h) to double precision. */
class ExactSpectrumTest {

    @Test
    void equalsTheDirectWindowedSumOfANaiveDftOfTheExponential() {
        // a tall patch (x = k |w| max|h| up to ~ 20) where the thesis' series around 0 would cancel badly
        HeightField h = NaiveDft.randomPatch(9, 12, 1.2, 0.05, 5);
        CoherenceWindow window = new CoherenceWindow(0.4); // wide in texels, so many texels take part
        ExactSpectrum exact = new ExactSpectrum(h, window);
        double sigmaX = window.sigmaTexels(h.widthUm());
        double sigmaY = window.sigmaTexels(h.heightExtentUm());
        Random random = new Random(1);
        for (int trial = 0; trial < 20; trial++) {
            double u = random.nextDouble() * 2 - 1;
            double v = random.nextDouble() * 2 - 1;
            double w = -2 * random.nextDouble();
            double lambdaUm = 0.38 + 0.4 * random.nextDouble();
            double a = 2 * Math.PI / lambdaUm * w;
            double sx = u * h.widthUm() / lambdaUm;
            double sy = v * h.heightExtentUm() / lambdaUm;
            double[] f = NaiveDft.expIAH(h, a);
            double re = 0;
            double im = 0;
            for (int my = -h.rows() / 2; my < h.rows() - h.rows() / 2; my++) {
                for (int mx = -h.cols() / 2; mx < h.cols() - h.cols() / 2; mx++) {
                    double weight = CoherenceWindow.weight(mx - sx, sigmaX) * CoherenceWindow.weight(my - sy, sigmaY);
                    if (weight < ExactSpectrum.WINDOW_CUTOFF) {
                        continue;
                    }
                    double[] d = NaiveDft.inverseAt(f, h.rows(), h.cols(), mx, my);
                    re += weight * d[0];
                    im += weight * d[1];
                }
            }
            double[] p = exact.transformAt(u, v, w, lambdaUm);
            assertEquals(re, p[0], 1e-12, "Re at trial " + trial);
            assertEquals(im, p[1], 1e-12, "Im at trial " + trial);
        }
    }
}
