package diffract.optics.numerics;

/**
 * Gauss-Legendre nodes and weights on [0, 1]: the n-point rule exact for polynomials of degree 2n - 1 (Abramowitz and
 * Stegun 25.4.29). The nodes are the roots of P_n, found by Newton's method from Tricomi's estimate
 * cos(pi (i - 1/4) / (n + 1/2)) (Numerical Recipes, gauleg), P_n and P_n' from the three-term recurrence
 * (k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1}; the weight on [-1, 1] is 2 / ((1 - x^2) P_n'(x)^2), halved on [0, 1].
 */
public final class GaussLegendre {
    private GaussLegendre() {
    }

    /** {nodes, weights} of the n-point rule on [0, 1], the weights summing to 1. */
    public static double[][] unitInterval(int n) {
        if (n < 1) {
            throw new IllegalArgumentException("a Gauss-Legendre rule needs at least one node, got " + n);
        }
        double[] nodes = new double[n];
        double[] weights = new double[n];
        for (int i = 0; i < (n + 1) / 2; i++) {
            double x = Math.cos(Math.PI * (i + 0.75) / (n + 0.5));
            double derivative = 0;
            for (int iteration = 0; iteration < 100; iteration++) {
                double p0 = 1;
                double p1 = x;
                for (int k = 1; k < n; k++) {
                    double p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
                    p0 = p1;
                    p1 = p2;
                }
                // P_n = p1, P_{n-1} = p0 (for n = 1: P_1 = x, P_0 = 1); P_n' = n (x P_n - P_{n-1}) / (x^2 - 1)
                derivative = n * (x * p1 - p0) / (x * x - 1);
                double step = p1 / derivative;
                x -= step;
                if (Math.abs(step) < 1e-15) {
                    break;
                }
            }
            double w = 1.0 / ((1 - x * x) * derivative * derivative); // half of 2 / ((1 - x^2) P_n'^2)
            nodes[i] = 0.5 * (1 - x);
            nodes[n - 1 - i] = 0.5 * (1 + x);
            weights[i] = w;
            weights[n - 1 - i] = w;
        }
        return new double[][] {nodes, weights};
    }
}
