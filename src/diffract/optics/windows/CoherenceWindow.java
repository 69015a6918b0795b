package diffract.optics.windows;

/**
 * The Gaussian coherence window (004 section "Spatial Coherence and Windowing"): a spatial window g of standard
 * deviation sigma_s with 4 sigma_s = 65 um (the coherence area of filtered sunlight), whose Fourier transform is
 * G(f) = exp(-f^2 / (2 sigma_f^2)) with sigma_f = 1 / (2 pi sigma_s) (eq. {@code gaussianwindowfrequencyspace}).
 *
 * <p>Convolving the DFT with G reconstructs the DTFT (eq. {@code wnwindowingapproachsub}; 003 Algorithm 3 applies
 * it to the complex DFT values before squaring, which is what we do). In texel units of a DFT of a patch of
 * extent L = N dH, the frequency spacing is 1 / L, so sigma in texels is sigma_f * L = L / (2 pi sigma_s).
 * The weight's peak is 1, so a flat patch at the exact specular direction has |P|^2 = 1. (004's {@code gaussweight}
 * writes an extra factor pi; the thesis' shader had none, and with it a flat mirror would not be white.)
 *
 * <p>The window's {@link WindowPlacement}: averaged over its position on the patch (every texel's power summed,
 * sum_m G^2 |T_m|^2), or fixed at the DFT's origin (complex amplitudes summed, |sum_m G T_m|^2, the thesis').
 */
public final class CoherenceWindow {
    /** 4 sigma_s = 65 um (004, "Spatial Coherence and Windowing", after Mandel and Wolf pp. 153-154). */
    public static final double COHERENCE_LENGTH_UM = 65.0;

    private final double sigmaSpatialUm;
    private final WindowPlacement placement;

    /** Averaged over its position. */
    public CoherenceWindow(double sigmaSpatialUm) {
        this(sigmaSpatialUm, WindowPlacement.AVERAGED);
    }

    public CoherenceWindow(double sigmaSpatialUm, WindowPlacement placement) {
        if (!(sigmaSpatialUm > 0) || !Double.isFinite(sigmaSpatialUm)) {
            throw new IllegalArgumentException("sigma_s must be a positive number of micrometres, got " + sigmaSpatialUm);
        }
        if (placement == null) {
            throw new NullPointerException("the window's placement is required");
        }
        this.sigmaSpatialUm = sigmaSpatialUm;
        this.placement = placement;
    }

    /** The thesis' window, sigma_s = 65 um / 4, averaged over its position. */
    public static CoherenceWindow thesis() {
        return new CoherenceWindow(COHERENCE_LENGTH_UM / 4.0);
    }

    /** This window placed as {@code p}. */
    public CoherenceWindow placed(WindowPlacement p) {
        return new CoherenceWindow(sigmaSpatialUm, p);
    }

    public double sigmaSpatialUm() {
        return sigmaSpatialUm;
    }

    public WindowPlacement placement() {
        return placement;
    }

    /** Whether texels add as powers (the window averaged over its position) rather than as amplitudes. */
    public boolean averaged() {
        return placement == WindowPlacement.AVERAGED;
    }

    /** sigma_f = 1 / (2 pi sigma_s), in cycles per micrometre. */
    public double sigmaFrequencyPerUm() {
        return 1.0 / (2.0 * Math.PI * sigmaSpatialUm);
    }

    /** sigma_f in DFT texels of a patch whose extent along this axis is {@code extentUm}. */
    public double sigmaTexels(double extentUm) {
        return sigmaFrequencyPerUm() * extentUm;
    }

    /**
     * The projected solid angle of a flat mirror's lobe at {@code lambdaNm}: the window on the complex spectrum makes
     * |P|^2 = exp(-f^2 / sigma_f^2) at spatial frequency f = (u, v) / lambda, and (u, v) are direction cosines, so
     * integral |P|^2 du dv = pi (lambda sigma_f)^2 (du dv = cos theta_r d omega_r at fixed omega_i).
     */
    public double mirrorLobeProjectedSolidAngleSr(double lambdaNm) {
        double s = lambdaNm * 1e-3 * sigmaFrequencyPerUm();
        return Math.PI * s * s;
    }

    /** exp(-d^2 / (2 sigma^2)) for an offset of d texels. */
    public static double weight(double offsetTexels, double sigmaTexels) {
        double q = offsetTexels / sigmaTexels;
        return Math.exp(-0.5 * q * q);
    }

    /** The offset in sigmas beyond which the weight drops below {@code cutoff}: sqrt(2 ln(1 / cutoff)). */
    public static double sigmasForCutoff(double cutoff) {
        return Math.sqrt(2.0 * Math.log(1.0 / cutoff));
    }
}
