package diffract.optics.rigorous;

import org.ejml.data.ZMatrixRMaj;
import org.hipparchus.complex.Complex;
import org.hipparchus.linear.Array2DRowRealMatrix;
import org.hipparchus.linear.EigenDecompositionNonSymmetric;
import org.hipparchus.linear.FieldVector;

/**
 * The eigenvalues and eigenvectors of a general complex matrix M (n x n), by Hipparchus' non-symmetric eigen
 * decomposition (real Schur form and back substitution) of a real matrix twice its size: EJML decomposes complex
 * matrices in many ways but not into eigenvectors, and Hipparchus decomposes real matrices only.
 *
 * <p>The real matrix is M' = M + i c I written on (Re z, Im z): R = [[Re M', -Im M'], [Im M', Re M']], which acts on
 * the real pair (a, b) as M' acts on z = a + i b. Its eigenvalues are those of M' and their conjugates: an eigenvector
 * of M' with eigenvalue nu gives R's eigenvector (x, -i x) for nu, one of conj(M') with eigenvalue nu gives (y, i y).
 * The shift c exceeds every |Im mu| of M (at most the Frobenius norm of M's skew-Hermitian part) by half of M's norm,
 * so M''s eigenvalues lie strictly above the real axis and the conjugates' strictly below: the n eigenvalues of R with
 * a positive imaginary part are exactly M''s, and from each of their eigenvectors (a, b), x = a + i b is M''s (the
 * other family's part, a - i b, is zero). Then mu = nu - i c. Without the shift, the two families meet wherever M has
 * real eigenvalues (every lossless layer has them), and no eigenvector could be told from its twin.
 *
 * <p>Each pair is checked: |M x - mu x| &lt;= {@link #RESIDUAL_TOLERANCE} |M|_F |x|, or the decomposition is refused
 * (an {@link IllegalStateException}: a wrong mode would give wrong efficiencies without a word).
 */
public final class ComplexEigen {
    /** The largest relative residual an eigenpair may have. */
    static final double RESIDUAL_TOLERANCE = 1e-8;
    /**
     * The Schur iteration's deflation threshold, relative to the neighbouring diagonal: a few units in the last place.
     * Hipparchus' default, 1e-12, leaves residuals of about 1e-11 |M|, which the grating's energy balance shows.
     */
    static final double SCHUR_EPSILON = 4 * Math.ulp(1.0);
    /**
     * The threshold tried when the Schur iteration does not converge at {@link #SCHUR_EPSILON} (Hipparchus' default):
     * the larger matrices of 2-D cells, with near-degenerate modes, can stall at a few ulps; the residual check below
     * still holds every pair to {@link #RESIDUAL_TOLERANCE}.
     */
    static final double FALLBACK_EPSILON = 1e-12;

    private final double[] valuesRe;
    private final double[] valuesIm;
    /** Eigenvectors as columns, unit 2-norm. */
    private final ZMatrixRMaj vectors;
    /** Whether the Schur iteration needed {@link #FALLBACK_EPSILON}. */
    private final boolean relaxed;

    private ComplexEigen(double[] valuesRe, double[] valuesIm, ZMatrixRMaj vectors) {
        this(valuesRe, valuesIm, vectors, false);
    }

    private ComplexEigen(double[] valuesRe, double[] valuesIm, ZMatrixRMaj vectors, boolean relaxed) {
        this.relaxed = relaxed;
        this.valuesRe = valuesRe;
        this.valuesIm = valuesIm;
        this.vectors = vectors;
    }

    /** The eigenpairs of {@code m}, which is not changed. */
    public static ComplexEigen of(ZMatrixRMaj m) {
        int n = m.numRows;
        if (m.numCols != n) {
            throw new IllegalArgumentException("an eigen decomposition needs a square matrix, got " + m.numRows + " x "
                    + m.numCols);
        }
        double[] d = m.data;
        double norm2 = 0;
        double skew2 = 0;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                int ij = 2 * (i * n + j);
                int ji = 2 * (j * n + i);
                norm2 += d[ij] * d[ij] + d[ij + 1] * d[ij + 1];
                // (M - M^H) / 2 at (i, j): ((re_ij - re_ji) + i (im_ij + im_ji)) / 2
                double sr = 0.5 * (d[ij] - d[ji]);
                double si = 0.5 * (d[ij + 1] + d[ji + 1]);
                skew2 += sr * sr + si * si;
            }
        }
        double norm = Math.sqrt(norm2);
        double[] re = new double[n];
        double[] im = new double[n];
        ZMatrixRMaj x = new ZMatrixRMaj(n, n);
        if (norm == 0) {
            for (int i = 0; i < n; i++) {
                x.set(i, i, 1, 0);
            }
            return new ComplexEigen(re, im, x);
        }
        double shift = Math.sqrt(skew2) + 0.5 * norm;
        double[][] r = new double[2 * n][2 * n];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                int ij = 2 * (i * n + j);
                double a = d[ij];
                double b = d[ij + 1] + (i == j ? shift : 0);
                r[i][j] = a;
                r[i][n + j] = -b;
                r[n + i][j] = b;
                r[n + i][n + j] = a;
            }
        }
        Array2DRowRealMatrix real = new Array2DRowRealMatrix(r, false);
        EigenDecompositionNonSymmetric eigen;
        boolean relaxed = false;
        try {
            eigen = new EigenDecompositionNonSymmetric(real, SCHUR_EPSILON);
        } catch (org.hipparchus.exception.MathIllegalStateException stalled) {
            eigen = new EigenDecompositionNonSymmetric(real, FALLBACK_EPSILON);
            relaxed = true;
        }
        Complex[] nu = eigen.getEigenvalues();
        int found = 0;
        for (int k = 0; k < nu.length; k++) {
            if (!(nu[k].getImaginary() > 0)) {
                continue;
            }
            if (found == n) {
                throw new IllegalStateException("the eigen decomposition found more than " + n
                        + " eigenvalues above the real axis (shift " + shift + ")");
            }
            FieldVector<Complex> v = eigen.getEigenvector(k);
            double sum = 0;
            double[] xr = new double[n];
            double[] xi = new double[n];
            for (int i = 0; i < n; i++) {
                Complex a = v.getEntry(i);
                Complex b = v.getEntry(n + i);
                // x = a + i b
                xr[i] = a.getReal() - b.getImaginary();
                xi[i] = a.getImaginary() + b.getReal();
                sum += xr[i] * xr[i] + xi[i] * xi[i];
            }
            double scale = 1 / Math.sqrt(sum);
            for (int i = 0; i < n; i++) {
                x.set(i, found, xr[i] * scale, xi[i] * scale);
            }
            re[found] = nu[k].getReal();
            im[found] = nu[k].getImaginary() - shift;
            found++;
        }
        if (found != n) {
            throw new IllegalStateException("the eigen decomposition found " + found + " of " + n
                    + " eigenvalues above the real axis (shift " + shift + ")");
        }
        ComplexEigen result = new ComplexEigen(re, im, x, relaxed);
        result.requireSmallResiduals(m, norm);
        return result;
    }

    private void requireSmallResiduals(ZMatrixRMaj m, double norm) {
        int n = m.numRows;
        double[] d = m.data;
        double[] v = vectors.data;
        for (int k = 0; k < n; k++) {
            double worst = 0;
            for (int i = 0; i < n; i++) {
                double sr = 0;
                double si = 0;
                for (int j = 0; j < n; j++) {
                    int ij = 2 * (i * n + j);
                    int jk = 2 * (j * n + k);
                    sr += d[ij] * v[jk] - d[ij + 1] * v[jk + 1];
                    si += d[ij] * v[jk + 1] + d[ij + 1] * v[jk];
                }
                int ik = 2 * (i * n + k);
                sr -= valuesRe[k] * v[ik] - valuesIm[k] * v[ik + 1];
                si -= valuesRe[k] * v[ik + 1] + valuesIm[k] * v[ik];
                worst += sr * sr + si * si;
            }
            if (Math.sqrt(worst) > RESIDUAL_TOLERANCE * norm) {
                throw new IllegalStateException(String.format(java.util.Locale.ROOT,
                        "eigenpair %d of %d is inaccurate: |M x - mu x| = %.3g |M|", k, n, Math.sqrt(worst) / norm));
            }
        }
    }

    /** Whether the Schur iteration stalled at {@link #SCHUR_EPSILON} and converged at {@link #FALLBACK_EPSILON}. */
    boolean relaxed() {
        return relaxed;
    }

    public int size() {
        return valuesRe.length;
    }

    public double valueRe(int k) {
        return valuesRe[k];
    }

    public double valueIm(int k) {
        return valuesIm[k];
    }

    /** The eigenvectors as the columns of an n x n matrix (unit 2-norm each); the caller may change it. */
    public ZMatrixRMaj vectors() {
        return vectors;
    }
}
