package diffract.jrtr.textures;

import org.junit.jupiter.api.Test;

import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

/** The bounds of every block at every level equal the smallest and largest depth of its texels, counted directly. */
class DepthBoundsTest {
    @Test
    void everyBlockHoldsTheMinimumAndMaximumOfItsTexels() {
        int size = 64;
        float[] depth = new float[size * size];
        Random random = new Random(7);
        for (int t = 0; t < depth.length; t++) {
            depth[t] = random.nextFloat();
        }
        depth[17 + size * 40] = -0.5f; // one outlier per sign: the levels above it must all carry it
        depth[50 + size * 3] = 1.5f;
        DepthBounds bounds = new DepthBounds(size);
        float[][] levels = levelsOf(bounds, size);
        DepthBounds.of(depth, size, levels);
        assertEquals(7, bounds.levelCount(), "blocks of 1, 2, 4, ..., 64 texels");
        for (int p = 0; p < levels.length; p++) {
            int block = 1 << p;
            int side = size >> p;
            for (int j = 0; j < side; j++) {
                for (int i = 0; i < side; i++) {
                    float min = Float.POSITIVE_INFINITY;
                    float max = Float.NEGATIVE_INFINITY;
                    for (int y = j * block; y < (j + 1) * block; y++) {
                        for (int x = i * block; x < (i + 1) * block; x++) {
                            min = Math.min(min, depth[x + size * y]);
                            max = Math.max(max, depth[x + size * y]);
                        }
                    }
                    assertEquals(min, levels[p][2 * (i + side * j)], "min of block " + i + ", " + j + " at " + p);
                    assertEquals(max, levels[p][2 * (i + side * j) + 1], "max of block " + i + ", " + j + " at " + p);
                }
            }
        }
        assertEquals(-0.5f, levels[6][0]);
        assertEquals(1.5f, levels[6][1]);
    }

    @Test
    void aMapWhoseSideIsNoPowerOfTwoOrValuesOfAnotherSizeAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new DepthBounds(48));
        assertThrows(IllegalArgumentException.class, () -> new DepthBounds(1));
        DepthBounds bounds = new DepthBounds(16);
        assertThrows(IllegalArgumentException.class, () -> DepthBounds.of(new float[100], 16, levelsOf(bounds, 16)));
    }

    private static float[][] levelsOf(DepthBounds bounds, int size) {
        float[][] levels = new float[bounds.levelCount()][];
        for (int p = 0; p < levels.length; p++) {
            levels[p] = new float[2 * (size >> p) * (size >> p)];
        }
        return levels;
    }
}
