package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.rigorous.Resolution;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.settings.GainModel;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.optics.validity.OrderComparison;
import diffract.util.DiskCache;
import diffract.util.Reporter;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The rigorous method as a method: how it reads a patch (1-D along x or y, repeats), where its orders land on a map
 * (the grating equation, on the same side as the scalar model's), that Rayleigh-Rice's scalar gain matches it on a
 * shallow grating where Stam's does not, the disk cache of its orders, and its refusal of 2-D patches.
 */
class RigorousMethodTest {
    private static final HeightField BLAZED = SyntheticPatches.blazed(2.5, 0.2, 25, 4, 4).meanSubtracted();

    private static BrdfSettings settings() {
        return BrdfSettings.thesis(Variant.RIGOROUS).with(b -> b.lambdaStepNm(10)
                .rigorous(RigorousSettings.DEFAULT.withResolution(new Resolution(0, 12, true))));
    }

    @Test
    void aPatchOfWholePeriodsIsSolvedOnOnePeriodAlongItsAxis() {
        RigorousPatch x = RigorousPatch.of(BLAZED);
        assertTrue(x.oneDimensional());
        assertEquals(RigorousPatch.Axis.X, x.axis());
        assertEquals(4, x.repeats());
        assertEquals(2.5, x.profile().periodUm(), 1e-12);
        assertEquals(0.2 * 24 / 25, x.profile().depthUm(), 1e-12);
        // order m lands on texel -m P: order -1 of a 4-period patch on texel +4 along x
        assertEquals(List.of(4, 0), List.of(x.texel(-1)[0], x.texel(-1)[1]));
        assertEquals(java.util.Optional.of(-1), x.order(4, 0));
        assertEquals(java.util.Optional.empty(), x.order(3, 0));
        RigorousPatch y = RigorousPatch.of(PatchCatalogue.named("elaphe-ridge").build().meanSubtracted());
        assertEquals(RigorousPatch.Axis.Y, y.axis());
        assertEquals(8, y.repeats());
        assertEquals(SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, y.profile().periodUm(), 1e-12);
        assertEquals(List.of(0, 8), List.of(y.texel(-1)[0], y.texel(-1)[1]));
    }

    /**
     * A 2-D cell beyond {@link RigorousPatch#MAX_UNKNOWNS} at the settings' harmonics is refused before any work, with
     * the estimate, the limit and the ways out: a random 3.2 x 2.4 um patch at the default harmonics, the snake patch
     * (128 x 128 samples, 9.15 um) even at --harmonics 7.
     */
    @Test
    void aTwoDimensionalPatchBeyondTheLimitIsRefusedWithTheWayOut() {
        HeightField rough = NaiveDft.randomPatch(12, 16, 0.2, 0.1, 3);
        InvalidSettingException e = assertThrows(InvalidSettingException.class,
                () -> DiffractionBrdf.create(settings(), rough, null));
        assertEquals(Quantity.VARIANT, e.quantity());
        assertTrue(e.getMessage().contains("1-D patches") && e.getMessage().contains("elaphe-ridge")
                && e.getMessage().contains("fewer harmonics") && e.getMessage().contains("crop")
                && e.getMessage().contains("up to " + RigorousPatch.MAX_UNKNOWNS + " complex unknowns"),
                e.getMessage());
        RigorousPatch.Cost cost = RigorousPatch.twoDimensionalCost(rough.widthUm(), rough.heightExtentUm(),
                settings().rigorous().resolution(), 0.38);
        assertTrue(cost.unknowns() > RigorousPatch.MAX_UNKNOWNS);
        assertTrue(e.getMessage().contains(cost.harmonicsX() + " x " + cost.harmonicsY() + " harmonics")
                && e.getMessage().contains(cost.unknowns() + " complex unknowns"), e.getMessage());
        assertTrue(Variant.RIGOROUS.fieldRefusal(rough).isPresent());
        assertThrows(InvalidSettingException.class, () -> Variant.RIGOROUS.heapMemory(rough, settings(), 0, 380, 780));

        HeightField snake = PatchCatalogue.named("elaphe-like").build().meanSubtracted();
        BrdfSettings seven = settings().with(b -> b.rigorous(RigorousSettings.DEFAULT.withResolution(
                new Resolution(7, 12, true))));
        InvalidSettingException s = assertThrows(InvalidSettingException.class,
                () -> DiffractionBrdf.create(seven, snake, null));
        assertTrue(s.getMessage().contains("15 x 15 harmonics") && s.getMessage().contains("450 complex unknowns"),
                s.getMessage());
        assertTrue(Variant.RIGOROUS.fieldRefusal(snake).orElseThrow().contains("123 x 123 harmonics"));
    }

    /** The largest square set of harmonics within the limit: M = 6, 2 x 13^2 = 338 unknowns. */
    @Test
    void theLimitAllowsSixHarmonicsEachWay() {
        assertEquals(6, RigorousPatch.largestSquareOrder());
        assertTrue(2L * 13 * 13 <= RigorousPatch.MAX_UNKNOWNS && 2L * 15 * 15 > RigorousPatch.MAX_UNKNOWNS);
    }

    /** A square pillar of {@code side} samples in a cell of {@code samples} x {@code samples}, 1.5 um wide. */
    static HeightField pillarCell(int samples, int side, double heightUm) {
        double[] h = new double[samples * samples];
        for (int r = 0; r < side; r++) {
            for (int c = 0; c < side; c++) {
                h[r * samples + c] = heightUm;
            }
        }
        return HeightField.of(samples, samples, h, 1.5 / samples).meanSubtracted();
    }

    /**
     * A small 2-D cell (a square pillar in a 1.5 um cell, M = 3 each way) is drawn: its orders (p, q) light the map
     * where the grating equation puts them in both directions, omega_r = -omega_i + (p, q) lambda / 1.5 um (x and y),
     * and nothing lies between them; the orders' efficiencies are the cell solver's (texel (-p, -q) of the table).
     */
    @Test
    void aSmallTwoDimensionalCellIsDrawnWithItsOrdersAtTheGratingEquation() {
        HeightField cell = pillarCell(8, 3, 0.25);
        assertTrue(!RigorousPatch.of(cell).oneDimensional());
        BrdfSettings small = settings().with(b -> b.lambdaRangeNm(500, 600).lambdaStepNm(50)
                .rigorous(RigorousSettings.DEFAULT.withResolution(new Resolution(3, 2, true))));
        assertTrue(RigorousPatch.of(cell).refusal(small.rigorous().resolution(), 0.5).isEmpty());
        assertTrue(Variant.RIGOROUS.heapMemory(cell, small, 20, 500, 600).bytes() > 0);
        DiffractionBrdf rigorous = DiffractionBrdf.create(small, cell, null);
        Direction wi = Direction.fromSphericalDeg(20, 30);
        double lambdaNm = 550;
        double step = lambdaNm * 1e-3 / 1.5;
        diffract.optics.rigorous.CellEfficiencies solved = diffract.optics.rigorous.CellSolver.solve(
                RigorousPatch.of(cell).relief(), small.illumination().material(), lambdaNm * 1e-3, -wi.x(), -wi.y(),
                small.rigorous().resolution());
        int lit = 0;
        for (int p = -2; p <= 2; p++) {
            for (int q = -2; q <= 2; q++) {
                double x = -wi.x() + p * step;
                double y = -wi.y() + q * step;
                if (x * x + y * y >= 0.95) {
                    continue;
                }
                double r = rigorous.relative(wi, Direction.fromProjected(x, y), lambdaNm);
                double between = rigorous.relative(wi, Direction.fromProjected(x + 0.5 * step, y + 0.5 * step),
                        lambdaNm);
                String where = "order (" + p + ", " + q + ")";
                // at 550 nm (a node) the lobe's peak is cos theta_i / R_0 eta_pq: the solver's unpolarised efficiency
                double expected = wi.z() / small.illumination().material().normalReflectance()
                        * solved.reflected(p, q);
                assertEquals(expected, r, 1e-6 * expected + 1e-12, where);
                assertTrue(between < 1e-9 * Math.max(r, 1e-3), "between the orders next to " + where);
                if (p != 0 && q != 0 && solved.reflected(p, q) > 1e-5) {
                    lit++;
                }
            }
        }
        assertTrue(lit >= 4, "orders off both axes are lit: " + lit);
        // a small map: its brightest pixels off the specular sit on the grating equation
        int size = 32;
        double best = 0;
        int[] at = null;
        for (int row = 0; row < size; row++) {
            for (int col = 0; col < size; col++) {
                double x = BrdfMap.xOf(col, size);
                double y = BrdfMap.yOf(row, size);
                if (x * x + y * y >= 1 || Math.hypot(x + wi.x(), y + wi.y()) < 0.5 * step) {
                    continue;
                }
                double v = rigorous.mapPixel(wi, col, row, size).y();
                if (v > best) {
                    best = v;
                    at = new int[] {col, row};
                }
            }
        }
        assertTrue(best > 0, "the map is lit off the specular");
        double x = BrdfMap.xOf(at[0], size);
        double y = BrdfMap.yOf(at[1], size);
        // within a pixel (2 / 32) and the band's spread (500-600 nm moves order 1 by 0.067) of some order
        double nearest = Double.MAX_VALUE;
        for (int p = -3; p <= 3; p++) {
            for (int q = -3; q <= 3; q++) {
                nearest = Math.min(nearest, Math.hypot(x - (-wi.x() + p * step), y - (-wi.y() + q * step)));
            }
        }
        assertTrue(nearest < 0.15, "the brightest pixel off the specular is " + nearest + " from an order");
    }

    /**
     * The estimate a 2-D cell is refused with, by hand: a 1 um square cell at 380 nm keeps M = ceil(2 / 0.38) + 12 =
     * 18 harmonics each way (37 x 37), so 2 x 37^2 = 2738 complex unknowns, 16 x 2738^2 bytes per matrix and
     * 10 (2 x 2738)^3 operations; the snake patch's 9.152 um cell keeps 61 each way (123 x 123).
     */
    @Test
    void aTwoDimensionalCellsCostIsTheHarmonicsOfBothSides() {
        RigorousPatch.Cost square = RigorousPatch.twoDimensionalCost(1.0, 1.0);
        assertEquals(List.of(37, 37, 2738L), List.of(square.harmonicsX(), square.harmonicsY(), square.unknowns()));
        assertEquals(16.0 * 2738 * 2738, square.matrixBytes(), 1e-6);
        assertEquals(10.0 * 5476 * 5476 * 5476, square.operations(), 1);
        RigorousPatch.Cost snake = RigorousPatch.twoDimensionalCost(9.152, 9.152);
        assertEquals(List.of(123, 123, 30258L), List.of(snake.harmonicsX(), snake.harmonicsY(), snake.unknowns()));
    }

    /** Monochromatic maps: the orders sit where the grating equation puts them, and on the scalar model's side. */
    @Test
    void ordersLandAtTheGratingEquationOnTheScalarModelsSide() {
        Direction wi = Direction.fromSphericalDeg(30, 0);
        double lambdaNm = 550;
        DiffractionBrdf rigorous = DiffractionBrdf.create(settings(), BLAZED, null);
        DiffractionBrdf scalar = DiffractionBrdf.create(BrdfSettings.thesis(Variant.REFERENCE), BLAZED, null);
        double brightestRigorous = 0;
        double brightestScalar = 0;
        int atRigorous = 0;
        int atScalar = 0;
        for (int m = -6; m <= 1; m++) {
            double x = -wi.x() + m * lambdaNm * 1e-3 / 2.5;
            if (Math.abs(x) >= 1) {
                continue;
            }
            Direction wr = Direction.fromProjected(x, 0);
            double r = rigorous.relative(wi, wr, lambdaNm);
            double s = scalar.relative(wi, wr, lambdaNm);
            // between the orders nothing: half-way to the next order the lobes (65 um coherence) have faded
            Direction between = Direction.fromProjected(x + 0.5 * lambdaNm * 1e-3 / 2.5, 0);
            assertTrue(rigorous.relative(wi, between, lambdaNm) < 1e-9 * Math.max(r, 1e-3), "between orders " + m);
            if (m != 0 && r > brightestRigorous) {
                brightestRigorous = r;
                atRigorous = m;
            }
            if (m != 0 && s > brightestScalar) {
                brightestScalar = s;
                atScalar = m;
            }
        }
        // the sawtooth rises along +x: both models blaze its light into the same negative order
        assertEquals(atScalar, atRigorous);
        assertTrue(atRigorous < 0, "the blazed order is " + atRigorous);
    }

    /**
     * On a shallow grating (20 nm of 1 um) Rayleigh-Rice's factor is the first-order perturbation result: the scalar
     * model with it matches the rigorous orders to 2 %, at 60 degrees too, where Stam's gain misses by more than 10 %.
     */
    @Test
    void rayleighRicesGainMatchesAShallowGratingWhereStamsDoesNot() {
        HeightField shallow = SyntheticPatches.sinusoid(1.0, 0.02, 32, 1, 1).meanSubtracted();
        double worstStam = 0;
        for (double theta : new double[] {0, 30, 60}) {
            Direction wi = Direction.fromSphericalDeg(theta, 0);
            for (double lambdaNm : new double[] {450, 650}) {
                OrderComparison rr = OrderComparison.of(shallow, settings(), wi, lambdaNm);
                OrderComparison stam = OrderComparison.of(shallow, settings().with(b -> b.gain(GainModel.STAM)), wi,
                        lambdaNm);
                for (int i = 0; i < rr.orders().size(); i++) {
                    OrderComparison.Order o = rr.orders().get(i);
                    if (Math.abs(o.order()) != 1) {
                        continue;
                    }
                    String where = "order " + o.order() + " at " + theta + " degrees, " + lambdaNm + " nm";
                    assertEquals(o.rigorous(), o.scalar(), 0.02 * o.rigorous(), where);
                    worstStam = Math.max(worstStam, Math.abs(stam.orders().get(i).relativeError()));
                }
            }
        }
        assertTrue(worstStam > 0.1, "Stam's gain misses by " + worstStam);
    }

    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // a whole order table: a long test
    void theOrdersAreKeptInTheDiskCache(@TempDir Path dir) {
        DiskCache cache = DiskCache.at(dir);
        Direction wi = Direction.fromSphericalDeg(20, 0);
        RigorousPatch patch = RigorousPatch.of(BLAZED);
        RigorousOrders solved = RigorousOrders.of(patch, settings(), wi, cache, Reporter.SILENT);
        Reporter.Collecting reporter = new Reporter.Collecting();
        RigorousOrders loaded = RigorousOrders.of(patch, settings(), wi, cache, reporter);
        assertTrue(reporter.infos().isEmpty(), "loaded without a solve: " + reporter.infos());
        for (int m = -4; m <= 4; m++) {
            for (double lambdaNm = 380; lambdaNm <= 780; lambdaNm += 13) {
                assertEquals(solved.efficiency(m, lambdaNm), loaded.efficiency(m, lambdaNm), 0);
            }
        }
        double reflectance = 0;
        for (int m = -6; m <= 6; m++) {
            reflectance += solved.efficiency(m, 550);
        }
        assertTrue(reflectance > 0.02 && reflectance < 0.1, "the grating reflects " + reflectance + " at 550 nm");
    }
}
