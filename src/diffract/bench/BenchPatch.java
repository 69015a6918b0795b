package diffract.bench;

import diffract.optics.patches.HeightField;
import diffract.optics.patches.PatchCatalogue;

import java.util.ArrayList;
import java.util.List;

/**
 * A patch the bench measures, with the light's azimuth in the plane of its period (so the orders cross the map).
 *
 * @param field    mean-subtracted height field
 * @param phiIDeg  light azimuth: 0 for gratings (period along x), 90 for the snake patches (period along y)
 */
public record BenchPatch(String name, HeightField field, double phiIDeg) {

    /**
     * The bench's default patches: each about one coherence length (10 um) wide, so their orders are a few map
     * pixels wide; and the tall patch, where the thesis' series needs the phase-centred expansion.
     */
    public static final String DEFAULT_NAMES = "blazed-10um,elaphe-like,xenopeltis-like,tall";

    /** A patch of the {@link PatchCatalogue}. */
    public static BenchPatch named(String name) {
        PatchCatalogue.Entry e = PatchCatalogue.named(name);
        return new BenchPatch(e.name(), e.build().meanSubtracted(), e.phiIDeg());
    }

    public static List<BenchPatch> named(List<String> names) {
        List<BenchPatch> patches = new ArrayList<>();
        for (String n : names) {
            patches.add(named(n.trim()));
        }
        return patches;
    }
}
