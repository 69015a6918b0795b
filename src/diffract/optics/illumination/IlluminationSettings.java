package diffract.optics.illumination;

import diffract.optics.settings.GainModel;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.PixelFilter;
import diffract.optics.settings.Quantity;
import diffract.optics.windows.CoherenceWindow;

/**
 * How the patch is lit, what a pixel sees of it, and how its reflection is weighed: the spatial coherence of the
 * light (004, "Spatial Coherence and Windowing": 4 sigma_s, 65 um for filtered sunlight), the light's angular size
 * ({@link LightSource}: a Gaussian of sigma D / 4 per axis), what a BRDF-map pixel shows ({@link PixelFilter}), and
 * the gain factor's Fresnel term (004 eq. {@code gainfactor}: Schlick's with refractive index n, counted as
 * {@link GainModel} says). docs/design/filtering.md defines the light and the pixel.
 *
 * @param sigmaSpatialUm  sigma_s of the Gaussian coherence window; 4 sigma_s is the coherence length
 * @param refractiveIndex n of the surface (1.5 for snake skin)
 * @param extinction      k of the surface, its complex index being n + i k: 0 for keratin; melanin absorbs
 *                        (k about 0.02-0.1 over the visible). The rigorous method reads it; Schlick's Fresnel term of
 *                        the scalar model reads n alone
 * @param light           the light's angular diameter, 0..20 degrees (0: a point light)
 * @param gain            the factor in front of |P|^2 ({@link GainModel}: Rayleigh-Rice's, the default; Stam's;
 *                        or the thesis' squared Schlick reflectance)
 * @param pixelFilter     a BRDF-map pixel's value: the BRDF at its centre ({@link PixelFilter#POINT}, the thesis'
 *                        map) or its average over the pixel's square ({@link PixelFilter#BOX}, the definition)
 */
public record IlluminationSettings(double sigmaSpatialUm, double refractiveIndex, double extinction,
                                   LightSource light, GainModel gain, PixelFilter pixelFilter) {
    public static final double MAX_COHERENCE_LENGTH_UM = 40_000;
    public static final double MAX_REFRACTIVE_INDEX = 4;
    /** The largest extinction coefficient k accepted (metals reach 3-7; a scale's pigment stays below 1). */
    public static final double MAX_EXTINCTION = 10;

    public IlluminationSettings {
        if (!(sigmaSpatialUm > 0 && 4 * sigmaSpatialUm <= MAX_COHERENCE_LENGTH_UM)) {
            throw new InvalidSettingException(Quantity.COHERENCE_LENGTH, Quantity.COHERENCE_LENGTH.words()
                    + " must be in (0, " + InvalidSettingException.number(MAX_COHERENCE_LENGTH_UM) + "] um, got "
                    + InvalidSettingException.number(4 * sigmaSpatialUm));
        }
        InvalidSettingException.requireWithin(Quantity.REFRACTIVE_INDEX, refractiveIndex, 1, MAX_REFRACTIVE_INDEX);
        if (!(extinction >= 0 && extinction <= MAX_EXTINCTION)) {
            throw new InvalidSettingException(Quantity.REFRACTIVE_INDEX, "the extinction coefficient k of n + k i must"
                    + " be in [0, " + InvalidSettingException.number(MAX_EXTINCTION) + "], got "
                    + InvalidSettingException.number(extinction));
        }
        if (light == null || gain == null || pixelFilter == null) {
            throw new NullPointerException("the light, the gain model and the pixel filter are required");
        }
    }

    /** A point light, Rayleigh-Rice's gain, point-sampled map pixels. */
    public IlluminationSettings(double sigmaSpatialUm, double refractiveIndex) {
        this(sigmaSpatialUm, refractiveIndex, 0, LightSource.POINT, GainModel.RAYLEIGH_RICE, PixelFilter.POINT);
    }

    /** From the coherence length 4 sigma_s; a point light, Rayleigh-Rice's gain, point-sampled map pixels. */
    public static IlluminationSettings ofCoherenceLength(double coherenceLengthUm, double refractiveIndex) {
        return new IlluminationSettings(coherenceLengthUm / 4.0, refractiveIndex);
    }

    /**
     * The default illumination: the thesis' 4 sigma_s = 65 um, seen as the thesis' maps see it (a point light, the BRDF
     * at each pixel's centre), on keratin (n = 1.56; the thesis took 1.5) with the gain model that Maxwell's
     * equations confirm for shallow reliefs (Rayleigh-Rice's; the thesis' is {@link GainModel#THESIS}).
     */
    public static IlluminationSettings thesis() {
        return new IlluminationSettings(CoherenceWindow.COHERENCE_LENGTH_UM / 4.0, GainFactor.KERATIN_REFRACTIVE_INDEX);
    }

    public double coherenceLengthUm() {
        return 4 * sigmaSpatialUm;
    }

    /** Whether a pixel averages anything (its square or an extended light) rather than point-sampling. */
    public boolean filters() {
        return pixelFilter == PixelFilter.BOX || !light.isPoint();
    }

    public IlluminationSettings withCoherenceLengthUm(double um) {
        return new IlluminationSettings(um / 4.0, refractiveIndex, extinction, light, gain, pixelFilter);
    }

    public IlluminationSettings withRefractiveIndex(double n) {
        return new IlluminationSettings(sigmaSpatialUm, n, extinction, light, gain, pixelFilter);
    }

    /** The complex index n + i k as a whole. */
    public IlluminationSettings withMaterial(diffract.optics.rigorous.ComplexIndex index) {
        return new IlluminationSettings(sigmaSpatialUm, index.n(), index.k(), light, gain, pixelFilter);
    }

    /** The surface's complex index n + i k. */
    public diffract.optics.rigorous.ComplexIndex material() {
        return new diffract.optics.rigorous.ComplexIndex(refractiveIndex, extinction);
    }

    public IlluminationSettings withLight(LightSource l) {
        return new IlluminationSettings(sigmaSpatialUm, refractiveIndex, extinction, l, gain, pixelFilter);
    }

    public IlluminationSettings withGain(GainModel f) {
        return new IlluminationSettings(sigmaSpatialUm, refractiveIndex, extinction, light, f, pixelFilter);
    }

    public IlluminationSettings withPixelFilter(PixelFilter p) {
        return new IlluminationSettings(sigmaSpatialUm, refractiveIndex, extinction, light, gain, p);
    }
}
