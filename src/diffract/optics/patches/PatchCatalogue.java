package diffract.optics.patches;

import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * The named patches made by code, the one list every command and scene file draws from ({@code patch KIND},
 * {@code view --synthetic KIND}, a scene's {@code "procedural"}, the bench's {@code --patches}). Names are
 * lower case with hyphens; a scene's camelCase spelling ({@code "elapheLike"}) names the same patch.
 */
public final class PatchCatalogue {
    /**
     * A named patch.
     *
     * @param phiIDeg the light azimuth in the plane of its period, where its orders cross a BRDF map: 0 for the
     *                gratings (period along x), 90 for the snake patches (period along y)
     */
    public record Entry(String name, String description, ProceduralPatches.Spec spec, double phiIDeg) {
        public HeightField build() {
            return spec.build();
        }
    }

    /** Peak-to-valley height of the tall patch: 1 um, where the thesis' 30 float32 terms stop converging. */
    public static final double TALL_HEIGHT_UM = 1.0;

    public static final List<Entry> ALL = List.of(
            new Entry("blazed", "sawtooth grating, d = 2.5 um, 0.2 um high, 65 x 1.6 um", grating(ProceduralPatches.Kind.BLAZED, 26, 25), 0),
            new Entry("sinusoid", "sinusoidal grating, d = 2.5 um, 0.2 um high, 65 x 1.6 um", grating(ProceduralPatches.Kind.SINUSOID, 26, 25), 0),
            new Entry("elaphe-like", "Elaphe-like snake skin, 9.2 um square, ridges every 1.144 um, 0.3 um high",
                    new ProceduralPatches.Spec(ProceduralPatches.Kind.ELAPHE_LIKE, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM,
                            0.3, 8, 16, 128, 128, 0.01, 1L), 90),
            new Entry("xenopeltis-like", "Xenopeltis-like snake skin, 10.4 um square, ridges every 0.65 um, 0.1 um high",
                    new ProceduralPatches.Spec(ProceduralPatches.Kind.XENOPELTIS_LIKE,
                            ProceduralPatches.XENOPELTIS_RIDGE_PERIOD_UM, ProceduralPatches.XENOPELTIS_RIDGE_HEIGHT_UM,
                            16, 8, 128, 128, 0.002, 1L), 90),
            // one (10 um) coherence length wide, as the snake patches: a wider grating needs a wider window
            new Entry("blazed-10um", "sawtooth grating, d = 2.5 um, 0.2 um high, 10 x 2 um",
                    grating(ProceduralPatches.Kind.BLAZED, 4, 20), 0),
            // a scan as the microscope takes it: 52 um, as wide as the coherence window, its edges not matching
            new Entry("elaphe-scan", "the Elaphe-like skin scanned at AFM size, 528 x 512 samples, 52 x 51 um",
                    new ProceduralPatches.Spec(ProceduralPatches.Kind.ELAPHE_SCAN, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM,
                            0.3, 50, 16, 512, 512, 0.01, 1L), 90),
            // the snake patches' ridges alone: 1-D gratings the rigorous method solves as they are
            new Entry("elaphe-ridge", "the Elaphe-like ridges alone (1-D), every 1.144 um, 0.3 um high, 9.2 x 0.6 um",
                    new ProceduralPatches.Spec(ProceduralPatches.Kind.ELAPHE_RIDGE,
                            SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, 0.3, 8, 32, 16, 128, 0, 1L), 90),
            new Entry("xenopeltis-ridge", "the Xenopeltis-like ridges alone (1-D), every 0.65 um, 0.1 um high, 10.4 x "
                    + "0.3 um", new ProceduralPatches.Spec(ProceduralPatches.Kind.XENOPELTIS_RIDGE,
                            ProceduralPatches.XENOPELTIS_RIDGE_PERIOD_UM, ProceduralPatches.XENOPELTIS_RIDGE_HEIGHT_UM,
                            16, 32, 16, 128, 0, 1L), 90),
            // x = k |w| max|h| reaches ~17: the thesis' series of 30 float32 terms no longer converges
            new Entry("tall", "the Elaphe-like profile 1 um high, 4.6 um square",
                    new ProceduralPatches.Spec(ProceduralPatches.Kind.ELAPHE_LIKE, SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM,
                            TALL_HEIGHT_UM, 4, 16, 128, 64, 0.01, 1L), 90));

    private PatchCatalogue() {
    }

    private static ProceduralPatches.Spec grating(ProceduralPatches.Kind kind, int periods, int samplesPerPeriod) {
        return new ProceduralPatches.Spec(kind, 2.5, 0.2, periods, samplesPerPeriod, 16, 128, 0, 1L);
    }

    /** The names, in catalogue order. */
    public static List<String> names() {
        return ALL.stream().map(Entry::name).toList();
    }

    /** The entry of a name: any case, hyphens optional ("elapheLike" is "elaphe-like"). */
    public static Entry named(String name) {
        String key = normalised(name);
        for (Entry e : ALL) {
            if (normalised(e.name()).equals(key)) {
                return e;
            }
        }
        throw new diffract.util.UserInputException("unknown patch '" + name + "': use "
                + ALL.stream().map(Entry::name).collect(Collectors.joining(", ")));
    }

    private static String normalised(String name) {
        return name.trim().toLowerCase(Locale.ROOT).replace("-", "");
    }
}
