package diffract.optics.rigorous;

import org.ejml.data.ZMatrixRMaj;
import org.ejml.dense.row.CommonOps_ZDRM;

/**
 * The eigenmodes of one slab of a 2-D cell on N = (2 M_x + 1)(2 M_y + 1) harmonics (p, q), as {@link Modes} are a
 * 1-D slab's and in its conventions, so that {@link ScatteringMatrix} joins them unchanged: the harmonic
 * exp(i (alpha_p x + beta_q y)), Kx = diag(alpha_p), Ky = diag(beta_q) over the flattened harmonics (p fastest), and
 * (M. G. Moharam et al., JOSA A 12, 1077, 1995; R. C. Rumpf, PIER B 35, 241, 2011, whose Q this one negates as the
 * 1-D code does)
 * <pre>
 *   P = [[Kx E^-1 Ky, I - Kx E^-1 Kx], [Ky E^-1 Ky - I, -Ky E^-1 Kx]],
 *   Q = [[-Ky Kx, Kx^2 - E], [E - Ky^2, Ky Kx]],
 * </pre>
 * the 1-D P and Q with beta replaced by Ky and Ex = Ey = Ez = E, the permittivity's 2-D convolution (block-Toeplitz)
 * matrix E_(pq),(p'q') = eps_(p - p', q - q') by Laurent's rule. Li's rules for crossed gratings (L. Li, J. Opt. Soc.
 * Am. A 14, 2758, 1997: the inverse rule along one axis and Laurent's along the other for each field component) need
 * the mask's row-wise and column-wise inverse Toeplitz matrices and are not applied: with Laurent's rule alone TM-like
 * light converges more slowly in the harmonics than TE-like light (on a y-invariant cell, the 1-D solver's Li's rule
 * differs for p polarisation by what CellFourierModalMethodTest reports). The full 2N x 2N eigenproblem
 * P Q e = kappa^2 e (no block structure in 2-D) is solved by {@link ComplexEigen}; kappa is the forward root
 * (Im kappa &gt;= 0) as in 1-D, W the eigenvectors and V = -Q W kappa^-1.
 */
final class CellModes {
    private CellModes() {
    }

    /**
     * The modes of a slab whose material (permittivity eps) fills part of the cell; chi holds the mask's coefficients
     * for |p| &lt;= 2 M_x, |q| &lt;= 2 M_y ({@link CellSlab#fourier}).
     */
    static Modes of(double[][] chi, double epsRe, double epsIm, int maxX, int maxY, double[] alpha, double[] beta) {
        ZMatrixRMaj[] pq = operators(chi, epsRe, epsIm, maxX, maxY, alpha, beta);
        ZMatrixRMaj q = pq[1];
        int n = alpha.length;
        ComplexEigen eigen = ComplexEigen.of(pq[2]);
        return modes(eigen, q, n);
    }

    /** P, Q and P Q of the slab. */
    static ZMatrixRMaj[] operators(double[][] chi, double epsRe, double epsIm, int maxX, int maxY, double[] alpha,
                                   double[] beta) {
        int nx = 2 * maxX + 1;
        int n = nx * (2 * maxY + 1);
        int chiWidth = 4 * maxX + 1;
        ZMatrixRMaj e = new ZMatrixRMaj(n, n);
        for (int i = 0; i < n; i++) {
            int pi = i % nx;
            int qi = i / nx;
            for (int j = 0; j < n; j++) {
                int dp = pi - j % nx;
                int dq = qi - j / nx;
                double[] c = chi[(dq + 2 * maxY) * chiWidth + dp + 2 * maxX];
                double re = (epsRe - 1) * c[0] - epsIm * c[1] + (i == j ? 1 : 0);
                double im = (epsRe - 1) * c[1] + epsIm * c[0];
                e.set(i, j, re, im);
            }
        }
        ZMatrixRMaj eInverse = Modes.invert(e);
        ZMatrixRMaj p = new ZMatrixRMaj(2 * n, 2 * n);
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double re = eInverse.getReal(i, j);
                double im = eInverse.getImag(i, j);
                double d = i == j ? 1 : 0;
                double s11 = alpha[i] * beta[j];
                double s12 = -alpha[i] * alpha[j];
                double s21 = beta[i] * beta[j];
                double s22 = -beta[i] * alpha[j];
                p.set(i, j, re * s11, im * s11);
                p.set(i, n + j, d + re * s12, im * s12);
                p.set(n + i, j, -d + re * s21, im * s21);
                p.set(n + i, n + j, re * s22, im * s22);
            }
        }
        ZMatrixRMaj q = new ZMatrixRMaj(2 * n, 2 * n);
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double re = e.getReal(i, j);
                double im = e.getImag(i, j);
                q.set(i, n + j, -re, -im);
                q.set(n + i, j, re, im);
            }
            q.set(i, i, -beta[i] * alpha[i], 0);
            q.set(n + i, n + i, beta[i] * alpha[i], 0);
            q.set(i, n + i, q.getReal(i, n + i) + alpha[i] * alpha[i], q.getImag(i, n + i));
            q.set(n + i, i, q.getReal(n + i, i) - beta[i] * beta[i], q.getImag(n + i, i));
        }
        ZMatrixRMaj pq = new ZMatrixRMaj(2 * n, 2 * n);
        CommonOps_ZDRM.mult(p, q, pq);
        return new ZMatrixRMaj[] {p, q, pq};
    }

    /** W = the eigenvectors, kappa the forward roots, V = -Q W kappa^-1. */
    private static Modes modes(ComplexEigen eigen, ZMatrixRMaj q, int n) {
        ZMatrixRMaj w = eigen.vectors();
        double[] kappa = new double[4 * n];
        for (int j = 0; j < 2 * n; j++) {
            double[] k = Modes.forward(eigen.valueRe(j), eigen.valueIm(j));
            kappa[2 * j] = k[0];
            kappa[2 * j + 1] = k[1];
        }
        ZMatrixRMaj v = new ZMatrixRMaj(2 * n, 2 * n);
        CommonOps_ZDRM.mult(q, w, v);
        for (int j = 0; j < 2 * n; j++) {
            double[] s = Modes.inverse(kappa[2 * j], kappa[2 * j + 1]);
            for (int i = 0; i < 2 * n; i++) {
                double re = v.getReal(i, j);
                double im = v.getImag(i, j);
                v.set(i, j, -(re * s[0] - im * s[1]), -(re * s[1] + im * s[0]));
            }
        }
        return new Modes(w, v, kappa);
    }
}
