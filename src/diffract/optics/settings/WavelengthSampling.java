package diffract.optics.settings;

import diffract.colour.MirrorNormalisation;
import diffract.colour.SpectralIntegrator;
import diffract.colour.Trapezoid;

import java.util.Arrays;

/**
 * Which wavelengths a variant integrates over, with their quadrature weights (004 eq. {@code finalexpression}
 * integrates over Lambda = [380, 780] nm). Each rule carries its CMF x D65 weights, normalised over its own nodes,
 * so that a reflectance of 1 gives exactly D65 white (Y = 1) whatever the nodes.
 */
public abstract class WavelengthSampling {

    /** The nodes and XYZ weights for a lookup direction (u, v). */
    public abstract Quadrature quadratureFor(double u, double v);

    /** Nodes (nm) and per-node XYZ weights {wx, wy, wz}: XYZ = sum_j reflectance_j * weights_j. */
    public record Quadrature(double[] lambdasNm, double[][] xyzWeights) {
        static Quadrature trapezoid(double[] nodesNm, MirrorNormalisation normalisation) {
            return new Quadrature(nodesNm, SpectralIntegrator.xyzWeights(nodesNm, Trapezoid.weights(nodesNm),
                    normalisation));
        }
    }

    /** FLSS, PQ and the reference: lambda_min, lambda_min + step, ..., lambda_max, trapezoid rule (003 sec. 1.3.2). */
    public static WavelengthSampling uniform(double lambdaMinNm, double lambdaMaxNm, double stepNm) {
        return uniform(lambdaMinNm, lambdaMaxNm, stepNm, MirrorNormalisation.PEAK);
    }

    /** As above with the mirror's normalisation. */
    public static WavelengthSampling uniform(double lambdaMinNm, double lambdaMaxNm, double stepNm,
                                             MirrorNormalisation normalisation) {
        Quadrature q = Quadrature.trapezoid(Trapezoid.uniformNodes(lambdaMinNm, lambdaMaxNm, stepNm), normalisation);
        return new WavelengthSampling() {
            @Override
            public Quadrature quadratureFor(double u, double v) {
                return q;
            }
        };
    }

    /**
     * NMM (003 section 1.5.2, bounds re-derived from eq. 1.8): the lookup s(u) = u L / lambda lands exactly on DFT
     * texel m when lambda = |u| L / m, so the nodes are those wavelengths for the x and the y axis (m = 1, 2, ...
     * within [lambda_min, lambda_max]), merged and sorted, plus the two interval ends. The trapezoid rule on these
     * non-uniform nodes weights each node by the spacing of its neighbours, i.e. by the Jacobian
     * |d lambda / d m| = lambda^2 / (|u| L): the thesis summed the nodes with equal weights, which over-weights
     * the short wavelengths (nodes crowd there) and rendered purple. Where fewer than two texel crossings fall in
     * the interval (near the specular direction, (u, v) -> 0), it falls back to the uniform grid (the thesis
     * returned white there).
     */
    public static WavelengthSampling nmm(double lambdaMinNm, double lambdaMaxNm, double fallbackStepNm,
                                         double extentXUm, double extentYUm, int maxNodes,
                                         MirrorNormalisation normalisation) {
        WavelengthSampling fallback = uniform(lambdaMinNm, lambdaMaxNm, fallbackStepNm, normalisation);
        return new WavelengthSampling() {
            @Override
            public Quadrature quadratureFor(double u, double v) {
                double[] nodes = nmmNodes(Math.abs(u) * extentXUm * 1e3, Math.abs(v) * extentYUm * 1e3,
                        lambdaMinNm, lambdaMaxNm, maxNodes);
                if (nodes == null) {
                    return fallback.quadratureFor(u, v);
                }
                return Quadrature.trapezoid(nodes, normalisation);
            }
        };
    }

    /**
     * lambda_m = S / m for S in {|u| L_x, |v| L_y} (nm), m >= 1, inside [min, max], merged with the ends;
     * null when fewer than two crossings exist or more than maxNodes would be needed.
     */
    static double[] nmmNodes(double sxNm, double syNm, double lambdaMinNm, double lambdaMaxNm, int maxNodes) {
        int countX = crossings(sxNm, lambdaMinNm, lambdaMaxNm);
        int countY = crossings(syNm, lambdaMinNm, lambdaMaxNm);
        if (countX + countY < 2 || countX + countY + 2 > maxNodes) {
            return null;
        }
        double[] nodes = new double[countX + countY + 2];
        int k = 0;
        nodes[k++] = lambdaMinNm;
        nodes[k++] = lambdaMaxNm;
        k = appendCrossings(sxNm, lambdaMinNm, lambdaMaxNm, nodes, k);
        k = appendCrossings(syNm, lambdaMinNm, lambdaMaxNm, nodes, k);
        Arrays.sort(nodes, 0, k);
        // merge coincident nodes (e.g. u L_x = v L_y): the trapezoid rule needs strictly increasing nodes
        int unique = 1;
        for (int i = 1; i < k; i++) {
            if (nodes[i] - nodes[unique - 1] > 1e-9) {
                nodes[unique++] = nodes[i];
            }
        }
        return unique < 3 ? null : Arrays.copyOf(nodes, unique);
    }

    /** Number of integers m >= 1 with min <= S / m <= max. */
    private static int crossings(double sNm, double lambdaMinNm, double lambdaMaxNm) {
        if (!(sNm > 0)) {
            return 0;
        }
        long first = (long) Math.ceil(sNm / lambdaMaxNm);
        long last = (long) Math.floor(sNm / lambdaMinNm);
        first = Math.max(first, 1);
        return (int) Math.max(0, Math.min(Integer.MAX_VALUE / 4, last - first + 1));
    }

    private static int appendCrossings(double sNm, double lambdaMinNm, double lambdaMaxNm, double[] nodes, int k) {
        if (!(sNm > 0)) {
            return k;
        }
        long first = Math.max(1, (long) Math.ceil(sNm / lambdaMaxNm));
        long last = (long) Math.floor(sNm / lambdaMinNm);
        for (long m = first; m <= last; m++) {
            double lambda = sNm / m;
            if (lambda > lambdaMinNm && lambda < lambdaMaxNm) {
                nodes[k++] = lambda;
            }
        }
        return k;
    }
}
