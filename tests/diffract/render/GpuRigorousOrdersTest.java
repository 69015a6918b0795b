package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.optics.maps.AutoExposure;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.settings.OrderWeights;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.settings.PixelFilter;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.Variant;
import diffract.optics.rigorous.Resolution;
import diffract.pipeline.DiffractionPipeline;
import diffract.pipeline.NamedPatch;
import diffract.util.Reporter;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes shader with the rigorous orders (RIGOROUS_ORDERS, orderRatios): its BRDF map equals the CPU's lobes with
 * the same table, and differs from the scalar orders' map (the table is read). A cheap table: two wavelengths, 21
 * harmonics, a coarse staircase.
 */
@Tag("gl")
class GpuRigorousOrdersTest {
    @Test
    void theShaderTakesTheTableAsTheCpuDoes() {
        GlTestSupport.assumeOffscreenGl();
        BrdfSettings corrected = BrdfSettings.thesis(Variant.LOBES).with(b -> b.lambdaRangeNm(500, 520)
                .pixelFilter(PixelFilter.BOX).lightSizeDeg(0.53)
                .rigorous(RigorousSettings.DEFAULT.withResolution(new Resolution(10, 4, true))
                        .withOrders(OrderWeights.RIGOROUS)));
        BrdfSettings scalar = corrected.with(b -> b.rigorous(corrected.rigorous().withOrders(OrderWeights.SCALAR)));
        DiffractionPipeline pipeline = DiffractionPipeline.cached(NamedPatch.of("elaphe-ridge",
                PatchCatalogue.named("elaphe-ridge").build()), 500);
        Direction wi = Direction.fromSphericalDeg(30, 90);
        int size = 24;
        float[] cpu = BrdfMap.xyz(pipeline.cpuBrdf(corrected, 500, Reporter.SILENT), wi, size, Reporter.SILENT);
        float[] gpu;
        float[] gpuScalar;
        try (GpuBrdfMap map = pipeline.gpuMap(corrected, 500, Reporter.SILENT)) {
            gpu = map.xyz(wi, size);
            assertEquals(0, map.truncatedPixels());
        }
        try (GpuBrdfMap map = pipeline.gpuMap(scalar, 500, Reporter.SILENT)) {
            gpuScalar = map.xyz(wi, size);
        }
        float[] luminance = new float[size * size];
        for (int p = 0; p < luminance.length; p++) {
            luminance[p] = cpu[3 * p + 1];
        }
        double exposure = AutoExposure.of(luminance, size, -wi.x(), -wi.y());
        BrdfMapDifference same = BrdfMapDifference.of(gpu, cpu, size, exposure);
        BrdfMapDifference other = BrdfMapDifference.of(gpuScalar, cpu, size, exposure);
        assertTrue(same.litPixels() >= 5, "lit pixels: " + same.litPixels());
        assertTrue(same.lit().mean() < 0.05, "GPU against CPU: " + same.summary());
        assertTrue(other.lit().mean() > 0.5, "the scalar orders' map is another: " + other.summary());
    }
}
