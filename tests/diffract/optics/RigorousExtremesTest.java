package diffract.optics;

import diffract.colour.Xyz;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import diffract.optics.rigorous.Resolution;
import diffract.optics.rigorous.RigorousSettings;
import diffract.optics.validity.OrderComparison;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The rigorous method at the extremes the other methods are held to (ExtremesTest): light at 89.9 degrees, a relief
 * 2 um deep, a period shorter than half the shortest wavelength (only the mirror propagates), an absorbing surface, a
 * patch of one sample: finite, non-negative values, and the energy the solver conserves.
 */
class RigorousExtremesTest {
    private static BrdfSettings settings() {
        return BrdfSettings.thesis(Variant.RIGOROUS).with(b -> b.lambdaStepNm(50)
                .rigorous(RigorousSettings.DEFAULT.withResolution(new Resolution(0, 8, true))));
    }

    private static void assertSane(DiffractionBrdf brdf, Direction wi, String name) {
        for (double x : new double[] {-0.9, -0.4, 0, 0.35, 0.8}) {
            Direction wr = Direction.fromProjected(x, 0.1);
            Xyz xyz = brdf.xyz(wi, wr);
            assertTrue(Double.isFinite(xyz.y()) && xyz.y() >= 0, name + " at x " + x + ": " + xyz);
            assertTrue(Double.isFinite(xyz.x()) && Double.isFinite(xyz.z()), name + " at x " + x + ": " + xyz);
            double r = brdf.relative(wi, wr, 380);
            assertTrue(Double.isFinite(r) && r >= 0, name + " at 380 nm, x " + x + ": " + r);
        }
    }

    @Test
    void grazingLightTallReliefsAndAbsorption() {
        HeightField sinusoid = SyntheticPatches.sinusoid(1.0, 0.3, 32, 1, 1).meanSubtracted();
        assertSane(DiffractionBrdf.create(settings(), sinusoid, null), Direction.fromSphericalDeg(89.9, 0),
                "89.9 degrees");
        HeightField tall = SyntheticPatches.sinusoid(1.0, 2.0, 32, 1, 1).meanSubtracted();
        assertSane(DiffractionBrdf.create(settings().with(b -> b.rigorous(RigorousSettings.DEFAULT.withResolution(
                new Resolution(0, 40, true)))), tall, null), Direction.fromSphericalDeg(30, 0), "2 um deep");
        assertSane(DiffractionBrdf.create(settings().with(b -> b.material(
                new diffract.optics.rigorous.ComplexIndex(1.56, 0.5))), sinusoid, null), Direction.fromSphericalDeg(30,
                0), "absorbing");
        HeightField one = HeightField.of(1, 1, new double[] {0.4}, 0.1).meanSubtracted();
        assertSane(DiffractionBrdf.create(settings(), one, null), Direction.fromSphericalDeg(30, 0), "one sample");
    }

    @Test
    void aPeriodBelowHalfTheWavelengthReflectsOnlyItsMirror() {
        // 0.15 um: from any direction orders +-1 leave at |x| >= 380 / 150 - 1 > 1, evanescent
        HeightField fine = SyntheticPatches.sinusoid(0.15, 0.05, 16, 1, 1).meanSubtracted();
        Direction wi = Direction.fromSphericalDeg(40, 0);
        for (double lambdaNm : new double[] {380, 550, 780}) {
            OrderComparison c = OrderComparison.of(fine, settings(), wi, lambdaNm);
            assertEquals(1, c.orders().size(), "only the mirror at " + lambdaNm + " nm");
            assertEquals(c.reflected(), c.orders().get(0).rigorous(), 1e-15);
            assertEquals(1, c.reflected() + c.transmitted(), 1e-9, "energy at " + lambdaNm + " nm");
        }
    }

    @Test
    void twoMicrometresDeepStillConservesEnergy() {
        HeightField tall = SyntheticPatches.sinusoid(1.0, 2.0, 32, 1, 1).meanSubtracted();
        OrderComparison c = OrderComparison.of(tall, settings().with(b -> b.rigorous(RigorousSettings.DEFAULT
                .withResolution(new Resolution(0, 40, false)))), Direction.fromSphericalDeg(60, 0), 400);
        assertEquals(1, c.reflected() + c.transmitted(), 1e-9);
        assertTrue(c.orders().size() >= 4, "orders: " + c.orders().size());
    }
}
