package diffract.pipeline;

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
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes method with the rigorous orders draws the rigorous method's map of the ridges where the scalar model's
 * orders are off: the Elaphe-like and Xenopeltis-like ridges at normal and 30-degree incidence under the sun's disc,
 * each map measured against the rigorous one (CIEDE2000 over the lit pixels at the rigorous map's exposure).
 *
 * <p>Both sides solve Maxwell's equations at the same coarse resolution (17 harmonics, 4 slabs extrapolated from 2):
 * what is measured is how the lobes carry the rigorous efficiencies into a picture (the interpolation of the ratio
 * table, the lobes' shapes over a disc light), not the solver's convergence, which {@code FourierModalMethodTest}
 * and {@code IndependentSolverTest} measure. The band is 480-620 nm to keep the table small; the scalar model's error
 * is there at every wavelength.
 */
@Tag(diffract.jrtr.GlTestSupport.LONG_TAG)
class RigorousOrdersMapTest {
    private static final int SIZE = 32;

    @ParameterizedTest(name = "{0} at {1} degrees")
    @CsvSource({"elaphe-ridge, 0, 5", "elaphe-ridge, 30, 5", "xenopeltis-ridge, 0, 1", "xenopeltis-ridge, 30, 0.8"})
    void theCorrectedLobesDrawTheRigorousMap(String name, double thetaDeg, double scalarAtLeast) {
        BrdfSettings scalar = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                .lightSizeDeg(0.53).lambdaRangeNm(480, 620).rigorous(RigorousSettings.DEFAULT
                        .withResolution(new Resolution(8, 4, true))));
        BrdfSettings corrected = scalar.with(b -> b.rigorous(scalar.rigorous().withOrders(OrderWeights.RIGOROUS)));
        BrdfSettings rigorous = scalar.with(b -> b.variant(Variant.RIGOROUS));
        DiffractionPipeline pipeline = DiffractionPipeline.cached(NamedPatch.of(name, PatchCatalogue.named(name)
                .build()), scalar.spectral().lambdaMinNm());
        Direction wi = Direction.fromSphericalDeg(thetaDeg, 90); // in the plane of the ridges' period (along y)
        float[] exact = map(pipeline, rigorous, wi);
        float[] luminance = new float[SIZE * SIZE];
        for (int i = 0; i < luminance.length; i++) {
            luminance[i] = exact[3 * i + 1];
        }
        double exposure = AutoExposure.of(luminance, SIZE, -wi.x(), -wi.y());
        BrdfMapDifference scalarError = BrdfMapDifference.of(map(pipeline, scalar, wi), exact, SIZE, exposure);
        BrdfMapDifference correctedError = BrdfMapDifference.of(map(pipeline, corrected, wi), exact, SIZE, exposure);
        TestReport.printf(RigorousOrdersMapTest.class, "%s at %.0f deg: scalar orders %s; rigorous orders %s%n", name,
                thetaDeg, scalarError.summary(), correctedError.summary());
        assertTrue(correctedError.litPixels() >= 10, "lit pixels: " + correctedError.litPixels());
        assertTrue(scalarError.lit().mean() >= scalarAtLeast, "the scalar orders are off here: "
                + scalarError.summary());
        assertTrue(correctedError.lit().mean() <= 2, "the rigorous orders: " + correctedError.summary());
        assertTrue(correctedError.lit().mean() <= 0.4 * scalarError.lit().mean(), "the rigorous orders "
                + correctedError.summary() + " against the scalar ones " + scalarError.summary());
    }

    private static float[] map(DiffractionPipeline pipeline, BrdfSettings settings, Direction wi) {
        return BrdfMap.xyz(pipeline.cpuBrdf(settings, settings.spectral().lambdaMinNm(), Reporter.SILENT), wi, SIZE,
                Reporter.SILENT);
    }
}
