package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.Direction;
import diffract.optics.HeightField;
import diffract.optics.LightProfile;
import diffract.optics.PixelFilter;
import diffract.optics.TaylorTerms;
import diffract.optics.Variant;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes shader under a disc light (lobes_footprint.glsl's LIGHT_DISC) equals its CPU mirror (DiscFootprint in
 * LobeSpectrum) on a BRDF map of the Elaphe-like patch at theta_i = 30 degrees, across the pixel's box (a small disc,
 * the Gaussian regime), the blend and the blurred rim (a wide one); and a map under the Gaussian profile of the same
 * diameter does not (the negative control).
 */
class GpuDiscLobesTest {
    static final int SIZE = 32;

    @ParameterizedTest
    @ValueSource(doubles = {2, 10, 20})
    void gpuEqualsCpuUnderADisc(double lightDeg) {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        BrdfSettings disc = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                .lightSizeDeg(lightDeg).lightProfile(LightProfile.DISC));
        Direction wi = RenderTestSupport.light(patch, 30);
        float[] cpu = BrdfMap.xyz(DiffractionBrdf.create(disc, patch, terms), wi, SIZE, Reporter.SILENT);
        float[] gpu;
        float[] gaussian;
        try (GpuBrdfMap map = new GpuBrdfMap(terms, disc)) {
            gpu = map.xyz(wi, SIZE);
        }
        try (GpuBrdfMap map = new GpuBrdfMap(terms, disc.with(b -> b.lightProfile(LightProfile.GAUSSIAN)))) {
            gaussian = map.xyz(wi, SIZE);
        }
        BrdfMapDifference d = RenderTestSupport.difference(cpu, gpu, SIZE, wi);
        BrdfMapDifference g = RenderTestSupport.difference(cpu, gaussian, SIZE, wi);
        String where = String.format(java.util.Locale.ROOT, "elaphe-like, %d px, %.0f-degree disc: GPU against CPU %s;"
                + " the Gaussian profile on the GPU against the CPU's disc %s", SIZE, lightDeg, d.summary(), g.summary());
        TestReport.line(GpuDiscLobesTest.class, where);
        assertTrue(d.litPixels() >= 10, where);
        assertTrue(d.lit().mean() <= GpuCpuAgreementTest.MAX_LIT_MEAN && d.lit().p99() <= GpuCpuAgreementTest.MAX_LIT_P99,
                where);
        if (lightDeg >= 10) {
            assertTrue(g.lit().mean() > 10 * GpuCpuAgreementTest.MAX_LIT_MEAN, where);
        }
    }
}
