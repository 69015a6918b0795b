package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.Shapes;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.LightProfile;
import diffract.optics.illumination.LightSource;
import diffract.optics.LobeQuadrature;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.optics.windows.WindowPlacement;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import javax.vecmath.Vector3f;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes shader on surfaces: point-sampled pixels show the CPU's BRDF (LobeSpectrum) in the tangent frame, pixel
 * footprints and the sun's size spread the orders over more fragments and stay finite; a patch that needs texel pairs
 * (the window fixed at the DFT's origin) is refused in one line. GpuCpuAgreementTest holds the lobes' BRDF maps to the
 * CPU.
 */
@Tag("gl")
class GpuLobesTest {
    /**
     * A square seen head-on (GpuFinitenessTest's scene) with point-sampled pixels: each fragment's display sRGB is
     * the CPU's lobes XYZ of its (omega_i, omega_r); with pixel footprints the specular highlight spreads over more
     * fragments, and stays finite.
     */
    @Test
    void surfacePixelsShowTheCpuBrdfAndTheirFootprints() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        BrdfSettings point = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.POINT));
        DiffractionTextures textures = DiffractionTextures.of(terms, point);
        float exposure = 20;
        Vector3f towardsLight = new Vector3f(0, 0.3f, 1);
        towardsLight.normalize();
        int size = 33;
        Material material = DiffractionMaterials.surface(textures, point, exposure, null, 0);
        float[] rgba = GpuFinitenessTest.render(material, towardsLight, Shapes.rectangle("square", -1, -1, 1, 1, 0),
                size);
        Direction wi = new Direction(towardsLight.y, -towardsLight.x, towardsLight.z); // T = world y, B = world -x
        DiffractionBrdf cpu = DiffractionBrdf.create(point, patch, terms);
        int lit = GpuFinitenessTest.assertCpuColours(rgba, size, 2, cpu, wi, exposure);
        assertTrue(lit >= 2, "only " + lit + " of the checked pixels are lit");
        BrdfSettings sun = point.with(b -> b.pixelFilter(PixelFilter.BOX).lightSizeDeg(LightSource.SUN_DEG));
        Material filtered = DiffractionMaterials.surface(DiffractionTextures.of(terms, sun), sun, exposure, null, 0);
        float[] footprints = GpuFinitenessTest.render(filtered, towardsLight, Shapes.rectangle("square", -1, -1, 1, 1, 0),
                size);
        int litPoint = 0;
        int litFiltered = 0;
        for (int p = 0; p < size * size; p++) {
            for (int k = 0; k < 3; k++) {
                assertTrue(Float.isFinite(footprints[4 * p + k]) && footprints[4 * p + k] >= 0);
            }
            litPoint += rgba[4 * p + 1] > 0.02 ? 1 : 0;
            litFiltered += footprints[4 * p + 1] > 0.02 ? 1 : 0;
        }
        assertTrue(litFiltered > litPoint, "footprints spread the orders: " + litFiltered + " vs " + litPoint);
    }

    /**
     * Where a scan is wider than about two thirds of the coherence length the shader sums the texels under each pixel
     * from the texel sums (LobeSumTable) as the CPU does: the 52 um scan's maps equal the CPU's at 32 x 32 (under a
     * point light and a Gaussian light 2 degrees wide, whose covariance widens the box) and at 8 x 8, where the march
     * over lobes runs past llvmpipe's loop budget, with no pixel left short.
     */
    @Test
    void texelSumsOfAScanWiderThanTheWindowEqualTheCpu() {
        GlTestSupport.assumeOffscreenGl();
        HeightField scan = scan52();
        TaylorTerms terms = TaylorTermComputer.compute(scan, 20, Reporter.SILENT);
        Direction wi = Direction.fromSphericalDeg(30, 90);
        BrdfSettings point = BrdfSettings.thesis(Variant.LOBES).with(b -> b.highestOrder(20)
                .pixelFilter(PixelFilter.BOX));
        BrdfSettings gaussian = point.with(b -> b.lightSizeDeg(2).lightProfile(LightProfile.GAUSSIAN));
        for (BrdfSettings settings : java.util.List.of(point, gaussian)) {
            DiffractionBrdf brdf = DiffractionBrdf.create(settings, scan, terms);
            try (GpuBrdfMap map = new GpuBrdfMap(terms, settings)) {
                for (int size : new int[] {32, 8}) {
                    float[] cpu = BrdfMap.xyz(brdf, wi, size, Reporter.SILENT);
                    float[] gpu = map.xyz(wi, size);
                    String where = "52 um scan, texel sums, " + settings.illumination().light() + ", " + size + " x "
                            + size;
                    assertEquals(0, map.truncatedPixels(), where);
                    if (size == 32) {
                        BrdfMapDifference d = RenderTestSupport.difference(cpu, gpu, size, wi);
                        where += ": " + d.summary();
                        assertTrue(d.lit().mean() <= GpuCpuAgreementTest.MAX_LIT_MEAN
                                && d.lit().p99() <= GpuCpuAgreementTest.MAX_LIT_P99, where);
                    } else {
                        for (int p = 0; p < size * size; p++) {
                            assertEquals(cpu[3 * p + 1], gpu[3 * p + 1], 1e-3 * cpu[3 * p + 1] + 1e-9,
                                    where + ": pixel " + p);
                        }
                    }
                    TestReport.line(GpuLobesTest.class, where);
                }
            }
        }
    }

    /**
     * A map whose pixels reach more lobes than the GL lets one fragment sum says which pixels its loops left short:
     * every pixel it does not flag equals the CPU's, every flagged one is darker than the CPU's or as bright (lobes
     * left out only take light away). The 52 um scan on a 32 x 32 map (a pixel's box 6 texels wide, its segment 60
     * long) equals the CPU everywhere (lit mean CIEDE2000 0.05, p99 0.5, as GpuCpuAgreementTest); on an 8 x 8 map,
     * four times as wide a pixel and without the cutoff (every lobe within reach summed), llvmpipe, which ends a SIMD
     * group's loops after 65535 iterations, flags some pixels.
     */
    @Test
    void pixelsWhoseLoopsWereEndedEarlyAreFlaggedAndTheOthersEqualTheCpu() {
        GlTestSupport.assumeOffscreenGl();
        HeightField scan = scan52();
        TaylorTerms terms = TaylorTermComputer.compute(scan, 20, Reporter.SILENT);
        // the march over lobes, which this scan's texel sums (texelSumsOfAScanWiderThanTheWindowEqualTheCpu) avoid; on
        // the 8 x 8 map over every lobe, without the cutoff that skips most of this scan's halo
        LobeQuadrature q = LobeQuadrature.DEFAULT.withSumNodesPerBox(0);
        LobeQuadrature everyLobe = new LobeQuadrature(q.pairThreshold(), q.nodesPerSigma(), q.maxStepNm(),
                q.reachSigmas(), q.weightStepNm(), q.lightNodes(), 0, q.weightTolerance(), 0);
        Direction wi = Direction.fromSphericalDeg(30, 90);
        for (int size : new int[] {32, 8}) {
            BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES).with(b -> b.highestOrder(20)
                    .pixelFilter(PixelFilter.BOX).lobes(size == 8 ? everyLobe : q));
            DiffractionBrdf brdf = DiffractionBrdf.create(settings, scan, terms);
            try (GpuBrdfMap map = new GpuBrdfMap(terms, settings)) {
                boolean llvmpipe = map.info().renderer().contains("llvmpipe");
                float[] cpu = BrdfMap.xyz(brdf, wi, size, Reporter.SILENT);
                float[] gpu = map.xyz(wi, size);
                float[] unflagged = gpu.clone();
                int flagged = 0;
                int darker = 0;
                for (int p = 0; p < size * size; p++) {
                    if (map.truncatedAt(p)) {
                        flagged++;
                        // float32 against double: within 1e-4 of the CPU's value, or below it
                        darker += gpu[3 * p + 1] <= cpu[3 * p + 1] * (1 + 1e-4) + 1e-9 ? 1 : 0;
                        System.arraycopy(cpu, 3 * p, unflagged, 3 * p, 3); // left out of the comparison
                    }
                }
                assertEquals(flagged, map.truncatedPixels());
                String where = "52 um scan, " + size + " x " + size + ", " + flagged + " pixels flagged, " + darker
                        + " no brighter than the CPU";
                assertEquals(flagged, darker, where);
                if (size == 32) {
                    BrdfMapDifference d = RenderTestSupport.difference(cpu, unflagged, size, wi);
                    where += ": " + d.summary();
                    assertTrue(d.lit().mean() <= GpuCpuAgreementTest.MAX_LIT_MEAN
                            && d.lit().p99() <= GpuCpuAgreementTest.MAX_LIT_P99, where);
                } else {
                    // too few pixels for colour statistics: every unflagged pixel's luminance to 1e-3 of the CPU's
                    for (int p = 0; p < size * size; p++) {
                        if (!map.truncatedAt(p)) {
                            assertEquals(cpu[3 * p + 1], gpu[3 * p + 1], 1e-3 * cpu[3 * p + 1] + 1e-9,
                                    where + ": pixel " + p);
                        }
                    }
                    if (llvmpipe) {
                        assertTrue(flagged > 0, where);
                    }
                }
                TestReport.line(GpuLobesTest.class, where);
            }
        }
    }

    /**
     * At 10 um coherence the 9.2 um patch has sigma_f = 0.58 texels: with the window fixed at the DFT's origin, pairs
     * up to 3 texels apart weigh more than 1e-4 and the shader, which sums whole texels, refuses in one line; averaged
     * over its position the window keeps no pairs and the same patch draws.
     */
    @Test
    void aPatchThatNeedsTexelPairsIsRefusedWithOneLineOnlyUnderTheFixedWindow() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        BrdfSettings averaged = BrdfSettings.thesis(Variant.LOBES).with(b -> b.coherenceLengthUm(10));
        BrdfSettings fixed = averaged.with(b -> b.windowPlacement(WindowPlacement.FIXED));
        InvalidSettingException e = assertThrows(InvalidSettingException.class,
                () -> new GpuBrdfMap(terms, fixed).close());
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
        assertTrue(e.getMessage().contains("lobes variant on the CPU"), e.getMessage());
        assertTrue(e.getMessage().contains("averaged"), e.getMessage());
        try (GpuBrdfMap map = new GpuBrdfMap(terms, averaged)) {
            float[] xyz = map.xyz(RenderTestSupport.light(patch, 30), 32);
            double brightest = 0;
            for (int p = 0; p < xyz.length / 3; p++) {
                brightest = Math.max(brightest, xyz[3 * p + 1]);
            }
            assertTrue(brightest > 1e-4, "the averaged window draws the patch: " + brightest);
        }
    }

    /** The 52 um scan of these tests: 512 samples, 50 ridges of the Elaphe-like relief. */
    private static HeightField scan52() {
        return SyntheticPatches.elapheScan(512, 50, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, 0.3, 1L).meanSubtracted();
    }
}
