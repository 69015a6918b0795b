package diffract.render;

import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.precompute.TaylorTermComputer;
import diffract.precompute.ThesisExtrema;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The thesis' [0, 1]-normalised 8-bit term storage (003 eq. 1.1): what the shader reads back. */
class NormalisedTermsTest {
    /** Terms 0..12 of a small Elaphe-like patch: DFTs of (i h)^n, ranges from ~1 down to ~1e-9. */
    private static final TaylorTerms TERMS = TaylorTermComputer.compute(
            SyntheticPatches.elapheLike(32, 2, 1.144, 0.3, 7L).meanSubtracted(), 12, Reporter.SILENT);

    /**
     * Every stored value, de-normalised as the shader does (min + byte / 255 range, float32), lies within half a
     * quantisation step, range / 510, of the float term; the slack of 4 ulp of the channel's largest magnitude
     * covers the float32 rounding of v = (x - min) / range before quantising and of min + v range after. The
     * largest error seen in terms 1..N must also be a sizeable part of the half step, or the bytes would not be
     * 8-bit at all (term 0, the DFT of 1, is 1 at the centre and 0 elsewhere: its extrema, stored exactly).
     */
    @Test
    void deNormalisedBytesAreWithinHalfAQuantisationStep() {
        for (int n = 0; n <= TERMS.highestOrder(); n++) {
            ThesisExtrema.Term map = NormalisedTerms.mapping(TERMS, n);
            float[] data = TERMS.termData(n);
            double worstRelative = 0;
            for (int i = 0; i < data.length; i++) {
                ThesisExtrema.Channel channel = i % 2 == 0 ? map.re() : map.im();
                double halfStep = channel.range() / 510;
                double slack = 4 * Math.ulp((float) Math.max(Math.abs(channel.min()),
                        Math.abs(channel.min() + channel.range())));
                double error = Math.abs(NormalisedTerms.decoded(data[i], channel) - data[i]);
                assertTrue(error <= halfStep + slack, "term " + n + " value " + i + ": " + data[i] + " read back with error "
                        + error + " > half step " + halfStep);
                worstRelative = Math.max(worstRelative, error / halfStep);
            }
            assertTrue(n == 0 ? worstRelative == 0 : worstRelative > 0.5, "term " + n + ": worst error only " + worstRelative + " half steps");
        }
    }

    /**
     * The layers are the eq. 1.1 values in [0, 1], 0 and 1 at each channel's extrema (terms 1..N; term 0's
     * imaginary part is 0 everywhere, a zero range the thesis' guard stores as 1, so it maps to 0).
     */
    @Test
    void layersSpanZeroToOnePerTermAndChannel() {
        List<float[]> layers = NormalisedTerms.layers(TERMS, TERMS.highestOrder());
        assertEquals(TERMS.termCount(), layers.size());
        for (int i = 1; i < layers.get(0).length; i += 2) {
            assertEquals(0.0f, layers.get(0)[i]);
        }
        for (int n = 1; n < layers.size(); n++) {
            for (int channel = 0; channel < 2; channel++) {
                double min = Double.POSITIVE_INFINITY;
                double max = Double.NEGATIVE_INFINITY;
                for (int i = channel; i < layers.get(n).length; i += 2) {
                    min = Math.min(min, layers.get(n)[i]);
                    max = Math.max(max, layers.get(n)[i]);
                }
                assertEquals(0.0, min, 1e-6, "term " + n + " channel " + channel);
                assertEquals(1.0, max, 1e-6, "term " + n + " channel " + channel);
            }
        }
    }

    /** The shader's table holds the extrema the sidecar records (TaylorTerms.extrema). */
    @Test
    void extremaTableHoldsMinAndRangeOfEachTerm() {
        assertEquals(TERMS.termCount(), NormalisedTerms.extremaTable(TERMS, TERMS.highestOrder()).size());
        TaylorTerms.Extrema e = TERMS.extrema(3);
        ThesisExtrema.Term map = NormalisedTerms.mapping(TERMS, 3);
        assertEquals(e.reMin(), map.re().min(), 0);
        assertEquals(e.reMax() - e.reMin(), map.re().range(), 1e-12 * Math.abs(e.reMax()));
        assertEquals(e.imMax() - e.imMin(), map.im().range(), 1e-12 * Math.abs(e.imMax()));
    }
}
