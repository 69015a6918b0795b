package diffract.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.junit.jupiter.api.Test;

class SpectralIntegratorTest {
    private static double[] ones(int n) {
        double[] r = new double[n];
        Arrays.fill(r, 1.0);
        return r;
    }

    private static Xyz mirror(double[] nodes) {
        return SpectralIntegrator.reflectedXyz(nodes, Trapezoid.weights(nodes), ones(nodes.length));
    }

    // 360..830 nm with steps cycling through 2, 5 and 9 nm (the last one cut to end at 830).
    private static double[] irregularNodes() {
        double[] steps = {2, 5, 9};
        java.util.List<Double> nodes = new java.util.ArrayList<>();
        double lambda = 360;
        for (int i = 0; lambda < 830; i++) {
            nodes.add(lambda);
            lambda += steps[i % steps.length];
        }
        nodes.add(830.0);
        return nodes.stream().mapToDouble(Double::doubleValue).toArray();
    }

    @Test
    void unitReflectanceIsD65WhiteAtYOneForAnyNodes() {
        double[][] nodeSets = {
            Trapezoid.uniformNodes(360, 830, 1),
            Trapezoid.uniformNodes(360, 830, 5),
            Trapezoid.uniformNodes(360, 830, 25),
            Trapezoid.uniformNodes(380, 780, 7.3),
            irregularNodes(),
        };
        for (double[] nodes : nodeSets) {
            Xyz white = mirror(nodes);
            String label = nodes.length + " nodes";
            assertEquals(1.0, white.y(), 1e-12, label);
            assertEquals(0.3127, white.chromaticityX(), 1e-3, label);
            assertEquals(0.3290, white.chromaticityY(), 1e-3, label);
        }
    }

    @Test
    void scalesLinearlyWithReflectance() {
        double[] nodes = Trapezoid.uniformNodes(360, 830, 5);
        double[] half = ones(nodes.length);
        Arrays.fill(half, 0.5);
        Xyz xyz = SpectralIntegrator.reflectedXyz(nodes, Trapezoid.weights(nodes), half);
        assertEquals(0.5, xyz.y(), 1e-12);
        assertEquals(0.5 * mirror(nodes).x(), xyz.x(), 1e-12);
    }

    @Test
    void singleNodeReflectanceLiesOnTheSpectralLocus() {
        // Reflectance 1 at the 550 nm node only: XYZ is proportional to the CMFs there.
        double[] nodes = Trapezoid.uniformNodes(360, 830, 1);
        double[] r = new double[nodes.length];
        r[550 - 360] = 1;
        Xyz xyz = SpectralIntegrator.reflectedXyz(nodes, Trapezoid.weights(nodes), r);
        double sum = Cie1931.xBar(550) + Cie1931.yBar(550) + Cie1931.zBar(550);
        assertEquals(Cie1931.xBar(550) / sum, xyz.chromaticityX(), 1e-12);
        assertEquals(Cie1931.yBar(550) / sum, xyz.chromaticityY(), 1e-12);
    }

    @Test
    void narrowBandAt550NmIsGreenNearTheLocus() {
        double[] nodes = Trapezoid.uniformNodes(360, 830, 1);
        double[] r = new double[nodes.length];
        for (int j = 0; j < nodes.length; j++) {
            r[j] = Math.exp(-0.5 * Math.pow((nodes[j] - 550) / 2.0, 2)); // Gaussian, sigma 2 nm
        }
        Xyz xyz = SpectralIntegrator.reflectedXyz(nodes, Trapezoid.weights(nodes), r);
        double sum = Cie1931.xBar(550) + Cie1931.yBar(550) + Cie1931.zBar(550);
        // Spectral locus at 550 nm: (0.3016, 0.6923).
        assertEquals(Cie1931.xBar(550) / sum, xyz.chromaticityX(), 2e-3);
        assertEquals(Cie1931.yBar(550) / sum, xyz.chromaticityY(), 2e-3);
        double[] rgb = Srgb.linearFromXyz(xyz);
        assertTrue(rgb[1] > rgb[0] && rgb[1] > rgb[2], "green dominates: " + Arrays.toString(rgb));
    }

    @Test
    void precomputedWeightsGiveTheSameXyz() {
        double[] nodes = Trapezoid.uniformNodes(380, 780, 10);
        double[] quadrature = Trapezoid.weights(nodes);
        double[] r = new double[nodes.length];
        for (int j = 0; j < r.length; j++) {
            r[j] = 0.5 + 0.4 * Math.sin(nodes[j] / 37.0);
        }
        double[][] w = SpectralIntegrator.xyzWeights(nodes, quadrature);
        double ySum = 0;
        for (double[] wj : w) {
            ySum += wj[1];
        }
        assertEquals(1.0, ySum, 1e-12);
        // Against the definition X = sum w r S xbar / sum w S ybar, written out directly.
        double x = 0;
        double n = 0;
        for (int j = 0; j < nodes.length; j++) {
            x += quadrature[j] * r[j] * D65.relativePower(nodes[j]) * Cie1931.xBar(nodes[j]);
            n += quadrature[j] * D65.relativePower(nodes[j]) * Cie1931.yBar(nodes[j]);
        }
        Xyz xyz = SpectralIntegrator.weightedSum(w, r);
        assertEquals(x / n, xyz.x(), 1e-12);
        assertEquals(xyz, SpectralIntegrator.reflectedXyz(nodes, quadrature, r));
    }

    @Test
    void rejectsMismatchedOrInvisibleInput() {
        double[] nodes = {500, 510, 520};
        assertThrows(IllegalArgumentException.class, () -> SpectralIntegrator.xyzWeights(nodes, new double[] {1, 1}));
        assertThrows(IllegalArgumentException.class,
                () -> SpectralIntegrator.reflectedXyz(nodes, Trapezoid.weights(nodes), new double[] {1}));
        double[] infrared = {900, 950};
        assertThrows(IllegalArgumentException.class,
                () -> SpectralIntegrator.xyzWeights(infrared, Trapezoid.weights(infrared)));
    }
}
