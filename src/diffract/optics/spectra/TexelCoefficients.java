package diffract.optics.spectra;

/**
 * The coefficients T_m(a) of the windowed sum P(s) = sum_m G(s - m) T_m(a) (004 eq. {@code finalexpression}), one
 * per DFT texel m (frequency index from the centre texel), as functions of the phase factor a = k w: the thesis'
 * series sum_n a^n / n! DFT_n(m) over float32 terms, its phase-centred form, or the exact DFT of exp(i a h). The
 * lobe methods read a texel's terms once and evaluate its coefficient at many wavelengths.
 */
public interface TexelCoefficients {
    /** L_x = cols dH_x, micrometres. */
    double extentXUm();

    /** L_y = rows dH_y, micrometres. */
    double extentYUm();

    /** Rows of the DFT grid (frequency indices -rows/2 .. rows - rows/2 - 1 along y). */
    int rows();

    /** Columns of the DFT grid. */
    int cols();

    /** max |h| of the mean-subtracted patch: T_m(a) is band-limited to it in a. */
    double maxAbsHeightUm();

    /** The texel of frequency index (mx, my), or null when it lies outside the stored band (T_m = 0 there). */
    Texel texel(int mx, int my);

    /** One texel's coefficient. Not thread-safe: each thread asks for its own. */
    interface Texel {
        /** T_m(a) as (Re, Im) into {@code out}; with {@code derivative} also dT_m/da as (dRe, dIm) after them. */
        void sum(double a, double[] out, boolean derivative);

        /** T_m(a) as (Re, Im) into {@code out}. */
        default void at(double a, double[] out) {
            sum(a, out, false);
        }

        /** T_m(a) and dT_m/da as (Re, Im, dRe, dIm) into {@code out}. */
        default void withDerivative(double a, double[] out) {
            sum(a, out, true);
        }
    }

    /** Whether frequency index (mx, my) lies inside a rows x cols DFT whose centre is at (cols / 2, rows / 2). */
    static boolean inBand(int mx, int my, int rows, int cols) {
        int col = mx + cols / 2;
        int row = my + rows / 2;
        return col >= 0 && col < cols && row >= 0 && row < rows;
    }
}
