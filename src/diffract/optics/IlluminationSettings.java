package diffract.optics;

/**
 * How the patch is lit and how its reflection is weighed: the spatial coherence of the light (004, "Spatial
 * Coherence and Windowing": 4 sigma_s, 65 um for filtered sunlight) and the refractive index of Schlick's Fresnel
 * term in the gain factor (004 eq. {@code gainfactor}). The light's angular size and profile, a pixel's footprint
 * and the choice of Fresnel model belong to this group too.
 *
 * @param sigmaSpatialUm  sigma_s of the Gaussian coherence window; 4 sigma_s is the coherence length
 * @param refractiveIndex n of the surface (1.5 for snake skin)
 */
public record IlluminationSettings(double sigmaSpatialUm, double refractiveIndex) {
    public static final double MAX_COHERENCE_LENGTH_UM = 40_000;
    public static final double MAX_REFRACTIVE_INDEX = 4;

    public IlluminationSettings {
        if (!(sigmaSpatialUm > 0 && 4 * sigmaSpatialUm <= MAX_COHERENCE_LENGTH_UM)) {
            throw new InvalidSettingException(Quantity.COHERENCE_LENGTH, Quantity.COHERENCE_LENGTH.words()
                    + " must be in (0, " + InvalidSettingException.number(MAX_COHERENCE_LENGTH_UM) + "] um, got "
                    + InvalidSettingException.number(4 * sigmaSpatialUm));
        }
        InvalidSettingException.requireWithin(Quantity.REFRACTIVE_INDEX, refractiveIndex, 1, MAX_REFRACTIVE_INDEX);
    }

    /** From the coherence length 4 sigma_s. */
    public static IlluminationSettings ofCoherenceLength(double coherenceLengthUm, double refractiveIndex) {
        return new IlluminationSettings(coherenceLengthUm / 4.0, refractiveIndex);
    }

    /** 4 sigma_s = 65 um, n = 1.5. */
    public static IlluminationSettings thesis() {
        return new IlluminationSettings(CoherenceWindow.COHERENCE_LENGTH_UM / 4.0, GainFactor.SNAKE_SKIN_REFRACTIVE_INDEX);
    }

    public double coherenceLengthUm() {
        return 4 * sigmaSpatialUm;
    }

    public CoherenceWindow coherenceWindow() {
        return new CoherenceWindow(sigmaSpatialUm);
    }
}
