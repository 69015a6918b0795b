package diffract.optics;

import diffract.optics.patches.Direction;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Checks a BRDF-map row through the incidence plane of a 1-D grating against the grating equation
 * sin theta_r = m lambda / d - sin theta_i (001 chapter 5): shared by the CPU and the GPU grating tests.
 */
public final class GratingOrders {
    /**
     * Peaks below this fraction of the row's maximum count as dark: orders of a sinusoid fall off like Bessel
     * functions J_m(k |w| h / 2)^2 (the 9th order ~ 1e-9 of the brightest), far above the float32 noise of the
     * stored terms (~1e-16 in intensity), which is this floor.
     */
    public static final double DARK = 1e-12;

    private GratingOrders() {
    }

    /** The relative BRDF along map row y (pixel convention of {@link BrdfMap}), 0 outside the unit disk. */
    public static double[] row(DiffractionBrdf brdf, Direction wi, double lambdaNm, double y, int size) {
        double[] values = new double[size];
        for (int i = 0; i < size; i++) {
            double x = BrdfMap.xOf(i, size);
            values[i] = x * x + y * y < 1 ? brdf.relative(wi, Direction.fromProjected(x, y), lambdaNm) : 0;
        }
        return values;
    }

    /**
     * Every order that propagates (lies inside the disk) and is not dark in {@code reference} (the exact model)
     * is a peak of {@code values} within one pixel of its predicted position; with {@code nothingElseShines},
     * every other local maximum above {@link #DARK} of the row's peak is an error.
     *
     * @return the number of orders checked
     */
    public static int assertOrders(double[] values, double[] reference, double periodUm, double thetaIDeg,
                                   double lambdaNm, double y, boolean nothingElseShines, String where) {
        int size = values.length;
        List<Double> expected = new ArrayList<>();
        int geometric = 0;
        for (int m = -20; m <= 20; m++) {
            double pixel = predictedPixel(m, periodUm, thetaIDeg, lambdaNm, size);
            double x = m * lambdaNm * 1e-3 / periodUm - Math.sin(Math.toRadians(thetaIDeg));
            if (x * x + y * y < Math.pow(1 - 2.0 / size, 2)) {
                geometric++;
                if (reference[peakNear(reference, pixel)] > DARK * max(reference)) {
                    expected.add(pixel);
                }
            }
        }
        assertTrue(expected.size() >= Math.min(3, geometric), where + ": too few bright orders " + expected);
        double rowMax = max(values);
        for (double pixel : expected) {
            int best = peakNear(values, pixel);
            assertTrue(Math.abs(best - pixel) <= 1.0, where + ": order at pixel " + pixel + ", peak at " + best);
            assertTrue(values[best] > DARK * rowMax, where + ": order at " + pixel + " is dark");
        }
        if (nothingElseShines) {
            for (int i = 1; i < size - 1; i++) {
                if (values[i] > DARK * rowMax && values[i] >= values[i - 1] && values[i] > values[i + 1]) {
                    boolean known = false;
                    for (int m = -20; m <= 20 && !known; m++) {
                        known = Math.abs(predictedPixel(m, periodUm, thetaIDeg, lambdaNm, size) - i) <= 1.0;
                    }
                    assertTrue(known, where + ": peak at pixel " + i + " (" + values[i] / rowMax
                            + " of the maximum) where the grating equation has no order");
                }
            }
        }
        return expected.size();
    }

    /** The (fractional) pixel column of order m: x = m lambda / d - sin theta_i. */
    static double predictedPixel(int m, double periodUm, double thetaIDeg, double lambdaNm, int size) {
        double x = m * lambdaNm * 1e-3 / periodUm - Math.sin(Math.toRadians(thetaIDeg));
        return (x + 1) * size / 2 - 0.5;
    }

    public static double max(double[] values) {
        double m = 0;
        for (double v : values) {
            m = Math.max(m, v);
        }
        return m;
    }

    /** Index of the largest value within 3 pixels of {@code pixel}. */
    static int peakNear(double[] values, double pixel) {
        int size = values.length;
        int centre = (int) Math.round(pixel);
        int best = Math.max(1, Math.min(size - 2, centre));
        for (int i = Math.max(1, centre - 3); i <= Math.min(size - 2, centre + 3); i++) {
            if (values[i] > values[best]) {
                best = i;
            }
        }
        return best;
    }
}
