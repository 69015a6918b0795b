package diffract.optics;

import diffract.colour.MirrorNormalisation;
import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.illumination.GainFactor;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.settings.WavelengthSampling;
import diffract.optics.spectra.ExactSpectrum;
import diffract.optics.windows.CoherenceWindow;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A flat mirror at normal incidence at the thesis' 65 um coherence, its relative BRDF integrated numerically over
 * the projected solid angle (cos theta_r d omega_r = dx dy of omega_r's projection) on a grid fine against the lobe
 * (a third of its standard deviation at 380 nm): under the energy normalisation the light it reflects is D65 white
 * of luminance Omega(555 nm) = pi (0.555 um sigma_f)^2, and the radiometric gain turns it into the Fresnel
 * reflectance R_0; under the thesis' peak normalisation the reflected light is tinted as lambda^2 (less blue).
 */
class RadiometricGainTest {
    private static final HeightField FLAT = SyntheticPatches.flat(16, 16, 0.5).meanSubtracted();
    private static final CoherenceWindow WINDOW = CoherenceWindow.thesis();
    /** D65 white at Y = 1 (CIE 015:2018, 2 degrees). */
    private static final double WHITE_X = 0.95047;
    private static final double WHITE_Z = 1.08883;

    @Test
    void underTheEnergyNormalisationAFlatMirrorReflectsWhiteLight() {
        Xyz reflected = reflected(MirrorNormalisation.ENERGY);
        double omega = WINDOW.mirrorLobeProjectedSolidAngleSr(MirrorNormalisation.REFERENCE_NM);
        assertEquals(1.0, reflected.y() / omega, 1e-4, "luminance of the lobe over Omega(555 nm)");
        assertEquals(WHITE_X, reflected.x() / reflected.y(), 2e-3, "x of the reflected light");
        assertEquals(WHITE_Z, reflected.z() / reflected.y(), 2e-3, "z of the reflected light");
    }

    @Test
    void theRadiometricGainTurnsTheMirrorsLobeIntoItsFresnelReflectance() {
        Xyz reflected = reflected(MirrorNormalisation.ENERGY);
        double gain = RadiometricGain.of(WINDOW, 1.5);
        // the gain is pi x radiance per irradiance: the radiance's integral over the projected solid angle is R_0
        assertEquals(GainFactor.schlickR0(1.5), gain / Math.PI * reflected.y(), 1e-5);
        assertEquals(1354.0, gain, 1.0, "pi R_0 / (pi (0.555 um / (2 pi 16.25 um))^2)");
        double longer = RadiometricGain.of(new CoherenceWindow(2 * WINDOW.sigmaSpatialUm()), 1.5);
        assertEquals(4.0, longer / gain, 1e-12, "twice the coherence length: lobes a quarter of the solid angle");
    }

    @Test
    void underThePeakNormalisationTheReflectedLightIsTintedAsLambdaSquared() {
        Xyz reflected = reflected(MirrorNormalisation.PEAK);
        // the lobe at lambda holds Omega(lambda) = Omega(555 nm) (lambda / 555 nm)^2 of the peak's weight
        double[] nodes = diffract.colour.Trapezoid.uniformNodes(380, 780, 5);
        double[][] w = diffract.colour.SpectralIntegrator.xyzWeights(nodes, diffract.colour.Trapezoid.weights(nodes));
        double omega = WINDOW.mirrorLobeProjectedSolidAngleSr(MirrorNormalisation.REFERENCE_NM);
        double[] expected = new double[3];
        for (int j = 0; j < nodes.length; j++) {
            double r = nodes[j] / MirrorNormalisation.REFERENCE_NM;
            for (int c = 0; c < 3; c++) {
                expected[c] += w[j][c] * r * r * omega;
            }
        }
        assertEquals(expected[0], reflected.x(), 1e-4 * expected[0]);
        assertEquals(expected[1], reflected.y(), 1e-4 * expected[1]);
        assertEquals(expected[2], reflected.z(), 1e-4 * expected[2]);
        double zOverY = reflected.z() / reflected.y();
        assertTrue(zOverY < 0.8 * WHITE_Z, "the thesis' mirror reflects z/y = " + zOverY + ", white is " + WHITE_Z);
    }

    /** integral over the disk of XYZ(omega_0, omega_r) dx dy around the mirror direction. */
    private static Xyz reflected(MirrorNormalisation normalisation) {
        DiffractionBrdf brdf = new DiffractionBrdf(new ExactSpectrum(FLAT, WINDOW),
                WavelengthSampling.uniform(380, 780, 5, normalisation), 1.5);
        Direction wi = Direction.fromSphericalDeg(0, 0);
        double reach = 6 * 0.78 * WINDOW.sigmaFrequencyPerUm(); // six lobe widths lambda sigma_f at 780 nm
        double h = 0.33 * 0.38 * WINDOW.sigmaFrequencyPerUm() / Math.sqrt(2);
        int n = (int) Math.ceil(2 * reach / h);
        double x = 0;
        double y = 0;
        double z = 0;
        for (int a = 0; a < n; a++) {
            for (int b = 0; b < n; b++) {
                Xyz v = brdf.xyz(wi, Direction.fromProjected(-reach + (a + 0.5) * h, -reach + (b + 0.5) * h));
                x += v.x() * h * h;
                y += v.y() * h * h;
                z += v.z() * h * h;
            }
        }
        return new Xyz(x, y, z);
    }
}
