package diffract.colour;

/**
 * Tristimulus values of a spectral reflectance seen under CIE illuminant D65 by the CIE 1931 2-degree
 * observer (the tristimulus integrals of CIE 015:2018, evaluated by a quadrature on caller-chosen nodes):
 *
 * <pre>
 *   X = sum_j w_j r_j S(l_j) xbar(l_j) / N,   Y = ... ybar ...,   Z = ... zbar ...,
 *   N = sum_j w_j S(l_j) ybar(l_j)
 * </pre>
 *
 * The normaliser N is computed with the same nodes and weights as the numerator, so a reflectance of 1 gives
 * Y = 1 exactly (to rounding) for any node set: a flat mirror is D65 white at unit luminance, however coarsely
 * the renderer samples wavelengths. X and Z of that white still depend slightly on the nodes: against the
 * 1 nm result (0.950470, 1, 1.088827) they move by about 1e-4 at 5 nm steps and up to 3e-3 at 25 nm steps
 * (chromaticity by 2e-4).
 */
public final class SpectralIntegrator {
    private SpectralIntegrator() {
    }

    /**
     * Per-node weights {wx, wy, wz}, already divided by N, so that XYZ = sum_j r_j {wx_j, wy_j, wz_j}. The
     * renderer's inner loop and the GPU's 1-D table use these instead of re-reading the CIE tables.
     *
     * @param quadratureWeights e.g. {@link Trapezoid#weights(double[])} of the same nodes
     * @throws IllegalArgumentException if the lengths differ, or if N is not positive (no node inside
     *         300..780 nm where both D65 and ybar are nonzero)
     */
    public static double[][] xyzWeights(double[] nodesNm, double[] quadratureWeights) {
        return xyzWeights(nodesNm, quadratureWeights, MirrorNormalisation.PEAK);
    }

    /**
     * As above with the mirror's spectrum of {@code normalisation}: each weight times its factor
     * ({@link MirrorNormalisation#factor}), the normaliser N unchanged.
     */
    public static double[][] xyzWeights(double[] nodesNm, double[] quadratureWeights,
                                        MirrorNormalisation normalisation) {
        if (nodesNm.length != quadratureWeights.length) {
            throw new IllegalArgumentException(nodesNm.length + " nodes but " + quadratureWeights.length + " weights");
        }
        double[][] w = new double[nodesNm.length][];
        double normaliser = 0;
        for (int j = 0; j < nodesNm.length; j++) {
            double lambda = nodesNm[j];
            double power = quadratureWeights[j] * D65.relativePower(lambda);
            w[j] = new double[] {
                power * Cie1931.xBar(lambda), power * Cie1931.yBar(lambda), power * Cie1931.zBar(lambda),
            };
            normaliser += w[j][1];
            double factor = normalisation.factor(lambda);
            w[j][0] *= factor;
            w[j][1] *= factor;
            w[j][2] *= factor;
        }
        if (!(normaliser > 0) || !Double.isFinite(normaliser)) {
            throw new IllegalArgumentException("the nodes see no D65 luminance (sum w S ybar = " + normaliser + ")");
        }
        for (double[] wj : w) {
            wj[0] /= normaliser;
            wj[1] /= normaliser;
            wj[2] /= normaliser;
        }
        return w;
    }

    /** XYZ = sum_j r_j * xyzWeights[j]. */
    public static Xyz weightedSum(double[][] xyzWeights, double[] reflectance) {
        if (xyzWeights.length != reflectance.length) {
            throw new IllegalArgumentException(
                    xyzWeights.length + " weights but " + reflectance.length + " reflectances");
        }
        double x = 0;
        double y = 0;
        double z = 0;
        for (int j = 0; j < reflectance.length; j++) {
            x += reflectance[j] * xyzWeights[j][0];
            y += reflectance[j] * xyzWeights[j][1];
            z += reflectance[j] * xyzWeights[j][2];
        }
        return new Xyz(x, y, z);
    }

    /**
     * XYZ of {@code reflectance} (one value per node, any sign or size) under D65, normalised so that
     * reflectance 1 gives Y = 1. See the class comment.
     */
    public static Xyz reflectedXyz(double[] nodesNm, double[] weights, double[] reflectance) {
        return weightedSum(xyzWeights(nodesNm, weights), reflectance);
    }
}
