package diffract.bench;

import diffract.colour.Srgb;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The picture statistics on a synthetic frame whose answer is known by construction. */
class IridescenceStatisticsTest {
    @Test
    void maskShareSaturatedShareSeparatePatchesAndHueBins() {
        int w = 100;
        int h = 50;
        float[] mask = new float[w * h];
        float[] rgb = new float[3 * w * h];
        // the animal: the left half of the frame, mid grey (no chroma)
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < 50; x++) {
                mask[y * w + x] = 1;
                java.util.Arrays.fill(rgb, 3 * (y * w + x), 3 * (y * w + x) + 3, 0.5f);
            }
        }
        // six 3 x 3 patches of saturated red, green, blue, yellow, cyan, pink, apart from each other on the animal
        float[][] colours = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 0.5f}};
        for (int k = 0; k < 6; k++) {
            for (int dy = 0; dy < 3; dy++) {
                for (int dx = 0; dx < 3; dx++) {
                    int p = (5 + dy) * w + 5 + 7 * k + dx;
                    System.arraycopy(colours[k], 0, rgb, 3 * p, 3);
                }
            }
        }
        // the same colour off the animal (the ground) counts for nothing; a 2-pixel speck is no patch but is colour
        for (int k = 0; k < 9; k++) {
            System.arraycopy(colours[0], 0, rgb, 3 * (20 * w + 60 + k), 3);
        }
        System.arraycopy(colours[1], 0, rgb, 3 * (40 * w + 10), 3);
        System.arraycopy(colours[1], 0, rgb, 3 * (40 * w + 11), 3);
        // a dark saturated pixel (L* < 20) is not structural colour one sees
        float dark = (float) Srgb.encode(0.01);
        rgb[3 * (30 * w + 30)] = dark;
        rgb[3 * (30 * w + 30) + 1] = 0;
        rgb[3 * (30 * w + 30) + 2] = 0;

        IridescenceStatistics s = IridescenceStatistics.of(mask, rgb, w, h);
        assertEquals(0.5, s.maskFraction(), 1e-12);
        assertEquals((6 * 9 + 2) / 5000.0, s.saturatedFraction(), 1e-12);
        assertEquals(6, s.patches());
        assertEquals(9, s.medianPatchPx());
        // pink below 30, red 40, yellow 103, green 136, cyan 197, blue 306 degrees of h_ab: six different bins
        assertEquals(6, s.hueBins());
        // the README asks how much of the shape shows saturated colour: 56 of the animal's 2500 pixels
        assertEquals(56 / 2500.0, s.saturatedShareOfShape(), 1e-12);
        assertTrue(s.toString().contains("1.12 % of the frame (2.2 % of the snake)"), s.toString());
    }
}
