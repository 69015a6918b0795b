package diffract.colour;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class LabTest {
    @Test
    void whiteIsL100Neutral() {
        Xyz white = D65.whiteXyz();
        Lab lab = Lab.fromXyz(white, white);
        assertEquals(100.0, lab.l(), 1e-12);
        assertEquals(0.0, lab.a(), 1e-12);
        assertEquals(0.0, lab.b(), 1e-12);
        assertEquals(50.0, Lab.fromXyz(white.scaled(0.18418651851244416), white).l(), 1e-9);
    }

    @Test
    void darkColoursUseTheLinearSegmentContinuously() {
        Xyz white = new Xyz(0.95047, 1, 1.08883);
        double epsilon = 216.0 / 24389.0;
        // kappa * epsilon = 8 exactly: L* is 8 at the break from both sides.
        assertEquals(8.0, Lab.fromXyz(new Xyz(0, epsilon, 0), white).l(), 1e-12);
        assertEquals(8.0, Lab.fromXyz(new Xyz(0, Math.nextUp(epsilon), 0), white).l(), 1e-12);
        assertEquals(24389.0 / 27.0 * 0.001, Lab.fromXyz(new Xyz(0, 0.001, 0), white).l(), 1e-12);
        assertEquals(0.0, Lab.fromXyz(new Xyz(0, 0, 0), white).l(), 1e-12);
    }

    @Test
    void knownSrgbRedValue() {
        // sRGB red (1, 0, 0) relative to the sRGB white, from colour-science 0.4.7:
        // colour.XYZ_to_Lab(colour.normalised_primary_matrix(primaries, (0.3127, 0.3290)) @ (1, 0, 0),
        //                   (0.3127, 0.3290))
        // = (53.2371156, 80.09011352, 67.20326351). (The often quoted 53.2408 uses the white (0.95047, 1, 1.08883).)
        Lab lab = Lab.fromXyz(Srgb.xyzFromLinear(new double[] {1, 0, 0}), Srgb.whiteXyz());
        assertEquals(53.2371156, lab.l(), 1e-6);
        assertEquals(80.09011352, lab.a(), 1e-6);
        assertEquals(67.20326351, lab.b(), 1e-6);
    }
}
