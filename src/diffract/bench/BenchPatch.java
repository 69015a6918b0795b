package diffract.bench;

import diffract.optics.HeightField;
import diffract.optics.ProceduralPatches;
import diffract.optics.SyntheticPatches;
import diffract.util.UserInputException;

import java.util.ArrayList;
import java.util.List;

/**
 * A patch the bench measures, with the light's azimuth in the plane of its period (so the orders cross the map).
 *
 * @param field    mean-subtracted height field
 * @param phiIDeg  light azimuth: 0 for gratings (period along x), 90 for the snake patches (period along y)
 */
public record BenchPatch(String name, HeightField field, double phiIDeg) {

    /** The bench's patches, by name: {@code blazed}, {@code elaphe-like}, {@code xenopeltis-like}, {@code tall}. */
    public static final List<String> NAMES = List.of("blazed", "elaphe-like", "xenopeltis-like", "tall");

    /** Peak-to-valley height of the tall patch: 1 um, where the thesis' 30 float32 terms stop converging. */
    public static final double TALL_HEIGHT_UM = 1.0;

    public static BenchPatch named(String name) {
        switch (name) {
            case "blazed":
                // d = 2.5 um, 0.2 um high, 4 periods of 20 pixels, 16 rows: 80 x 16 pixels of 0.125 um, 10 x 2 um, about
                // one (default) coherence length wide, as the snake patches (a wider grating needs a wider window)
                return new BenchPatch(name, SyntheticPatches.blazed(2.5, 0.2, 20, 4, 16).meanSubtracted(), 0);
            case "elaphe-like":
                return new BenchPatch(name, SyntheticPatches.elapheLike().meanSubtracted(), 90);
            case "xenopeltis-like":
                return new BenchPatch(name, ProceduralPatches.Spec.defaults("xenopeltisLike").build().meanSubtracted(), 90);
            case "tall":
                // the Elaphe-like profile, 64 x 64 pixels of 0.0715 um, 1 um high: x = k |w| max|h| reaches ~17
                return new BenchPatch(name, SyntheticPatches.elapheLike(64, 4, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM,
                        TALL_HEIGHT_UM, 1L).meanSubtracted(), 90);
            default:
                throw new UserInputException("unknown bench patch '" + name + "': use " + String.join(", ", NAMES));
        }
    }

    public static List<BenchPatch> named(List<String> names) {
        List<BenchPatch> patches = new ArrayList<>();
        for (String n : names) {
            patches.add(named(n.trim()));
        }
        return patches;
    }
}
