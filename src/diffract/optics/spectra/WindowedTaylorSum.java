package diffract.optics.spectra;

import diffract.optics.windows.LocalWindow;
import diffract.optics.windows.WindowPlacement;
import diffract.optics.windows.WindowRadii;

import java.util.function.DoubleUnaryOperator;

/**
 * The inner loops of 003 Algorithm 3, shared by every Taylor-term variant: the complex sum
 * P = sum_{texels m in the (2R+1)^2 window around round(s)} weightX(s_x - m_x) weightY(s_y - m_y)
 * sum_{n=0}^{N} c_n DFT_n(m), with c_n = (k w)^n / n!, over the float32 terms. Texels outside the stored band
 * contribute nothing. The variants differ only in the window's weight (Gaussian for FLSS/NMM, sinc for PQ).
 *
 * <p>With the window averaged over its position ({@link WindowPlacement#AVERAGED}) the texels add as powers,
 * sum_m weightX^2 weightY^2 |sum_n c_n DFT_n(m)|^2, over the same texels; fixed, as complex amplitudes, squared after;
 * under one surface point ({@link #localPower}), in pairs damped by the pixel's footprint. A LOCAL window read by
 * {@link #power} sits at x0 = 0 with a point footprint: the fixed window.
 *
 * <p>Two settings do less work: the window's half-widths per axis ({@link WindowRadii}, e.g. from
 * sigma_f), and a tolerance at which the Taylor loop stops early ({@link TaylorBound#stopOrder} with this lookup's
 * x = |k w| max|h|); tolerance 0 keeps the fixed N and the very same arithmetic.
 */
final class WindowedTaylorSum {
    private final TaylorTerms terms;
    private final int highestOrder;
    private final WindowRadii radii;
    private final double taylorTolerance;
    private final DoubleUnaryOperator weightX;
    private final DoubleUnaryOperator weightY;
    private final boolean averaged;

    WindowedTaylorSum(TaylorTerms terms, int highestOrder, WindowRadii radii, double taylorTolerance,
                      DoubleUnaryOperator weightX, DoubleUnaryOperator weightY, WindowPlacement placement) {
        if (highestOrder < 0 || highestOrder > terms.highestOrder()) {
            throw new IllegalArgumentException("Taylor order " + highestOrder + " requested, the terms hold 0.."
                    + terms.highestOrder());
        }
        if (!(taylorTolerance >= 0)) {
            throw new IllegalArgumentException("Taylor tolerance must be >= 0, got " + taylorTolerance);
        }
        this.terms = terms;
        this.highestOrder = highestOrder;
        this.radii = radii;
        this.taylorTolerance = taylorTolerance;
        this.weightX = weightX;
        this.weightY = weightY;
        this.averaged = placement == WindowPlacement.AVERAGED;
    }

    double extentXUm() {
        return terms.cols() * terms.pixelSizeXUm();
    }

    double extentYUm() {
        return terms.rows() * terms.pixelSizeYUm();
    }

    /**
     * |P|^2 at the lookup s = (sx, sy) texels from the centre (eq. 1.8) for the phase factor a = k w: averaged over
     * the window's position, or of the one window at the origin.
     */
    double power(double sx, double sy, double a) {
        double[] p = sum(sx, sy, a, averaged);
        return averaged ? p[0] : p[0] * p[0] + p[1] * p[1];
    }

    /** The order this lookup's loop stops at: N, or earlier where the remainder bound meets the tolerance. */
    int stopOrder(double a) {
        return TaylorBound.stopOrder(Math.abs(a) * terms.maxAbsHeightUm(), taylorTolerance, highestOrder);
    }

    /** P = (Re, Im) of the window at the origin, before |.|^2. */
    double[] amplitude(double sx, double sy, double a) {
        return sum(sx, sy, a, false);
    }

    /**
     * |P|^2 of the window under one surface point, averaged over the pixel's footprint ({@link LocalWindow}): the
     * window's complex amplitudes A_m = weight T_m over the same texels, summed in pairs.
     */
    double localPower(double sx, double sy, double a, LocalWindow local) {
        double[] coefficients = TaylorCoefficients.of(a, highestOrder);
        int lastOrder = stopOrder(a);
        int anchorX = (int) Math.floor(sx + 0.5);
        int anchorY = (int) Math.floor(sy + 0.5);
        int capacity = (2 * radii.x() + 1) * (2 * radii.y() + 1);
        double[] re = new double[capacity];
        double[] im = new double[capacity];
        int[] offX = new int[capacity];
        int[] offY = new int[capacity];
        double[] texel = new double[2];
        int count = 0;
        for (int j = -radii.y(); j <= radii.y(); j++) {
            int row = anchorY + j + terms.centreRow();
            if (row < 0 || row >= terms.rows()) {
                continue;
            }
            double wy = weightY.applyAsDouble(anchorY + j - sy);
            for (int i = -radii.x(); i <= radii.x(); i++) {
                int col = anchorX + i + terms.centreCol();
                if (col < 0 || col >= terms.cols()) {
                    continue;
                }
                double weight = wy * weightX.applyAsDouble(anchorX + i - sx);
                taylorSum(2 * (row * terms.cols() + col), coefficients, lastOrder, texel);
                re[count] = weight * texel[0];
                im[count] = weight * texel[1];
                offX[count] = i;
                offY[count] = j;
                count++;
            }
        }
        return local.power(re, im, offX, offY, count, extentXUm(), extentYUm());
    }

    /** The window's sum: of the texels' powers ({power, 0}), or of their complex amplitudes ({Re, Im}). */
    private double[] sum(double sx, double sy, double a, boolean powers) {
        double[] coefficients = TaylorCoefficients.of(a, highestOrder);
        int lastOrder = stopOrder(a);
        int anchorX = (int) Math.floor(sx + 0.5);
        int anchorY = (int) Math.floor(sy + 0.5);
        int cols = terms.cols();
        int rows = terms.rows();
        WindowSum window = new WindowSum(powers);
        double[] texel = new double[2];
        for (int j = anchorY - radii.y(); j <= anchorY + radii.y(); j++) {
            int row = j + terms.centreRow();
            if (row < 0 || row >= rows) {
                continue;
            }
            double wy = weightY.applyAsDouble(j - sy);
            for (int i = anchorX - radii.x(); i <= anchorX + radii.x(); i++) {
                int col = i + terms.centreCol();
                if (col < 0 || col >= cols) {
                    continue;
                }
                taylorSum(2 * (row * cols + col), coefficients, lastOrder, texel);
                window.add(wy * weightX.applyAsDouble(i - sx), texel[0], texel[1]);
            }
        }
        return window.result();
    }

    /** Texel {@code index}'s Taylor sum T_m = sum_{n <= lastOrder} c_n DFT_n(m), as {Re, Im} into {@code out}. */
    private void taylorSum(int index, double[] coefficients, int lastOrder, double[] out) {
        double sumRe = 0;
        double sumIm = 0;
        for (int n = 0; n <= lastOrder; n++) {
            float[] term = terms.termUnsafe(n);
            sumRe += coefficients[n] * term[index];
            sumIm += coefficients[n] * term[index + 1];
        }
        out[0] = sumRe;
        out[1] = sumIm;
    }
}
