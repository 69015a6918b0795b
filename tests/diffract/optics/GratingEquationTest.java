package diffract.optics;

import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The diffraction orders of gratings made by code sit where the grating equation puts them:
 * sin theta_r = m lambda / d - sin theta_i (001 chapter 5), with theta_r signed along the map's x axis.
 */
class GratingEquationTest {
    private static final int MAP_SIZE = 256;
    private static final double PERIOD_UM = 2.5;

    /** 0.13 um: no blaze extinction of an order inside 380-780 nm (k |w| h = 2 pi would put all light in one order). */
    private static final HeightField BLAZED = SyntheticPatches.blazed(PERIOD_UM, 0.13, 25, 10, 4).meanSubtracted();
    private static final HeightField SINUSOID = SyntheticPatches.sinusoid(PERIOD_UM, 0.3, 25, 10, 4).meanSubtracted();
    /**
     * Orders of a sinusoid fall off like Bessel functions J_m(k |w| h / 2)^2 (9th order ~ 1e-9 of the brightest):
     * dark, but far above float32 noise of the stored terms (~1e-16 in intensity), which is the floor used here.
     */
    private static final double DARK = 1e-12;

    @Test
    void blazedGratingOrdersInTheMapAreWhereTheGratingEquationSays() {
        checkOrders(BLAZED, Variant.FLSS);
        checkOrders(BLAZED, Variant.REFERENCE);
    }

    @Test
    void sinusoidalGratingOrdersInTheMapAreWhereTheGratingEquationSays() {
        checkOrders(SINUSOID, Variant.FLSS);
        checkOrders(SINUSOID, Variant.REFERENCE);
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

    private static void checkOrders(HeightField patch, Variant variant) {
        TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
        DiffractionBrdf brdf = DiffractionBrdf.create(BrdfSettings.thesis(variant), patch, terms);
        DiffractionBrdf exact = DiffractionBrdf.create(BrdfSettings.thesis(Variant.REFERENCE), patch, null);
        int mapRow = MAP_SIZE / 2; // y = -1/S, the map row through the incidence plane
        double y = BrdfMap.yOf(mapRow, MAP_SIZE);
        for (double thetaI : new double[] {0, 30, 75}) {
            Direction wi = Direction.fromSphericalDeg(thetaI, 0);
            for (double lambdaNm : new double[] {400, 550, 700}) {
                double[] values = row(brdf, wi, lambdaNm, y);
                double[] reference = row(exact, wi, lambdaNm, y);
                String where = variant + " theta_i " + thetaI + " lambda " + lambdaNm;
                // the orders that exist: propagating (inside the disk) and not dark in the exact model
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
                // and nothing else shines: every local maximum belongs to a predicted order
                for (int i = 1; i < MAP_SIZE - 1; i++) {
                    if (values[i] > DARK * rowMax && values[i] >= values[i - 1] && values[i] > values[i + 1]) {
                        final int peak = i;
                        boolean known = false;
                        for (int m = -20; m <= 20 && !known; m++) {
                            double x = m * lambdaNm * 1e-3 / PERIOD_UM - Math.sin(Math.toRadians(thetaI));
                            known = Math.abs((x + 1) * MAP_SIZE / 2 - 0.5 - peak) <= 1.0;
                        }
                        assertTrue(known, where + ": peak at pixel " + i + " where the grating equation has no order");
                    }
                }
            }
        }
    }

    /** As the thesis did (001 ch. 5: 2499.997 nm for d = 2.5 um): d from the first order at theta_i = 75 deg. */
    @Test
    void periodEstimatedFromTheFirstOrderAt75DegreesIsWithinAPerMille() {
        TaylorTerms terms = TaylorTermComputer.compute(BLAZED, 30, Reporter.SILENT);
        for (Variant variant : new Variant[] {Variant.FLSS, Variant.REFERENCE}) {
            DiffractionBrdf brdf = DiffractionBrdf.create(BrdfSettings.thesis(variant), BLAZED, terms);
            double estimate = PeakFinder.meanPeriodFromFirstOrderUm(brdf, 75, 0, 380, 780, 20);
            System.out.printf("blazed grating d = 2.5 um, %s: estimated d = %.4f nm%n", variant, estimate * 1e3);
            assertEquals(PERIOD_UM, estimate, 1e-3 * PERIOD_UM, variant + " estimated d = " + estimate + " um");
        }
    }
}
