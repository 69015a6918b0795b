package diffract.pipeline;

import diffract.optics.patches.HeightField;
import diffract.optics.patches.SyntheticPatches;
import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A patch's strongest period: a grating's, along its direction, the Elaphe-like skin's ridges, none in noise. */
class PatchPeriodTest {
    @Test
    void aSinusoidAlongXHasItsPeriodAtZeroDegrees() {
        PatchPeriod p = PatchPeriod.of(SyntheticPatches.sinusoid(2.5, 0.1, 16, 6, 8)).orElseThrow();
        assertEquals(2.5, p.periodUm(), 1e-9);
        assertEquals(0, p.azimuthDeg(), 1e-9);
        assertTrue(p.powerShare() > 0.99, "a pure sinusoid holds all its power in its order: " + p.powerShare());
    }

    @Test
    void theElapheLikeRidgesRunAcrossY() {
        PatchPeriod p = PatchPeriod.of(SyntheticPatches.elapheLike()).orElseThrow();
        assertEquals(90, p.azimuthDeg(), 1e-9, "the ridges' period lies along y");
        assertEquals(SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM, p.periodUm(), 0.1 * SyntheticPatches.ELAPHE_RIDGE_PERIOD_UM);
    }

    @Test
    void noiseHasNoPeriod() {
        int n = 64;
        double[] h = new double[n * n];
        Random random = new Random(3);
        for (int i = 0; i < h.length; i++) {
            h[i] = random.nextGaussian() * 0.05;
        }
        assertTrue(PatchPeriod.of(HeightField.of(n, n, h, 0.1)).isEmpty());
        assertTrue(PatchPeriod.of(HeightField.of(n, n, new double[n * n], 0.1)).isEmpty(), "a flat patch");
    }
}
