package diffract.optics;

import java.util.function.DoubleUnaryOperator;

/**
 * The inner loops of 003 Algorithm 3, shared by every Taylor-term variant: the complex sum
 * P = sum_{texels m in the (2R+1)^2 window around round(s)} weightX(s_x - m_x) weightY(s_y - m_y)
 * sum_{n=0}^{N} c_n DFT_n(m), with c_n = (k w)^n / n!, over the float32 terms. Texels outside the stored band
 * contribute nothing. The variants differ only in the window's weight (Gaussian for FLSS/NMM, sinc for PQ).
 */
final class WindowedTaylorSum {
    private final TaylorTerms terms;
    private final int highestOrder;
    private final int windowRadius;
    private final DoubleUnaryOperator weightX;
    private final DoubleUnaryOperator weightY;

    WindowedTaylorSum(TaylorTerms terms, int highestOrder, int windowRadius, DoubleUnaryOperator weightX,
                      DoubleUnaryOperator weightY) {
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
        this.weightX = weightX;
        this.weightY = weightY;
    }

    double extentXUm() {
        return terms.cols() * terms.pixelSizeXUm();
    }

    double extentYUm() {
        return terms.rows() * terms.pixelSizeYUm();
    }

    /**
     * |P|^2 at the lookup s = (sx, sy) texels from the centre (eq. 1.8) for the phase factor a = k w.
     */
    double power(double sx, double sy, double a) {
        double[] coefficients = TaylorCoefficients.of(a, highestOrder);
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
            double wy = weightY.applyAsDouble(j - sy);
            for (int i = anchorX - windowRadius; i <= anchorX + windowRadius; i++) {
                int col = i + terms.centreCol();
                if (col < 0 || col >= cols) {
                    continue;
                }
                double weight = wy * weightX.applyAsDouble(i - sx);
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
