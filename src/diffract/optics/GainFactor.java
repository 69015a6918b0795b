package diffract.optics;

/**
 * The direction-dependent factors of the relative BRDF that do not depend on the wavelength: the gain factor C
 * (004 eq. {@code cfact}) with Schlick's Fresnel term (000 appendix B.1), times Stam's shadowing and masking
 * factor for V-shaped grooves (Stam 1999, appendix; the thesis' {@code shadowF}, 003 Algorithm 3 line 27).
 *
 * <p>C = Phi(F(omega_i, omega_r), F_0) (1 + omega_i . omega_r)^2 / (w^2 cos(theta_r)) with
 * w^2 = (cos theta_i + cos theta_r)^2 and the Fresnel factor Phi of {@link FresnelModel}: F / F_0 (Schlick's
 * power reflectance counted once, the default) or the printed eq. {@code cfact}'s F^2 / F_0^2. The 1 / N_samples^2
 * of eq. {@code cfact} is already inside our DFT terms: {@code ifft2} divides by N_samples, so a flat patch has
 * DFT_0 = 1 at the zero frequency. At normal incidence and viewing, C = 1 and the shadowing is 1: the relative BRDF
 * of a flat mirror is exactly 1 under either model.
 */
public final class GainFactor {
    /** Refractive index of snake skin used by the thesis (003, after Algorithm 3: "close to the measured value"). */
    public static final double SNAKE_SKIN_REFRACTIVE_INDEX = 1.5;

    private GainFactor() {
    }

    /** Schlick's R_0 = ((n1 - n2) / (n1 + n2))^2 with n1 = 1 (air), eq. B.2. */
    public static double schlickR0(double refractiveIndex) {
        double r = (1.0 - refractiveIndex) / (1.0 + refractiveIndex);
        return r * r;
    }

    /** Schlick's approximation R = R_0 + (1 - R_0)(1 - cos beta)^5, beta between half vector and view (eq. B.1). */
    public static double schlickFresnel(double cosHalfToView, double r0) {
        double c = Math.min(1.0, Math.max(0.0, cosHalfToView));
        double m = 1.0 - c;
        double m2 = m * m;
        return r0 + (1.0 - r0) * m2 * m2 * m;
    }

    /** C(omega_i, omega_r) with the {@link FresnelModel#PHYSICAL} Fresnel factor. */
    public static double gain(Direction wi, Direction wr, double refractiveIndex) {
        return gain(wi, wr, refractiveIndex, FresnelModel.PHYSICAL);
    }

    /**
     * C(omega_i, omega_r) of eq. {@code cfact} with the given Fresnel factor; 0 when either direction is at or below
     * the horizon.
     */
    public static double gain(Direction wi, Direction wr, double refractiveIndex, FresnelModel fresnel) {
        if (!(wi.z() > 0) || !(wr.z() > 0)) {
            return 0;
        }
        double r0 = schlickR0(refractiveIndex);
        double f = schlickFresnel(cosHalfToView(wi, wr), r0);
        double oneplusDot = 1.0 + wi.dot(wr);
        double w = wi.z() + wr.z(); // |w|, w = -(cos theta_i + cos theta_r); w^2 >= cos^2 theta_r > 0 here
        return fresnel.factor(f, r0) * oneplusDot * oneplusDot / (w * w * wr.z());
    }

    /**
     * Stam's V-cavity shadowing and masking: min(1, 2 (n.h)(n.v) / (v.h), 2 (n.h)(n.l) / (v.h)) with n = z, the
     * half vector h, v = omega_r and l = omega_i (the thesis' {@code getShadowMaskFactor}).
     */
    public static double shadowing(Direction wi, Direction wr) {
        if (!(wi.z() > 0) || !(wr.z() > 0)) {
            return 0;
        }
        double hx = wi.x() + wr.x();
        double hy = wi.y() + wr.y();
        double hz = wi.z() + wr.z();
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz); // >= hz > 0
        double nDotH = hz / len;
        double vDotH = (wr.x() * hx + wr.y() * hy + wr.z() * hz) / len; // = cos(half angle) > 0 above the horizon
        double masking = 2.0 * nDotH * wr.z() / vDotH;
        double shadowing = 2.0 * nDotH * wi.z() / vDotH;
        return Math.min(1.0, Math.min(masking, shadowing));
    }

    /** C times the shadowing factor with the {@link FresnelModel#PHYSICAL} Fresnel factor. */
    public static double gainTimesShadowing(Direction wi, Direction wr, double refractiveIndex) {
        return gainTimesShadowing(wi, wr, refractiveIndex, FresnelModel.PHYSICAL);
    }

    /** C times the shadowing factor: everything of the relative BRDF except |P|^2 (eq. {@code cpterm}). */
    public static double gainTimesShadowing(Direction wi, Direction wr, double refractiveIndex, FresnelModel fresnel) {
        return gain(wi, wr, refractiveIndex, fresnel) * shadowing(wi, wr);
    }

    /** cos of the angle between the half vector of omega_i and omega_r and the view direction omega_r. */
    static double cosHalfToView(Direction wi, Direction wr) {
        double hx = wi.x() + wr.x();
        double hy = wi.y() + wr.y();
        double hz = wi.z() + wr.z();
        double len = Math.sqrt(hx * hx + hy * hy + hz * hz);
        if (len < 1e-300) {
            return 0;
        }
        return (wr.x() * hx + wr.y() * hy + wr.z() * hz) / len;
    }
}
