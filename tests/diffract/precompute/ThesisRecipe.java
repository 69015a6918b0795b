package diffract.precompute;

import diffract.optics.patches.HeightField;
import diffract.optics.NaiveDft;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The thesis script's recipe restated literally for the tests, without any of ThesisLayout's algebra: rot90 on
 * arrays, (i h)^t, a naive ifft2 at every frequency, fftshift by index moves, rot90 back. Everything in double.
 */
final class ThesisRecipe {
    private ThesisRecipe() {
    }

    /** Octave's rot90(A, k) for k = 1 (counter-clockwise) or -1 (clockwise); A is rows x cols, row-major. */
    static double[] rot90(double[] a, int rows, int cols, int k) {
        double[] out = new double[a.length];
        // the result is cols x rows
        for (int i = 0; i < cols; i++) {
            for (int j = 0; j < rows; j++) {
                int src = k == 1 ? (j * cols + (cols - 1 - i)) : ((rows - 1 - j) * cols + i);
                out[i * rows + j] = a[src];
            }
        }
        return out;
    }

    /** Octave's fftshift along both axes: element k moves to (k + floor(n/2)) mod n. */
    static double[] fftshift(double[] a, int rows, int cols) {
        double[] out = new double[a.length];
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                out[((r + rows / 2) % rows) * cols + (c + cols / 2) % cols] = a[r * cols + c];
            }
        }
        return out;
    }

    /** Term t in the script's image orientation: {re, im}, each rows x cols row-major, row 0 at the top. */
    static double[][] scriptImage(HeightField h, int t) {
        int rows = h.rows();
        int cols = h.cols();
        double[] heights = h.heightsUm();
        double[] g = rot90(heights, rows, cols, -1); // cols x rows
        HeightField rotated = HeightField.of(cols, rows, g, 1.0);
        double[] power = NaiveDft.powerIH(rotated, t);
        double[] re = new double[rows * cols];
        double[] im = new double[rows * cols];
        for (int k1 = 0; k1 < cols; k1++) {
            for (int k2 = 0; k2 < rows; k2++) {
                double[] v = NaiveDft.inverseAt(power, cols, rows, k2, k1); // mx along g's columns, my along its rows
                re[k1 * rows + k2] = v[0];
                im[k1 * rows + k2] = v[1];
            }
        }
        double[] reShifted = fftshift(re, cols, rows);
        double[] imShifted = fftshift(im, cols, rows);
        return new double[][] {rot90(reShifted, cols, rows, 1), rot90(imShifted, cols, rows, 1)};
    }

    /** A term file as written: {width, height} and per file texel the (Re, Im, B) floats. */
    record TermFile(int width, int height, float[] values) {
        /** Channel 0 (Re), 1 (Im) or 2 of the script's image row {@code row} (0 = top), column {@code col}. */
        float at(int row, int col, int channel) {
            int fileRow = height - 1 - row;
            return values[3 * (fileRow * width + col) + channel];
        }

        static TermFile read(Path file) throws IOException {
            ByteBuffer in = ByteBuffer.wrap(Files.readAllBytes(file)).order(ByteOrder.BIG_ENDIAN);
            int w = in.getInt();
            int h = in.getInt();
            float[] v = new float[3 * w * h];
            in.asFloatBuffer().get(v);
            return new TermFile(w, h, v);
        }
    }
}
