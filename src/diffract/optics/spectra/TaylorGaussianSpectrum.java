package diffract.optics.spectra;

import diffract.optics.windows.CoherenceWindow;
import diffract.optics.windows.LocalWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.windows.WindowRadii;

/**
 * The thesis' Taylor-series spectrum with a Gaussian window, exactly as 003 Algorithm 3 computes it (and as the
 * FLSS and NMM shaders must): P = sum_{texels m in window} G(s - m) sum_{n=0}^{N} (k w)^n / n! DFT_n(m), then |P|^2;
 * with the window averaged over its position ({@link WindowPlacement}), sum_m G(s - m)^2 |T_m|^2 over the same texels.
 *
 * <p>Lookup (003 eq. 1.8): s = (u L_x / lambda, v L_y / lambda) in texels from the centre texel, L = N dH the
 * patch extent. The window is the (2R+1)^2 texels around the nearest texel, round(s); the thesis anchored at
 * floor(s) (eq. 1.9), which shifts a 3 x 3 window by up to a texel away from s. Texels outside the stored band
 * contribute nothing: the band-limited patch has no energy beyond Nyquist (the thesis clamped, which repeats
 * edge texels). Reads the float32 terms, sums in double: the GPU does the same in float32.
 */
public final class TaylorGaussianSpectrum extends WindowedTaylorSpectrum {

    /**
     * @param highestOrder  N, the last Taylor order used (at most terms.highestOrder())
     * @param windowRadius  R: the window covers (2R + 1)^2 texels; the thesis used R = 1
     */
    public TaylorGaussianSpectrum(TaylorTerms terms, int highestOrder, int windowRadius, CoherenceWindow window) {
        this(terms, highestOrder, new WindowRadii(windowRadius, windowRadius), 0.0, window);
    }

    /**
     * @param radii           the window's half-widths per axis (fixed, or {@link WindowRadii#automatic})
     * @param taylorTolerance 0 = the fixed N; else each lookup stops at {@link TaylorBound#stopOrder}
     */
    public TaylorGaussianSpectrum(TaylorTerms terms, int highestOrder, WindowRadii radii, double taylorTolerance,
                                  CoherenceWindow window) {
        super(gaussianSum(terms, highestOrder, radii, taylorTolerance, window));
    }

    private static WindowedTaylorSum gaussianSum(TaylorTerms terms, int highestOrder, WindowRadii radii,
                                                 double taylorTolerance, CoherenceWindow window) {
        double sigmaX = window.sigmaTexels(terms.cols() * terms.pixelSizeXUm());
        double sigmaY = window.sigmaTexels(terms.rows() * terms.pixelSizeYUm());
        return new WindowedTaylorSum(terms, highestOrder, radii, taylorTolerance,
                d -> CoherenceWindow.weight(d, sigmaX), d -> CoherenceWindow.weight(d, sigmaY), window.placement());
    }

    /**
     * This spectrum read through the window under one surface point, averaged over the pixel's footprint
     * ({@link LocalWindow}): what FLSS and NMM draw on a mesh with {@link WindowPlacement#LOCAL}, in double precision.
     */
    public PatchSpectrum under(LocalWindow local) {
        TaylorGaussianSpectrum self = this;
        return new PatchSpectrum() {
            @Override
            public double power(double u, double v, double w, double lambdaUm) {
                return sum.localPower(u * extentXUm() / lambdaUm, v * extentYUm() / lambdaUm, // eq. 1.8
                        2.0 * Math.PI / lambdaUm * w, local);
            }

            @Override
            public double extentXUm() {
                return self.extentXUm();
            }

            @Override
            public double extentYUm() {
                return self.extentYUm();
            }
        };
    }

    /** P = (Re, Im) before |.|^2 (tests of the early stop's bound). */
    double[] amplitude(double u, double v, double w, double lambdaUm) {
        return sum.amplitude(u * extentXUm() / lambdaUm, v * extentYUm() / lambdaUm, 2.0 * Math.PI / lambdaUm * w);
    }

    /** The Taylor order the lookup at this (w, lambda) stops at. */
    int stopOrder(double w, double lambdaUm) {
        return sum.stopOrder(2.0 * Math.PI / lambdaUm * w);
    }
}
