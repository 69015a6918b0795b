package diffract.optics.patches;

import diffract.util.UserInputException;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The procedural Elaphe-like patch: size, pixel size, heights, seeding, and its ridge period along y. */
class ElapheLikePatchTest {
    @Test
    void defaultsAre128PixelsOf0071UmAnd03UmHigh() {
        HeightField h = SyntheticPatches.elapheLike();
        assertEquals(128, h.rows());
        assertEquals(128, h.cols());
        assertEquals(8 * 1.144 / 128, h.pixelSizeXUm(), 1e-12);
        assertEquals(h.pixelSizeXUm(), h.pixelSizeYUm(), 0.0);
        double range = h.maxHeightUm() - h.minHeightUm();
        assertTrue(range > 0.25 && range < 0.4, "peak-to-valley " + range + " um");
    }

    @Test
    void theSeedDecidesTheNoise() {
        assertArrayEquals(SyntheticPatches.elapheLike(64, 4, 1.144, 0.3, 7).heightsUm(),
                SyntheticPatches.elapheLike(64, 4, 1.144, 0.3, 7).heightsUm(), 0.0);
        assertFalse(java.util.Arrays.equals(SyntheticPatches.elapheLike(64, 4, 1.144, 0.3, 7).heightsUm(),
                SyntheticPatches.elapheLike(64, 4, 1.144, 0.3, 8).heightsUm()));
    }

    /** The strongest non-zero spatial frequency along y is the ridge count (8 cycles over the rows); along x it is weak. */
    @Test
    void ridgesRunAlongXWithThePeriodAlongY() {
        HeightField h = SyntheticPatches.elapheLike().meanSubtracted();
        int best = 0;
        double bestPower = 0;
        for (int k = 1; k < 64; k++) {
            double power = power(h, 0, k);
            if (power > bestPower) {
                bestPower = power;
                best = k;
            }
        }
        assertEquals(8, best, "cycles along y");
        for (int k = 1; k < 64; k++) {
            assertTrue(power(h, k, 0) < 0.1 * bestPower, "along x, frequency " + k);
        }
    }

    @Test
    void theProfileIsAsymmetricAndContinuous() {
        assertEquals(0, SyntheticPatches.fingerProfile(0), 1e-15);
        assertEquals(1, SyntheticPatches.fingerProfile(0.7), 1e-15);
        assertEquals(0, SyntheticPatches.fingerProfile(1 - 1e-12), 1e-12);
        // 0.15 of a period before and after the peak: the rising side is still high, the falling side half down
        assertTrue(SyntheticPatches.fingerProfile(0.55) > SyntheticPatches.fingerProfile(0.85) + 0.3,
                "gentle rise, steep fall");
    }

    @Test
    void badSizesAreRefused() {
        assertThrows(UserInputException.class, () -> SyntheticPatches.elapheLike(100, 8, 1.144, 0.3, 1));
        assertThrows(UserInputException.class, () -> SyntheticPatches.elapheLike(128, 0, 1.144, 0.3, 1));
    }

    /** |sum h e^{-2 pi i (kx c + ky r) / N}|^2 (direct, one frequency). */
    private static double power(HeightField h, int kx, int ky) {
        double re = 0;
        double im = 0;
        int n = h.rows();
        for (int r = 0; r < n; r++) {
            for (int c = 0; c < h.cols(); c++) {
                double phase = -2 * Math.PI * ((double) kx * c / h.cols() + (double) ky * r / n);
                re += h.heightUm(r, c) * Math.cos(phase);
                im += h.heightUm(r, c) * Math.sin(phase);
            }
        }
        return re * re + im * im;
    }
}
