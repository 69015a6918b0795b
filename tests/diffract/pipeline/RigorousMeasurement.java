package diffract.pipeline;

import diffract.colour.ColourPath;
import diffract.colour.Xyz;
import diffract.optics.maps.AutoExposure;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.OrderWeights;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.settings.PixelFilter;
import diffract.optics.Variant;
import diffract.util.ImageFiles;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The fast path against Maxwell's equations on the snakes' ridges, a measurement run on request (docs/measurements/rigorous.sh,
 * {@code -Ddiffract.measure=rigorous}): 64 x 64 maps under the sun's disc (0.53 degrees, pixel boxes, 380-780 nm) of
 * the Elaphe-like and Xenopeltis-like ridges and of the blazed grating (where the scalar model holds), the light at 0
 * and 30 degrees in the plane of the period, at the default resolution. Each of the lobes method's maps (Rayleigh-Rice's
 * gain, Stam's, the rigorous orders) is measured against the rigorous method's map (CIEDE2000 over the lit pixels at
 * the rigorous map's auto exposure) and timed; the first map of a patch with the rigorous orders includes its table,
 * the first rigorous map of a direction its solves (the script empties the disk cache's folders of both first).
 * {@code -Ddiffract.measure.patches=elaphe-ridge} picks patches. Writes one line per map and a picture per case,
 * rigorous | lobes | lobes with the rigorous orders, into target/test-reports/rigorous/. No assertion.
 */
class RigorousMeasurement {
    static final int SIZE = 64;

    @Test
    void theLobesOrdersAgainstTheRigorousMethod() throws IOException {
        Assumptions.assumeTrue("rigorous".equals(System.getProperty("diffract.measure")), "measurement on request");
        Path pictures = Path.of("target", "test-reports", "rigorous");
        Files.createDirectories(pictures);
        for (String name : System.getProperty("diffract.measure.patches", "elaphe-ridge,xenopeltis-ridge,blazed")
                .split(",")) {
            DiffractionPipeline pipeline = DiffractionPipeline.cached(NamedPatch.of(name, PatchCatalogue.named(name)
                    .build()), 380);
            for (double thetaDeg : new double[] {0, 30}) {
                measure(name, pipeline, thetaDeg, pictures);
            }
        }
    }

    private static void measure(String name, DiffractionPipeline pipeline, double thetaDeg, Path pictures)
            throws IOException {
        BrdfSettings lobes = BrdfSettings.thesis(Variant.LOBES).with(b -> b.pixelFilter(PixelFilter.BOX)
                .lightSizeDeg(0.53).refractiveIndex(diffract.optics.illumination.GainFactor.KERATIN_REFRACTIVE_INDEX)
                .gain(GainModel.RAYLEIGH_RICE));
        Direction wi = Direction.fromSphericalDeg(thetaDeg, PatchCatalogue.named(name).phiIDeg());
        long start = System.nanoTime();
        float[] exact = map(pipeline, lobes.with(b -> b.variant(Variant.RIGOROUS)), wi);
        double rigorousSeconds = (System.nanoTime() - start) * 1e-9;
        float[] luminance = new float[SIZE * SIZE];
        for (int i = 0; i < luminance.length; i++) {
            luminance[i] = exact[3 * i + 1];
        }
        double exposure = AutoExposure.of(luminance, SIZE, -wi.x(), -wi.y());
        TestReport.printf(RigorousMeasurement.class, "%s, %.0f deg, rigorous: %.1f s, exposure %.4g%n", name, thetaDeg,
                rigorousSeconds, exposure);
        Map<String, BrdfSettings> methods = new LinkedHashMap<>();
        methods.put("lobes", lobes);
        methods.put("lobes, Stam's gain", lobes.with(b -> b.gain(GainModel.STAM)));
        methods.put("lobes, rigorous orders", lobes.with(b -> b.rigorous(lobes.rigorous()
                .withOrders(OrderWeights.RIGOROUS))));
        List<float[]> strip = new ArrayList<>(List.of(exact));
        Map<String, float[]> drawn = new LinkedHashMap<>();
        for (Map.Entry<String, BrdfSettings> method : methods.entrySet()) {
            start = System.nanoTime();
            float[] xyz = map(pipeline, method.getValue(), wi);
            double seconds = (System.nanoTime() - start) * 1e-9;
            BrdfMapDifference d = BrdfMapDifference.of(xyz, exact, SIZE, exposure);
            TestReport.printf(RigorousMeasurement.class, Locale.ROOT, "%s, %.0f deg, %s: lit mean %.2f, p95 %.2f over %d"
                    + " pixels, %.1f s%n", name, thetaDeg, method.getKey(), d.lit().mean(), d.lit().p95(),
                    d.litPixels(), seconds);
            if (!method.getKey().contains("Stam")) {
                strip.add(xyz);
            }
            drawn.put(method.getKey(), xyz);
        }
        // what the rigorous orders change in the lobes method's own map, where the scalar model holds and where not
        BrdfMapDifference change = BrdfMapDifference.of(drawn.get("lobes, rigorous orders"), drawn.get("lobes"), SIZE,
                exposure);
        TestReport.printf(RigorousMeasurement.class, Locale.ROOT, "%s, %.0f deg, the rigorous orders against the "
                + "scalar ones: lit mean %.2f, p95 %.2f over %d pixels%n", name, thetaDeg, change.lit().mean(),
                change.lit().p95(), change.litPixels());
        writeStrip(pictures.resolve(String.format(Locale.ROOT, "rigorous-%s-%.0f.png", name, thetaDeg)), strip,
                exposure);
    }

    /** The maps side by side, each pixel 2 x 2, 4 black pixels between them, at one exposure. */
    private static void writeStrip(Path file, List<float[]> maps, double exposure) throws IOException {
        int scale = 2;
        int gap = 4;
        int side = SIZE * scale;
        int width = maps.size() * side + (maps.size() - 1) * gap;
        float[] rgb = new float[width * side * 3];
        for (int k = 0; k < maps.size(); k++) {
            float[] xyz = maps.get(k);
            for (int y = 0; y < side; y++) {
                for (int x = 0; x < side; x++) {
                    int p = 3 * ((y / scale) * SIZE + x / scale);
                    float[] c = ColourPath.SRGB.displayRgb(new Xyz(xyz[p], xyz[p + 1], xyz[p + 2]).scaled(exposure));
                    System.arraycopy(c, 0, rgb, 3 * (y * width + k * (side + gap) + x), 3);
                }
            }
        }
        ImageFiles.writePng(file, rgb, width, side, 3);
    }

    private static float[] map(DiffractionPipeline pipeline, BrdfSettings settings, Direction wi) {
        return BrdfMap.xyz(pipeline.cpuBrdf(settings, settings.spectral().lambdaMinNm(), Reporter.SILENT), wi, SIZE,
                Reporter.SILENT);
    }
}
