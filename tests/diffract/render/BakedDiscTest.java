package diffract.render;

import diffract.optics.BakedGrid;
import diffract.optics.BrdfSettings;
import diffract.optics.settings.LightProfile;
import diffract.optics.Variant;
import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@link BakedDisc}'s host side: the running sums of a table's rows against the sums written out, and the light a table
 * holds (a point under a disc, so one table serves every disc; the Gaussian profile's own light).
 */
class BakedDiscTest {
    @Test
    void rowSumsAreTheIntegralOfTheTableAlongEachRow() {
        BakedGrid grid = new BakedGrid(9, 3);
        int n = grid.uvSamples();
        double h = (BakedGrid.U_MAX - BakedGrid.U_MIN) / (n - 1);
        float[] rgb = new float[3 * n * n * grid.wSamples()];
        Random random = new Random(7);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = random.nextFloat();
        }
        float[] sums = BakedDisc.rowSums(rgb, grid);
        for (int row = 0; row < n * grid.wSamples(); row++) {
            for (int c = 0; c < 3; c++) {
                double before = 0;
                for (int i = 0; i < n; i++) {
                    int at = 3 * (row * n + i) + c;
                    assertEquals(h * (before + 0.5 * rgb[at]), sums[at], 1e-6, "row " + row + ", sample " + i);
                    if (i > 0) {
                        // linear between samples: a sample's interval holds the mean of its two ends
                        assertEquals(h * 0.5 * (rgb[at - 3] + rgb[at]), sums[at] - sums[at - 3], 1e-6);
                    }
                    before += rgb[at];
                }
            }
        }
    }

    @Test
    void aTableUnderADiscHoldsThePointLight() {
        BrdfSettings disc = BrdfSettings.thesis(Variant.BAKED).with(b -> b.lightSizeDeg(10)
                .lightProfile(LightProfile.DISC));
        BrdfSettings sun = disc.with(b -> b.lightSizeDeg(0.53));
        BrdfSettings gaussian = disc.with(b -> b.lightProfile(LightProfile.GAUSSIAN));
        assertTrue(BakedDisc.heldBy(disc).illumination().light().isPoint());
        assertEquals(BakedDisc.heldBy(disc), BakedDisc.heldBy(sun), "one table for every disc");
        assertEquals(0, BakedDisc.heldSigmaRad(disc));
        assertEquals(gaussian, BakedDisc.heldBy(gaussian));
        assertEquals(gaussian.illumination().light().sigmaRad(), BakedDisc.heldSigmaRad(gaussian));
        assertTrue(BakedDisc.integrates(disc, true));
        assertFalse(BakedDisc.integrates(disc, false), "an FLSS table is point-sampled: no disc");
        assertFalse(BakedDisc.integrates(gaussian, true));
    }
}
