package diffract.geometry;

import java.util.Locale;

/**
 * The two snakes whose skin the project renders, with the scale counts taxonomists record for them and the shape
 * of their scales. Counts are mid-range values of the species' descriptions: Elaphe (Pantherophis) guttata, the
 * corn snake, 27 dorsal scale rows at mid-body and about 215 ventral scales; Xenopeltis unicolor, the sunbeam snake,
 * 15 rows and about 180 ventral scales. Corn snake scales are narrow, Xenopeltis' broad and smooth; both are gently
 * domed and each lies at its own small tilt, which is why the animal flashes scale by scale.
 */
public enum SnakeSpecies {
    ELAPHE_GUTTATA("elapheGuttata",
            new ScaleLattice.Parameters(27, 215, 0.28, 8, 6, 5, 5, 1.3, 1)),
    XENOPELTIS_UNICOLOR("xenopeltisUnicolor",
            new ScaleLattice.Parameters(15, 180, 0.22, 8, 7, 6, 6, 1.3, 1));

    private final String sceneName;
    private final ScaleLattice.Parameters scales;

    SnakeSpecies(String sceneName, ScaleLattice.Parameters scales) {
        this.sceneName = sceneName;
        this.scales = scales;
    }

    /** The scene-file spelling, e.g. "elapheGuttata". */
    public String sceneName() {
        return sceneName;
    }

    /** The species' scale lattice. */
    public ScaleLattice.Parameters scales() {
        return scales;
    }

    /** The species' procedural pigmentation painted on a lattice. */
    public SkinPattern pattern(ScaleLattice lattice, long seed) {
        return this == ELAPHE_GUTTATA ? new SkinPattern.ElapheGuttata(lattice, seed)
                : new SkinPattern.XenopeltisUnicolor(lattice, seed);
    }

    /** The species by its scene-file spelling, in any case (scene files check the exact spelling first). */
    public static SnakeSpecies fromSceneName(String name) {
        for (SnakeSpecies s : values()) {
            if (s.sceneName.equalsIgnoreCase(name)) {
                return s;
            }
        }
        throw new IllegalArgumentException("unknown species " + name);
    }

    static String format(double value) {
        return value == Math.rint(value) ? Long.toString((long) value) : String.format(Locale.ROOT, "%.4g", value);
    }
}
