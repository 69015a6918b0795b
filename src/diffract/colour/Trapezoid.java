package diffract.colour;

import java.util.function.DoubleUnaryOperator;

/**
 * The composite trapezoid rule on strictly increasing, possibly non-uniform nodes:
 * integral of f ~ sum_j w_j f(x_j) with w_0 = (x_1 - x_0)/2, w_j = (x_{j+1} - x_{j-1})/2,
 * w_{n-1} = (x_{n-1} - x_{n-2})/2. On uniform spacing h it overestimates the integral by
 * (b - a) h^2 f''(xi)/12 for some xi in [a, b]. CIE 015:2018 computes tristimulus values as the plain sum
 * sum S xbar dlambda at 1 nm; on 1 nm nodes over 360..830 nm the trapezoid rule differs from that only by
 * halving the two end nodes, where the colour-matching functions are below 1e-3.
 */
public final class Trapezoid {
    // uniformNodes refuses grids larger than this, which would only come from a mistyped step.
    static final int MAX_NODES = 1 << 24;

    private Trapezoid() {
    }

    /**
     * Trapezoid weights for {@code nodesNm}.
     *
     * @throws IllegalArgumentException for fewer than 2 nodes, or nodes that are not finite and strictly increasing
     */
    public static double[] weights(double[] nodesNm) {
        requireIncreasing(nodesNm);
        int n = nodesNm.length;
        double[] w = new double[n];
        w[0] = 0.5 * (nodesNm[1] - nodesNm[0]);
        for (int j = 1; j < n - 1; j++) {
            w[j] = 0.5 * (nodesNm[j + 1] - nodesNm[j - 1]);
        }
        w[n - 1] = 0.5 * (nodesNm[n - 1] - nodesNm[n - 2]);
        return w;
    }

    /** Trapezoid-rule integral of {@code f} over [first node, last node]. */
    public static double integrate(double[] nodesNm, DoubleUnaryOperator f) {
        double[] w = weights(nodesNm);
        double sum = 0;
        for (int j = 0; j < w.length; j++) {
            sum += w[j] * f.applyAsDouble(nodesNm[j]);
        }
        return sum;
    }

    /**
     * The nodes from, from + step, from + 2 step, ... that are below {@code toNm}, then {@code toNm} itself:
     * the last interval may be shorter than {@code stepNm}, and the last node is exactly {@code toNm}. A node
     * within 1e-9 step of {@code toNm} is dropped in favour of {@code toNm}, so that (360, 830, 1) gives
     * exactly 471 nodes despite rounding. Nodes are computed as from + k step, so rounding does not accumulate.
     *
     * @throws IllegalArgumentException unless from &lt; to and step &gt; 0 are finite, or if the grid would
     *         have more than 2^24 nodes
     */
    public static double[] uniformNodes(double fromNm, double toNm, double stepNm) {
        if (!Double.isFinite(fromNm) || !Double.isFinite(toNm) || !(fromNm < toNm)) {
            throw new IllegalArgumentException("need finite from < to, got " + fromNm + " .. " + toNm + " nm");
        }
        if (!Double.isFinite(stepNm) || !(stepNm > 0)) {
            throw new IllegalArgumentException("step must be positive and finite, got " + stepNm + " nm");
        }
        double intervals = (toNm - fromNm) / stepNm;
        if (intervals > MAX_NODES) {
            throw new IllegalArgumentException("a step of " + stepNm + " nm over " + fromNm + " .. " + toNm
                    + " nm gives more than " + MAX_NODES + " nodes");
        }
        // Nodes from + k step for k = 0 .. inner lie below to - 1e-9 step (k = 0 always kept).
        int inner = Math.max(0, (int) Math.ceil(intervals - 1e-9) - 1);
        double[] nodes = new double[inner + 2];
        for (int k = 0; k <= inner; k++) {
            nodes[k] = fromNm + k * stepNm;
        }
        nodes[inner + 1] = toNm;
        return nodes;
    }

    private static void requireIncreasing(double[] nodesNm) {
        if (nodesNm.length < 2) {
            throw new IllegalArgumentException("the trapezoid rule needs at least 2 nodes, got " + nodesNm.length);
        }
        for (int j = 0; j < nodesNm.length; j++) {
            if (!Double.isFinite(nodesNm[j])) {
                throw new IllegalArgumentException("node " + j + " is not finite: " + nodesNm[j]);
            }
            if (j > 0 && !(nodesNm[j] > nodesNm[j - 1])) {
                throw new IllegalArgumentException("nodes must increase strictly, but node " + j + " = "
                        + nodesNm[j] + " follows " + nodesNm[j - 1]);
            }
        }
    }
}
