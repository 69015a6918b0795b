package diffract.optics.rigorous;

import org.ejml.data.ZMatrixRMaj;
import org.junit.jupiter.api.Test;

import java.util.Arrays;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The complex eigendecomposition through its real twin: known spectra, residuals, degenerate and real spectra. */
class ComplexEigenTest {
    @Test
    void anUpperTriangularMatrixHasItsDiagonalAsEigenvalues() {
        double[][] diagonal = {{2, 1}, {-1, 0.5}, {0, -3}, {4, 0}};
        ZMatrixRMaj m = new ZMatrixRMaj(4, 4);
        Random r = new Random(5);
        for (int i = 0; i < 4; i++) {
            m.set(i, i, diagonal[i][0], diagonal[i][1]);
            for (int j = i + 1; j < 4; j++) {
                m.set(i, j, r.nextGaussian(), r.nextGaussian());
            }
        }
        ComplexEigen e = ComplexEigen.of(m);
        boolean[] used = new boolean[4];
        for (double[] expected : diagonal) {
            int nearest = -1;
            for (int k = 0; k < 4; k++) {
                if (!used[k] && Math.hypot(e.valueRe(k) - expected[0], e.valueIm(k) - expected[1]) < 1e-9) {
                    nearest = k;
                }
            }
            assertTrue(nearest >= 0, "eigenvalue " + expected[0] + " + " + expected[1] + "i found");
            used[nearest] = true;
        }
    }

    @Test
    void aRealSymmetricMatrixWithRepeatedEigenvaluesGivesIndependentVectors() {
        // diag(1, 1, 2) rotated: a real spectrum with a double eigenvalue, where the unshifted real twin would hold
        // every eigenvalue four times
        ZMatrixRMaj m = new ZMatrixRMaj(3, 3);
        double c = Math.cos(0.7);
        double s = Math.sin(0.7);
        double[][] q = {{c, -s, 0}, {s, c, 0}, {0, 0, 1}};
        double[] d = {1, 2, 1};
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double v = 0;
                for (int k = 0; k < 3; k++) {
                    v += q[i][k] * d[k] * q[j][k];
                }
                m.set(i, j, v, 0);
            }
        }
        ComplexEigen e = ComplexEigen.of(m);
        double[] values = {e.valueRe(0), e.valueRe(1), e.valueRe(2)};
        Arrays.sort(values);
        assertArrayEquals(new double[] {1, 1, 2}, values, 1e-12);
        for (int k = 0; k < 3; k++) {
            assertEquals(0, e.valueIm(k), 1e-12);
        }
        // the three vectors span the space: their determinant is far from 0
        ZMatrixRMaj v = e.vectors();
        double det = org.ejml.dense.row.CommonOps_ZDRM.det(v).getMagnitude();
        assertTrue(det > 0.1, "|det V| = " + det);
    }

    @Test
    void randomComplexMatricesHaveSmallResiduals() {
        Random r = new Random(11);
        for (int n : new int[] {1, 2, 7, 30, 61}) {
            ZMatrixRMaj m = new ZMatrixRMaj(n, n);
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    m.set(i, j, r.nextGaussian(), r.nextGaussian() * (i == j ? 3 : 1));
                }
            }
            ComplexEigen e = ComplexEigen.of(m); // refuses a pair whose residual exceeds 1e-8 |M|
            double trace = 0;
            double sum = 0;
            for (int k = 0; k < n; k++) {
                trace += m.getReal(k, k);
                sum += e.valueRe(k);
            }
            assertEquals(trace, sum, 1e-9 * n, "the eigenvalues sum to the trace, n = " + n);
        }
    }
}
