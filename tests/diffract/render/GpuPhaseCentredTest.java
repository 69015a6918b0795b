package diffract.render;

import diffract.util.TestReport;
import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.spectra.PhaseCentredTerms;
import diffract.optics.spectra.PhaseCentres;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The phase-centred shader path ({@code taylor_centred.glsl}) on blazed gratings 0.5 to 2 um high
 * (x = 2 k max|h| = 16.5 to 66 at 380 nm), where the thesis' float32 series around 0 is noise: its monochromatic
 * map at 380 nm equals the exact reference, and its colour map equals the CPU mirror and the reference.
 */
@Tag("gl")
class GpuPhaseCentredTest {
    static java.util.stream.Stream<Variant> thesisMethods() {
        return java.util.stream.Stream.of(Variant.FLSS, Variant.NMM, Variant.PQ);
    }

    private static final int SIZE = 48;

    /** Relative error of a monochromatic map: max |rho - rho_ref| / max rho_ref over the map. */
    static double relativeError(float[] actual, float[] reference) {
        double peak = 0;
        double worst = 0;
        for (int i = 0; i < actual.length; i++) {
            assertTrue(Float.isFinite(actual[i]) && actual[i] >= 0, "pixel " + i + ": " + actual[i]);
            peak = Math.max(peak, reference[i]);
            worst = Math.max(worst, Math.abs(actual[i] - reference[i]));
        }
        return worst / peak;
    }

    /**
     * The centred path at the angular extremes, for every variant on the 2 um grating: grazing light
     * (89.9 degrees), and a 33 x 33 map at normal incidence whose centre pixel is the exact specular direction
     * ((u, v) = 0: NMM's fallback, PQ's 0/0, sinc(0); w = -2, the largest phase, the last centre). Every pixel
     * finite and non-negative; the specular pixel equals the CPU mirror to 1e-3 relative (float32 lookup).
     */
    /** The baked table holds the thesis' series around 0: on the centred path it is refused, with the reason. */
    @org.junit.jupiter.api.Test
    void theBakedTableIsRefusedOnTheCentredPath() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = SyntheticPatches.blazed(2.5, 4.0, 20, 4, 8).meanSubtracted();
        BrdfSettings settings = RenderTestSupport.settings(Variant.BAKED);
        PhaseCentredTerms centred = TaylorTermComputer.computeCentred(patch,
                PhaseCentres.forPatch(patch.maxAbsHeightUm(), settings.spectral().lambdaMinNm()), Reporter.SILENT);
        var refused = org.junit.jupiter.api.Assertions.assertThrows(
                diffract.optics.settings.InvalidSettingException.class,
                () -> new GpuBrdfMap(centred, settings).close());
        assertTrue(refused.getMessage().contains("phase-centred expansion"), refused.getMessage());
    }

    @ParameterizedTest
    @org.junit.jupiter.params.provider.MethodSource("thesisMethods")
    void everyPixelIsFiniteAtGrazingLightAndAtTheSpecularDirection(Variant variant) {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = SyntheticPatches.blazed(2.5, 4.0, 20, 4, 8).meanSubtracted();
        BrdfSettings settings = RenderTestSupport.settings(variant);
        PhaseCentredTerms centred = TaylorTermComputer.computeCentred(patch,
                PhaseCentres.forPatch(patch.maxAbsHeightUm(), settings.spectral().lambdaMinNm()), Reporter.SILENT);
        DiffractionBrdf mirror = DiffractionBrdf.createPhaseCentred(settings, centred);
        try (GpuBrdfMap gpu = new GpuBrdfMap(centred, settings)) {
            for (double phi : new double[] {0, 90}) {
                Direction grazing = Direction.fromSphericalDeg(89.9, phi);
                relativeError(gpu.xyz(grazing, 32), new float[32 * 32 * 3]); // asserts finite, >= 0
                relativeError(gpu.monochromatic(grazing, 380, 32), new float[32 * 32]);
            }
            Direction normal = Direction.fromSphericalDeg(0, 0);
            float[] map = gpu.xyz(normal, 33);
            relativeError(map, new float[map.length]);
            relativeError(gpu.monochromatic(normal, 780, 33), new float[33 * 33]);
            double expected = mirror.xyz(normal, new Direction(0, 0, 1)).y();
            float actual = map[3 * (16 * 33 + 16) + 1];
            assertTrue(expected > 1e-3, variant + ": the CPU's specular pixel is dark: " + expected);
            assertTrue(Math.abs(actual - expected) <= 1e-3 * expected, variant + ": specular Y " + actual
                    + ", CPU " + expected);
        }
    }

    @ParameterizedTest
    @ValueSource(doubles = {1.0, 2.0, 4.0})
    void tallGratingsMatchTheReferenceOnlyWhenCentred(double gratingHeightUm) {
        GlTestSupport.assumeOffscreenGl();
        // period 2.5 um, 20 pixels of 0.125 um, 4 periods, 8 rows; max|h| = half the height after the mean
        HeightField patch = SyntheticPatches.blazed(2.5, gratingHeightUm, 20, 4, 8).meanSubtracted();
        BrdfSettings flss = RenderTestSupport.settings(Variant.FLSS);
        // the monochromatic comparison uses the thesis' 65 um coherence length: sigma_f = 0.098 texels, so the
        // 3 x 3 window holds all the window's weight (beyond 1.5 texels: e^-117) and FLSS equals the exact model
        // up to the expansion; the colour maps keep 10 um, whose wider orders light many pixels
        BrdfSettings mono = BrdfSettings.builder(Variant.FLSS).highestOrder(30).windowRadius(1).lambdaRangeNm(380, 780).lambdaStepNm(5).coherenceLengthUm(4 * 65 / 4.0).refractiveIndex(1.5).pqReplicas(0).build();
        PhaseCentres centres = PhaseCentres.forPatch(patch.maxAbsHeightUm(), flss.spectral().lambdaMinNm());
        PhaseCentredTerms centred = TaylorTermComputer.computeCentred(patch, centres, Reporter.SILENT);
        TaylorTerms plain = RenderTestSupport.terms(patch);
        DiffractionBrdf reference = DiffractionBrdf.create(flss.with(b -> b.variant(Variant.REFERENCE)), patch, null);
        DiffractionBrdf monoReference = DiffractionBrdf.create(mono.with(b -> b.variant(Variant.REFERENCE)), patch, null);
        DiffractionBrdf mirror = DiffractionBrdf.createPhaseCentred(flss, centred);
        Direction wi = Direction.fromSphericalDeg(30, 0);
        float[] refMono = BrdfMap.monochromatic(monoReference, wi, 380, SIZE, Reporter.SILENT);
        float[] refXyz = BrdfMap.xyz(reference, wi, SIZE, Reporter.SILENT);
        float[] mirrorXyz = BrdfMap.xyz(mirror, wi, SIZE, Reporter.SILENT);
        double centredMono;
        double plainMono;
        BrdfMapDifference toMirror;
        BrdfMapDifference toReference;
        try (GpuBrdfMap gpu = new GpuBrdfMap(centred, mono)) {
            centredMono = relativeError(gpu.monochromatic(wi, 380, SIZE), refMono);
        }
        try (GpuBrdfMap gpu = new GpuBrdfMap(centred, flss)) {
            float[] xyz = gpu.xyz(wi, SIZE);
            toMirror = RenderTestSupport.difference(mirrorXyz, xyz, SIZE, wi);
            toReference = RenderTestSupport.difference(refXyz, xyz, SIZE, wi);
        }
        try (GpuBrdfMap gpu = new GpuBrdfMap(plain, mono)) {
            float[] plainMap = gpu.monochromatic(wi, 380, SIZE);
            double peak = 0;
            double worst = 0;
            for (int i = 0; i < plainMap.length; i++) {
                peak = Math.max(peak, refMono[i]);
                worst = Math.max(worst, Math.abs(plainMap[i] - refMono[i])); // NaN and Inf fail below too
            }
            plainMono = Double.isFinite(worst) ? worst / peak : Double.POSITIVE_INFINITY;
        }
        String line = String.format(Locale.ROOT, "max|h| %.2f um (x = %.1f, %d centres x %d orders): 380 nm relative"
                + " error centred %.2g, plain N = 30 %.2g; colour vs CPU mirror %s; vs reference %s",
                patch.maxAbsHeightUm(), 2 * 2 * Math.PI / 0.38 * patch.maxAbsHeightUm(), centres.centreCount(),
                centres.ordersPerCentre(), centredMono, plainMono, toMirror.summary(), toReference.summary());
        TestReport.line(GpuPhaseCentredTest.class, "GPU phase-centred, " + line);
        // the GPU's float32 sum around a centre at most b = 2 away: ~2^-24 e^2 |P| per term sum, 1e-6 relative
        // to the peak of |P|^2, plus the lookup's float32 rounding. Measured: see the printed lines.
        assertTrue(centredMono < 1e-3, line);
        assertTrue(toMirror.disk().mean() <= 0.01 && toMirror.disk().p99() <= 0.1, line);
        // the colour map's remaining difference is FLSS's own (5 nm steps, 3 x 3 window), not the expansion's
        assertTrue(toReference.disk().mean() <= 1, line);
        assertTrue(plainMono > 0.1, "the plain float32 series should be noise here: " + line);
    }
}
