package diffract.bench;

import diffract.colour.DeltaEStatistics;
import diffract.optics.maps.BrdfMapDifference;

import java.util.List;

/**
 * The error of a variant's BRDF maps against the reference maps of the same lights, pooled over the lights:
 * every map is multiplied by its light's display exposure (the reference's {@link diffract.optics.maps.AutoExposure}),
 * then CIEDE2000 (D65 white) per pixel, over the lit pixels of all maps together (exposed Y above
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
     * @param reference  per light, the reference map (3 floats per pixel, rows from the top, {@link diffract.optics.BrdfMap})
     * @param variant    per light, the variant's map of the same size
     * @param exposures  per light, the display exposure
     */
    public static MapError pooled(List<float[]> reference, List<float[]> variant, List<Double> exposures, int size) {
        if (variant.size() != reference.size() || exposures.size() != reference.size()) {
            throw new IllegalArgumentException("need one variant map and one exposure per reference map");
        }
        BrdfMapDifference.Exposed e = BrdfMapDifference.Exposed.of(reference, variant, exposures, size);
        DeltaEStatistics all = DeltaEStatistics.of(e.a(), e.b(), e.disk());
        if (e.litCount() == 0) {
            return new MapError(Double.NaN, Double.NaN, all.mean(), 0);
        }
        DeltaEStatistics litStats = DeltaEStatistics.of(e.a(), e.b(), e.lit());
        return new MapError(litStats.mean(), litStats.p95(), all.mean(), e.litCount());
    }
}
