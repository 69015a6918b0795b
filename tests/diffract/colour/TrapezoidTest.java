package diffract.colour;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class TrapezoidTest {
    @Test
    void weightsOfANonUniformGrid() {
        assertArrayEquals(new double[] {0.5, 1.5, 2.5, 1.5}, Trapezoid.weights(new double[] {0, 1, 3, 6}), 0);
    }

    @Test
    void squareOnUnitIntervalHasTheKnownH2Error() {
        // For f = x^2 the trapezoid error on each interval of length h is exactly h^3 / 6.
        double[] coarse = Trapezoid.uniformNodes(0, 1, 0.1);
        double[] fine = Trapezoid.uniformNodes(0, 1, 0.05);
        double errCoarse = Trapezoid.integrate(coarse, x -> x * x) - 1.0 / 3;
        double errFine = Trapezoid.integrate(fine, x -> x * x) - 1.0 / 3;
        assertEquals(0.01 / 6, errCoarse, 1e-14);
        assertEquals(0.0025 / 6, errFine, 1e-14);
        assertEquals(4.0, errCoarse / errFine, 1e-9);
    }

    @Test
    void squareOnNonUniformNodes() {
        double[] nodes = {0, 0.1, 0.15, 0.5, 0.9, 1};
        double expectedError = 0;
        for (int i = 1; i < nodes.length; i++) {
            expectedError += Math.pow(nodes[i] - nodes[i - 1], 3) / 6;
        }
        assertEquals(1.0 / 3 + expectedError, Trapezoid.integrate(nodes, x -> x * x), 1e-15);
    }

    @Test
    void linearFunctionsAreExact() {
        assertEquals(0.5 * (9 - 1) + 3 * 2, Trapezoid.integrate(new double[] {1, 1.3, 2.9, 3}, x -> x + 3), 1e-14);
    }

    @Test
    void uniformNodesEndExactlyAtTo() {
        double[] oneNm = Trapezoid.uniformNodes(360, 830, 1);
        assertEquals(471, oneNm.length);
        assertEquals(360.0, oneNm[0]);
        assertEquals(829.0, oneNm[469]);
        assertEquals(830.0, oneNm[470]);

        double[] twentyFive = Trapezoid.uniformNodes(360, 830, 25);
        assertEquals(20, twentyFive.length);
        assertEquals(810.0, twentyFive[18]);
        assertEquals(830.0, twentyFive[19]);

        // A step that does not divide the range in binary: no drift, no sliver interval at the end.
        double[] tenths = Trapezoid.uniformNodes(0, 1, 0.1);
        assertEquals(11, tenths.length);
        assertEquals(0.7000000000000001, tenths[7]); // 7 * 0.1, computed not accumulated
        assertEquals(1.0, tenths[10]);

        assertArrayEquals(new double[] {400, 450}, Trapezoid.uniformNodes(400, 450, 100), 0);
    }

    @Test
    void rejectsBadInput() {
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.weights(new double[] {1}));
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.weights(new double[] {1, 1}));
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.weights(new double[] {1, 3, 2}));
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.weights(new double[] {1, Double.NaN}));
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.uniformNodes(2, 1, 0.1));
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.uniformNodes(1, 1, 0.1));
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.uniformNodes(0, 1, 0));
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.uniformNodes(0, 1, -1));
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.uniformNodes(0, Double.POSITIVE_INFINITY, 1));
        assertThrows(IllegalArgumentException.class, () -> Trapezoid.uniformNodes(0, 1, 1e-9));
    }
}
