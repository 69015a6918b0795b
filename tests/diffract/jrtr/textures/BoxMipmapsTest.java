package diffract.jrtr.textures;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@link BoxMipmaps}: each level holds every texel's share of the total (a level's mean is its base's), a narrow line
 * in the middle of an odd-sized texture survives into every level (where sampling at the new texel centres skips
 * it), and power-of-two sizes reduce to plain 2 x 2 averages.
 */
class BoxMipmapsTest {
    @Test
    void levelsCountDownToOneTexel() {
        assertEquals(10, BoxMipmaps.levels(513, 513));
        assertEquals(9, BoxMipmaps.levels(256, 256));
        assertEquals(9, BoxMipmaps.levels(256, 4)); // 256 x 4 -> 128 x 2 -> 64 x 1 -> ... -> 1 x 1
        assertEquals(1, BoxMipmaps.levels(1, 1));
    }

    @Test
    void aPowerOfTwoLevelIsTheTwoByTwoAverage() {
        float[] base = {1, 2, 3, 4, /* row 1 */ 5, 6, 7, 8};
        float[] next = BoxMipmaps.next(base, 4, 2, 1, 1);
        assertArrayEquals(new float[] {(1 + 2 + 5 + 6) / 4f, (3 + 4 + 7 + 8) / 4f}, next, 1e-6f);
    }

    @Test
    void everyLevelKeepsTheMeanAndAMiddleLine() {
        int n = 513;
        int channels = 3;
        float[] level = new float[n * n * channels * 2];
        for (int y = 0; y < n; y++) {
            // layer 0: a line of unit mass at the middle column; layer 1: a ramp
            level[(y * n + n / 2) * channels + 1] = 1f;
            for (int x = 0; x < n; x++) {
                level[((n + y) * n + x) * channels] = x;
            }
        }
        double lineMean = 1.0 / n;
        double rampMean = (n - 1) / 2.0;
        int w = n;
        int h = n;
        for (int k = 1; k < BoxMipmaps.levels(n, n); k++) {
            level = BoxMipmaps.next(level, w, h, 2, channels);
            w = BoxMipmaps.halved(w);
            h = BoxMipmaps.halved(h);
            double line = 0;
            double ramp = 0;
            double largest = 0;
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    float value = level[(y * w + x) * channels + 1];
                    line += value;
                    largest = Math.max(largest, value);
                    ramp += level[((h + y) * w + x) * channels];
                }
            }
            assertEquals(lineMean, line / (w * h), 1e-6 * lineMean, "level " + k + ": the line's mean");
            assertEquals(rampMean, ramp / (w * h), 1e-6 * rampMean, "level " + k + ": the ramp's mean");
            // a row of the level holds the line's mass w / n in one texel, or in two where it straddles their border
            assertTrue(largest >= 0.49 * w / n, "level " + k + ": the line's peak " + largest);
        }
    }
}
