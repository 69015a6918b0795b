package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.spectra.TaylorTerms;
import diffract.precompute.TaylorTermComputer;
import diffract.util.Reporter;
import diffract.util.TestReport;
import org.junit.jupiter.api.Test;

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

    private static void checkOrders(HeightField patch, Variant variant) {
        TaylorTerms terms = TaylorTermComputer.compute(patch, 30, Reporter.SILENT);
        DiffractionBrdf brdf = DiffractionBrdf.create(BrdfSettings.thesis(variant), patch, terms);
        DiffractionBrdf exact = DiffractionBrdf.create(BrdfSettings.thesis(Variant.REFERENCE), patch, null);
        double y = BrdfMap.yOf(MAP_SIZE / 2, MAP_SIZE); // y = -1/S, the map row through the incidence plane
        for (double thetaI : new double[] {0, 30, 75}) {
            Direction wi = Direction.fromSphericalDeg(thetaI, 0);
            for (double lambdaNm : new double[] {400, 550, 700}) {
                GratingOrders.assertOrders(GratingOrders.row(brdf, wi, lambdaNm, y, MAP_SIZE),
                        GratingOrders.row(exact, wi, lambdaNm, y, MAP_SIZE), PERIOD_UM, thetaI, lambdaNm, y, true,
                        variant + " theta_i " + thetaI + " lambda " + lambdaNm);
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
            TestReport.printf(GratingEquationTest.class, "blazed grating d = 2.5 um, %s: estimated d = %.4f nm%n", variant, estimate * 1e3);
            assertEquals(PERIOD_UM, estimate, 1e-3 * PERIOD_UM, variant + " estimated d = " + estimate + " um");
        }
    }
}
