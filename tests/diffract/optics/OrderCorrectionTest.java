package diffract.optics;

import diffract.optics.patches.Direction;
import diffract.optics.illumination.GainFactor;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.PatchCatalogue;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.rigorous.OrderEfficiencies;
import diffract.optics.rigorous.Resolution;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.rigorous.RigorousSolver;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.OrderWeights;
import diffract.optics.settings.Quantity;
import diffract.util.DiskCache;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The rigorous orders for the fast path: a patch's ridge (its own, or a 2-D snake patch's average one), the table's
 * definition at its nodes (ratio times the scalar efficiency is the rigorous efficiency), the lobes that take it, and
 * the methods that refuse it.
 */
class OrderCorrectionTest {
    /** A cheap table: two wavelengths, 21 harmonics, a coarse staircase. */
    private static BrdfSettings settings() {
        return BrdfSettings.thesis(Variant.LOBES).with(b -> b.lambdaRangeNm(500, 520)
                .rigorous(RigorousSettings.DEFAULT.withResolution(new Resolution(10, 4, true))
                        .withOrders(OrderWeights.RIGOROUS)));
    }

    @Test
    void aOneDimensionalPatchIsItsOwnRidgeAndASnakePatchHasAnAverageOne() {
        OrderCorrection.Ridge own = OrderCorrection.ridgeOf(PatchCatalogue.named("elaphe-ridge").build()
                .meanSubtracted());
        assertEquals(RigorousPatch.Axis.Y, own.axis());
        assertEquals(8, own.ridges());
        assertEquals(SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, own.profile().periodUm(), 1e-12);
        OrderCorrection.Ridge average = OrderCorrection.ridgeOf(PatchCatalogue.named("elaphe-like").build()
                .meanSubtracted());
        assertEquals(RigorousPatch.Axis.Y, average.axis());
        assertEquals(8, average.ridges());
        assertEquals(SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, average.profile().periodUm(), 1e-9);
        // the meander and the fingers lower and smooth the average ridge: shallower than the 0.3 um ridge, not flat
        assertTrue(average.profile().depthUm() > 0.12 && average.profile().depthUm() < 0.3,
                "depth " + average.profile().depthUm());
    }

    /** At a node the corrected scalar efficiency of each propagating order is the rigorous one. */
    @Test
    void atItsNodesTheTableTurnsTheScalarOrdersIntoTheRigorousOnes(@TempDir Path dir) {
        HeightField ridge = PatchCatalogue.named("xenopeltis-ridge").build().meanSubtracted();
        BrdfSettings settings = settings();
        OrderCorrection table = OrderCorrection.of(ridge, settings, DiskCache.at(dir), Reporter.SILENT);
        double lambdaNm = 520; // a node: 500 + 20
        double alpha = 0.375;  // a node: -1 + 11 x 0.125
        double beta = 0.25;    // a node
        // in the patch's frame the ridges' period lies along y: alpha = -omega_i.y, beta = |omega_i.x|
        Direction wi = new Direction(-beta, -alpha, Math.sqrt(1 - alpha * alpha - beta * beta));
        OrderEfficiencies e = RigorousSolver.solve(RigorousPatch.of(ridge).profile(), settings.illumination().material(),
                lambdaNm * 1e-3, alpha, beta, settings.rigorous().resolution());
        OrderCorrection.Ridge r = OrderCorrection.ridgeOf(ridge);
        double r0 = GainFactor.normalReflectance(settings.illumination().refractiveIndex());
        int checked = 0;
        for (int m = -3; m <= 3; m++) {
            double am = alpha + m * lambdaNm * 1e-3 / 0.65;
            if (am * am + beta * beta >= 1) {
                continue;
            }
            Direction ridgeWi = new Direction(-alpha, -beta, wi.z());
            Direction ridgeWr = Direction.fromProjected(am, beta);
            double scalar = r0 * GainFactor.gainTimesShadowing(ridgeWi, ridgeWr, settings.illumination()
                    .refractiveIndex(), settings.illumination().gain()) * OrderCorrection.coefficientPower(r.samples(),
                    2 * Math.PI / (lambdaNm * 1e-3) * (-ridgeWi.z() - ridgeWr.z()), m) / ridgeWi.z();
            double rigorous = e.reflected(m);
            int texel = -m * r.ridges();
            double ratio = table.ratio(0, texel, lambdaNm, wi);
            if (rigorous > 1e-4) {
                assertEquals(rigorous, ratio * scalar, 1e-5 * rigorous + 1e-9, "order " + m);
                checked++;
            }
        }
        assertTrue(checked >= 2, "orders checked: " + checked);
        assertTrue(table.largest() >= 1 && table.largest() <= OrderCorrection.MAX_RATIO);
    }

    @Test
    void onlyTheLobesTakeTheRigorousOrders() {
        for (Variant v : Variant.values()) {
            if (v.takesRigorousOrders()) {
                continue;
            }
            InvalidSettingException e = assertThrows(InvalidSettingException.class, () -> settings().with(b -> b
                    .variant(v)));
            assertEquals(Quantity.ORDERS, e.quantity());
            assertTrue(e.getMessage().contains("lobes"), e.getMessage());
        }
    }
}
