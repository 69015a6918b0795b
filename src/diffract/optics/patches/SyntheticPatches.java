package diffract.optics.patches;

import diffract.util.UserInputException;

/**
 * Height fields made by code, for tests and demos: 1-D gratings whose grooves run along y (rows), so their period
 * lies along x (columns) and their diffraction orders along the x axis of a BRDF map; and an Elaphe-like snake-skin
 * patch whose ridges run along x, with the period along y.
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

    /** Ridge period of the Elaphe patch along its rows: the measured 1.144 um (assets/patches, ElaphePatchTest). */
    public static final double ELAPHE_RIDGE_PERIOD_UM = 1.144;

    /**
     * An Elaphe-like nanostructure made by code: 128 x 128 pixels, 8 ridges of period 1.144 um along y (rows),
     * so the pixel size is 8 x 1.144 / 128 = 0.0715 um, heights 0.3 um, seed 1. See
     * {@link #elapheLike(int, int, double, double, long)}.
     */
    public static HeightField elapheLike() {
        return elapheLike(128, 8, ELAPHE_RIDGE_PERIOD_UM, 0.3, 1L);
    }

    /**
     * A procedural stand-in for the scales of Elaphe snakes (no measured data): ridges running along x (columns),
     * repeating with {@code periodUm} along y (rows), as on the measured patch. Every ingredient is periodic over
     * the patch, so the DFT's implied tiling is seamless:
     *
     * <ul>
     *   <li>profile across a ridge, phase t in [0, 1): an asymmetric "finger" that rises gently over 70 % of the
     *       period, sin^2(pi t / 1.4), and falls steeply over the last 30 %, cos^2(pi (t - 0.7) / 0.6), peak-to-valley
     *       {@code heightUm};</li>
     *   <li>waviness: the ridges meander by 8 % of a period, y + 0.08 d sin(2 pi x / width + phi);</li>
     *   <li>fingers along each ridge: the height dips by up to 25 % with a pitch of size / 16 pixels, in a random
     *       phase per ridge;</li>
     *   <li>noise: seeded Gaussian, 0.01 um per pixel, smoothed by a 3 x 3 box with wrap-around (AFM-like roughness).</li>
     * </ul>
     *
     * @param size     pixels per side (rows = cols), a multiple of 16
     * @param ridges   whole ridge periods along y; the pixel size is ridges * periodUm / size
     * @param seed     the same seed gives the same field
     */
    public static HeightField elapheLike(int size, int ridges, double periodUm, double heightUm, long seed) {
        if (size < 16 || size % 16 != 0 || ridges < 1 || !(periodUm > 0) || !(heightUm >= 0)) {
            throw new UserInputException("an Elaphe-like patch needs a size that is a multiple of 16, >= 1 ridge, "
                    + "period > 0 and height >= 0");
        }
        java.util.Random random = new java.util.Random(seed);
        double pixelUm = ridges * periodUm / size;
        double widthUm = size * pixelUm;
        double wavinessPhase = 2 * Math.PI * random.nextDouble();
        double[] fingerPhase = new double[ridges];
        for (int k = 0; k < ridges; k++) {
            fingerPhase[k] = 2 * Math.PI * random.nextDouble();
        }
        double[] noise = new double[size * size];
        for (int i = 0; i < noise.length; i++) {
            noise[i] = 0.01 * random.nextGaussian();
        }
        double fingerPitchPx = size / 16.0;
        double[] h = new double[size * size];
        for (int r = 0; r < size; r++) {
            for (int c = 0; c < size; c++) {
                double x = c * pixelUm;
                double y = r * pixelUm + 0.08 * periodUm * Math.sin(2 * Math.PI * x / widthUm + wavinessPhase);
                double ridgePosition = y / periodUm;
                int ridge = Math.floorMod((int) Math.floor(ridgePosition), ridges);
                double t = ridgePosition - Math.floor(ridgePosition);
                double finger = 1.0 - 0.25 * 0.5 * (1 - Math.cos(2 * Math.PI * c / fingerPitchPx + fingerPhase[ridge]));
                h[r * size + c] = heightUm * fingerProfile(t) * finger + smoothed(noise, size, r, c);
            }
        }
        return HeightField.of(size, size, h, pixelUm);
    }

    /**
     * The Elaphe-like skin as an atomic force microscope scans it: a window of {@code rows} x (rows + rows / 32)
     * samples cut out of an {@link #elapheLike} field of (rows + rows / 8) pixels and {@code ridges} ridges, so that
     * neither the ridges nor the meander fit a whole number of times: the scan's opposite edges do not match, and the
     * DFT's periodic patch has a seam, as a real scan's has. 512 rows and 50 ridges of 1.144 um: 528 x 512 samples of
     * 0.0993 um, 52.4 x 50.8 um, as wide as the 65 um coherence window.
     *
     * @param rows   scan lines, a multiple of 32
     * @param ridges whole ridges over the field the scan is cut from
     */
    public static HeightField elapheScan(int rows, int ridges, double periodUm, double heightUm, long seed) {
        if (rows < 32 || rows % 32 != 0) {
            throw new UserInputException("an Elaphe scan needs a number of scan lines that is a multiple of 32, got "
                    + rows);
        }
        int fieldSize = rows + rows / 8;
        HeightField field = elapheLike(fieldSize, ridges, periodUm, heightUm, seed);
        int cols = rows + rows / 32;
        double[] h = new double[rows * cols];
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                h[r * cols + c] = field.heightUm(r, c);
            }
        }
        return HeightField.of(rows, cols, h, field.pixelSizeXUm(), field.pixelSizeYUm());
    }

    /**
     * A snake patch's ridges alone, as a 1-D grating: the cross-section {@code profile} (peak 1, over t in [0, 1)) of
     * peak-to-valley {@code heightUm}, repeating along y every {@code periodUm}, the ridges running along x over
     * {@code along} columns, without the snake patch's meander, fingers and noise: the 1-D structure the rigorous
     * method solves as it is.
     */
    public static HeightField ridges(java.util.function.DoubleUnaryOperator profile, double periodUm, double heightUm,
                                     int samplesPerPeriod, int periods, int along) {
        check(periodUm, heightUm, samplesPerPeriod, periods, along);
        int rows = samplesPerPeriod * periods;
        double[] h = new double[rows * along];
        for (int r = 0; r < rows; r++) {
            double height = heightUm * profile.applyAsDouble((r % samplesPerPeriod) / (double) samplesPerPeriod);
            for (int c = 0; c < along; c++) {
                h[r * along + c] = height;
            }
        }
        return HeightField.of(rows, along, h, periodUm / samplesPerPeriod);
    }

    /** The asymmetric ridge profile of {@link #elapheLike}: 0 at t = 0 and 1, peak 1 at t = 0.7, smooth. */
    static double fingerProfile(double t) {
        if (t < 0.7) {
            double s = Math.sin(0.5 * Math.PI * t / 0.7);
            return s * s;
        }
        double c = Math.cos(0.5 * Math.PI * (t - 0.7) / 0.3);
        return c * c;
    }

    /** 3 x 3 box mean of a size x size field, wrapping around the edges. */
    private static double smoothed(double[] field, int size, int r, int c) {
        double sum = 0;
        for (int dr = -1; dr <= 1; dr++) {
            for (int dc = -1; dc <= 1; dc++) {
                sum += field[Math.floorMod(r + dr, size) * size + Math.floorMod(c + dc, size)];
            }
        }
        return sum / 9;
    }

    /** A flat patch: a perfect mirror. */
    public static HeightField flat(int rows, int cols, double pixelSizeUm) {
        return HeightField.of(rows, cols, new double[rows * cols], pixelSizeUm);
    }

    private static void check(double periodUm, double heightUm, int samplesPerPeriod, int periods, int rows) {
        if (!(periodUm > 0) || !Double.isFinite(periodUm)) {
            throw new UserInputException("a grating's period must be > 0 um, got " + periodUm);
        }
        if (!(heightUm >= 0) || !Double.isFinite(heightUm)) {
            throw new UserInputException("a grating's height must be >= 0 um, got " + heightUm);
        }
        if (samplesPerPeriod < 2) {
            throw new UserInputException("a grating needs at least 2 samples per period, got " + samplesPerPeriod);
        }
        if (periods < 1 || rows < 1) {
            throw new UserInputException("a grating needs at least 1 period and 1 row, got " + periods + " periods and "
                    + rows + " rows");
        }
        if ((long) samplesPerPeriod * periods * rows > Integer.MAX_VALUE - 8) {
            throw new UserInputException("a grating of " + samplesPerPeriod + " x " + periods + " x " + rows
                    + " samples exceeds what one array holds (2^31)");
        }
    }
}
