package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.settings.LightProfile;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes method's baked table, what the viewer and the scenes draw by default (each pixel its footprint's average,
 * under a light of finite size), against the CPU lobes method it tabulates: BRDF maps of 64 x 64 of the blazed grating
 * and the Elaphe-like patch (coherence 10 um, so that their orders span a few map pixels), theta_i 0 and 45, under a
 * 2-degree light, CIEDE2000 over the lit pixels at the CPU map's auto exposure. The bounds sit near what is measured
 * (target/test-reports/BakedLobesTableTest.txt: lit mean 0.67-1.18, p95 1.7-3.1 with 257 x 257 x 13 samples; 0.23-0.58
 * and 0.6-1.7 with 513), so that a regression by a factor of 2 fails; a table baked for another light must fail them.
 */
@Tag("gl")
class BakedLobesTableTest {
    static final int SIZE = 64;
    static final int UV_SAMPLES = 257;
    static final int W_SAMPLES = 13;
    static final double LIGHT_DEG = 2;
    static final double MAX_LIT_MEAN = 1.5;
    static final double MAX_LIT_P95 = 4.0;

    static BrdfSettings lobes(double lightDeg) {
        return RenderTestSupport.settings(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                .lightSizeDeg(lightDeg).lightProfile(LightProfile.GAUSSIAN));
    }

    @Test
    void theTableIsTheCpuLobesMethodWithinWhatItsSamplesLose() {
        GlTestSupport.assumeOffscreenGl();
        for (HeightField patch : new HeightField[] {RenderTestSupport.BLAZED, RenderTestSupport.ELAPHE_LIKE}) {
            for (double thetaI : new double[] {0, 45}) {
                BrdfMapDifference d = difference(patch, thetaI, LIGHT_DEG);
                String where = RenderTestSupport.name(patch) + " theta_i " + thetaI + ": " + d.summary();
                TestReport.line(BakedLobesTableTest.class, "baked lobes table vs CPU lobes, " + where);
                assertTrue(d.litPixels() >= 20, where);
                assertTrue(d.lit().mean() <= MAX_LIT_MEAN, where);
                assertTrue(d.lit().p95() <= MAX_LIT_P95, where);
            }
        }
    }

    /** The measure catches a table of the wrong light: baked for a 6-degree light, drawn for the 2-degree one. */
    @Test
    void aTableBakedForAnotherLightFailsTheBounds() {
        GlTestSupport.assumeOffscreenGl();
        BrdfMapDifference d = difference(RenderTestSupport.ELAPHE_LIKE, 45, 6);
        TestReport.line(BakedLobesTableTest.class, "negative control, elaphe-like theta_i 45, table of a 6-degree light: "
                + d.summary());
        assertTrue(d.lit().mean() > MAX_LIT_MEAN || d.lit().p95() > MAX_LIT_P95, d.summary());
    }

    /** The CPU lobes method under the 2-degree light against the table baked under {@code tableLightDeg}. */
    private static BrdfMapDifference difference(HeightField patch, double thetaI, double tableLightDeg) {
        TaylorTerms terms = RenderTestSupport.terms(patch);
        Direction wi = RenderTestSupport.light(patch, thetaI);
        float[] cpu = BrdfMap.xyz(DiffractionBrdf.create(lobes(LIGHT_DEG), patch, terms), wi, SIZE, Reporter.SILENT);
        BrdfSettings baked = lobes(tableLightDeg).with(b -> b.variant(Variant.BAKED)
                .bakedSamples(UV_SAMPLES, W_SAMPLES));
        return RenderTestSupport.difference(cpu, RenderTestSupport.gpuXyz(terms, baked, wi, SIZE), SIZE, wi);
    }
}
