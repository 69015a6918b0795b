package diffract.optics.rigorous;

/**
 * One period of a 2-D periodic (crossed) relief: heights on a grid of cols x rows samples spanning the periods
 * periodXUm x periodYUm, each sample standing for the rectangle around it.
 *
 * @param periodXUm the period along x, um
 * @param periodYUm the period along y, um
 * @param cols      samples along x
 * @param rows      samples along y
 * @param heightsUm heights, row-major: heightsUm[row * cols + col]
 */
public record CellRelief(double periodXUm, double periodYUm, int cols, int rows, double[] heightsUm) {
    public CellRelief {
        if (!(periodXUm > 0) || !(periodYUm > 0) || !Double.isFinite(periodXUm) || !Double.isFinite(periodYUm)) {
            throw new IllegalArgumentException("a cell's periods must be > 0 um, got " + periodXUm + " x " + periodYUm);
        }
        if (cols < 1 || rows < 1 || heightsUm.length != (long) cols * rows) {
            throw new IllegalArgumentException("a cell holds cols x rows heights, got " + heightsUm.length + " for "
                    + cols + " x " + rows);
        }
        heightsUm = heightsUm.clone();
    }

    /** The peak-to-valley height, um. */
    public double depthUm() {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double h : heightsUm) {
            lo = Math.min(lo, h);
            hi = Math.max(hi, h);
        }
        return hi - lo;
    }

    /** The lowest height, um. */
    public double minHeightUm() {
        double lo = Double.POSITIVE_INFINITY;
        for (double h : heightsUm) {
            lo = Math.min(lo, h);
        }
        return lo;
    }

    @Override
    public double[] heightsUm() {
        return heightsUm.clone();
    }

    double heightUm(int row, int col) {
        return heightsUm[row * cols + col];
    }
}
