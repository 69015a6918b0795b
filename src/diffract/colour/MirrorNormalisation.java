package diffract.colour;

/**
 * What a flat mirror holds at D65 white: the spectrum L_spec(lambda) of a flat mirror's specular radiance that the
 * relative BRDF is scaled by (004 eq. {@code radianceomegarspec}, L = rho_lambda L_spec).
 *
 * <ul>
 *   <li>{@link #PEAK}: the thesis' choice L_spec(lambda) = S(lambda), D65. A flat mirror's point-sampled peak is D65
 *       white, but its lobe is lambda sigma_f wide in direction cosines, so the light it reflects, the lobe's
 *       integral, grows as lambda^2: a mirror seen through a pixel or under a light wider than the lobe reflects
 *       D65 tinted by lambda^2 (less blue, more red).</li>
 *   <li>{@link #ENERGY}: Stam's k^2 kept (004 eq. {@code minoradaptedstam}: BRDF = F^2 G |P|^2 / (A lambda^2 w^2)),
 *       L_spec(lambda) = S(lambda) (lambda_0 / lambda)^2 with lambda_0 = {@link #REFERENCE_NM}. The lobe's integral
 *       is then the same at every wavelength: a flat mirror reflects D65 white, whatever the pixel, the light or the
 *       coherence length, as energy conservation asks; its point-sampled peak is bluish (it is, for coherent
 *       light). Radiometric rendering needs this normalisation.</li>
 * </ul>
 * The normaliser N = integral of S ybar is the same for both, so {@link #PEAK} is the thesis' weighting unchanged.
 */
public enum MirrorNormalisation {
    PEAK,
    ENERGY;

    /** lambda_0 of {@link #ENERGY}, nm: the CIE 1931 luminous efficiency's peak. */
    public static final double REFERENCE_NM = 555.0;

    /** The factor L_spec(lambda) / S(lambda): 1, or (lambda_0 / lambda)^2. */
    public double factor(double lambdaNm) {
        if (this == PEAK) {
            return 1.0;
        }
        double r = REFERENCE_NM / lambdaNm;
        return r * r;
    }

    /** The option's and the scene key's spelling. */
    public String key() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
