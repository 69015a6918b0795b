package diffract.render;

import diffract.util.TestReport;
import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfMap;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.GratingOrders;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The monochromatic GPU map of a blazed grating puts its peaks where the grating equation says,
 * sin theta_r = m lambda / d - sin theta_i (001 chapter 5), with the logic of
 * {@code diffract.optics.GratingEquationTest}: along the map row through the incidence plane, every order that
 * propagates and is not dark in the exact reference (CPU) has a peak within 1 pixel of its predicted position, and
 * (FLSS) no other local maximum above 1e-12 of the peak shines (measured on llvmpipe: the strongest is 8e-33;
 * between the orders the Gaussian window's weights are themselves below 1e-30). PQ's Dirichlet kernel has R - 2 genuine side lobes between orders, so for
 * PQ only the orders are checked. The GPU row also equals the CPU row of the same variant to 1e-4 of the row's peak.
 */
@Tag("gl")
class GpuGratingEquationTest {
    static java.util.stream.Stream<Variant> flssAndPq() {
        return java.util.stream.Stream.of(Variant.FLSS, Variant.PQ);
    }

    private static final int MAP_SIZE = 256;
    private static final double PERIOD_UM = 2.5;
    /** GratingEquationTest's grating: 10 periods of 25 pixels, 4 rows, 0.13 um high. */
    private static final HeightField BLAZED = SyntheticPatches.blazed(PERIOD_UM, 0.13, 25, 10, 4).meanSubtracted();
    @ParameterizedTest
    @org.junit.jupiter.params.provider.MethodSource("flssAndPq")
    void ordersOfTheGpuMapAreWhereTheGratingEquationSays(Variant variant) {
        GlTestSupport.assumeOffscreenGl();
        TaylorTerms terms = TaylorTermComputer.compute(BLAZED, 30, Reporter.SILENT);
        BrdfSettings settings = BrdfSettings.thesis(variant);
        DiffractionBrdf cpu = DiffractionBrdf.create(settings, BLAZED, terms);
        DiffractionBrdf exact = DiffractionBrdf.create(BrdfSettings.thesis(Variant.REFERENCE), BLAZED, null);
        int mapRow = MAP_SIZE / 2; // y = -1/S, the map row through the incidence plane
        double y = BrdfMap.yOf(mapRow, MAP_SIZE);
        try (GpuBrdfMap gpu = new GpuBrdfMap(terms, settings)) {
            for (double thetaI : new double[] {0, 30, 75}) {
                Direction wi = Direction.fromSphericalDeg(thetaI, 0);
                for (double lambdaNm : new double[] {400, 550, 700}) {
                    float[] map = gpu.monochromatic(wi, lambdaNm, MAP_SIZE);
                    double[] values = new double[MAP_SIZE];
                    for (int i = 0; i < MAP_SIZE; i++) {
                        values[i] = map[mapRow * MAP_SIZE + i];
                    }
                    String where = variant + " theta_i " + thetaI + " lambda " + lambdaNm;
                    checkAgainstCpu(values, GratingOrders.row(cpu, wi, lambdaNm, y, MAP_SIZE), where);
                    int orders = GratingOrders.assertOrders(values, GratingOrders.row(exact, wi, lambdaNm, y, MAP_SIZE),
                            PERIOD_UM, thetaI, lambdaNm, y, variant == Variant.FLSS, where);
                    TestReport.printf(GpuGratingEquationTest.class, java.util.Locale.ROOT, "GPU grating equation, %s: %d orders in place%n", where, orders);
                }
            }
        }
    }

    private static void checkAgainstCpu(double[] gpu, double[] cpu, String where) {
        double peak = GratingOrders.max(cpu);
        double worst = 0;
        for (int i = 0; i < MAP_SIZE; i++) {
            assertTrue(Double.isFinite(gpu[i]), where + ": pixel " + i + " is " + gpu[i]);
            worst = Math.max(worst, Math.abs(gpu[i] - cpu[i]));
        }
        assertTrue(worst <= 1e-4 * peak, where + ": GPU differs from CPU by " + worst + " at peak " + peak);
        TestReport.printf(GpuGratingEquationTest.class, java.util.Locale.ROOT, "GPU vs CPU row, %s: largest difference %.2g of the peak%n", where,
                worst / peak);
    }

}
