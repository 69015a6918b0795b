package diffract.optics.windows;

import diffract.optics.numerics.Covariance2;

/**
 * What a pixel covers of the skin, as the distribution of the coherence window's centre x0 over it, seen through its
 * characteristic function: averaging a texel pair's phase exp(2 pi i (m - m') . x0 / L) over x0 = x0_c + t multiplies
 * it by E[exp(2 pi i k . t)] at the pair's spatial frequency k = (m - m') / L (cycles per um), which is what
 * {@link #pairFactor} returns ({@link LocalWindow}; docs/design/theory.md, "The window under each surface point").
 *
 * <p>Three shapes: a point (every factor 1: the fixed window at x0), a Gaussian of covariance Sigma (factor
 * exp(-2 pi^2 k^T Sigma k), what the shaders use: a pixel's box has the covariance (J_x J_x^T + J_y J_y^T) / 12 of
 * its screen-space derivatives J), and a box of widths (F_x, F_y) (factor sinc(pi k_x F_x) sinc(pi k_y F_y), exactly
 * 0 at every integer pair offset when F = L: the box that covers one period is the averaged window).
 */
public interface SkinFootprint {
    /** E[exp(2 pi i k . t)] over the footprint's offsets t, at k = (kx, ky) cycles per um. */
    double pairFactor(double kxPerUm, double kyPerUm);

    /** A point: the window at x0 itself. */
    SkinFootprint POINT = (kx, ky) -> 1.0;

    /** A Gaussian footprint of covariance {@code covarianceUm2} (um^2): exp(-2 pi^2 k^T Sigma k). */
    static SkinFootprint gaussian(Covariance2 covarianceUm2) {
        return (kx, ky) -> Math.exp(-2.0 * Math.PI * Math.PI
                * (covarianceUm2.xx() * kx * kx + 2.0 * covarianceUm2.xy() * kx * ky + covarianceUm2.yy() * ky * ky));
    }

    /** An isotropic Gaussian footprint of standard deviation {@code sigmaUm} per axis. */
    static SkinFootprint gaussian(double sigmaUm) {
        return gaussian(Covariance2.isotropic(sigmaUm * sigmaUm));
    }

    /**
     * The Gaussian with the covariance of a pixel's box mapped onto the skin by its screen-space derivatives
     * dx0/dx = (jxx, jxy) and dx0/dy = (jyx, jyy), um per pixel: (J_x J_x^T + J_y J_y^T) / 12.
     */
    static Covariance2 pixelCovarianceUm2(double jxx, double jxy, double jyx, double jyy) {
        return new Covariance2((jxx * jxx + jyx * jyx) / 12.0, (jxx * jxy + jyx * jyy) / 12.0,
                (jxy * jxy + jyy * jyy) / 12.0);
    }

    /** A box of widths (F_x, F_y) um along the scan's axes: sinc(pi k_x F_x) sinc(pi k_y F_y). */
    static SkinFootprint box(double widthXUm, double widthYUm) {
        return (kx, ky) -> sinc(Math.PI * kx * widthXUm) * sinc(Math.PI * ky * widthYUm);
    }

    private static double sinc(double x) {
        return Math.abs(x) < 1e-12 ? 1.0 : Math.sin(x) / x;
    }
}
