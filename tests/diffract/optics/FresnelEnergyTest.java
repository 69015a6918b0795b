package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.illumination.GainFactor;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.WavelengthSampling;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.windows.CoherenceWindow;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Energy of a flat mirror under the gain models. Its directional albedo (absolute: the normal-incidence
 * mirror reflects F_0 of the light) is
 * a(theta_i) = F_0 integral rho(omega_i, omega_r) cos theta_r d omega_r / (cos theta_i integral rho(omega_0,
 * omega_r) cos theta_r d omega_r), with cos theta_r d omega_r = dx dy over the unit disk of omega_r's projection.
 * Integrated numerically over the disk at 550 nm with a mirror lobe narrow enough to follow F and wide enough to grid (4 sigma_s = 80
 * um), theta_i = 0..89 degrees: Stam's counts Schlick's reflectance once and stays at F(theta_i) &lt;= 1; the
 * thesis' squared factor gives F^2 / F_0, above 1 beyond about 72 degrees; Rayleigh-Rice's reflects Fresnel's exact
 * unpolarised reflectance, computed here from the amplitude coefficients.
 */
class FresnelEnergyTest {
    private static final HeightField FLAT = SyntheticPatches.flat(16, 16, 0.5).meanSubtracted();
    private static final CoherenceWindow WINDOW = new CoherenceWindow(20.0);

    @Test
    void stamsAlbedoIsSchlicksReflectanceAndNeverExceedsOne() {
        double r0 = GainFactor.schlickR0(1.5);
        double normal = integral(0, GainModel.STAM);
        for (int theta = 0; theta <= 89; theta++) {
            double albedo = r0 * integral(theta, GainModel.STAM) / (Math.cos(Math.toRadians(theta)) * normal);
            assertTrue(albedo <= 1 + 1e-3, "albedo " + albedo + " at " + theta + " degrees");
            if (theta <= 80) {
                double f = GainFactor.schlickFresnel(Math.cos(Math.toRadians(theta)), r0);
                assertEquals(f, albedo, 0.01 * f, "albedo at " + theta + " degrees");
            }
        }
    }

    @Test
    void rayleighRiceAlbedoIsFresnelsExactReflectance() {
        double n = GainFactor.KERATIN_REFRACTIVE_INDEX;
        double r0 = GainFactor.normalReflectance(n);
        double normal = integral(0, GainModel.RAYLEIGH_RICE, n);
        assertEquals(Math.pow((n - 1) / (n + 1), 2), r0, 1e-15);
        for (int theta = 0; theta <= 89; theta++) {
            double albedo = r0 * integral(theta, GainModel.RAYLEIGH_RICE, n) / (Math.cos(Math.toRadians(theta)) * normal);
            double c = Math.cos(Math.toRadians(theta));
            double t = Math.sqrt(n * n - (1 - c * c));
            double rs = (c - t) / (c + t);
            double rp = (n * n * c - t) / (n * n * c + t);
            double exact = 0.5 * (rs * rs + rp * rp);
            assertTrue(albedo <= 1 + 1e-3, "albedo " + albedo + " at " + theta + " degrees");
            if (theta <= 80) {
                assertEquals(exact, albedo, 0.01 * exact, "albedo at " + theta + " degrees");
            }
        }
    }

    @Test
    void thesisAlbedoExceedsOneAtGrazingIncidence() {
        double r0 = GainFactor.schlickR0(1.5);
        double normal = integral(0, GainModel.THESIS);
        double at60 = r0 * integral(60, GainModel.THESIS) / (Math.cos(Math.toRadians(60)) * normal);
        double at80 = r0 * integral(80, GainModel.THESIS) / (Math.cos(Math.toRadians(80)) * normal);
        double f60 = GainFactor.schlickFresnel(0.5, r0);
        double f80 = GainFactor.schlickFresnel(Math.cos(Math.toRadians(80)), r0);
        assertEquals(f60 * f60 / r0, at60, 0.01 * at60);
        assertEquals(f80 * f80 / r0, at80, 0.02 * at80); // F^2 varies fast here: the lobe's width shows
        assertTrue(at80 > 4, "the thesis' mirror reflects " + at80 + " of the light at 80 degrees");
    }

    /** integral over the disk of rho(omega_i, omega_r) dx dy, on a grid fine around the mirror direction. */
    private static double integral(double thetaDeg, GainModel model) {
        return integral(thetaDeg, model, 1.5);
    }

    private static double integral(double thetaDeg, GainModel model, double refractiveIndex) {
        DiffractionBrdf brdf = new DiffractionBrdf(new ExactSpectrum(FLAT, WINDOW),
                WavelengthSampling.uniform(380, 780, 5), refractiveIndex, model);
        Direction wi = Direction.fromSphericalDeg(thetaDeg, 0);
        double lobe = 0.55 * WINDOW.sigmaFrequencyPerUm(); // lambda sigma_f: |P|^2 = exp(-|uv|^2 / lobe^2)
        double centre = -wi.x();
        int n = 240;
        double h = 12 * lobe / n;
        double sum = 0;
        for (int a = 0; a < n; a++) {
            for (int b = 0; b < n; b++) {
                double x = centre - 6 * lobe + (a + 0.5) * h;
                double y = -6 * lobe + (b + 0.5) * h;
                if (x * x + y * y >= 1) {
                    continue;
                }
                sum += brdf.relative(wi, Direction.fromProjected(x, y), 550) * h * h;
            }
        }
        return sum;
    }
}
