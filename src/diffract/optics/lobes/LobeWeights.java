package diffract.optics.lobes;

import diffract.optics.patches.Direction;
import diffract.optics.illumination.GainFactor;
import diffract.optics.settings.GainModel;
import diffract.optics.spectra.ExactSpectrum;

/**
 * What the filtered drawing of orders ({@code FilteredReference}) weighs each Gaussian lobe with, and
 * the direction factor in front of them: Stam's scalar model ({@link #scalar}: |T_m(k w)|^2 of the exact coefficients,
 * times the gain factor C and the shadowing S at each direction), or the orders' efficiencies from Maxwell's equations
 * ({@code RigorousOrders}: eta_m(lambda), times cos theta_i / R_0). The lobes' places and shapes, the
 * pixel's box, the light and the wavelength integral are the drawing's, the same for both: a map of one against the
 * other measures the physics alone (docs/design/rigorous.md).
 */
public interface LobeWeights {
    /** Whether lobes also sit on half texels (pairs of texels: the window fixed at the DFT's origin). */
    boolean hasPairs();

    /** The lobe centred at (twiceCx / 2, twiceCy / 2) texels, or null where none is. */
    Lobe lobe(int twiceCx, int twiceCy);

    /**
     * An upper bound on the weight of whole texel (mx, my)'s lobe for wavelengths in [fromNm, toNm] and w within
     * {@code dw} of {@code w}.
     */
    double bound(int mx, int my, double fromNm, double toNm, double w, double dw);

    /** How much the weight can grow across a box whose w spans +-dw at wave number up to kHi: a factor &gt;= 1. */
    double slope(double kHi, double dw);

    /** The factor in front of every lobe at omega_r = (x, y) for light from omega_i: 0 below either horizon. */
    double gain(Direction wi, Direction wr);

    /** One lobe's weight; thread-safe or made per thread, as its maker says. */
    interface Lobe {
        /** W at wavelength {@code lambdaUm} and w. */
        double weight(double lambdaUm, double w);

        /** W and dW / dw into out[0], out[1]. */
        void weightWithDerivative(double lambdaUm, double w, double[] out);
    }

    /**
     * Stam's scalar model of the exact reference: W_c(k w) of {@link GaussianLobes} over {@code exact}'s coefficients
     * (whole texels, or pairs down to {@code pairThreshold}), bounded by {@link ExactSpectrum#texelBound}, and the gain
     * factor of {@code gain} (with its shadowing, where it has one).
     */
    static LobeWeights scalar(ExactSpectrum exact, double pairThreshold, double refractiveIndex, GainModel gain) {
        GaussianLobes lobes = new GaussianLobes(exact, exact.sigmaTexelsX(), exact.sigmaTexelsY(), pairThreshold);
        double maxAbsHeightUm = exact.maxAbsHeightUm();
        return new LobeWeights() {
            @Override
            public boolean hasPairs() {
                return lobes.hasPairs();
            }

            @Override
            public Lobe lobe(int twiceCx, int twiceCy) {
                GaussianLobes.Lobe lobe = lobes.lobe(twiceCx, twiceCy);
                if (lobe == null) {
                    return null;
                }
                return new Lobe() {
                    @Override
                    public double weight(double lambdaUm, double w) {
                        return lobe.weight(2 * Math.PI / lambdaUm * w);
                    }

                    @Override
                    public void weightWithDerivative(double lambdaUm, double w, double[] out) {
                        double k = 2 * Math.PI / lambdaUm;
                        lobe.weightWithDerivative(k * w, out);
                        out[1] = k * out[1]; // dW/dw = k dW/da
                    }
                };
            }

            @Override
            public double bound(int mx, int my, double fromNm, double toNm, double w, double dw) {
                double kLo = 2 * Math.PI / (toNm * 1e-3);
                double kHi = 2 * Math.PI / (fromNm * 1e-3);
                double a1 = kLo * (w - dw);
                double a2 = kHi * (w - dw);
                double a3 = kLo * (w + dw);
                double a4 = kHi * (w + dw);
                double aLo = Math.min(Math.min(a1, a2), Math.min(a3, a4));
                double aHi = Math.max(Math.max(a1, a2), Math.max(a3, a4));
                return exact.texelBound(mx, my, aLo, aHi);
            }

            @Override
            public double slope(double kHi, double dw) {
                return 1 + 2 * kHi * dw * maxAbsHeightUm;
            }

            @Override
            public double gain(Direction wi, Direction wr) {
                return GainFactor.gainTimesShadowing(wi, wr, refractiveIndex, gain);
            }
        };
    }
}
