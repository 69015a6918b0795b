package diffract.render;

import diffract.app.BrdfMapDifference;
import diffract.bench.BenchPatch;
import diffract.colour.ColourPath;
import diffract.jrtr.FloatTextureArray;
import diffract.jrtr.Material;
import diffract.jrtr.Shapes;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.Direction;
import diffract.optics.HeightField;
import diffract.optics.LightSource;
import diffract.optics.OpticsOptions;
import diffract.optics.PixelFilter;
import diffract.optics.TaylorEvaluation;
import diffract.optics.TaylorTerms;
import diffract.optics.Variant;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.UserInputException;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import javax.vecmath.Vector3f;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes shader equals its CPU mirror (LobeSpectrum): 64 x 64 BRDF maps at the thesis' 65 um coherence, pixel
 * boxes, a point light, a 2-degree light in the plane of the patch's period and one tilted 30 degrees off it (the
 * Gauss-Hermite shifts), theta_i 30 and 60 degrees; over the pixels lit in either map (exposure of the CPU map's
 * brightest diffracted pixel), mean CIEDE2000 at most 0.05 and 99th percentile at most 0.5 (float32 against double:
 * measured 0.000 / 0.00x). The phase-centred path of a tall patch likewise; a surface of point-sampled pixels shows
 * the CPU's BRDF in the tangent frame; a patch that needs texel pairs is refused.
 */
@Tag("gl")
class GpuLobesTest {
    static final int SIZE = 64;
    static final double MAX_MEAN = 0.05;
    static final double MAX_P99 = 0.5;

    @Test
    void mapsEqualTheCpuOnLitPixels() {
        RenderTestSupport.assumeDisplay();
        BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES);
        for (HeightField patch : new HeightField[] {RenderTestSupport.BLAZED, RenderTestSupport.ELAPHE_LIKE}) {
            TaylorTerms terms = RenderTestSupport.terms(patch);
            double phi = patch == RenderTestSupport.ELAPHE_LIKE ? 90 : 0;
            for (double[] light : new double[][] {{0, 0}, {2, 0}, {2, 30}}) {
                OpticsOptions options = OpticsOptions.DEFAULT.withLight(new LightSource(light[0]));
                DiffractionBrdf cpu = DiffractionBrdf.create(settings, patch, terms, options);
                try (GpuBrdfMap gpu = new GpuBrdfMap(terms, settings, options, FloatTextureArray.Precision.FLOAT32)) {
                    for (double thetaI : new double[] {30, 60}) {
                        Direction wi = Direction.fromSphericalDeg(thetaI, phi + light[1]);
                        assertAgree(BrdfMap.xyz(cpu, wi, SIZE, Reporter.SILENT), gpu.xyz(wi, SIZE), wi,
                                RenderTestSupport.name(patch) + " light " + light[0] + " deg at phi + " + light[1]
                                        + ", theta_i " + thetaI);
                    }
                }
            }
        }
    }

    @Test
    void phaseCentredMapsOfATallPatchEqualTheCpu() {
        RenderTestSupport.assumeDisplay();
        HeightField tall = BenchPatch.named("tall").field();
        TaylorTerms terms = TaylorTermComputer.compute(tall, 30, Reporter.SILENT);
        BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES).withExpansion(TaylorEvaluation.Mode.CENTRED);
        TaylorEvaluation evaluation = TaylorEvaluation.choose(TaylorEvaluation.Mode.CENTRED, tall, terms, 30, 380,
                (p, c) -> TaylorTermComputer.computeCentred(p, c, Reporter.SILENT), Reporter.SILENT);
        assertTrue(evaluation.isPhaseCentred());
        OpticsOptions options = OpticsOptions.DEFAULT.withLight(new LightSource(2));
        DiffractionBrdf cpu = evaluation.brdf(settings, tall, options);
        Direction wi = Direction.fromSphericalDeg(30, 90);
        try (GpuBrdfMap gpu = GpuBrdfMap.of(evaluation, settings, options, FloatTextureArray.Precision.FLOAT32)) {
            assertAgree(BrdfMap.xyz(cpu, wi, SIZE, Reporter.SILENT), gpu.xyz(wi, SIZE), wi, "tall, centred, 2 deg");
        }
    }

    private static void assertAgree(float[] cpu, float[] gpu, Direction wi, String where) {
        BrdfMapDifference d = RenderTestSupport.difference(cpu, gpu, SIZE, wi);
        assertTrue(d.litPixels() >= 20, where + ": too few lit pixels: " + d.summary());
        assertTrue(d.lit().mean() <= MAX_MEAN, where + ": " + d.summary());
        assertTrue(d.lit().p99() <= MAX_P99, where + ": " + d.summary());
    }

    /**
     * A square seen head-on (GpuFinitenessTest's scene) with point-sampled pixels: each fragment's display sRGB is
     * the CPU's lobes XYZ of its (omega_i, omega_r); with pixel footprints the specular highlight spreads over more
     * fragments, and stays finite.
     */
    @Test
    void surfacePixelsShowTheCpuBrdfAndTheirFootprints() {
        RenderTestSupport.assumeDisplay();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES);
        DiffractionTextures textures = DiffractionTextures.of(terms, settings, FloatTextureArray.Precision.FLOAT32);
        OpticsOptions point = OpticsOptions.DEFAULT.withPixelFilter(PixelFilter.POINT);
        float exposure = 20;
        Vector3f towardsLight = new Vector3f(0, 0.3f, 1);
        towardsLight.normalize();
        int size = 33;
        Material material = DiffractionMaterials.surface(textures, settings, point, exposure, null, 0);
        float[] rgba = GpuFinitenessTest.render(material, towardsLight, Shapes.rectangle("square", -1, -1, 1, 1, 0),
                size);
        Direction wi = new Direction(towardsLight.y, -towardsLight.x, towardsLight.z); // T = world y, B = world -x
        DiffractionBrdf cpu = DiffractionBrdf.create(settings, patch, terms, OpticsOptions.POINT_SAMPLED);
        int lit = 0;
        for (int j = 0; j < size; j += 2) {
            for (int i = 0; i < size; i += 2) {
                double x = 2.0 * (i + 0.5) / size - 1;
                double y = 1 - 2.0 * (j + 0.5) / size;
                double len = Math.sqrt(x * x + y * y + 1);
                Direction wr = new Direction(-y / len, x / len, 1 / len);
                float[] expected = ColourPath.SRGB.displayRgb(cpu.xyz(wi, wr).scaled(exposure));
                int p = 4 * (j * size + i);
                for (int k = 0; k < 3; k++) {
                    assertEquals(expected[k], rgba[p + k], 2.0 / 255, "pixel (" + i + ", " + j + ") channel " + k);
                }
                lit += expected[1] > 0.05 ? 1 : 0;
            }
        }
        assertTrue(lit >= 2, "only " + lit + " of the checked pixels are lit");
        Material filtered = DiffractionMaterials.surface(textures, settings,
                OpticsOptions.DEFAULT.withLight(new LightSource(LightSource.SUN_DEG)), exposure, null, 0);
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

    @Test
    void aPatchThatNeedsTexelPairsIsRefusedWithOneLine() {
        RenderTestSupport.assumeDisplay();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        // 10 um coherence: sigma_f = 0.58 texels, pairs up to 3 texels apart weigh more than 1e-4
        BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES).withSigmaSpatialUm(2.5);
        UserInputException e = assertThrows(UserInputException.class,
                () -> new GpuBrdfMap(terms, settings, OpticsOptions.DEFAULT, FloatTextureArray.Precision.FLOAT32)
                        .close());
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
        assertTrue(e.getMessage().contains("--engine cpu"), e.getMessage());
    }
}
