package diffract.optics.patches;

import java.util.Locale;

/**
 * How a measured height field is levelled before use, as AFM software does: a scan carries the tilt of the sample
 * on its stage and, line by line, the drift of the scanner, and either can be taller than the nanostructure. The
 * DFT takes the patch as periodic, so a tilt becomes a sawtooth whose jump at the patch's edge scatters light into
 * the low orders around the mirror direction, and row offsets become stripes that spread light along y.
 */
public enum Levelling {
    /** Removes the least-squares plane a + b x + c y (Gwyddion's Data Process > Level > Plane Level). */
    PLANE,
    /**
     * Subtracts from each row (a scan line) its own mean: Gwyddion's Correct Data > Align Rows with the mean (it
     * also offers the median, more robust to spikes; the mean keeps levelling linear).
     */
    ROWS,
    /** The heights as read. */
    NONE;

    /**
     * What a file gets without asking: {@link #PLANE} for the instruments' own files (.gwy, .ibw), which hold the scan
     * as measured, tilt and all; {@link #NONE} for exports (grey images, text matrices, .gsf), which AFM software
     * writes after levelling and which a plane fit would change again: on a patch of k whole periods the fitted tilt
     * takes about 6 / (pi k) of the profile's amplitude with it.
     */
    public static Levelling defaultFor(boolean instrumentFile) {
        return instrumentFile ? PLANE : NONE;
    }

    /** The spelling on the command line and in scene files: {@code plane}, {@code rows}, {@code none}. */
    public String label() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** The constant a {@link #label()} names, or null. */
    public static Levelling fromLabel(String label) {
        for (Levelling l : values()) {
            if (l.label().equals(label)) {
                return l;
            }
        }
        return null;
    }

    /** The levelled field, with the same grid and pixel sizes. */
    public HeightField apply(HeightField field) {
        return switch (this) {
            case PLANE -> plane(field);
            case ROWS -> rows(field);
            case NONE -> field;
        };
    }

    /**
     * On a regular grid the centred coordinates x - mean(x) and y - mean(y) are orthogonal to each other and to
     * the constant, so the least-squares plane's three coefficients decouple: a = mean(h),
     * b = sum((x - xm) h) / sum((x - xm)^2), c likewise along y. Coordinates are sample indices; the plane is
     * the same whatever the pixel size.
     */
    private static HeightField plane(HeightField field) {
        int rows = field.rows();
        int cols = field.cols();
        double[] h = field.heightsUm();
        double xMean = (cols - 1) / 2.0;
        double yMean = (rows - 1) / 2.0;
        double sum = 0;
        double sumX = 0;
        double sumY = 0;
        for (int r = 0; r < rows; r++) {
            double y = r - yMean;
            for (int c = 0; c < cols; c++) {
                double value = h[r * cols + c];
                sum += value;
                sumX += (c - xMean) * value;
                sumY += y * value;
            }
        }
        // sum over the grid of (c - xm)^2 = rows * cols (cols^2 - 1) / 12, and likewise along y
        double xx = rows * (double) cols * ((double) cols * cols - 1) / 12.0;
        double yy = cols * (double) rows * ((double) rows * rows - 1) / 12.0;
        double a = sum / h.length;
        double b = xx == 0 ? 0 : sumX / xx;
        double c = yy == 0 ? 0 : sumY / yy;
        double[] out = new double[h.length];
        for (int r = 0; r < rows; r++) {
            double y = r - yMean;
            for (int col = 0; col < cols; col++) {
                out[r * cols + col] = h[r * cols + col] - (a + b * (col - xMean) + c * y);
            }
        }
        return HeightField.of(rows, cols, out, field.pixelSizeXUm(), field.pixelSizeYUm());
    }

    private static HeightField rows(HeightField field) {
        int rows = field.rows();
        int cols = field.cols();
        double[] h = field.heightsUm();
        for (int r = 0; r < rows; r++) {
            double mean = 0;
            for (int c = 0; c < cols; c++) {
                mean += h[r * cols + c];
            }
            mean /= cols;
            for (int c = 0; c < cols; c++) {
                h[r * cols + c] -= mean;
            }
        }
        return HeightField.of(rows, cols, h, field.pixelSizeXUm(), field.pixelSizeYUm());
    }
}
