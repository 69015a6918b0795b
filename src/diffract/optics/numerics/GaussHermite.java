package diffract.optics.numerics;

/**
 * Gauss-Hermite rules for the expectation of a function of a normal variable: E[f(t)], t ~ N(0, sigma^2), is
 * sum_k weight_k f(sigma node_k) (probabilists' nodes; the weights sum to 1). Tabulated for 1..8 nodes.
 */
public final class GaussHermite {
    public static final int MAX_NODES = 8;
    private static final double[][] NODES = new double[MAX_NODES + 1][];
    private static final double[][] WEIGHTS = new double[MAX_NODES + 1][];

    static {
        // Golub-Welsch: the eigenvalues of the Jacobi matrix of the probabilists' Hermite polynomials (off-diagonal
        // sqrt(k)) are the nodes, the squared first components of the eigenvectors the weights
        for (int n = 1; n <= MAX_NODES; n++) {
            double[] diagonal = new double[n];
            double[] offDiagonal = new double[n];
            for (int k = 1; k < n; k++) {
                offDiagonal[k] = Math.sqrt(k);
            }
            org.apache.commons.math3.linear.EigenDecomposition e = new org.apache.commons.math3.linear.EigenDecomposition(
                    diagonal, java.util.Arrays.copyOfRange(offDiagonal, 1, n));
            double[] nodes = e.getRealEigenvalues();
            double[] weights = new double[n];
            for (int k = 0; k < n; k++) {
                double first = e.getEigenvector(k).getEntry(0);
                weights[k] = first * first;
            }
            NODES[n] = nodes;
            WEIGHTS[n] = weights;
        }
    }

    private GaussHermite() {
    }

    /** The nodes of the n-point rule for N(0, 1). */
    public static double[] nodes(int n) {
        return NODES[n].clone();
    }

    /** The weights of the n-point rule (they sum to 1). */
    public static double[] weights(int n) {
        return WEIGHTS[n].clone();
    }
}
