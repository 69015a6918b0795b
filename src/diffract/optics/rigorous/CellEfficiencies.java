package diffract.optics.rigorous;

/**
 * What a 2-D cell does with a plane wave of one wavelength from one direction, as {@link OrderEfficiencies} says it
 * for a 1-D grating: each order (p, q)'s share of the incident power, reflected and transmitted, for s- and
 * p-polarised light. Order (p, q) leaves with the direction cosines (alpha_p, beta_q) = (alpha_0 + p lambda / L_x,
 * beta_0 + q lambda / L_y): the grating equation in both directions. The orders are held p fastest: index
 * (q + M_y) (2 M_x + 1) + p + M_x.
 *
 * @param lambdaUm     the wavelength, um
 * @param maxOrderX    M_x
 * @param maxOrderY    M_y
 * @param alpha        alpha of each order
 * @param beta         beta of each order
 * @param reflectedS   reflected efficiency per order, s-polarised incidence
 * @param reflectedP   reflected efficiency per order, p-polarised incidence
 * @param transmittedS transmitted efficiency per order, s
 * @param transmittedP transmitted efficiency per order, p
 */
public record CellEfficiencies(double lambdaUm, int maxOrderX, int maxOrderY, double[] alpha, double[] beta,
                               double[] reflectedS, double[] reflectedP, double[] transmittedS,
                               double[] transmittedP) {
    /** The orders held, (2 M_x + 1)(2 M_y + 1). */
    public int count() {
        return alpha.length;
    }

    /** p of the order at index i. */
    public int orderX(int index) {
        return index % (2 * maxOrderX + 1) - maxOrderX;
    }

    /** q of the order at index i. */
    public int orderY(int index) {
        return index / (2 * maxOrderX + 1) - maxOrderY;
    }

    /** The index of order (p, q), or -1 when it is not held. */
    public int index(int p, int q) {
        if (Math.abs(p) > maxOrderX || Math.abs(q) > maxOrderY) {
            return -1;
        }
        return (q + maxOrderY) * (2 * maxOrderX + 1) + p + maxOrderX;
    }

    /** The reflected efficiency of order (p, q) for unpolarised light (0 for an order not held). */
    public double reflected(int p, int q) {
        int i = index(p, q);
        return i < 0 ? 0 : 0.5 * (reflectedS[i] + reflectedP[i]);
    }

    /** Sum of the reflected efficiencies, unpolarised. */
    public double totalReflected() {
        return 0.5 * (sum(reflectedS) + sum(reflectedP));
    }

    /** R + T for s and for p: 1 for a lossless cell (energy conservation). */
    public double[] energy() {
        return new double[] {sum(reflectedS) + sum(transmittedS), sum(reflectedP) + sum(transmittedP)};
    }

    private static double sum(double[] values) {
        double s = 0;
        for (double v : values) {
            s += v;
        }
        return s;
    }
}
