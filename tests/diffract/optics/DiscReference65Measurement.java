package diffract.optics;

import diffract.colour.Xyz;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.IntStream;

/**
 * The lobes method under a disc against the reference's exact disc at the thesis' 65 um coherence on the
 * Elaphe-like patch, a measurement run on request ({@code mvn test -Dtest=DiscReference65Measurement
 * -Ddiffract.measure=disc-65}, with {@code -Ddiffract.measure.quick=true} the 2-degree disc alone): a whole
 * 64 x 64 map of the reference's disc would take about 33 hours on 2 cores, so the reference is evaluated on the lit
 * pixels of the map's column through the line of orders (theta_i = 30 degrees in the plane of the ridges' period),
 * every second one, for discs of 0.53, 2, 10 and 20 degrees; CIEDE2000 over those pixels at the exposure the lobes
 * method's whole map takes ({@link AutoExposure}). No assertion: the pixels are a sample, not the map.
 */
class DiscReference65Measurement {
    static final int SIZE = 64;
    static final int COLUMN = SIZE / 2;
    static final Direction WI = Direction.fromSphericalDeg(30, 90);

    @Test
    void lobesUnderADiscAgainstTheReferencesDiscAt65Um() {
        Assumptions.assumeTrue("disc-65".equals(System.getProperty("diffract.measure")), "measurement on request");
        double[] lights = Boolean.getBoolean("diffract.measure.quick") ? new double[] {2} : new double[] {0.53, 2, 10,
                20};
        HeightField patch = SyntheticPatches.elapheLike().meanSubtracted();
        TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
        for (double lightDeg : lights) {
            BrdfSettings reference = BrdfSettings.thesis(Variant.REFERENCE).with(b -> b.pixelFilter(PixelFilter.BOX)
                    .lightSizeDeg(lightDeg).lightProfile(LightProfile.DISC));
            DiffractionBrdf lobes = DiffractionBrdf.create(reference.with(b -> b.variant(Variant.LOBES)), patch, terms);
            float[] lobesMap = BrdfMap.xyz(lobes, WI, SIZE, Reporter.SILENT);
            float[] luminance = new float[SIZE * SIZE];
            for (int p = 0; p < luminance.length; p++) {
                luminance[p] = lobesMap[3 * p + 1];
            }
            double exposure = AutoExposure.of(luminance, SIZE, -WI.x(), -WI.y());
            List<Integer> lit = new ArrayList<>();
            for (int row = 0; row < SIZE; row++) {
                if (exposure * luminance[row * SIZE + COLUMN] > BrdfMapDifference.LIT_Y) {
                    lit.add(row);
                }
            }
            int[] sampled = IntStream.range(0, lit.size()).filter(k -> k % 2 == 0).map(lit::get).toArray();
            DiffractionBrdf exact = DiffractionBrdf.create(reference, patch, null);
            long start = System.nanoTime();
            // both maps hold the sampled pixels only; the rest stay 0, unlit in both
            float[] referenceMap = new float[3 * SIZE * SIZE];
            float[] lobesSampled = new float[3 * SIZE * SIZE];
            IntStream.of(sampled).parallel().forEach(row -> {
                int p = row * SIZE + COLUMN;
                Xyz c = exact.mapPixel(WI, COLUMN, row, SIZE);
                referenceMap[3 * p] = (float) c.x();
                referenceMap[3 * p + 1] = (float) c.y();
                referenceMap[3 * p + 2] = (float) c.z();
                System.arraycopy(lobesMap, 3 * p, lobesSampled, 3 * p, 3);
            });
            double seconds = (System.nanoTime() - start) * 1e-9;
            BrdfMapDifference d = BrdfMapDifference.of(referenceMap, lobesSampled, SIZE, exposure);
            TestReport.line(DiscReference65Measurement.class, String.format(java.util.Locale.ROOT,
                    "elaphe-like, 65 um, %d px, %.2f-degree disc, theta_i 30: lobes against the reference's disc over "
                            + "%d of the %d lit pixels of column %d: %s; reference %.0f s", SIZE, lightDeg,
                    sampled.length, lit.size(), COLUMN, d.summary(), seconds));
        }
    }
}
