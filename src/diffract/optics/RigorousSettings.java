package diffract.optics;

import diffract.optics.rigorous.Resolution;

/**
 * The rigorous method's settings: how finely the Fourier modal method resolves the patch ({@link Resolution}: the
 * harmonics kept, the staircase's layers and its extrapolation) and the light's polarisation. The material's complex
 * index is the illumination's ({@link IlluminationSettings#material}); the wavelength nodes are the spectral
 * settings' step. Every other method ignores these.
 *
 * @param resolution   harmonics and layers
 * @param polarisation the incident light's polarisation
 */
public record RigorousSettings(Resolution resolution, Polarisation polarisation) {
    /** Harmonics chosen per wavelength, 24 layers extrapolated from 12, unpolarised light. */
    public static final RigorousSettings DEFAULT = new RigorousSettings(Resolution.DEFAULT, Polarisation.UNPOLARISED);

    public RigorousSettings {
        if (resolution == null || polarisation == null) {
            throw new NullPointerException("the resolution and the polarisation are required");
        }
    }

    public RigorousSettings withResolution(Resolution r) {
        return new RigorousSettings(r, polarisation);
    }

    public RigorousSettings withPolarisation(Polarisation p) {
        return new RigorousSettings(resolution, p);
    }
}
