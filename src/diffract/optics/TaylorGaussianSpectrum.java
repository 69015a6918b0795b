package diffract.optics;

/**
 * The thesis' Taylor-series spectrum with a Gaussian window, exactly as 003 Algorithm 3 computes it (and as the
 * FLSS and NMM shaders must): P = sum_{texels m in window} G(s - m) sum_{n=0}^{N} (k w)^n / n! DFT_n(m), then |P|^2.
 *
 * <p>Lookup (003 eq. 1.8): s = (u L_x / lambda, v L_y / lambda) in texels from the centre texel, L = N dH the
 * patch extent. The window is the (2R+1)^2 texels around the nearest texel, round(s); the thesis anchored at
 * floor(s) (eq. 1.9), which shifts a 3 x 3 window by up to a texel away from s. Texels outside the stored band
 * contribute nothing: the band-limited patch has no energy beyond Nyquist (the thesis clamped, which repeats
 * edge texels). Reads the float32 terms, sums in double: the GPU does the same in float32.
 */
public final class TaylorGaussianSpectrum implements PatchSpectrum {
    private final TaylorTerms terms;
    private final int highestOrder;
    private final int windowRadius;
    private final double sigmaTexelsX;
    private final double sigmaTexelsY;

    /**
     * @param highestOrder  N, the last Taylor order used (at most terms.highestOrder())
     * @param windowRadius  R: the window covers (2R + 1)^2 texels; the thesis used R = 1
     */
    public TaylorGaussianSpectrum(TaylorTerms terms, int highestOrder, int windowRadius, CoherenceWindow window) {
        if (highestOrder < 0 || highestOrder > terms.highestOrder()) {
            throw new IllegalArgumentException("Taylor order " + highestOrder + " requested, the terms hold 0.."
                    + terms.highestOrder());
        }
        if (windowRadius < 0) {
            throw new IllegalArgumentException("window radius must be >= 0, got " + windowRadius);
        }
        this.terms = terms;
        this.highestOrder = highestOrder;
        this.windowRadius = windowRadius;
        this.sigmaTexelsX = window.sigmaTexels(extentXUm());
        this.sigmaTexelsY = window.sigmaTexels(extentYUm());
    }

    @Override
    public double extentXUm() {
        return terms.cols() * terms.pixelSizeXUm();
    }

    @Override
    public double extentYUm() {
        return terms.rows() * terms.pixelSizeYUm();
    }

    @Override
    public double power(double u, double v, double w, double lambdaUm) {
        double sx = u * extentXUm() / lambdaUm; // eq. 1.8
        double sy = v * extentYUm() / lambdaUm;
        double[] coefficients = TaylorCoefficients.of(2.0 * Math.PI / lambdaUm * w, highestOrder);
        int anchorX = (int) Math.floor(sx + 0.5);
        int anchorY = (int) Math.floor(sy + 0.5);
        int cols = terms.cols();
        int rows = terms.rows();
        double re = 0;
        double im = 0;
        for (int j = anchorY - windowRadius; j <= anchorY + windowRadius; j++) {
            int row = j + terms.centreRow();
            if (row < 0 || row >= rows) {
                continue;
            }
            double weightY = CoherenceWindow.weight(j - sy, sigmaTexelsY);
            for (int i = anchorX - windowRadius; i <= anchorX + windowRadius; i++) {
                int col = i + terms.centreCol();
                if (col < 0 || col >= cols) {
                    continue;
                }
                double weight = weightY * CoherenceWindow.weight(i - sx, sigmaTexelsX);
                int index = 2 * (row * cols + col);
                double sumRe = 0;
                double sumIm = 0;
                for (int n = 0; n <= highestOrder; n++) {
                    float[] term = terms.termUnsafe(n);
                    sumRe += coefficients[n] * term[index];
                    sumIm += coefficients[n] * term[index + 1];
                }
                re += weight * sumRe;
                im += weight * sumIm;
            }
        }
        return re * re + im * im;
    }
}
