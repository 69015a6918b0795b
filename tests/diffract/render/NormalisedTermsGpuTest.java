package diffract.render;

import diffract.util.TestReport;
import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.settings.TermFormat;
import diffract.optics.Variant;
import diffract.precompute.ThesisExtrema;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The shader's 8-bit term lookup (TERMS_UNORM8): the GPU map of RG8 terms equals the CPU map of the same terms
 * de-normalised on the CPU ({@link NormalisedTerms#decoded}), so the shader reads exactly the bytes and extrema
 * eq. 1.1 defines; the remaining error against float terms is the quantisation's alone.
 */
class NormalisedTermsGpuTest {
    static final int SIZE = 64;

    @Test
    void gpuMapOfByteTermsEqualsTheCpuMapOfTheDeNormalisedTerms() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        BrdfSettings settings = RenderTestSupport.settings(Variant.FLSS).with(b -> b.highestOrder(12));
        DiffractionBrdf cpu = DiffractionBrdf.create(settings, patch, deNormalised(terms, settings.taylor().highestOrder()));
        try (GpuBrdfMap gpu = new GpuBrdfMap(terms, settings.with(b -> b.termFormat(TermFormat.RG8)))) {
            for (double thetaI : new double[] {0, 45}) {
                Direction wi = RenderTestSupport.light(patch, thetaI);
                BrdfMapDifference c = RenderTestSupport.difference(BrdfMap.xyz(cpu, wi, SIZE, Reporter.SILENT),
                        gpu.xyz(wi, SIZE), SIZE, wi);
                TestReport.line(NormalisedTermsGpuTest.class, "RG8 GPU vs CPU of de-normalised terms, theta_i " + thetaI + ": " + c.summary());
                // measured on llvmpipe: mean 0.000, p99 <= 0.007 (float32 against double sums); 10x that as margin,
                // far below the RG8 quantisation's own error against float terms (mean ~1, docs/measurements/bench.md)
                assertTrue(c.litPixels() >= 20, c.summary());
                assertTrue(c.disk().mean() <= 0.01, c.summary());
                assertTrue(c.disk().p99() <= 0.07, c.summary());
            }
        }
    }

    /** Terms 0..n as the shader sees them: every value through byte quantisation and back. */
    private static TaylorTerms deNormalised(TaylorTerms terms, int highestOrder) {
        float[][] data = new float[highestOrder + 1][];
        for (int n = 0; n <= highestOrder; n++) {
            ThesisExtrema.Term map = NormalisedTerms.mapping(terms, n);
            float[] t = terms.termData(n);
            data[n] = new float[t.length];
            for (int i = 0; i < t.length; i++) {
                data[n][i] = NormalisedTerms.decoded(t[i], i % 2 == 0 ? map.re() : map.im());
            }
        }
        return new TaylorTerms(terms.rows(), terms.cols(), terms.pixelSizeXUm(), terms.pixelSizeYUm(),
                terms.maxAbsHeightUm(), data);
    }
}
