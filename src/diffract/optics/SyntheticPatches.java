package diffract.optics;

import diffract.util.UserInputException;

/**
 * Height fields made by code, for tests and demos: 1-D gratings whose grooves run along y (rows), so their period
 * lies along x (columns) and their diffraction orders along the x axis of a BRDF map.
 */
public final class SyntheticPatches {
    private SyntheticPatches() {
    }

    /**
     * A blazed (sawtooth) grating: height rises linearly from 0 to {@code heightUm} over each period, then drops.
     *
     * @param samplesPerPeriod pixels per period (the pixel size is periodUm / samplesPerPeriod)
     * @param periods          whole periods across the patch, so the DFT's implied replication is seamless
     */
    public static HeightField blazed(double periodUm, double heightUm, int samplesPerPeriod, int periods, int rows) {
        check(periodUm, heightUm, samplesPerPeriod, periods, rows);
        int cols = samplesPerPeriod * periods;
        double[] h = new double[rows * cols];
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                h[r * cols + c] = heightUm * (c % samplesPerPeriod) / (double) samplesPerPeriod;
            }
        }
        return HeightField.of(rows, cols, h, periodUm / samplesPerPeriod);
    }

    /** A sinusoidal grating of peak-to-valley height {@code heightUm}: h = heightUm / 2 * (1 + sin(2 pi x / d)). */
    public static HeightField sinusoid(double periodUm, double heightUm, int samplesPerPeriod, int periods, int rows) {
        check(periodUm, heightUm, samplesPerPeriod, periods, rows);
        int cols = samplesPerPeriod * periods;
        double[] h = new double[rows * cols];
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                h[r * cols + c] = 0.5 * heightUm * (1.0 + Math.sin(2.0 * Math.PI * c / samplesPerPeriod));
            }
        }
        return HeightField.of(rows, cols, h, periodUm / samplesPerPeriod);
    }

    /** A flat patch: a perfect mirror. */
    public static HeightField flat(int rows, int cols, double pixelSizeUm) {
        return HeightField.of(rows, cols, new double[rows * cols], pixelSizeUm);
    }

    private static void check(double periodUm, double heightUm, int samplesPerPeriod, int periods, int rows) {
        if (!(periodUm > 0) || !(heightUm >= 0) || samplesPerPeriod < 2 || periods < 1 || rows < 1) {
            throw new UserInputException("a grating needs period > 0, height >= 0, >= 2 samples per period, "
                    + ">= 1 period and >= 1 row");
        }
    }
}
