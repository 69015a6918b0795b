package diffract.optics;

import diffract.colour.MirrorNormalisation;
import diffract.optics.illumination.GainFactor;
import diffract.optics.windows.CoherenceWindow;

/**
 * The gain that turns the relative BRDF (004 eq. {@code cpterm}, a flat mirror's peak at normal incidence = 1) into
 * an absolute one, in the units a Lambertian surface of albedo a reflects as a E cos(theta_i): pi times radiance per
 * unit irradiance.
 *
 * <p>Under {@link MirrorNormalisation#ENERGY} a flat mirror's relative lobe integrates over the projected solid angle
 * to Omega(lambda_0) = pi (lambda_0 sigma_f)^2 (CoherenceWindow#mirrorLobeProjectedSolidAngleSr) at every
 * wavelength, D65 white, while the mirror reflects the Fresnel reflectance R_0 of the light at normal incidence
 * (energy: integral of L cos theta_r d omega_r = R_0 E). rho R_0 / Omega(lambda_0) is therefore the absolute BRDF
 * times cos theta_i, f cos theta_i (rho holds the incident cosine; the gain factor C carries R(theta) / R_0 away from
 * normal incidence): the reflected radiance per unit of the light's normal irradiance E. A Lambertian surface's
 * a E cos(theta_i) / pi is matched, times pi, by
 * <pre>
 *   gain = pi R_0 / Omega(lambda_0) = R_0 / (lambda_0 sigma_f)^2.
 * </pre>
 * For 4 sigma_s = 65 um and n = 1.5 it is 1.35e3; it grows as the coherence length squared (a longer coherence
 * length makes the lobes narrower and their peaks higher, their energy unchanged). Under
 * {@link MirrorNormalisation#PEAK} no single gain is right: the lobes' energy there grows as lambda^2.
 */
public final class RadiometricGain {
    private RadiometricGain() {
    }

    /** pi R_0 / Omega(lambda_0) for the window and the refractive index (Schlick's R_0, appendix B.2). */
    public static double of(CoherenceWindow window, double refractiveIndex) {
        return Math.PI * GainFactor.schlickR0(refractiveIndex)
                / window.mirrorLobeProjectedSolidAngleSr(MirrorNormalisation.REFERENCE_NM);
    }

    /** The gain for the settings' coherence window and refractive index. */
    public static double of(BrdfSettings settings) {
        return of(settings.coherenceWindow(), settings.illumination().refractiveIndex());
    }
}
