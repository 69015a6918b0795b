package diffract.pipeline;

import diffract.colour.Xyz;
import diffract.jrtr.GlTestSupport;
import diffract.optics.maps.AutoExposure;
import diffract.optics.BrdfMap;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.BrdfSettings;
import diffract.optics.DiscLightAverage;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.LightProfile;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.settings.PixelFilter;
import diffract.optics.Variant;
import diffract.optics.io.HeightFieldReader;
import diffract.render.GpuBrdfMap;
import diffract.util.MeasureProperties;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;

/**
 * The lobes method and its baked table under a disc light against the reference's exact disc at the thesis' 65 um
 * coherence, a measurement run on request ({@code mvn test -Dtest=DiscReference65Measurement
 * -Ddiffract.measure=disc-65}; {@code -Ddiffract.measure.patches=a,b} picks patches of the catalogue, or
 * {@code elaphe-measured} for assets/patches/elaphe-100px.gwy, {@code -Ddiffract.measure.discs=2,10} the diameters
 * and {@code -Ddiffract.measure.maxPixels=N} at most N pixels per map). A whole 64 x 64 map of the reference's disc
 * takes hours to days on 2 cores, so the reference is evaluated on the lit pixels of the map's line through the
 * orders (theta_i = 30 degrees in the plane of the patch's period: the column through the specular for phi_i 90, the
 * row for phi_i 0), every second one or at most N evenly spaced; CIEDE2000 over those pixels at the exposure the
 * lobes method's whole map takes ({@link AutoExposure}; the lobes method and the baked table drawn for it, as
 * brdfmap draws a map again for its exposure), and the reference's disc rule against the rule before it
 * (its own estimate of its error). Every map comes from {@link DiffractionPipeline} with the settings the commands
 * take (the baked table's grid automatic). No assertion: the pixels are a sample, not the map.
 */
class DiscReference65Measurement {
    static final int SIZE = 64;
    static final double THETA_I_DEG = 30;
    static final String MEASURED = "elaphe-measured";

    @Test
    void lobesAndBakedUnderADiscAgainstTheReferencesDiscAt65Um() {
        Assumptions.assumeTrue("disc-65".equals(System.getProperty("diffract.measure")), "measurement on request");
        GlTestSupport.assumeOffscreenGl();
        double[] discs = MeasureProperties.doubles("diffract.measure.discs", "0.53,2,10,20");
        for (String name : System.getProperty("diffract.measure.patches", "elaphe-like").split(",")) {
            for (double discDeg : discs) {
                TestReport.line(DiscReference65Measurement.class, measure(name, discDeg));
            }
        }
    }

    private static String measure(String name, double discDeg) {
        NamedPatch patch;
        double phiIDeg;
        if (MEASURED.equals(name)) {
            HeightField field = HeightFieldReader.load(Path.of("assets", "patches", "elaphe-100px.gwy"), null, null,
                    null, null, Reporter.SILENT);
            patch = new NamedPatch(name, field.meanSubtracted(), null);
            phiIDeg = 90;
        } else {
            PatchCatalogue.Entry entry = PatchCatalogue.named(name);
            patch = NamedPatch.of(name, entry.build());
            phiIDeg = entry.phiIDeg();
        }
        Direction wi = Direction.fromSphericalDeg(THETA_I_DEG, phiIDeg);
        BrdfSettings reference = BrdfSettings.thesis(Variant.REFERENCE).with(b -> b.pixelFilter(PixelFilter.BOX)
                .lightSizeDeg(discDeg).lightProfile(LightProfile.DISC));
        BrdfSettings lobes = reference.with(b -> b.variant(Variant.LOBES));
        BrdfSettings baked = reference.with(b -> b.variant(Variant.BAKED));
        DiffractionPipeline pipeline = DiffractionPipeline.cached(patch, reference.spectral().lambdaMinNm());
        double lambdaMinNm = reference.spectral().lambdaMinNm();
        float[] firstMap = BrdfMap.xyz(pipeline.cpuBrdf(lobes, lambdaMinNm, Reporter.SILENT), wi, SIZE,
                Reporter.SILENT);
        // as brdfmap --exposure auto: a map shown brighter than the lobes' cutoff assumes is drawn again for its
        // exposure (LobeQuadrature.shownAt), the lobes method and the baked table alike
        double firstExposure = AutoExposure.ofXyz(firstMap, wi, SIZE);
        BrdfSettings lobesShown = lobes.shownAt(firstExposure);
        float[] lobesMap = lobesShown == lobes ? firstMap
                : BrdfMap.xyz(pipeline.cpuBrdf(lobesShown, lambdaMinNm, Reporter.SILENT), wi, SIZE, Reporter.SILENT);
        float[] bakedMap = bakedMap(pipeline, baked.shownAt(firstExposure), wi);
        double exposure = AutoExposure.ofXyz(lobesMap, wi, SIZE);
        boolean column = Math.abs(wi.y()) >= Math.abs(wi.x());
        List<Integer> lit = new ArrayList<>();
        for (int k = 0; k < SIZE; k++) {
            int p = pixel(column, k);
            if (exposure * lobesMap[3 * p + 1] > BrdfMapDifference.LIT_Y) {
                lit.add(p);
            }
        }
        int[] sampled = sample(lit, Integer.getInteger("diffract.measure.maxPixels", Integer.MAX_VALUE));
        DiscLightAverage exact = pipeline.cpuBrdf(reference, lambdaMinNm, Reporter.SILENT).discLight().orElseThrow();
        long start = System.nanoTime();
        // every map holds the sampled pixels only; the rest stay 0, unlit in all
        float[] referenceMap = new float[3 * SIZE * SIZE];
        float[] coarserRule = new float[3 * SIZE * SIZE];
        AtomicInteger stopped = new AtomicInteger();
        float[] lobesSampled = new float[3 * SIZE * SIZE];
        float[] bakedSampled = new float[3 * SIZE * SIZE];
        IntStream.of(sampled).parallel().forEach(p -> {
            DiscLightAverage.Rules r = exact.mapPixelRules(wi, p % SIZE, p / SIZE, SIZE);
            put(referenceMap, p, r.value());
            put(coarserRule, p, r.coarser());
            stopped.addAndGet(r.converged() ? 0 : 1);
            System.arraycopy(lobesMap, 3 * p, lobesSampled, 3 * p, 3);
            if (bakedMap != null) {
                System.arraycopy(bakedMap, 3 * p, bakedSampled, 3 * p, 3);
            }
        });
        double seconds = (System.nanoTime() - start) * 1e-9;
        BrdfMapDifference l = BrdfMapDifference.of(referenceMap, lobesSampled, SIZE, exposure);
        BrdfMapDifference b = bakedMap == null ? null
                : BrdfMapDifference.of(referenceMap, bakedSampled, SIZE, exposure);
        BrdfMapDifference rule = BrdfMapDifference.of(referenceMap, coarserRule, SIZE, exposure);
        String worst = worstPixel(sampled, referenceMap, lobesSampled, coarserRule, exposure);
        return String.format(Locale.ROOT, "%s, 65 um, %d px, %.2f-degree disc, theta_i %.0f, %d of the %d lit pixels "
                        + "of %s %d: lobes %s; baked %s; reference %.0f s, its disc rule against the one before it %s "
                        + "(%d pixels stopped by the finest rule); %s; the lobes' cutoff %.3g of white", name, SIZE,
                discDeg, THETA_I_DEG, sampled.length, lit.size(), column ? "column" : "row", SIZE / 2, stats(l),
                stats(b), seconds, stats(rule), stopped.get(), worst, lobesShown.lobes().cutoff());
    }

    /**
     * The baked table's map, or null where the pipeline makes no table: on the phase-centred path (the tall patch),
     * whose sums a table of the thesis' series cannot hold.
     */
    private static float[] bakedMap(DiffractionPipeline pipeline, BrdfSettings baked, Direction wi) {
        if (pipeline.evaluation(baked, baked.spectral().lambdaMinNm(), Reporter.SILENT).isPhaseCentred()) {
            return null;
        }
        try (GpuBrdfMap map = pipeline.gpuMap(baked, baked.spectral().lambdaMinNm(), Reporter.SILENT)) {
            return map.xyz(wi, SIZE);
        }
    }

    /**
     * The sampled pixel where the lobes method differs most from the reference: where it is, the exposed Y of both,
     * and the reference's coarser rule's.
     */
    private static String worstPixel(int[] sampled, float[] reference, float[] lobes, float[] coarser,
                                     double exposure) {
        double largest = -1;
        int at = -1;
        for (int p : sampled) {
            float[] a = new float[reference.length];
            float[] b = new float[reference.length];
            System.arraycopy(reference, 3 * p, a, 3 * p, 3);
            System.arraycopy(lobes, 3 * p, b, 3 * p, 3);
            BrdfMapDifference d = BrdfMapDifference.of(a, b, SIZE, exposure);
            if (d.lit() != null && d.lit().max() > largest) {
                largest = d.lit().max();
                at = p;
            }
        }
        return at < 0 ? "no lit pixel" : String.format(Locale.ROOT, "the lobes method's worst pixel (%d, %d): "
                + "CIEDE2000 %.2f, exposed Y reference %.4f (coarser rule %.4f), lobes %.4f", at % SIZE, at / SIZE,
                largest, exposure * reference[3 * at + 1], exposure * coarser[3 * at + 1], exposure * lobes[3 * at + 1]);
    }

    /** "mean M, p95 P, max X" over the lit sampled pixels; dashes where there is no map. */
    private static String stats(BrdfMapDifference d) {
        return d == null ? "mean -, p95 -, max -" : d.lit() == null ? "no lit pixel" : String.format(Locale.ROOT,
                "mean %.2f, p95 %.2f, max %.2f", d.lit().mean(), d.lit().p95(), d.lit().max());
    }

    /** Every second lit pixel, or {@code most} of them evenly spaced where that is fewer. */
    static int[] sample(List<Integer> lit, int most) {
        int count = Math.min((lit.size() + 1) / 2, most);
        return IntStream.range(0, count).map(k -> lit.get((int) ((k + 0.5) * lit.size() / count))).toArray();
    }

    private static void put(float[] map, int p, Xyz c) {
        map[3 * p] = (float) c.x();
        map[3 * p + 1] = (float) c.y();
        map[3 * p + 2] = (float) c.z();
    }

    /** The k-th pixel of the map's middle column or row. */
    private static int pixel(boolean column, int k) {
        return column ? k * SIZE + SIZE / 2 : (SIZE / 2) * SIZE + k;
    }
}
