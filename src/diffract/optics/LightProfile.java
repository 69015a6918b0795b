package diffract.optics;

import java.util.Locale;

/**
 * How a light of angular diameter D spreads its radiance over its directions (docs/filtering.md, "Light of angular
 * diameter D").
 */
public enum LightProfile {
    /**
     * Uniform radiance over the cone of half-angle D / 2 around the light's direction: what a scene's sun or lamp
     * is. Only the reference integrates it, every direction exactly ({@link DiscLightAverage}).
     */
    DISC,
    /**
     * A Gaussian of per-axis angular standard deviation D / 4 (the disc's), linearised about the light's centre
     * ({@link LightSource#uvCovariance}): the model every fast method filters by, kept as the default.
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
                + "': use gaussian (sigma D/4 per axis, the default) or disc (uniform over the diameter)");
    }
}
