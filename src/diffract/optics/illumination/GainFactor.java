package diffract.optics.illumination;

import diffract.optics.patches.Direction;
import diffract.optics.settings.GainModel;

/**
 * The direction-dependent factors of the relative BRDF that do not depend on the wavelength, by {@link GainModel}:
 * Rayleigh-Rice's factor ({@link #rayleighRice}, the default), or Stam's gain factor C (004 eq. {@code cfact}) with
 * Schlick's Fresnel term (000 appendix B.1) times Stam's shadowing and masking factor for V-shaped grooves (Stam
 * 1999, appendix; the thesis' {@code shadowF}, 003 Algorithm 3 line 27).
 *
 * <p>Stam's C = Phi(F(omega_i, omega_r), F_0) (1 + omega_i . omega_r)^2 / (w^2 cos(theta_r)) with
 * w^2 = (cos theta_i + cos theta_r)^2 and the Fresnel factor Phi of {@link GainModel}: F / F_0 (Schlick's
 * power reflectance counted once) or the printed eq. {@code cfact}'s F^2 / F_0^2. The 1 / N_samples^2
 * of eq. {@code cfact} is already inside our DFT terms: {@code ifft2} divides by N_samples, so a flat patch has
 * DFT_0 = 1 at the zero frequency. At normal incidence and viewing every model gives 1 (and the shadowing is 1): the
 * relative BRDF of a flat mirror is exactly 1.
 */
public final class GainFactor {
    /** Refractive index of snake skin used by the thesis (003, after Algorithm 3: "close to the measured value"). */
    public static final double THESIS_REFRACTIVE_INDEX = 1.5;
    /**
     * Refractive index of beta-keratin, the stuff of snake scales, measured in the visible (1.56: D. G. Stavenga et al.,
     * J. Exp. Biol. 2015; H. L. Leertouwer, B. D. Wilts and D. G. Stavenga, Opt. Express 19, 24061, 2011): the default.
     */
    public static final double KERATIN_REFRACTIVE_INDEX = 1.56;

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

    /** Stam's C(omega_i, omega_r) with Schlick's reflectance counted once ({@link GainModel#STAM}). */
    public static double gain(Direction wi, Direction wr, double refractiveIndex) {
        return gain(wi, wr, refractiveIndex, GainModel.STAM);
    }

    /**
     * C(omega_i, omega_r) of the model: Rayleigh-Rice's factor, or eq. {@code cfact} with the model's Fresnel factor;
     * 0 when either direction is at or below the horizon.
     */
    public static double gain(Direction wi, Direction wr, double refractiveIndex, GainModel model) {
        if (model == GainModel.RAYLEIGH_RICE) {
            return rayleighRice(wi, wr, refractiveIndex);
        }
        if (!(wi.z() > 0) || !(wr.z() > 0)) {
            return 0;
        }
        double r0 = schlickR0(refractiveIndex);
        double f = schlickFresnel(cosHalfToView(wi, wr), r0);
        double oneplusDot = 1.0 + wi.dot(wr);
        double w = wi.z() + wr.z(); // |w|, w = -(cos theta_i + cos theta_r); w^2 >= cos^2 theta_r > 0 here
        return model.factor(f, r0) * oneplusDot * oneplusDot / (w * w * wr.z());
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

    /** Stam's C times the shadowing factor with Schlick's reflectance counted once ({@link GainModel#STAM}). */
    public static double gainTimesShadowing(Direction wi, Direction wr, double refractiveIndex) {
        return gainTimesShadowing(wi, wr, refractiveIndex, GainModel.STAM);
    }

    /**
     * The model's factor with its shadowing (Stam's models; Rayleigh-Rice's has none): everything of the relative
     * BRDF except |P|^2 (eq. {@code cpterm}).
     */
    public static double gainTimesShadowing(Direction wi, Direction wr, double refractiveIndex, GainModel model) {
        if (model == GainModel.RAYLEIGH_RICE) {
            return rayleighRice(wi, wr, refractiveIndex);
        }
        return gain(wi, wr, refractiveIndex, model) * shadowing(wi, wr);
    }

    /**
     * The gain factor to first order in the relief's height (Rayleigh-Rice perturbation theory; J. M. Elson and J. M.
     * Bennett, Opt. Eng. 18, 116, 1979; J. C. Stover, Optical Scattering, ch. 5): a shallow relief of any period
     * scatters light of unpolarised incidence from omega_i into omega_r with efficiency
     * 4 (k a / 2)^2 cos^2 theta_i cos theta_r ... written so that, with the scalar model's |T_m|^2 = (k w a / 2)^2 of a
     * small sinusoid of amplitude a, the relative BRDF's order carries exactly that: C_RR = 4 cos^2 theta_i cos theta_r
     * Q / (R_0 w^2), Q the polarisation factor averaged over both incident and both scattered polarisations,
     * <pre>
     *   q_ss = (eps - 1) cos phi / ((c_i + r_i)(c_r + r_r)),     q_sp = (eps - 1) r_r sin phi / ((c_i + r_i)(eps c_r + r_r)),
     *   q_ps = (eps - 1) r_i sin phi / ((eps c_i + r_i)(c_r + r_r)),
     *   q_pp = (eps - 1)(r_i r_r cos phi - eps s_i s_r) / ((eps c_i + r_i)(eps c_r + r_r)),
     * </pre>
     * c = cos theta, s = sin theta, r = sqrt(eps - s^2), phi the azimuth of omega_r from the specular direction's,
     * eps = n^2. At the specular direction q_ss and q_pp are Fresnel's r_s and r_p, so C_RR is the mirror's exact
     * Fresnel reflectance R(theta_i) cos theta_i / R_0, as Stam's C is with Schlick's. The Fourier modal method
     * confirms it for shallow gratings of any period and angle (docs/design/rigorous.md); Stam's geometric term
     * (1 + omega_i . omega_r)^2 / (w^2 cos theta_r) and Schlick's reflectance at the half vector miss it by 15-20 %
     * there. There is no shadowing term: a shallow relief shadows nothing, and Stam's V-cavity term made the deep
     * ones worse, not better. 0 at or below either horizon.
     */
    public static double rayleighRice(Direction wi, Direction wr, double refractiveIndex) {
        if (!(wi.z() > 0) || !(wr.z() > 0)) {
            return 0;
        }
        double eps = refractiveIndex * refractiveIndex;
        double ci = wi.z();
        double cr = wr.z();
        double si2 = Math.max(0, 1 - ci * ci);
        double sr2 = Math.max(0, 1 - cr * cr);
        double ri = Math.sqrt(eps - si2);
        double rr = Math.sqrt(eps - sr2);
        // s_i s_r cos phi and s_i s_r sin phi from the in-plane components (phi = 0 at the specular direction)
        double sinProduct = Math.sqrt(si2 * sr2);
        double cosPart = -(wi.x() * wr.x() + wi.y() * wr.y());
        double sinPart = wi.x() * wr.y() - wi.y() * wr.x();
        double cos2;
        double sin2;
        double cosPhi;
        if (sinProduct < 1e-12) {
            // at normal incidence or viewing the azimuth is undefined and the sum over polarisations independent of it
            cos2 = 1;
            sin2 = 0;
            cosPhi = 1;
        } else {
            cosPhi = cosPart / sinProduct;
            cos2 = cosPart * cosPart / (sinProduct * sinProduct);
            sin2 = sinPart * sinPart / (sinProduct * sinProduct);
        }
        double e1 = eps - 1;
        double ss = e1 / ((ci + ri) * (cr + rr));
        double sp = e1 * rr / ((ci + ri) * (eps * cr + rr));
        double ps = e1 * ri / ((eps * ci + ri) * (cr + rr));
        double pp = e1 * (ri * rr * cosPhi - eps * sinProduct) / ((eps * ci + ri) * (eps * cr + rr));
        double q = 0.5 * (ss * ss * cos2 + (sp * sp + ps * ps) * sin2 + pp * pp);
        double w = ci + cr;
        return 4 * ci * ci * cr * q / (normalReflectance(refractiveIndex) * w * w);
    }

    /** ((n - 1) / (n + 1))^2: the exact reflectance at normal incidence (Schlick's R_0 is the same number). */
    public static double normalReflectance(double refractiveIndex) {
        return schlickR0(refractiveIndex);
    }

    /** cos of the angle between the half vector of omega_i and omega_r and the view direction omega_r. */
    public static double cosHalfToView(Direction wi, Direction wr) {
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
