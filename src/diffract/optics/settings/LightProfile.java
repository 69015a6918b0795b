package diffract.optics.settings;

import java.util.Locale;

/**
 * How a light of angular diameter D spreads its radiance over its directions (docs/design/filtering.md, "Light of angular
 * diameter D").
 */
public enum LightProfile {
    /**
     * Uniform radiance over the cone of half-angle D / 2 around the light's direction: what a scene's sun or lamp
     * is, and the default. The reference integrates it, every direction exactly ({@code
     * DiscLightAverage}); the lobes method averages each lobe over it ({@code
     * DiscFootprint}); its baked table holds the point light and the lookup integrates the
     * disc over the table's rows.
     */
    DISC,
    /**
     * A Gaussian of per-axis angular standard deviation D / 4 (the disc's), linearised about the light's centre
     * ({@code LightSource.uvCovariance}): kept for comparisons, and the profile of an
     * environment's lights.
     */
    GAUSSIAN;

    /** disc, gaussian: the name on the command line and in scene files. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The profile of a {@link #label()} (any case). */
    public static LightProfile parse(String text) {
        for (LightProfile p : values()) {
            if (p.label().equalsIgnoreCase(text.trim())) {
                return p;
            }
        }
        throw new InvalidSettingException(Quantity.LIGHT_PROFILE, "unknown light profile '" + text
                + "': use disc (uniform over the diameter, the default) or gaussian (sigma D/4 per axis)");
    }
}
