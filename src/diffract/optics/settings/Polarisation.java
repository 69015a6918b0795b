package diffract.optics.settings;

import java.util.Locale;

/**
 * The light's polarisation, as the rigorous method sees it (the scalar model has none): unpolarised (sunlight, the
 * default: the mean of any two orthogonal polarisations), or linearly polarised perpendicular to the plane of
 * incidence (s, TE) or in it (p, TM), as behind a polariser. Efficiencies are summed over the reflected light's
 * polarisations (no analyser).
 */
public enum Polarisation {
    UNPOLARISED,
    S,
    P;

    /** This polarisation's efficiency from the s and p ones. */
    public double of(double s, double p) {
        return switch (this) {
            case UNPOLARISED -> 0.5 * (s + p);
            case S -> s;
            case P -> p;
        };
    }

    /** unpolarised, s, p: the name on the command line and in scene files. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The polarisation of a {@link #label()} (any case). */
    public static Polarisation parse(String text) {
        for (Polarisation p : values()) {
            if (p.label().equalsIgnoreCase(text.trim())) {
                return p;
            }
        }
        throw new InvalidSettingException(Quantity.POLARISATION, "unknown polarisation '" + text
                + "': use unpolarised, s (perpendicular to the plane of incidence) or p (in it)");
    }
}
