package diffract.render;

import diffract.jrtr.FloatTextureArray;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.Direction;
import diffract.optics.HeightField;
import diffract.optics.SyntheticPatches;
import diffract.optics.TaylorTerms;
import diffract.optics.Variant;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The monochromatic GPU map of a blazed grating puts its peaks where the grating equation says,
 * sin theta_r = m lambda / d - sin theta_i (001 chapter 5), with the logic of
 * {@code diffract.optics.GratingEquationTest}: along the map row through the incidence plane, every order that
 * propagates and is not dark in the exact reference (CPU) has a peak within 1 pixel of its predicted position, and
 * (FLSS) no other local maximum shines. PQ's Dirichlet kernel has R - 2 genuine side lobes between orders, so for
 * PQ only the orders are checked. The GPU row also equals the CPU row of the same variant to 1e-4 of the row's peak.
 */
@Tag("gl")
class GpuGratingEquationTest {
    private static final int MAP_SIZE = 256;
    private static final double PERIOD_UM = 2.5;
    /** GratingEquationTest's grating: 10 periods of 25 pixels, 4 rows, 0.13 um high. */
    private static final HeightField BLAZED = SyntheticPatches.blazed(PERIOD_UM, 0.13, 25, 10, 4).meanSubtracted();
    /**
     * Peaks below this fraction of the row's maximum count as dark, as in the CPU test (the float32 noise floor of
     * the stored terms). Summing in float32 does not raise it: between the orders the Gaussian window's weights
     * are themselves below 1e-30, and the strongest maximum off the orders measured on llvmpipe is 8e-33 of the
     * row's peak.
     */
    private static final double DARK = 1e-12;

    @ParameterizedTest
    @EnumSource(value = Variant.class, names = {"FLSS", "PQ"})
    void ordersOfTheGpuMapAreWhereTheGratingEquationSays(Variant variant) {
        RenderTestSupport.assumeDisplay();
        TaylorTerms terms = TaylorTermComputer.compute(BLAZED, 30, Reporter.SILENT);
        BrdfSettings settings = BrdfSettings.thesis(variant);
        DiffractionBrdf cpu = DiffractionBrdf.create(settings, BLAZED, terms);
        DiffractionBrdf exact = DiffractionBrdf.create(BrdfSettings.thesis(Variant.REFERENCE), BLAZED, null);
        int mapRow = MAP_SIZE / 2; // y = -1/S, the map row through the incidence plane
        double y = BrdfMap.yOf(mapRow, MAP_SIZE);
        try (GpuBrdfMap gpu = new GpuBrdfMap(terms, settings, FloatTextureArray.Precision.FLOAT32)) {
            for (double thetaI : new double[] {0, 30, 75}) {
                Direction wi = Direction.fromSphericalDeg(thetaI, 0);
                for (double lambdaNm : new double[] {400, 550, 700}) {
                    float[] map = gpu.monochromatic(wi, lambdaNm, MAP_SIZE);
                    double[] values = new double[MAP_SIZE];
                    for (int i = 0; i < MAP_SIZE; i++) {
                        values[i] = map[mapRow * MAP_SIZE + i];
                    }
                    String where = variant + " theta_i " + thetaI + " lambda " + lambdaNm;
                    checkAgainstCpu(values, row(cpu, wi, lambdaNm, y), where);
                    checkOrders(values, row(exact, wi, lambdaNm, y), thetaI, lambdaNm, y,
                            variant == Variant.FLSS, where);
                }
            }
        }
    }

    private static void checkAgainstCpu(double[] gpu, double[] cpu, String where) {
        double peak = max(cpu);
        double worst = 0;
        for (int i = 0; i < MAP_SIZE; i++) {
            assertTrue(Double.isFinite(gpu[i]), where + ": pixel " + i + " is " + gpu[i]);
            worst = Math.max(worst, Math.abs(gpu[i] - cpu[i]));
        }
        assertTrue(worst <= 1e-4 * peak, where + ": GPU differs from CPU by " + worst + " at peak " + peak);
        System.out.printf(java.util.Locale.ROOT, "GPU vs CPU row, %s: largest difference %.2g of the peak%n", where,
                worst / peak);
    }

    private static void checkOrders(double[] values, double[] reference, double thetaI, double lambdaNm, double y,
                                    boolean nothingElseShines, String where) {
        List<Double> expected = new ArrayList<>();
        int geometric = 0;
        for (int m = -20; m <= 20; m++) {
            double x = m * lambdaNm * 1e-3 / PERIOD_UM - Math.sin(Math.toRadians(thetaI));
            if (x * x + y * y < Math.pow(1 - 2.0 / MAP_SIZE, 2)) {
                geometric++;
                double pixel = (x + 1) * MAP_SIZE / 2 - 0.5;
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
        if (!nothingElseShines) {
            return;
        }
        double strongestUnexplained = 0;
        for (int i = 1; i < MAP_SIZE - 1; i++) {
            if (values[i] > 0 && values[i] >= values[i - 1] && values[i] > values[i + 1]) {
                boolean known = false;
                for (int m = -20; m <= 20 && !known; m++) {
                    double x = m * lambdaNm * 1e-3 / PERIOD_UM - Math.sin(Math.toRadians(thetaI));
                    known = Math.abs((x + 1) * MAP_SIZE / 2 - 0.5 - i) <= 1.0;
                }
                if (!known) {
                    strongestUnexplained = Math.max(strongestUnexplained, values[i] / rowMax);
                }
                assertTrue(known || values[i] <= DARK * rowMax, where + ": peak at pixel " + i + " ("
                        + values[i] / rowMax + " of the maximum) where the grating equation has no order");
            }
        }
        System.out.printf(java.util.Locale.ROOT, "GPU grating equation, %s: %d orders in place, strongest "
                + "unexplained maximum %.2g of the row's peak%n", where, expected.size(), strongestUnexplained);
    }

    private static double[] row(DiffractionBrdf brdf, Direction wi, double lambdaNm, double y) {
        double[] values = new double[MAP_SIZE];
        for (int i = 0; i < MAP_SIZE; i++) {
            double x = BrdfMap.xOf(i, MAP_SIZE);
            values[i] = x * x + y * y < 1 ? brdf.relative(wi, Direction.fromProjected(x, y), lambdaNm) : 0;
        }
        return values;
    }

    private static double max(double[] values) {
        double m = 0;
        for (double v : values) {
            m = Math.max(m, v);
        }
        return m;
    }

    /** Index of the largest value within 3 pixels of {@code pixel}. */
    private static int peakNear(double[] values, double pixel) {
        int centre = (int) Math.round(pixel);
        int best = Math.max(1, Math.min(MAP_SIZE - 2, centre));
        for (int i = Math.max(1, centre - 3); i <= Math.min(MAP_SIZE - 2, centre + 3); i++) {
            if (values[i] > values[best]) {
                best = i;
            }
        }
        return best;
    }
}
