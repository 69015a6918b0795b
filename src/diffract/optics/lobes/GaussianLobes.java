package diffract.optics.lobes;

import diffract.optics.spectra.TexelCoefficients;
import diffract.optics.windows.WindowPlacement;

import java.util.ArrayList;
import java.util.List;

/**
 * The windowed power spectrum as a finite sum of Gaussian lobes (docs/design/filtering.md, section 1). With the Gaussian
 * window G(d) = exp(-sum_i d_i^2 / (2 sigma_i^2)) the product of two texels' windows is a Gaussian about their
 * midpoint c = (m + m') / 2,
 * G(s - m) G(s - m') = exp(-|m - m'|^2_sigma / 4) exp(-|s - c|^2_sigma), |d|^2_sigma = sum_i d_i^2 / sigma_i^2, so
 * exactly
 * <pre>
 *   |P(s)|^2 = sum_c W_c(a) exp(-|s - c|^2_sigma),
 *   W_c(a) = sum_{m + m' = 2c} exp(-|m - m'|^2_sigma / 4) Re(T_m(a) conj(T_m'(a))).
 * </pre>
 * Every lobe has the same shape, a Gaussian of variance sigma_i^2 / 2 per axis centred on a whole or half texel.
 * In (u, v) (s = (u L_x, v L_y) / lambda) lobe c sits at mu_c = lambda (c_x / L_x, c_y / L_y) with isotropic
 * variance (lambda sigma_f)^2 / 2, independent of the patch size.
 *
 * <p>Pairs are kept while their weight exp(-|d|^2_sigma / 4) is at least {@code pairThreshold} (relative to the
 * product of their coefficients): the pair radius per axis is K_i = floor(2 sigma_i sqrt(ln(1 / threshold))). For
 * sigma_f &lt;&lt; 1 texel (65 um coherence and patches below about 30 um: sigma &lt; 0.3) only m = m' survives a
 * threshold of 1e-4 and each lobe is |T_m|^2 on its own texel.
 *
 * <p>With the window averaged over its position ({@link WindowPlacement#AVERAGED}) every pair's phase averages to
 * zero and exactly the whole-texel lobes remain, at any sigma: the threshold {@link #WHOLE_TEXELS}.
 */
public final class GaussianLobes {
    /** The pair threshold that keeps only m = m': the window averaged over its position. */
    public static final double WHOLE_TEXELS = 1.0;

    private final TexelCoefficients coefficients;
    private final double sigmaX;
    private final double sigmaY;
    private final double pairThreshold;
    private final int pairRadiusX;
    private final int pairRadiusY;

    /**
     * @param sigmaX,sigmaY sigma_f in texels per axis
     * @param pairThreshold the smallest pair weight kept, in (0, 1]: 1 keeps only m = m'
     */
    public GaussianLobes(TexelCoefficients coefficients, double sigmaX, double sigmaY, double pairThreshold) {
        if (!(pairThreshold > 0 && pairThreshold <= 1)) {
            throw new IllegalArgumentException("the pair threshold must be in (0, 1], got " + pairThreshold);
        }
        this.coefficients = coefficients;
        this.sigmaX = sigmaX;
        this.sigmaY = sigmaY;
        this.pairThreshold = pairThreshold;
        this.pairRadiusX = pairRadius(sigmaX, pairThreshold);
        this.pairRadiusY = pairRadius(sigmaY, pairThreshold);
    }

    /** K = floor(2 sigma sqrt(ln(1 / threshold))): the largest |m - m'| along one axis whose weight reaches it. */
    public static int pairRadius(double sigmaTexels, double pairThreshold) {
        return (int) Math.floor(2.0 * sigmaTexels * Math.sqrt(Math.log(1.0 / pairThreshold)) + 1e-12);
    }

    public int pairRadiusX() {
        return pairRadiusX;
    }

    public int pairRadiusY() {
        return pairRadiusY;
    }

    /** Whether lobes sit on half texels too (some pair m != m' is kept). */
    public boolean hasPairs() {
        return pairRadiusX > 0 || pairRadiusY > 0;
    }

    double sigmaX() {
        return sigmaX;
    }

    double sigmaY() {
        return sigmaY;
    }

    TexelCoefficients coefficients() {
        return coefficients;
    }

    /**
     * The lobe centred at c = (twiceCx / 2, twiceCy / 2), or null when no kept pair of stored texels sums to it.
     * Without pairs only whole-texel centres (even arguments) have lobes.
     */
    public Lobe lobe(int twiceCx, int twiceCy) {
        List<TexelCoefficients.Texel> first = new ArrayList<>(1);
        List<TexelCoefficients.Texel> second = new ArrayList<>(1);
        List<Double> weights = new ArrayList<>(1);
        int startX = Math.floorMod(twiceCx, 2);
        int startY = Math.floorMod(twiceCy, 2);
        for (int dx = startX; dx <= pairRadiusX; dx += 2) {
            for (int dy = -pairRadiusY + Math.floorMod(pairRadiusY - startY, 2); dy <= pairRadiusY; dy += 2) {
                // d and -d give conjugate products with the same real part: keep d with dx > 0, or dx = 0 and dy >= 0
                if (dx == 0 && dy < 0) {
                    continue;
                }
                double q = dx * dx / (4 * sigmaX * sigmaX) + dy * dy / (4 * sigmaY * sigmaY);
                double g = Math.exp(-q);
                if (g < pairThreshold) {
                    continue;
                }
                TexelCoefficients.Texel m = coefficients.texel((twiceCx + dx) / 2, (twiceCy + dy) / 2);
                TexelCoefficients.Texel mPrime = coefficients.texel((twiceCx - dx) / 2, (twiceCy - dy) / 2);
                if (m == null || mPrime == null) {
                    continue;
                }
                boolean diagonal = dx == 0 && dy == 0;
                first.add(m);
                second.add(diagonal ? null : mPrime);
                weights.add(diagonal ? g : 2 * g);
            }
        }
        if (weights.isEmpty()) {
            return null;
        }
        return new Lobe(0.5 * twiceCx, 0.5 * twiceCy, first, second, weights);
    }

    /** One lobe: its centre c in texels and its weight W_c(a). Not thread-safe (its texels cache their terms). */
    public static final class Lobe {
        private final double cx;
        private final double cy;
        private final TexelCoefficients.Texel[] first;
        private final TexelCoefficients.Texel[] second;
        private final double[] weights;
        private final double[] a = new double[4];
        private final double[] b = new double[4];

        Lobe(double cx, double cy, List<TexelCoefficients.Texel> first, List<TexelCoefficients.Texel> second,
             List<Double> weights) {
            this.cx = cx;
            this.cy = cy;
            this.first = first.toArray(new TexelCoefficients.Texel[0]);
            this.second = second.toArray(new TexelCoefficients.Texel[0]);
            this.weights = weights.stream().mapToDouble(Double::doubleValue).toArray();
        }

        double cx() {
            return cx;
        }

        double cy() {
            return cy;
        }

        /** W_c(a) = sum of the kept pairs' g Re(T_m conj(T_m')) (2 g for m != m', counting d and -d). */
        public double weight(double phase) {
            double sum = 0;
            for (int k = 0; k < weights.length; k++) {
                first[k].at(phase, a);
                if (second[k] == null) {
                    sum += weights[k] * (a[0] * a[0] + a[1] * a[1]);
                } else {
                    second[k].at(phase, b);
                    sum += weights[k] * (a[0] * b[0] + a[1] * b[1]);
                }
            }
            return sum;
        }

        /** W_c(a) and dW_c/da into out[0], out[1]. */
        void weightWithDerivative(double phase, double[] out) {
            double sum = 0;
            double derivative = 0;
            for (int k = 0; k < weights.length; k++) {
                first[k].withDerivative(phase, a);
                if (second[k] == null) {
                    sum += weights[k] * (a[0] * a[0] + a[1] * a[1]);
                    derivative += weights[k] * 2 * (a[0] * a[2] + a[1] * a[3]);
                } else {
                    second[k].withDerivative(phase, b);
                    sum += weights[k] * (a[0] * b[0] + a[1] * b[1]);
                    derivative += weights[k] * (a[2] * b[0] + a[3] * b[1] + a[0] * b[2] + a[1] * b[3]);
                }
            }
            out[0] = sum;
            out[1] = derivative;
        }
    }

    /**
     * |P(s)|^2 as the lobe sum at texel position s for phase a, over every lobe within 12 sigma of s (for the test
     * of the identity; the renderers integrate lobes instead).
     */
    double power(double sx, double sy, double phase) {
        int reachX = (int) Math.ceil(12 * sigmaX) + 1;
        int reachY = (int) Math.ceil(12 * sigmaY) + 1;
        double sum = 0;
        for (int tx = (int) Math.floor(2 * (sx - reachX)); tx <= Math.ceil(2 * (sx + reachX)); tx++) {
            for (int ty = (int) Math.floor(2 * (sy - reachY)); ty <= Math.ceil(2 * (sy + reachY)); ty++) {
                Lobe lobe = lobe(tx, ty);
                if (lobe == null) {
                    continue;
                }
                double qx = (sx - lobe.cx) / sigmaX;
                double qy = (sy - lobe.cy) / sigmaY;
                sum += lobe.weight(phase) * Math.exp(-(qx * qx + qy * qy));
            }
        }
        return sum;
    }
}
