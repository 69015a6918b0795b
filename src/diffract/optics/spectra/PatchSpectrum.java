package diffract.optics.spectra;

/**
 * |P(k u, k v)|^2 of a patch, the windowed power spectrum of p = exp(i k w h) at one wavelength (004 eq.
 * {@code cpterm}). Implementations differ in how they evaluate it: exactly, by the Taylor series with a Gaussian
 * window (FLSS, NMM) or with sinc interpolation and periodic replication (PQ).
 */
public interface PatchSpectrum {
    /**
     * @param u        first component of (u, v, w) = -omega_i - omega_r
     * @param v        second component
     * @param w        third component, -(cos theta_i + cos theta_r), in [-2, 0]
     * @param lambdaUm wavelength in micrometres
     */
    double power(double u, double v, double w, double lambdaUm);

    /** Patch extent along x (cols * dH_x), micrometres: the DFT's period, for the lookup of eq. 1.8. */
    double extentXUm();

    /** Patch extent along y (rows * dH_y), micrometres. */
    double extentYUm();
}
