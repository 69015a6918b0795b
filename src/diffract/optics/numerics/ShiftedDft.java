package diffract.optics.numerics;

import org.jtransforms.fft.DoubleFFT_1D;
import org.jtransforms.fft.DoubleFFT_2D;

/**
 * fftshift(ifft2(f)) with JTransforms, in double: the one transform of the thesis (Algorithm 1).
 *
 * <p>{@code complexInverse(a, true)} scales by 1 / (rows * cols) exactly like Matlab's {@code ifft2} and uses its
 * sign, x[p] = (1/N) sum_k X[k] exp(+2 pi i k p / N): the thesis (and Stam, eq. 2.11) write the Fourier transform
 * with exp(+i k (u x + v y)), which is an inverse DFT. JTransforms has no fftshift; ours moves frequency index 0
 * to floor(n / 2) in each axis (003 eq. 1.5), so texel (r, c) holds frequency index (c - cols/2, r - rows/2).
 */
public final class ShiftedDft {
    private ShiftedDft() {
    }

    /** fftshift(ifft2(f)) of a row-major complex field, interleaved Re/Im; the input is not modified. */
    public static double[] inverse(double[] interleaved, int rows, int cols) {
        double[] a = interleaved.clone();
        new Plan(rows, cols).inverseInPlace(a);
        return fftshift(a, rows, cols);
    }

    /**
     * A reusable ifft2 of one size. JTransforms' 2-D transform needs at least 2 x 2; a single row or column is the
     * 1-D transform of the same data (row-major, interleaved), and a single sample is its own transform.
     */
    public static final class Plan {
        private final DoubleFFT_2D plan2d;
        private final DoubleFFT_1D plan1d;

        public Plan(int rows, int cols) {
            if (rows > 1 && cols > 1) {
                plan2d = new DoubleFFT_2D(rows, cols);
                plan1d = null;
            } else {
                plan2d = null;
                plan1d = rows * cols > 1 ? new DoubleFFT_1D((long) rows * cols) : null;
            }
        }

        /** ifft2 in place, scaled by 1/(rows cols) like Matlab's. */
        public void inverseInPlace(double[] interleaved) {
            if (plan2d != null) {
                plan2d.complexInverse(interleaved, true);
            } else if (plan1d != null) {
                plan1d.complexInverse(interleaved, true);
            }
        }
    }

    /** Output (r, c) receives input frequency ((r - rows/2) mod rows, (c - cols/2) mod cols). */
    public static double[] fftshift(double[] a, int rows, int cols) {
        double[] out = new double[a.length];
        int cr = rows / 2;
        int cc = cols / 2;
        for (int r = 0; r < rows; r++) {
            int sr = Math.floorMod(r - cr, rows);
            for (int c = 0; c < cols; c++) {
                int sc = Math.floorMod(c - cc, cols);
                int dst = 2 * (r * cols + c);
                int src = 2 * (sr * cols + sc);
                out[dst] = a[src];
                out[dst + 1] = a[src + 1];
            }
        }
        return out;
    }
}
