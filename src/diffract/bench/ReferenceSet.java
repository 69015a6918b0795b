package diffract.bench;

import diffract.optics.maps.AutoExposure;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.render.GpuBrdfMap;

import java.util.ArrayList;
import java.util.List;

/**
 * The reference maps of one patch at a sweep's lights (theta_i in degrees, at the patch's azimuth) and the exposure
 * each is shown and compared at, its own {@link AutoExposure}: what a variant's maps are drawn for
 * ({@link #drawnFor}) and measured against ({@link #error}).
 *
 * @param lights    the lights' directions, in the order of the maps
 * @param xyz       per light, the reference map (XYZ per pixel, {@link diffract.optics.BrdfMap})
 * @param exposures per light, the display exposure
 */
public record ReferenceSet(List<Direction> lights, int sizePx, List<float[]> xyz, List<Double> exposures) {

    public ReferenceSet {
        lights = List.copyOf(lights);
        xyz = List.copyOf(xyz);
        exposures = List.copyOf(exposures);
    }

    /** The reference maps of {@code patch} at {@code lightsDeg} with {@code base}'s light and pixels. */
    public static ReferenceSet of(ReferenceMaps maps, BenchPatch patch, List<Double> lightsDeg, int sizePx,
                                  BrdfSettings base) {
        List<Direction> lights = new ArrayList<>();
        List<float[]> xyz = new ArrayList<>();
        List<Double> exposures = new ArrayList<>();
        for (double theta : lightsDeg) {
            Direction wi = Direction.fromSphericalDeg(theta, patch.phiIDeg());
            float[] reference = maps.xyz(patch, theta, sizePx, base);
            lights.add(wi);
            xyz.add(reference);
            exposures.add(AutoExposure.ofXyz(reference, wi, sizePx));
        }
        return new ReferenceSet(lights, sizePx, xyz, exposures);
    }

    /**
     * {@code settings} drawn for the brightest exposure its maps are compared at (the lobes method's cutoff,
     * {@link BrdfSettings#shownAt}): a map compared at several exposures keeps what the brightest shows.
     */
    public BrdfSettings drawnFor(BrdfSettings settings) {
        return settings.shownAt(exposures.stream().mapToDouble(Double::doubleValue).max().orElse(1));
    }

    /** The variant's maps at the same lights and size. */
    public List<float[]> drawnBy(GpuBrdfMap map) {
        List<float[]> drawn = new ArrayList<>();
        for (Direction wi : lights) {
            drawn.add(map.xyz(wi, sizePx));
        }
        return drawn;
    }

    /** The error of {@code maps} (one per light, in order) against these, pooled over the lights. */
    public MapError error(List<float[]> maps) {
        return MapError.pooled(xyz, maps, exposures, sizePx);
    }
}
