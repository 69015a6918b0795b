package diffract.optics.rigorous;

import java.util.Arrays;

/**
 * One layer of a 2-D cell's staircase: uniform through its thickness, the material over some samples of the cell's
 * grid and air over the rest. Each sample stands for the rectangle of the grid around it (a pixel), so the mask is a
 * piecewise-constant function of (x, y) and its Fourier coefficients are exact, not sampled.
 *
 * @param thicknessUm the layer's thickness, um
 * @param cols        samples along x
 * @param rows        samples along y
 * @param mask        material at sample (row, col), row-major: mask[row * cols + col]
 */
public record CellSlab(double thicknessUm, int cols, int rows, boolean[] mask) {
    public CellSlab {
        if (!(thicknessUm > 0) || !Double.isFinite(thicknessUm)) {
            throw new IllegalArgumentException("a slab's thickness must be > 0 um, got " + thicknessUm);
        }
        if (cols < 1 || rows < 1 || mask.length != (long) cols * rows) {
            throw new IllegalArgumentException("a cell's mask holds cols x rows samples, got " + mask.length + " for "
                    + cols + " x " + rows);
        }
        mask = mask.clone();
    }

    /** The fraction of the cell the material fills. */
    public double fill() {
        int n = 0;
        for (boolean b : mask) {
            n += b ? 1 : 0;
        }
        return n / (double) mask.length;
    }

    /** Whether the slab is all air or all material (its modes are plane waves). */
    public boolean uniform() {
        double f = fill();
        return f <= 0 || f >= 1;
    }

    /**
     * The Fourier coefficients chi_pq = integral over the cell of chi(s, t) exp(-2 pi i (p s + q t)) ds dt of the
     * material's indicator (s, t the fractions of the periods), for |p| &lt;= maxP and |q| &lt;= maxQ, as
     * out[(q + maxQ) (2 maxP + 1) + p + maxP] = {Re, Im}. Sample (r, c) covers the rectangle of side 1 / cols by
     * 1 / rows centred on (c / cols, r / rows), whose transform is its area times sinc(pi p / cols) sinc(pi q / rows)
     * times the phase of its centre: the coefficients are the mask's DFT times these sinc factors, exact for the
     * pixelated mask at every p and q (no aliasing). Then epsilon(s, t) = sum eps_pq exp(2 pi i (p s + q t)) with
     * eps_pq = delta_p0 delta_q0 + (epsilon_material - 1) chi_pq, as {@link Slab#fourier} in 1-D.
     */
    public double[][] fourier(int maxP, int maxQ) {
        int np = 2 * maxP + 1;
        int nq = 2 * maxQ + 1;
        // the DFT along x of each row, then along y: cols rows np + rows np nq terms
        double[][] rowRe = new double[rows][np];
        double[][] rowIm = new double[rows][np];
        for (int pi = 0; pi < np; pi++) {
            int p = pi - maxP;
            double[] cos = new double[cols];
            double[] sin = new double[cols];
            for (int c = 0; c < cols; c++) {
                double a = -2 * Math.PI * p * c / cols;
                cos[c] = Math.cos(a);
                sin[c] = Math.sin(a);
            }
            for (int r = 0; r < rows; r++) {
                double re = 0;
                double im = 0;
                for (int c = 0; c < cols; c++) {
                    if (mask[r * cols + c]) {
                        re += cos[c];
                        im += sin[c];
                    }
                }
                rowRe[r][pi] = re;
                rowIm[r][pi] = im;
            }
        }
        double[][] out = new double[np * nq][2];
        double area = 1.0 / ((double) cols * rows);
        for (int qi = 0; qi < nq; qi++) {
            int q = qi - maxQ;
            double sincQ = sinc(Math.PI * q / rows);
            for (int pi = 0; pi < np; pi++) {
                int p = pi - maxP;
                double re = 0;
                double im = 0;
                for (int r = 0; r < rows; r++) {
                    double a = -2 * Math.PI * q * r / rows;
                    double cr = Math.cos(a);
                    double ci = Math.sin(a);
                    re += rowRe[r][pi] * cr - rowIm[r][pi] * ci;
                    im += rowRe[r][pi] * ci + rowIm[r][pi] * cr;
                }
                double scale = area * sincQ * sinc(Math.PI * p / cols);
                out[qi * np + pi][0] = re * scale;
                out[qi * np + pi][1] = im * scale;
            }
        }
        return out;
    }

    private static double sinc(double x) {
        return x == 0 ? 1 : Math.sin(x) / x;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof CellSlab s && s.thicknessUm == thicknessUm && s.cols == cols && s.rows == rows
                && Arrays.equals(s.mask, mask);
    }

    @Override
    public int hashCode() {
        return 31 * (31 * Double.hashCode(thicknessUm) + cols) + Arrays.hashCode(mask);
    }

    @Override
    public String toString() {
        return "CellSlab[" + thicknessUm + " um, " + cols + " x " + rows + ", fill " + fill() + "]";
    }

    @Override
    public boolean[] mask() {
        return mask.clone();
    }
}
