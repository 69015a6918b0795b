package diffract.precompute;

import diffract.optics.patches.HeightField;
import diffract.optics.NaiveDft;
import diffract.optics.spectra.TaylorTerms;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class TaylorTermComputerTest {

    /** Non-square, odd and even sizes: fftshift's centre differs (003 eq. 1.5). */
    @ParameterizedTest
    @CsvSource({"6, 8", "5, 7", "4, 9", "1, 6"})
    void termsEqualANaiveDftOfThePowers(int rows, int cols) {
        HeightField h = NaiveDft.randomPatch(rows, cols, 0.4, 0.1, 42 + rows * 31L + cols);
        for (int n = 0; n <= 6; n++) {
            double[] fast = TaylorTermComputer.termInDouble(h, n);
            double[] power = NaiveDft.powerIH(h, n);
            for (int r = 0; r < rows; r++) {
                for (int c = 0; c < cols; c++) {
                    int mx = c - cols / 2;
                    int my = r - rows / 2;
                    double[] naive = NaiveDft.inverseAt(power, rows, cols, mx, my);
                    int i = 2 * (r * cols + c);
                    assertEquals(naive[0], fast[i], 1e-12, "Re term " + n + " at (" + mx + "," + my + ")");
                    assertEquals(naive[1], fast[i + 1], 1e-12, "Im term " + n + " at (" + mx + "," + my + ")");
                }
            }
        }
    }

    @ParameterizedTest
    @CsvSource({"6, 8", "5, 7"})
    void zeroFrequencyIsAtTheCentreTexelOfEquation15(int rows, int cols) {
        HeightField h = NaiveDft.randomPatch(rows, cols, 0.3, 0.1, 7);
        TaylorTerms terms = TaylorTermComputer.compute(h, 2, Reporter.SILENT);
        // eq. 1.5: b = N/2 for even N, (N-1)/2 for odd N
        int cr = rows % 2 == 0 ? rows / 2 : (rows - 1) / 2;
        int cc = cols % 2 == 0 ? cols / 2 : (cols - 1) / 2;
        assertEquals(cr, terms.centreRow());
        assertEquals(cc, terms.centreCol());
        // DFT_0 of (i h)^0 = 1 everywhere is 1 at zero frequency and 0 elsewhere
        assertEquals(1.0, terms.re(0, cr, cc), 1e-7);
        assertEquals(0.0, terms.re(0, cr, (cc + 1) % cols), 1e-7);
        // DFT_1 = ifft2(i h) at zero frequency = i mean(h) = 0 (mean subtracted)
        assertEquals(0.0, terms.im(1, cr, cc), 1e-7);
        // DFT_2 = ifft2(-h^2) at zero frequency = -mean(h^2)
        double meanSquare = 0;
        for (double v : h.heightsUm()) {
            meanSquare += v * v;
        }
        meanSquare /= rows * cols;
        assertEquals(-meanSquare, terms.re(2, cr, cc), 1e-7);
    }

    @Test
    void storedFloatsAreTheDoubleTermsRoundedOnce() {
        HeightField h = NaiveDft.randomPatch(16, 12, 0.5, 0.07, 3);
        TaylorTerms terms = TaylorTermComputer.compute(h, 8, Reporter.SILENT);
        for (int n = 0; n <= 8; n++) {
            double[] exact = TaylorTermComputer.termInDouble(h, n);
            for (int r = 0; r < 16; r++) {
                for (int c = 0; c < 12; c++) {
                    int i = 2 * (r * 12 + c);
                    assertEquals((float) exact[i], terms.re(n, r, c));
                    assertEquals((float) exact[i + 1], terms.im(n, r, c));
                }
            }
        }
        assertTrue(terms.maxAbsHeightUm() > 0);
    }
}
