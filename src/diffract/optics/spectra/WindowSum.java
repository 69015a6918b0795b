package diffract.optics.spectra;

import diffract.optics.windows.WindowPlacement;

/**
 * One lookup's sum over the coherence window's texels, given each texel's window weight w_m and Taylor sum
 * T_m = sum_n c_n DFT_n(m) (003 Algorithm 3). With the window fixed on the patch the texels add as complex
 * amplitudes, P = sum_m w_m T_m, squared after; averaged over the window's position every pair of distinct texels
 * averages to zero and the texels add as powers, sum_m w_m^2 |T_m|^2 ({@link WindowPlacement}).
 */
final class WindowSum {
    private final boolean powers;
    private double re;
    private double im;

    /** @param powers whether the texels add as powers (the averaged window) or as amplitudes (a fixed one) */
    WindowSum(boolean powers) {
        this.powers = powers;
    }

    /** Adds texel m: its window weight and its Taylor sum (Re, Im). */
    void add(double weight, double sumRe, double sumIm) {
        if (powers) {
            re += weight * weight * (sumRe * sumRe + sumIm * sumIm);
        } else {
            re += weight * sumRe;
            im += weight * sumIm;
        }
    }

    /** {power, 0} for powers, {Re P, Im P} for amplitudes. */
    double[] result() {
        return new double[] {re, im};
    }
}
