package diffract.optics.validity;

import diffract.optics.BrdfSettings;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.GainFactor;
import diffract.optics.illumination.IlluminationSettings;
import diffract.optics.patches.HeightField;
import diffract.optics.rigorous.OrderEfficiencies;
import diffract.optics.RigorousPatch;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.rigorous.RigorousSolver;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.spectra.TexelCoefficients;

import java.util.ArrayList;
import java.util.List;

/**
 * The reflected orders of a 1-D patch at one wavelength and light, from Maxwell's equations and from the scalar
 * model side by side: what a biologist asks when a colour must be explained, and what the validity map measures.
 *
 * <p>The scalar model's efficiency of the order on texel c is what its lobe carries (docs/design/rigorous.md): the lobe
 * integrates to C S |T_c(k w)|^2 pi (lambda sigma_f)^2 over the projected solid angle, and a mirror's
 * R_0 / (pi (lambda sigma_f)^2 cos theta_i) turns that into a fraction of the incident power,
 * eta_c = R_0 C S |T_c(k w)|^2 / cos theta_i, with C S the settings' gain model at the order's direction and T_c the
 * exact coefficient of the patch ({@link ExactSpectrum}). For a flat mirror eta_0 is the model's reflectance.
 *
 * @param lambdaNm     the wavelength
 * @param orders       the propagating reflected orders, lowest first
 * @param reflected    the rigorous total reflectance for the settings' polarisation
 * @param transmitted  the rigorous total transmittance (0 into an absorbing material)
 * @param maxOrder     M, the highest harmonic the rigorous solve kept
 * @param layers       the staircase's layers it used
 */
public record OrderComparison(double lambdaNm, List<Order> orders, double reflected, double transmitted, int maxOrder,
                              int layers) {
    /**
     * One order.
     *
     * @param order      m: its direction cosine across the grooves is that of the specular direction + m lambda / period
     * @param texelX     its texel along x in the scalar model's DFT
     * @param texelY     along y
     * @param x          omega_r.x of its direction
     * @param y          omega_r.y
     * @param rigorousS  its efficiency for s-polarised light
     * @param rigorousP  for p-polarised light
     * @param rigorous   for the settings' polarisation
     * @param scalar     the scalar model's, with the settings' gain model
     */
    public record Order(int order, int texelX, int texelY, double x, double y, double rigorousS, double rigorousP,
                        double rigorous, double scalar) {
        /** The polar angle of its direction, degrees. */
        public double thetaDeg() {
            return Math.toDegrees(Math.asin(Math.min(1, Math.hypot(x, y))));
        }

        /** The scalar model's relative error, (scalar - rigorous) / rigorous. */
        public double relativeError() {
            return (scalar - rigorous) / rigorous;
        }
    }

    /** Why a patch has no order comparison, or empty where it has one (a 1-D patch). */
    public static java.util.Optional<String> refusal(HeightField meanSubtracted) {
        RigorousPatch patch = RigorousPatch.of(meanSubtracted);
        return patch.oneDimensional() ? java.util.Optional.empty() : java.util.Optional.of("the orders are solved for 1-D "
                + "patches (every row, or every column, the same): this one is " + patch.describe());
    }

    /** What the patch is to the rigorous method: "a 1-D grating: y profile of 32 samples (...), period 1.144 um". */
    public static String describe(HeightField meanSubtracted) {
        return RigorousPatch.of(meanSubtracted).describe();
    }

    /** The orders of {@code meanSubtracted} at {@code lambdaNm} for light from {@code wi}. */
    public static OrderComparison of(HeightField meanSubtracted, BrdfSettings settings, Direction wi, double lambdaNm) {
        RigorousPatch patch = RigorousPatch.of(meanSubtracted);
        if (!patch.oneDimensional()) {
            throw new InvalidSettingException(Quantity.VARIANT, refusal(meanSubtracted).orElseThrow());
        }
        IlluminationSettings illumination = settings.illumination();
        RigorousSettings rigorous = settings.rigorous();
        double[] in = patch.incidence(wi);
        OrderEfficiencies e = RigorousSolver.solve(patch.profile(), illumination.material(), lambdaNm * 1e-3, in[0],
                in[1], rigorous.resolution());
        ExactSpectrum exact = new ExactSpectrum(meanSubtracted, settings.coherenceWindow());
        double r0 = GainFactor.normalReflectance(illumination.refractiveIndex());
        double k = 2 * Math.PI / (lambdaNm * 1e-3);
        double[] t = new double[2];
        List<Order> orders = new ArrayList<>();
        for (int i = 0; i < e.count(); i++) {
            double alpha = e.alpha()[i];
            double beta = e.beta();
            if (alpha * alpha + beta * beta >= 1) {
                continue;
            }
            int m = e.order(i);
            int[] texel = patch.texel(m);
            // the order's direction in the patch's frame: the in-plane wave vector of the specular direction plus m G
            double x = patch.axis() == RigorousPatch.Axis.X ? alpha : beta;
            double y = patch.axis() == RigorousPatch.Axis.X ? beta : alpha;
            Direction wr = Direction.fromProjected(x, y);
            double w = -wi.z() - wr.z();
            TexelCoefficients.Texel texelCoefficients = exact.texel(texel[0], texel[1]);
            double power = 0;
            if (texelCoefficients != null) {
                texelCoefficients.at(k * w, t);
                power = t[0] * t[0] + t[1] * t[1];
            }
            double scalar = r0 * GainFactor.gainTimesShadowing(wi, wr, illumination.refractiveIndex(),
                    illumination.gain()) * power / wi.z();
            double s = e.reflectedS()[i];
            double p = e.reflectedP()[i];
            orders.add(new Order(m, texel[0], texel[1], x, y, s, p, rigorous.polarisation().of(s, p), scalar));
        }
        double reflected = rigorous.polarisation().of(sum(e.reflectedS()), sum(e.reflectedP()));
        double transmitted = rigorous.polarisation().of(sum(e.transmittedS()), sum(e.transmittedP()));
        return new OrderComparison(lambdaNm, List.copyOf(orders), reflected, transmitted,
                -e.firstOrder(), rigorous.resolution().layers());
    }

    private static double sum(double[] values) {
        double s = 0;
        for (double v : values) {
            s += v;
        }
        return s;
    }
}
