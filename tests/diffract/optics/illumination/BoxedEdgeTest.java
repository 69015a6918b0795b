package diffract.optics.illumination;

import diffract.optics.numerics.ErrorFunction;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * BoxedEdge against the average of Phi over the box taken by brute force (a midpoint rule of 400 x 400 points over
 * the two uniforms), across the trapezoid, the uniform and the point regimes, both sides of the edge and both erfc's.
 */
class BoxedEdgeTest {
    private static double bruteForce(double d, double ha, double hb, double s) {
        int n = 400;
        double sum = 0;
        for (int i = 0; i < n; i++) {
            double x = ha * (-1 + (2 * i + 1.0) / n);
            for (int j = 0; j < n; j++) {
                double y = hb * (-1 + (2 * j + 1.0) / n);
                sum += ErrorFunction.normalCdf((d + x + y) / s, false);
            }
        }
        return sum / ((double) n * n);
    }

    @Test
    void theClosedFormIsTheBoxsAverage() {
        double s = 0.003;
        double[][] boxes = {{0.0156, 0.011}, {0.0156, 0.0156}, {0.02, 0.0001}, {0.0156, 0}, {1e-6, 5e-7}, {0.004, 0.001}};
        for (double[] box : boxes) {
            for (double d : new double[] {-0.05, -0.025, -0.012, -0.004, 0, 0.003, 0.01, 0.02, 0.04}) {
                double expected = bruteForce(d, box[0], box[1], s);
                String where = "d " + d + ", half-widths " + box[0] + ", " + box[1];
                assertEquals(expected, BoxedEdge.average(d, box[0], box[1], s, false), 2e-5, where);
                assertEquals(expected, BoxedEdge.average(d, box[1], box[0], s, false), 2e-5, where + " swapped");
                assertEquals(expected, BoxedEdge.average(d, box[0], box[1], s, true), 2e-5, where + " fast erfc");
            }
        }
    }

    /** Beyond the box's half-widths and five blurs the edge is dark (or full), where the box's Gaussian leaks. */
    @Test
    void theBoxEndsWhereItEnds() {
        double s = 0.002;
        double h = 0.0156;
        double beyond = -(h + 0.006 + 5 * s);
        assertEquals(0, BoxedEdge.average(beyond, h, 0.006, s, false), 1e-6);
        assertEquals(1, BoxedEdge.average(-beyond, h, 0.006, s, false), 1e-6);
        double gaussianBox = ErrorFunction.normalCdf(beyond / Math.sqrt(s * s + (h * h + 0.006 * 0.006) / 3), false);
        assertTrue(gaussianBox > 3e-4, "the Gaussian of the box's variance leaks " + gaussianBox);
    }
}
