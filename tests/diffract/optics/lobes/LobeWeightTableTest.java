package diffract.optics.lobes;

import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.spectra.TaylorTexels;
import diffract.optics.spectra.TexelCoefficients;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes' weight table against what the estimates before the work say it takes: the same number of samples of
 * the phase and the same bytes (its blocks' bounds and orders included), for a low and a tall patch; and its lookups against the texel's coefficients summed
 * directly, within the stated tolerance of the texel's largest weight.
 */
class LobeWeightTableTest {
    @ParameterizedTest
    @ValueSource(doubles = {0.1, 0.6})
    void theEstimateIsTheTableAndItsLookupsMeetTheTolerance(double heightUm) {
        HeightField patch = SyntheticPatches.sinusoid(2.5, heightUm, 16, 4, 8).meanSubtracted();
        TaylorTerms terms = TaylorTermComputer.compute(patch, 40, Reporter.SILENT);
        double tolerance = 1e-4;
        LobeWeightTable table = LobeWeightTable.ofTerms(terms, 40, 380, tolerance);
        List<float[]> layers = table.layers();
        long bytes = 0;
        for (float[] layer : layers) {
            bytes += 4L * layer.length;
        }
        for (float[] layer : table.blockLayers()) {
            bytes += 4L * layer.length;
        }
        bytes += 4L * table.orderLayer().length;
        assertEquals(bytes, LobeWeightTable.bytes(terms.rows(), terms.cols(), terms.maxAbsHeightUm(), 380, tolerance));

        TexelCoefficients coefficients = new TaylorTexels(terms, 40);
        double[] t = new double[2];
        int row = terms.rows() / 2;
        for (int mx = -4; mx <= 4; mx++) {
            TexelCoefficients.Texel texel = coefficients.texel(mx, 0);
            double largest = 0;
            double worst = 0;
            for (double a = 0; a >= -table.maxPhasePerUm(); a -= 0.0137) {
                texel.at(a, t);
                double exact = t[0] * t[0] + t[1] * t[1];
                largest = Math.max(largest, exact);
                worst = Math.max(worst, Math.abs(table.weight(mx + terms.cols() / 2, row, a) - exact));
            }
            assertTrue(worst <= tolerance * largest + 1e-12, "texel " + mx + ": " + worst + " of " + largest);
        }
    }
}
