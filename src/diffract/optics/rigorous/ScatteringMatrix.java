package diffract.optics.rigorous;

import org.ejml.data.ZMatrixRMaj;
import org.ejml.dense.row.CommonOps_ZDRM;

/**
 * The scattering matrix of a layer or a stack: the outgoing modes' amplitudes from the incoming ones, in the
 * symmetric formulation with a gap medium between every two layers (R. C. Rumpf, "Improved formulation of
 * scattering matrices for semi-analytical methods that is consistent with convention", PIER B 35, 241, 2011):
 * every layer is joined to the same medium of zero thickness on both sides, so layers combine by the Redheffer star
 * product alone and no amplitude ever grows (each layer's evanescent modes enter as exp(i kappa k0 d), |.| &lt;= 1):
 * the product is stable for any number of layers and any thickness.
 *
 * <p>The gap medium is homogeneous with a permittivity at which every harmonic propagates ({@link
 * FourierModalMethod}), so none of its propagation constants is 0.
 */
record ScatteringMatrix(ZMatrixRMaj s11, ZMatrixRMaj s12, ZMatrixRMaj s21, ZMatrixRMaj s22) {
    /** A layer of normalised thickness k0 d between two gaps: S11 = S22, S12 = S21 (Rumpf's eq. 37). */
    static ScatteringMatrix layer(Modes modes, Modes gap, double k0ThicknessUm) {
        ZMatrixRMaj wInverse = Modes.invert(modes.w());
        ZMatrixRMaj vv = solve(modes.v(), gap.v());
        ZMatrixRMaj a = add(wInverse, vv, 1);
        ZMatrixRMaj b = add(wInverse, vv, -1);
        double[] kappa = modes.kappa();
        int n = kappa.length / 2;
        double[] x = new double[2 * n];
        for (int j = 0; j < n; j++) {
            // exp(i kappa k0 d)
            double decay = Math.exp(-kappa[2 * j + 1] * k0ThicknessUm);
            double phase = kappa[2 * j] * k0ThicknessUm;
            x[2 * j] = decay * Math.cos(phase);
            x[2 * j + 1] = decay * Math.sin(phase);
        }
        ZMatrixRMaj aInverse = Modes.invert(a);
        ZMatrixRMaj xb = diagonalTimes(x, b);
        ZMatrixRMaj xbaix = timesDiagonal(mult(xb, aInverse), x);
        ZMatrixRMaj d = add(a, mult(xbaix, b), -1);
        ZMatrixRMaj dInverse = Modes.invert(d);
        ZMatrixRMaj s11 = mult(dInverse, add(mult(xbaix, a), b, -1));
        ZMatrixRMaj s12 = mult(dInverse, diagonalTimes(x, add(a, mult(mult(b, aInverse), b), -1)));
        return new ScatteringMatrix(s11, s12, s12, s11);
    }

    /** The half-space above (where the light comes from) joined to the gap (Rumpf's eq. 46-47). */
    static ScatteringMatrix reflectionSide(Modes region, Modes gap) {
        ZMatrixRMaj vv = solve(gap.v(), region.v());
        ZMatrixRMaj a = add(region.w(), vv, 1);
        ZMatrixRMaj b = add(region.w(), vv, -1);
        ZMatrixRMaj aInverse = Modes.invert(a);
        ZMatrixRMaj s11 = mult(aInverse, b);
        CommonOps_ZDRM.scale(-1, 0, s11);
        ZMatrixRMaj s12 = aInverse.copy();
        CommonOps_ZDRM.scale(2, 0, s12);
        ZMatrixRMaj s21 = add(a, mult(mult(b, aInverse), b), -1);
        CommonOps_ZDRM.scale(0.5, 0, s21);
        ZMatrixRMaj s22 = mult(b, aInverse);
        return new ScatteringMatrix(s11, s12, s21, s22);
    }

    /** The gap joined to the half-space below (Rumpf's eq. 50-51). */
    static ScatteringMatrix transmissionSide(Modes region, Modes gap) {
        ZMatrixRMaj vv = solve(gap.v(), region.v());
        ZMatrixRMaj a = add(region.w(), vv, 1);
        ZMatrixRMaj b = add(region.w(), vv, -1);
        ZMatrixRMaj aInverse = Modes.invert(a);
        ZMatrixRMaj s11 = mult(b, aInverse);
        ZMatrixRMaj s12 = add(a, mult(mult(b, aInverse), b), -1);
        CommonOps_ZDRM.scale(0.5, 0, s12);
        ZMatrixRMaj s21 = aInverse.copy();
        CommonOps_ZDRM.scale(2, 0, s21);
        ZMatrixRMaj s22 = mult(aInverse, b);
        CommonOps_ZDRM.scale(-1, 0, s22);
        return new ScatteringMatrix(s11, s12, s21, s22);
    }

    /** This (above) joined to {@code below} by the Redheffer star product. */
    ScatteringMatrix star(ScatteringMatrix below) {
        int n = s11.numRows;
        ZMatrixRMaj identity = CommonOps_ZDRM.identity(n);
        ZMatrixRMaj d = mult(s12, Modes.invert(add(identity, mult(below.s11, s22), -1)));
        ZMatrixRMaj f = mult(below.s21, Modes.invert(add(identity, mult(s22, below.s11), -1)));
        ZMatrixRMaj n11 = add(s11, mult(mult(d, below.s11), s21), 1);
        ZMatrixRMaj n12 = mult(d, below.s12);
        ZMatrixRMaj n21 = mult(f, s21);
        ZMatrixRMaj n22 = add(below.s22, mult(mult(f, s22), below.s12), 1);
        return new ScatteringMatrix(n11, n12, n21, n22);
    }

    static ZMatrixRMaj mult(ZMatrixRMaj a, ZMatrixRMaj b) {
        ZMatrixRMaj c = new ZMatrixRMaj(a.numRows, b.numCols);
        CommonOps_ZDRM.mult(a, b, c);
        return c;
    }

    /** a + sign b. */
    static ZMatrixRMaj add(ZMatrixRMaj a, ZMatrixRMaj b, int sign) {
        ZMatrixRMaj c = new ZMatrixRMaj(a.numRows, a.numCols);
        if (sign > 0) {
            CommonOps_ZDRM.add(a, b, c);
        } else {
            CommonOps_ZDRM.subtract(a, b, c);
        }
        return c;
    }

    /** a^-1 b. */
    static ZMatrixRMaj solve(ZMatrixRMaj a, ZMatrixRMaj b) {
        ZMatrixRMaj x = new ZMatrixRMaj(a.numCols, b.numCols);
        if (!CommonOps_ZDRM.solve(a, b, x)) {
            throw new IllegalStateException("a singular matrix in the Fourier modal method");
        }
        return x;
    }

    /** diag(x) m, x interleaved (Re, Im). */
    static ZMatrixRMaj diagonalTimes(double[] x, ZMatrixRMaj m) {
        ZMatrixRMaj out = new ZMatrixRMaj(m.numRows, m.numCols);
        for (int i = 0; i < m.numRows; i++) {
            for (int j = 0; j < m.numCols; j++) {
                double re = m.getReal(i, j);
                double im = m.getImag(i, j);
                out.set(i, j, x[2 * i] * re - x[2 * i + 1] * im, x[2 * i] * im + x[2 * i + 1] * re);
            }
        }
        return out;
    }

    /** m diag(x). */
    static ZMatrixRMaj timesDiagonal(ZMatrixRMaj m, double[] x) {
        ZMatrixRMaj out = new ZMatrixRMaj(m.numRows, m.numCols);
        for (int i = 0; i < m.numRows; i++) {
            for (int j = 0; j < m.numCols; j++) {
                double re = m.getReal(i, j);
                double im = m.getImag(i, j);
                out.set(i, j, re * x[2 * j] - im * x[2 * j + 1], re * x[2 * j + 1] + im * x[2 * j]);
            }
        }
        return out;
    }
}
