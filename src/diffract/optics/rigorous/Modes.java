package diffract.optics.rigorous;

import org.ejml.data.ZMatrixRMaj;
import org.ejml.dense.row.CommonOps_ZDRM;

/**
 * The eigenmodes of one layer of a 1-D grating in the Fourier modal method, on N = 2M + 1 harmonics: the tangential
 * electric field (E_x, E_y) of each mode as a column of W (2N x 2N, the harmonics of E_x above those of E_y), the
 * tangential magnetic field of the forward mode as a column of V, and each mode's propagation constant kappa (the
 * field varies as exp(i kappa k0 zeta), zeta pointing down into the grating, Im kappa &gt;= 0).
 *
 * <p>Maxwell's equations with fields exp(-i omega t) in units of k0 (curl E = i H, curl H = -i eps E, H = Z0 H_SI),
 * for the harmonics exp(i (alpha_m x + beta y)) of a layer whose permittivity varies along x:
 * <pre>
 *   e' = i P h,   h' = i Q e,   e = (E_x, E_y), h = (H_x, H_y), ' = d / d zeta,
 *   P = [[Kx Ez^-1 beta, I - Kx Ez^-1 Kx], [beta Ez^-1 beta - I, -beta Ez^-1 Kx]],
 *   Q = [[-beta Kx, Kx^2 - Ey], [Ex - beta^2, beta Kx]],
 * </pre>
 * with Kx = diag(alpha_m) and the permittivity's Toeplitz matrices by Li's rules (L. Li, JOSA A 13, 1870, 1996): E_x
 * crosses the relief's walls, so D_x = eps E_x is continuous there and Ex = [[1 / eps]]^-1 (the inverse rule), while
 * E_y and E_z run along the walls: Ey = Ez = [[eps]] (Laurent's rule). A mode exp(i kappa zeta) solves
 * P Q e = kappa^2 e. For a 1-D layer P Q is block lower-triangular,
 * <pre>
 *   P Q = [[L11, 0], [L21, L22]],  L11 = (I - Kx Ez^-1 Kx) Ex - beta^2,  L22 = Ey - Kx^2 - beta^2,
 *                                  L21 = beta (Kx - Ez^-1 Kx Ex),
 * </pre>
 * so its 2N modes are N TE-like modes (0, v) with L22 v = kappa^2 v, and N TM-like modes (u, w) with L11 u = kappa^2 u
 * and w = (kappa^2 - L22)^-1 L21 u: two eigenproblems of size N instead of one of 2N. Out of the plane of
 * incidence (beta != 0: conical incidence) w couples them; in the plane w = 0 and the polarisations separate.
 * The forward mode's magnetic field is h = Q e / kappa; V = -Q W kappa^-1 is the sign {@link ScatteringMatrix}'s
 * formulas take (R. C. Rumpf, PIER B 35, 241, 2011).
 *
 * @param w     tangential E of the modes, columns
 * @param v     -Q W kappa^-1
 * @param kappa propagation constants, interleaved (Re, Im), 2N of them
 */
record Modes(ZMatrixRMaj w, ZMatrixRMaj v, double[] kappa) {
    /** Relative size below which a TM-like mode's kappa^2 counts as equal to a TE-like mode's (no coupling term). */
    static final double DEGENERATE = 1e-12;

    /**
     * The plane waves of a homogeneous medium of permittivity (epsRe, epsIm): W = I, kappa_m = sqrt(eps - alpha_m^2
     * - beta^2) for both polarisations (the outgoing branch: Im kappa &gt;= 0, and Re kappa &gt;= 0 where it is real).
     */
    static Modes homogeneous(double epsRe, double epsIm, double[] alpha, double beta) {
        double[] betas = new double[alpha.length];
        java.util.Arrays.fill(betas, beta);
        return homogeneous(epsRe, epsIm, alpha, betas);
    }

    /**
     * The plane waves of a homogeneous medium with a direction cosine beta_m per harmonic (a 2-D cell's harmonics
     * (p, q) flattened): as {@link #homogeneous(double, double, double[], double)} with beta replaced by diag(beta_m).
     */
    static Modes homogeneous(double epsRe, double epsIm, double[] alpha, double[] beta) {
        int n = alpha.length;
        double[] kappa = new double[4 * n];
        for (int m = 0; m < n; m++) {
            double[] k = outgoing(epsRe - alpha[m] * alpha[m] - beta[m] * beta[m], epsIm);
            kappa[2 * m] = k[0];
            kappa[2 * m + 1] = k[1];
            kappa[2 * (n + m)] = k[0];
            kappa[2 * (n + m) + 1] = k[1];
        }
        ZMatrixRMaj w = CommonOps_ZDRM.identity(2 * n);
        ZMatrixRMaj v = new ZMatrixRMaj(2 * n, 2 * n);
        for (int m = 0; m < n; m++) {
            // Q's four diagonal blocks at harmonic m, divided by kappa_m and negated
            double[] inv = inverse(kappa[2 * m], kappa[2 * m + 1]);
            set(v, m, m, -(-beta[m] * alpha[m]), 0, inv);
            set(v, m, n + m, -(alpha[m] * alpha[m] - epsRe), epsIm, inv);
            set(v, n + m, m, -(epsRe - beta[m] * beta[m]), -epsIm, inv);
            set(v, n + m, n + m, -(beta[m] * alpha[m]), 0, inv);
        }
        return new Modes(w, v, kappa);
    }

    /** v(r, c) = (re + i im) (invRe + i invIm). */
    private static void set(ZMatrixRMaj v, int r, int c, double re, double im, double[] inv) {
        v.set(r, c, re * inv[0] - im * inv[1], re * inv[1] + im * inv[0]);
    }

    /** The modes of a slab whose material (permittivity eps) fills part of the period. */
    static Modes slab(Slab slab, double epsRe, double epsIm, double[] alpha, double beta) {
        int n = alpha.length;
        double[] chi = new double[2];
        // the permittivity's and its inverse's harmonics: eps_k = delta_k0 + (eps - 1) chi_k
        double[] inv = inverse(epsRe, epsIm);
        ZMatrixRMaj laurent = new ZMatrixRMaj(n, n);
        ZMatrixRMaj inverseRule = new ZMatrixRMaj(n, n);
        for (int d = -(n - 1); d <= n - 1; d++) {
            slab.fourier(d, chi);
            double eRe = (epsRe - 1) * chi[0] - epsIm * chi[1] + (d == 0 ? 1 : 0);
            double eIm = (epsRe - 1) * chi[1] + epsIm * chi[0];
            double aRe = (inv[0] - 1) * chi[0] - inv[1] * chi[1] + (d == 0 ? 1 : 0);
            double aIm = (inv[0] - 1) * chi[1] + inv[1] * chi[0];
            for (int i = Math.max(0, d); i < Math.min(n, n + d); i++) {
                laurent.set(i, i - d, eRe, eIm);
                inverseRule.set(i, i - d, aRe, aIm);
            }
        }
        ZMatrixRMaj ex = invert(inverseRule);
        ZMatrixRMaj ezInverse = invert(laurent);
        // L22 = Ey - Kx^2 - beta^2
        ZMatrixRMaj l22 = laurent.copy();
        for (int m = 0; m < n; m++) {
            addDiagonal(l22, m, -(alpha[m] * alpha[m] + beta * beta));
        }
        // L11 = (I - Kx Ez^-1 Kx) Ex - beta^2
        ZMatrixRMaj kek = ezInverse.copy();
        scaleRowsAndColumns(kek, alpha, alpha);
        ZMatrixRMaj left = CommonOps_ZDRM.identity(n);
        CommonOps_ZDRM.subtract(left, kek, left);
        ZMatrixRMaj l11 = new ZMatrixRMaj(n, n);
        CommonOps_ZDRM.mult(left, ex, l11);
        for (int m = 0; m < n; m++) {
            addDiagonal(l11, m, -beta * beta);
        }
        ComplexEigen te = ComplexEigen.of(l22);
        ComplexEigen tm = ComplexEigen.of(l11);
        ZMatrixRMaj u = tm.vectors();
        ZMatrixRMaj v2 = te.vectors();
        ZMatrixRMaj w = new ZMatrixRMaj(2 * n, 2 * n);
        CommonOps_ZDRM.extract(u, 0, n, 0, n, w, 0, 0);
        CommonOps_ZDRM.extract(v2, 0, n, 0, n, w, n, n);
        if (beta != 0) {
            // L21 = beta (Kx - Ez^-1 Kx Ex); the TM-like modes' E_y = V2 ((V2^-1 L21 U) / (kappa_j^2 - d2_k))
            ZMatrixRMaj kxEx = ex.copy();
            scaleRows(kxEx, alpha);
            ZMatrixRMaj l21 = new ZMatrixRMaj(n, n);
            CommonOps_ZDRM.mult(ezInverse, kxEx, l21);
            CommonOps_ZDRM.scale(-1, 0, l21);
            for (int m = 0; m < n; m++) {
                addDiagonal(l21, m, alpha[m]);
            }
            CommonOps_ZDRM.scale(beta, 0, l21);
            ZMatrixRMaj l21u = new ZMatrixRMaj(n, n);
            CommonOps_ZDRM.mult(l21, u, l21u);
            ZMatrixRMaj g = new ZMatrixRMaj(n, n);
            if (!CommonOps_ZDRM.solve(v2, l21u, g)) {
                throw new IllegalStateException("the TE-like modes of a slab are not independent");
            }
            for (int k = 0; k < n; k++) {
                for (int j = 0; j < n; j++) {
                    double dr = tm.valueRe(j) - te.valueRe(k);
                    double di = tm.valueIm(j) - te.valueIm(k);
                    double scale = Math.max(1, Math.hypot(tm.valueRe(j), tm.valueIm(j)));
                    double gr = g.getReal(k, j);
                    double gi = g.getImag(k, j);
                    if (Math.hypot(dr, di) <= DEGENERATE * scale) {
                        g.set(k, j, 0, 0);
                        continue;
                    }
                    double[] q = inverse(dr, di);
                    g.set(k, j, gr * q[0] - gi * q[1], gr * q[1] + gi * q[0]);
                }
            }
            ZMatrixRMaj wy = new ZMatrixRMaj(n, n);
            CommonOps_ZDRM.mult(v2, g, wy);
            CommonOps_ZDRM.extract(wy, 0, n, 0, n, w, n, 0);
        }
        double[] kappa = new double[4 * n];
        for (int j = 0; j < n; j++) {
            double[] k = forward(tm.valueRe(j), tm.valueIm(j));
            kappa[2 * j] = k[0];
            kappa[2 * j + 1] = k[1];
            k = forward(te.valueRe(j), te.valueIm(j));
            kappa[2 * (n + j)] = k[0];
            kappa[2 * (n + j) + 1] = k[1];
        }
        // Q = [[-beta Kx, Kx^2 - Ey], [Ex - beta^2, beta Kx]]
        ZMatrixRMaj q = new ZMatrixRMaj(2 * n, 2 * n);
        ZMatrixRMaj q12 = laurent.copy();
        CommonOps_ZDRM.scale(-1, 0, q12);
        ZMatrixRMaj q21 = ex.copy();
        for (int m = 0; m < n; m++) {
            addDiagonal(q12, m, alpha[m] * alpha[m]);
            addDiagonal(q21, m, -beta * beta);
            q.set(m, m, -beta * alpha[m], 0);
            q.set(n + m, n + m, beta * alpha[m], 0);
        }
        CommonOps_ZDRM.extract(q12, 0, n, 0, n, q, 0, n);
        CommonOps_ZDRM.extract(q21, 0, n, 0, n, q, n, 0);
        ZMatrixRMaj v = new ZMatrixRMaj(2 * n, 2 * n);
        CommonOps_ZDRM.mult(q, w, v);
        for (int j = 0; j < 2 * n; j++) {
            double[] s = inverse(kappa[2 * j], kappa[2 * j + 1]);
            for (int i = 0; i < 2 * n; i++) {
                double re = v.getReal(i, j);
                double im = v.getImag(i, j);
                v.set(i, j, -(re * s[0] - im * s[1]), -(re * s[1] + im * s[0]));
            }
        }
        return new Modes(w, v, kappa);
    }

    /** The outgoing sqrt of (re + i im): Im &gt;= 0, and Re &gt;= 0 where the square is a non-negative real. */
    static double[] outgoing(double re, double im) {
        if (im == 0) {
            return re >= 0 ? new double[] {Math.sqrt(re), 0} : new double[] {0, Math.sqrt(-re)};
        }
        return forward(re, im);
    }

    /** A square root of (re + i im) with Im &gt;= 0 (a decaying forward mode), Re &gt;= 0 where Im is 0. */
    static double[] forward(double re, double im) {
        double r = Math.hypot(re, im);
        double sr = Math.sqrt(0.5 * (r + re));
        double si = Math.copySign(Math.sqrt(0.5 * Math.max(0, r - re)), im);
        if (si < 0 || (si == 0 && sr < 0)) {
            sr = -sr;
            si = -si;
        }
        return new double[] {sr, si};
    }

    /** 1 / (re + i im). */
    static double[] inverse(double re, double im) {
        double d = re * re + im * im;
        if (d == 0) {
            throw new ArithmeticException("division by a zero propagation constant (an order exactly at grazing)");
        }
        return new double[] {re / d, -im / d};
    }

    static ZMatrixRMaj invert(ZMatrixRMaj m) {
        ZMatrixRMaj out = new ZMatrixRMaj(m.numRows, m.numCols);
        if (!CommonOps_ZDRM.invert(m, out)) {
            throw new IllegalStateException("a singular matrix in the Fourier modal method");
        }
        return out;
    }

    private static void addDiagonal(ZMatrixRMaj m, int i, double value) {
        m.set(i, i, m.getReal(i, i) + value, m.getImag(i, i));
    }

    /** m(i, j) *= rows[i] cols[j]. */
    private static void scaleRowsAndColumns(ZMatrixRMaj m, double[] rows, double[] cols) {
        for (int i = 0; i < m.numRows; i++) {
            for (int j = 0; j < m.numCols; j++) {
                double s = rows[i] * cols[j];
                m.set(i, j, m.getReal(i, j) * s, m.getImag(i, j) * s);
            }
        }
    }

    /** m(i, j) *= rows[i]. */
    private static void scaleRows(ZMatrixRMaj m, double[] rows) {
        for (int i = 0; i < m.numRows; i++) {
            for (int j = 0; j < m.numCols; j++) {
                m.set(i, j, m.getReal(i, j) * rows[i], m.getImag(i, j) * rows[i]);
            }
        }
    }
}
