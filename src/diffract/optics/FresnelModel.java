package diffract.optics;

import java.util.Locale;

/**
 * How the gain factor C (004 eq. {@code cfact}) counts the Fresnel reflectance of Schlick's approximation.
 *
 * <p>Stam's BRDF carries F^2 with F an amplitude (field) coefficient. The thesis substitutes Schlick's formula
 * (000 appendix B.1), which approximates the power reflectance R = |r|^2 already, and keeps the square: C then
 * holds R^2 / R_0^2, so the Fresnel term is counted twice. {@link #PHYSICAL} counts it once,
 * C = R (1 + omega_i . omega_r)^2 / (R_0 w^2 cos theta_r): a flat mirror's directional albedo is then R(theta_i)
 * &lt;= 1 at every angle (absolute, with the normal-incidence mirror reflecting R_0 of the light), while
 * {@link #THESIS}' albedo R^2 / R_0 exceeds 1 where R &gt; sqrt(R_0) (beyond about 72 degrees for n = 1.5).
 * Both give C = 1 for a flat mirror at normal incidence, so a D65-white mirror stays exactly white.
 */
public enum FresnelModel {
    /** R / R_0: the power reflectance counted once (the default). */
    PHYSICAL,
    /** R^2 / R_0^2: eq. {@code cfact} as printed, Schlick's reflectance squared (for comparisons with the thesis). */
    THESIS;

    /** The Fresnel factor of C for Schlick's reflectance {@code r} and its normal-incidence value {@code r0}. */
    public double factor(double r, double r0) {
        double ratio = r / r0;
        return this == PHYSICAL ? ratio : ratio * ratio;
    }

    /** physical, thesis: the name on the command line and in scene files. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The model of a {@link #label()} (any case). */
    public static FresnelModel parse(String text) {
        for (FresnelModel m : values()) {
            if (m.label().equalsIgnoreCase(text.trim())) {
                return m;
            }
        }
        throw new InvalidSettingException(Quantity.FRESNEL, "unknown Fresnel model '" + text
                + "': use physical (the reflectance counted once) or thesis (squared)");
    }
}
