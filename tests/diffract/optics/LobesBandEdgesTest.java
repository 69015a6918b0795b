package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.maps.AutoExposure;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.PixelFilter;
import diffract.optics.spectra.TaylorTerms;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The lobes method's wavelength rule on bands of every width: its weights sum to the band's D65 white however narrow
 * the band (narrower than the nodes' spacing included), so an order keeps its energy and its place. Held against the
 * filtered reference on a blazed grating's BRDF map (the orders' total light, its centroid, and CIEDE2000 over the lit
 * pixels) on bands of 1, 2, 5 and 400 nm.
 */
class LobesBandEdgesTest {
    static final int SIZE = 48;

    @ParameterizedTest(name = "{0}..{1} nm")
    @CsvSource({"550, 551", "550, 552", "548, 553", "380, 780"})
    void everyBandKeepsTheOrdersEnergyAndPlace(double lambdaMinNm, double lambdaMaxNm) {
        HeightField patch = SyntheticPatches.blazed(2.5, 0.2, 20, 4, 16).meanSubtracted();
        TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
        BrdfSettings settings = BrdfSettings.thesis(Variant.REFERENCE).with(b -> b.pixelFilter(PixelFilter.BOX)
                .lambdaRangeNm(lambdaMinNm, lambdaMaxNm).coherenceLengthUm(10));
        Direction wi = Direction.fromSphericalDeg(30, 0);
        float[] reference = BrdfMap.xyz(DiffractionBrdf.create(settings, patch, null), wi, SIZE, Reporter.SILENT);
        float[] lobes = BrdfMap.xyz(DiffractionBrdf.create(settings.with(b -> b.variant(Variant.LOBES)), patch, terms),
                wi, SIZE, Reporter.SILENT);
        double[] r = moments(reference);
        double[] l = moments(lobes);
        BrdfMapDifference d = BrdfMapDifference.of(reference, lobes, SIZE, AutoExposure.ofXyz(reference, wi, SIZE));
        String where = String.format(java.util.Locale.ROOT, "%.0f..%.0f nm: Y %.5g (reference %.5g), centroid x %.4f "
                + "(reference %.4f); %s", lambdaMinNm, lambdaMaxNm, l[0], r[0], l[1], r[1], d.summary());
        TestReport.line(LobesBandEdgesTest.class, where);
        assertEquals(r[0], l[0], 0.02 * r[0], "the orders' light: " + where);
        assertEquals(r[1], l[1], 0.1 * 2.0 / SIZE, "the orders' centroid (a tenth of a pixel): " + where);
        assertTrue(d.lit().mean() <= 1.0, where);
    }

    /** The GPU's rule is the CPU's: a 2 nm band's lobes map on the GPU equals the CPU's. */
    @org.junit.jupiter.api.Test
    @org.junit.jupiter.api.Tag("gl")
    void theGpuKeepsANarrowBandAsTheCpuDoes() {
        diffract.jrtr.GlTestSupport.assumeOffscreenGl();
        HeightField patch = SyntheticPatches.blazed(2.5, 0.2, 20, 4, 16).meanSubtracted();
        TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
        BrdfSettings settings = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                .lambdaRangeNm(550, 552).coherenceLengthUm(10));
        Direction wi = Direction.fromSphericalDeg(30, 0);
        float[] cpu = BrdfMap.xyz(DiffractionBrdf.create(settings, patch, terms), wi, SIZE, Reporter.SILENT);
        float[] gpu;
        try (diffract.render.GpuBrdfMap map = new diffract.render.GpuBrdfMap(terms, settings)) {
            gpu = map.xyz(wi, SIZE);
        }
        double[] c = moments(cpu);
        double[] g = moments(gpu);
        TestReport.line(LobesBandEdgesTest.class, String.format(java.util.Locale.ROOT, "550..552 nm on the GPU: Y %.5g "
                + "(CPU %.5g)", g[0], c[0]));
        assertEquals(c[0], g[0], 1e-3 * c[0]);
        assertEquals(c[1], g[1], 1e-4);
    }

    /** The map's total Y off the specular pixels' row and the Y-weighted mean x of the pixel centres. */
    private static double[] moments(float[] xyz) {
        double total = 0;
        double x = 0;
        for (int j = 0; j < SIZE; j++) {
            for (int i = 0; i < SIZE; i++) {
                double y = xyz[3 * (j * SIZE + i) + 1];
                total += y;
                x += y * (2.0 * (i + 0.5) / SIZE - 1);
            }
        }
        return new double[] {total, x / total};
    }
}
