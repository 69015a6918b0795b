package diffract.bench;

import diffract.app.BrdfMapDifference;
import diffract.colour.DeltaEStatistics;
import diffract.optics.BrdfMap;

import java.util.List;

/**
 * The error of a variant's BRDF maps against the reference maps of the same lights, pooled over the lights:
 * every map is multiplied by its light's display exposure (the reference's {@link diffract.app.AutoExposure}), then
 * CIEDE2000 (D65 white) per pixel, over the lit pixels of all maps together (exposed Y above
 * {@link BrdfMapDifference#LIT_Y} in either map: what one sees; most of a BRDF map is black in both and would
 * dilute the mean) and over the whole unit disks.
 *
 * @param mean      mean CIEDE2000 over the lit pixels (NaN when none is lit)
 * @param p95       its 95th percentile (nearest rank)
 * @param diskMean  mean CIEDE2000 over every pixel inside the unit disks
 * @param litPixels how many pixels were lit
 */
public record MapError(double mean, double p95, double diskMean, int litPixels) {

    /**
     * @param reference  per light, the reference map (3 floats per pixel, rows from the top, {@link BrdfMap})
     * @param variant    per light, the variant's map of the same size
     * @param exposures  per light, the display exposure
     */
    public static MapError pooled(List<float[]> reference, List<float[]> variant, List<Double> exposures, int size) {
        int lights = reference.size();
        if (variant.size() != lights || exposures.size() != lights) {
            throw new IllegalArgumentException("need one variant map and one exposure per reference map");
        }
        int pixels = size * size;
        float[] a = new float[3 * pixels * lights];
        float[] b = new float[a.length];
        boolean[] disk = new boolean[pixels * lights];
        boolean[] lit = new boolean[disk.length];
        int litCount = 0;
        for (int l = 0; l < lights; l++) {
            float[] ref = reference.get(l);
            float[] var = variant.get(l);
            if (ref.length != 3 * pixels || var.length != 3 * pixels) {
                throw new IllegalArgumentException("maps must be " + size + "x" + size + " XYZ");
            }
            double e = exposures.get(l);
            for (int j = 0; j < size; j++) {
                for (int i = 0; i < size; i++) {
                    int p = j * size + i;
                    int q = l * pixels + p;
                    double x = BrdfMap.xOf(i, size);
                    double y = BrdfMap.yOf(j, size);
                    disk[q] = x * x + y * y < 1;
                    for (int k = 0; k < 3; k++) {
                        a[3 * q + k] = (float) (ref[3 * p + k] * e);
                        b[3 * q + k] = (float) (var[3 * p + k] * e);
                    }
                    lit[q] = disk[q] && Math.max(a[3 * q + 1], b[3 * q + 1]) > BrdfMapDifference.LIT_Y;
                    litCount += lit[q] ? 1 : 0;
                }
            }
        }
        DeltaEStatistics all = DeltaEStatistics.of(a, b, disk);
        if (litCount == 0) {
            return new MapError(Double.NaN, Double.NaN, all.mean(), 0);
        }
        DeltaEStatistics litStats = DeltaEStatistics.of(a, b, lit);
        return new MapError(litStats.mean(), litStats.p95(), all.mean(), litCount);
    }
}
