package diffract.optics;

/**
 * The physics a rendering adds to {@link BrdfSettings}: how the gain factor counts Fresnel, how large the light is,
 * what a map pixel averages, and the lobes method's quadrature. The reference and the lobes method honour the light
 * and the pixel filter; flss, nmm, pq and the baked table point-sample pixels and cannot render an extended light.
 *
 * @param fresnel     {@link FresnelModel#PHYSICAL} by default
 * @param light       the light's angular size ({@link LightSource}); a point by default
 * @param pixelFilter what a BRDF-map pixel of the reference and the lobes method shows
 * @param lobes       the lobes method's quadrature
 */
public record OpticsOptions(FresnelModel fresnel, LightSource light, PixelFilter pixelFilter, LobeQuadrature lobes) {
    /** Pixels and light point-sampled (the thesis' BRDF map), physical Fresnel. */
    public static final OpticsOptions POINT_SAMPLED = new OpticsOptions(FresnelModel.PHYSICAL, LightSource.POINT,
            PixelFilter.POINT, LobeQuadrature.DEFAULT);
    /** The definitions: a map pixel is its box average, a point light, physical Fresnel. */
    public static final OpticsOptions DEFAULT = new OpticsOptions(FresnelModel.PHYSICAL, LightSource.POINT,
            PixelFilter.BOX, LobeQuadrature.DEFAULT);

    public OpticsOptions {
        if (fresnel == null || light == null || pixelFilter == null || lobes == null) {
            throw new IllegalArgumentException("every optics option is required");
        }
    }

    public OpticsOptions withFresnel(FresnelModel model) {
        return new OpticsOptions(model, light, pixelFilter, lobes);
    }

    public OpticsOptions withLight(LightSource source) {
        return new OpticsOptions(fresnel, source, pixelFilter, lobes);
    }

    public OpticsOptions withPixelFilter(PixelFilter filter) {
        return new OpticsOptions(fresnel, light, filter, lobes);
    }

    public OpticsOptions withLobes(LobeQuadrature quadrature) {
        return new OpticsOptions(fresnel, light, pixelFilter, quadrature);
    }

    /** Whether a map of this variant averages anything (a box or a light) rather than point-sampling. */
    public boolean filters() {
        return pixelFilter == PixelFilter.BOX || !light.isPoint();
    }
}
