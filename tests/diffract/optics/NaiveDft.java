package diffract.optics;

import diffract.optics.patches.HeightField;

/** Textbook sums, written for clarity, that the fast code is checked against. */
public final class NaiveDft {
    private NaiveDft() {
    }

    /**
     * (1 / (rows cols)) sum_{r,c} f(r, c) exp(+2 pi i (mx c / cols + my r / rows)) for a complex field given as
     * interleaved Re/Im: Matlab's ifft2 at frequency index (mx, my), evaluated at any real (mx, my).
     */
    public static double[] inverseAt(double[] f, int rows, int cols, double mx, double my) {
        double re = 0;
        double im = 0;
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                double phase = 2 * Math.PI * (mx * c / cols + my * r / rows);
                double cr = Math.cos(phase);
                double ci = Math.sin(phase);
                double fr = f[2 * (r * cols + c)];
                double fi = f[2 * (r * cols + c) + 1];
                re += fr * cr - fi * ci;
                im += fr * ci + fi * cr;
            }
        }
        return new double[] {re / (rows * cols), im / (rows * cols)};
    }

    /** exp(i a h) as an interleaved complex field. */
    public static double[] expIAH(HeightField h, double a) {
        double[] heights = h.heightsUm();
        double[] f = new double[2 * heights.length];
        for (int p = 0; p < heights.length; p++) {
            f[2 * p] = Math.cos(a * heights[p]);
            f[2 * p + 1] = Math.sin(a * heights[p]);
        }
        return f;
    }

    /** (i h)^n as an interleaved complex field. */
    public static double[] powerIH(HeightField h, int n) {
        double[] heights = h.heightsUm();
        double[] f = new double[2 * heights.length];
        for (int p = 0; p < heights.length; p++) {
            double mag = Math.pow(heights[p], n);
            // i^n = 1, i, -1, -i
            switch (n % 4) {
                case 0: f[2 * p] = mag; break;
                case 1: f[2 * p + 1] = mag; break;
                case 2: f[2 * p] = -mag; break;
                default: f[2 * p + 1] = -mag; break;
            }
        }
        return f;
    }

    /** A reproducible random patch, mean subtracted. */
    public static HeightField randomPatch(int rows, int cols, double maxHeightUm, double pixelSizeUm, long seed) {
        java.util.Random random = new java.util.Random(seed);
        double[] h = new double[rows * cols];
        for (int i = 0; i < h.length; i++) {
            h[i] = maxHeightUm * random.nextDouble();
        }
        return HeightField.of(rows, cols, h, pixelSizeUm).meanSubtracted();
    }
}
