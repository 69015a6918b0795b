package diffract.optics.rigorous;

/**
 * What a grating does with a plane wave of one wavelength from one direction: the fraction of the incident power
 * (through the same area) that each diffraction order carries away, reflected into the air and transmitted into the
 * substrate, for light polarised perpendicular to the plane of incidence (s, TE) and in it (p, TM); unpolarised light
 * carries their mean. Orders that do not propagate carry 0.
 *
 * <p>Order m leaves with the in-plane direction cosines (alpha_m, beta) = (alpha_0 + m lambda / period, beta) in the
 * grating's frame (alpha across the grooves): the grating equation.
 *
 * @param lambdaUm    the wavelength, um
 * @param firstOrder  the order of index 0 in the arrays (-M)
 * @param alpha       alpha_m of each order
 * @param beta        the direction cosine along the grooves (the same for every order)
 * @param reflectedS  reflected efficiency per order for s-polarised incidence
 * @param reflectedP  reflected efficiency per order for p-polarised incidence
 * @param transmittedS transmitted efficiency per order, s
 * @param transmittedP transmitted efficiency per order, p
 */
public record OrderEfficiencies(double lambdaUm, int firstOrder, double[] alpha, double beta, double[] reflectedS,
                                double[] reflectedP, double[] transmittedS, double[] transmittedP) {
    /** The orders held, -M..M. */
    public int count() {
        return alpha.length;
    }

    /** The order at array index i. */
    public int order(int index) {
        return firstOrder + index;
    }

    /** The array index of order m, or -1 when it is not held. */
    public int index(int order) {
        int i = order - firstOrder;
        return i >= 0 && i < alpha.length ? i : -1;
    }

    /** The reflected efficiency of order m for unpolarised light (0 for an order not held). */
    public double reflected(int order) {
        int i = index(order);
        return i < 0 ? 0 : 0.5 * (reflectedS[i] + reflectedP[i]);
    }

    /** The transmitted efficiency of order m for unpolarised light. */
    public double transmitted(int order) {
        int i = index(order);
        return i < 0 ? 0 : 0.5 * (transmittedS[i] + transmittedP[i]);
    }

    /** Sum of the reflected efficiencies, unpolarised. */
    public double totalReflected() {
        return 0.5 * (sum(reflectedS) + sum(reflectedP));
    }

    /** Sum of the transmitted efficiencies, unpolarised. */
    public double totalTransmitted() {
        return 0.5 * (sum(transmittedS) + sum(transmittedP));
    }

    /** R + T for s and for p: 1 for a lossless grating (energy conservation). */
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
