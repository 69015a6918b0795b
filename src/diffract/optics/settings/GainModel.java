package diffract.optics.settings;

import java.util.Locale;

/**
 * How the scalar model weighs light scattered from omega_i into omega_r: the factor in front of |P|^2 (the gain factor
 * C of 004 eq. {@code cfact} and what goes with it), measured against the orders' efficiencies from Maxwell's
 * equations (docs/design/rigorous.md).
 *
 * <ul>
 *   <li>{@link #RAYLEIGH_RICE} (the default): the factor that first-order perturbation theory gives a shallow relief,
 *       C = 4 cos^2 theta_i cos theta_r Q / (R_0 w^2) with Rayleigh-Rice's polarisation factor Q for unpolarised
 *       light ({@code GainFactor.rayleighRice}). The Fourier modal method agrees with it
 *       to 1 % on shallow gratings of any period and angle; it is the mirror's exact Fresnel reflectance at the
 *       specular direction. No shadowing term.</li>
 *   <li>{@link #STAM}: Stam's C = R (1 + omega_i . omega_r)^2 / (R_0 w^2 cos theta_r) with Schlick's reflectance R at
 *       the half vector counted once, times Stam's V-cavity shadowing (the project's model before the rigorous method
 *       measured it: 15-20 % off on shallow gratings away from the normal, orders leaving near grazing too
 *       bright).</li>
 *   <li>{@link #THESIS}: as {@link #STAM} with Schlick's reflectance squared, F^2 / F_0^2, as the printed eq.
 *       {@code cfact} has it (a mirror's albedo then exceeds 1 beyond about 72 degrees for n = 1.5).</li>
 * </ul>
 * Each gives C = 1 for a flat mirror at normal incidence, so a D65-white mirror stays exactly white.
 */
public enum GainModel {
    RAYLEIGH_RICE,
    STAM,
    THESIS;

    /** The Fresnel factor of Stam's C for Schlick's reflectance {@code r} and its normal-incidence value {@code r0}. */
    public double factor(double r, double r0) {
        double ratio = r / r0;
        return this == THESIS ? ratio * ratio : ratio;
    }

    /** rayleigh-rice, stam, thesis: the name on the command line and in scene files. */
    public String label() {
        return name().toLowerCase(Locale.ROOT).replace('_', '-');
    }

    /**
     * The model of a {@link #label()} (any case); "physical", the name of Stam's model when it was the only one besides
     * the thesis', still names it.
     */
    public static GainModel parse(String text) {
        String t = text.trim();
        for (GainModel m : values()) {
            if (m.label().equalsIgnoreCase(t)) {
                return m;
            }
        }
        if (t.equalsIgnoreCase("physical")) {
            return STAM;
        }
        throw new InvalidSettingException(Quantity.GAIN, "unknown gain model '" + text + "': use rayleigh-rice (the "
                + "default, exact for shallow reliefs), stam (Stam's gain factor with Schlick's reflectance) or thesis "
                + "(Schlick's reflectance squared, as eq. cfact prints it)");
    }
}
