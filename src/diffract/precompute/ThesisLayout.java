package diffract.precompute;

/**
 * Where the thesis' Octave script puts a frequency, and with which phase, compared with our own fftshifted layout
 * ({@link diffract.optics.spectra.TaylorTerms}: texel (r, c) holds frequency index (m_x, m_y) = (c - floor(C/2),
 * r - floor(R/2)) of {@code ifft2((i h)^n)}, for an R x C field h).
 *
 * <p>The script rotates the R x C height field by -90 degrees before the transform and each output
 * channel by +90 degrees after it, in Octave's sense: {@code rot90(A, -1)} (clockwise) and {@code rot90(A, 1)}
 * (counter-clockwise). With 0-based indices:
 * <pre>
 *   g = rot90(h, -1)           C x R   g(a, b) = h(R-1-b, a)
 *   G = fftshift(ifft2(g^n))   C x R
 *   O = rot90(G, 1)            R x C   O(i, j) = G(j, R-1-i)
 * </pre>
 * The clockwise turn reverses the row axis of h about its first sample, not about its centre:
 * h(R-1-b) = h(-(b+1)) is the reversed field moved by one sample. Reversal maps frequency m_y to -m_y, the move
 * by one sample multiplies by a phase, and the turn back reverses the index of the (fftshifted) output along the
 * same axis. Working it through ifft2's sum gives, for every texel of O (the image the script writes):
 * <pre>
 *   O(i, j) = exp(+2 pi i m_y / R) * H(m_x, m_y),  m_x = j - floor(C/2),  m_y = i - floor(R/2) + delta(R)
 *   delta(R) = 1 for even R, 0 for odd R
 * </pre>
 * where H(m_x, m_y) is our unrotated term. So the columns are untouched; along the rows the output index is
 * reversed twice (no net flip), but fftshift's centre floor(R/2) is not symmetric for even R: reversing slot
 * i -> R-1-i about an even-length axis maps centre slot R/2 to R/2-1, one slot off. That is why rot90 of an
 * fftshift is not the fftshift of a rot90 for even sizes, and why thesis row i holds our row i+1 (mod R) then.
 * For odd R the centre (R-1)/2 is its own mirror image and the rows line up. Frequency m_y = R/2 of an even R
 * (thesis row R-1) is the alias of our row 0 (m_y = -R/2), with the same phase factor exp(+-i pi) = -1.
 *
 * <p>The phase exp(+2 pi i m_y / R) is the one-sample move: the script's terms are those of the field moved
 * by one row. It changes Re and Im separately (hence the stored extrema), not |H|; we apply it when writing
 * (to match the script bit for bit up to rounding) and undo it when reading, so that terms read from a thesis
 * folder equal our native terms texel by texel.
 *
 * <p>Files store O "from the bottom row to the top": file row k is O's row R-1-k.
 */
public final class ThesisLayout {
    private ThesisLayout() {
    }

    /** delta(R) above: 1 when fftshift's centre moves under the row reversal (even R). */
    public static int rowOffset(int rows) {
        return rows % 2 == 0 ? 1 : 0;
    }

    /** Our texel row that holds the frequency of the script's image row {@code thesisRow} (0 = top). */
    public static int nativeRowOfThesisRow(int thesisRow, int rows) {
        return Math.floorMod(thesisRow + rowOffset(rows), rows);
    }

    /** The script's image row (0 = top) of our texel row {@code nativeRow}. */
    public static int thesisRowOfNativeRow(int nativeRow, int rows) {
        return Math.floorMod(nativeRow - rowOffset(rows), rows);
    }

    /** The frequency index m_y the script's image row {@code thesisRow} holds (in -R/2 .. R/2). */
    public static int frequencyOfThesisRow(int thesisRow, int rows) {
        return thesisRow - rows / 2 + rowOffset(rows);
    }

    /** The script's image row written as file row {@code fileRow} (the file starts with the bottom row). */
    public static int thesisRowOfFileRow(int fileRow, int rows) {
        return rows - 1 - fileRow;
    }

    /**
     * Thesis image (R x C, row 0 at the top, interleaved Re/Im, double) from one of our terms, phase applied.
     *
     * @param nativeTerm interleaved Re/Im, our layout
     */
    public static double[] toThesis(float[] nativeTerm, int rows, int cols) {
        double[] out = new double[2 * rows * cols];
        rotateRows(rows, cols, 1, k -> nativeTerm[k], false, (d, re, im) -> {
            out[d] = re;
            out[d + 1] = im;
        });
        return out;
    }

    /**
     * One of our terms (float32, our layout) from a thesis image (R x C, row 0 at the top, interleaved Re/Im,
     * double), the phase undone in double and the result rounded once.
     */
    public static float[] toNative(double[] thesisImage, int rows, int cols) {
        float[] out = new float[2 * rows * cols];
        rotateRows(rows, cols, -1, k -> thesisImage[k], true, (d, re, im) -> {
            out[d] = (float) re;
            out[d + 1] = (float) im;
        });
        return out;
    }

    /** Receives one complex value at an interleaved index. */
    private interface ComplexSink {
        void put(int index, double re, double im);
    }

    /**
     * Each thesis row i and its native row r: the row's complex values times exp(sign i 2 pi f_i / R), read from
     * {@code in} (interleaved Re/Im; in thesis rows when {@code inThesisRows}, else native rows) and written to the
     * other layout.
     */
    private static void rotateRows(int rows, int cols, int sign, java.util.function.IntToDoubleFunction in,
                                   boolean inThesisRows, ComplexSink out) {
        for (int i = 0; i < rows; i++) {
            int r = nativeRowOfThesisRow(i, rows);
            double angle = sign * 2 * Math.PI * frequencyOfThesisRow(i, rows) / rows;
            double cos = Math.cos(angle);
            double sin = Math.sin(angle);
            int from = inThesisRows ? i : r;
            int to = inThesisRows ? r : i;
            for (int j = 0; j < cols; j++) {
                int src = 2 * (from * cols + j);
                double re = in.applyAsDouble(src);
                double im = in.applyAsDouble(src + 1);
                out.put(2 * (to * cols + j), re * cos - im * sin, re * sin + im * cos);
            }
        }
    }
}
