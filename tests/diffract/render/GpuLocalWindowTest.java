package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.numerics.Covariance2;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.windows.LocalWindow;
import diffract.optics.windows.SkinFootprint;
import diffract.optics.TaylorEvaluation;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.optics.windows.WindowPlacement;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The local window on the GPU ({@code localWindowPower} in {@code diffraction_common.glsl}) equals the CPU's
 * ({@link DiffractionBrdf#createLocal}) for a few window centres and footprints on the 48 um scan (sigma_f = 0.47
 * texels at 65 um: the nearest texel pairs weigh 0.3), compared as {@link GpuCpuAgreementTest} compares maps (its
 * limits: CIEDE2000 mean 0.05 and p99 0.5 over the lit pixels). A map has no surface point, so the window is placed
 * by uniforms ({@link GpuBrdfMap#placeWindow}); the surface's own placement from the texture coordinates is
 * {@code LocalWindowSceneTest}'s. The negative control: the GPU's window at one centre against the CPU's at another
 * fails the limits.
 */
@Tag("gl")
class GpuLocalWindowTest {
    static final int SIZE = 40;
    static final HeightField SCAN = RenderTestSupport.WIDE;
    static final double L_UM = 48.0;
    static final Direction LIGHT = RenderTestSupport.light(SCAN, 30);

    static BrdfSettings settings(Variant variant) {
        return BrdfSettings.thesis(variant).with(b -> b.highestOrder(16).automaticWindowRadius(true)
                .windowPlacement(WindowPlacement.LOCAL));
    }

    /** The GPU map with the window placed at (x, y) um under a Gaussian footprint of covariance c, against the CPU's. */
    static BrdfMapDifference compare(GpuBrdfMap gpu, BrdfSettings settings, TaylorTerms terms, double x, double y,
                                     Covariance2 c, double cpuX, double cpuY) {
        float[] gpuXyz = gpu.placeWindow(x, y, c).xyz(LIGHT, SIZE);
        DiffractionBrdf cpu = DiffractionBrdf.createLocal(settings, terms,
                new LocalWindow(cpuX, cpuY, SkinFootprint.gaussian(c)));
        return RenderTestSupport.difference(BrdfMap.xyz(cpu, LIGHT, SIZE, Reporter.SILENT), gpuXyz, SIZE, LIGHT);
    }

    static boolean within(BrdfMapDifference d) {
        return d.lit().mean() <= GpuCpuAgreementTest.MAX_LIT_MEAN && d.lit().p99() <= GpuCpuAgreementTest.MAX_LIT_P99;
    }

    @Test
    void gpuEqualsCpuAtSeveralCentresAndFootprints() {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = RenderTestSupport.terms(SCAN);
        double[][] places = {
            {0, 0, 0}, // the thesis' fixed window
            {13.7, 29.1, 0}, // a point footprint elsewhere
            {-7.9, 101.3, 0.15 * L_UM}, // a small footprint: the pairs damped
            {5.0, 5.0, 0.6 * L_UM}, // a footprint near the cut-off
            {31.0, 2.5, 2.0 * L_UM}, // a footprint that covers the scan: the diagonal, the averaged window
        };
        for (Variant variant : new Variant[] {Variant.FLSS, Variant.NMM}) {
            BrdfSettings settings = settings(variant);
            try (GpuBrdfMap gpu = new GpuBrdfMap(TaylorEvaluation.plain(terms), settings, Reporter.SILENT)) {
                for (double[] p : places) {
                    Covariance2 c = Covariance2.isotropic(p[2] * p[2]);
                    BrdfMapDifference d = compare(gpu, settings, terms, p[0], p[1], c, p[0], p[1]);
                    String where = String.format(Locale.ROOT, "%s local window at (%.1f, %.1f) um, footprint %.1f um:"
                            + " %s", variant, p[0], p[1], p[2], d.summary());
                    TestReport.line(GpuLocalWindowTest.class, where);
                    assertTrue(d.litPixels() >= GpuCpuAgreementTest.MIN_LIT_PIXELS, where + ": too few lit pixels");
                    assertTrue(within(d), where);
                }
                // an anisotropic footprint, as a pixel at grazing view has
                Covariance2 c = SkinFootprint.pixelCovarianceUm2(40.0, 12.0, -3.0, 9.0);
                BrdfMapDifference d = compare(gpu, settings, terms, 17.0, -4.0, c, 17.0, -4.0);
                String where = variant + " local window under an anisotropic footprint: " + d.summary();
                TestReport.line(GpuLocalWindowTest.class, where);
                assertTrue(within(d), where);
            }
        }
    }

    @Test
    void theWindowPlacedElsewhereFailsTheLimits() {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = RenderTestSupport.terms(SCAN);
        BrdfSettings settings = settings(Variant.FLSS);
        try (GpuBrdfMap gpu = new GpuBrdfMap(TaylorEvaluation.plain(terms), settings, Reporter.SILENT)) {
            BrdfMapDifference d = compare(gpu, settings, terms, 13.7, 29.1, Covariance2.ZERO, 0, 0);
            String where = "FLSS local window at (13.7, 29.1) um against the CPU's at the origin: " + d.summary();
            TestReport.line(GpuLocalWindowTest.class, where);
            assertTrue(!within(d), where);
        }
    }
}
