package diffract.geometry;

import org.junit.jupiter.api.Test;

import java.awt.image.BufferedImage;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** A tangent-space normal map becomes the frame map: unit normals' x and y, rows flipped to start at v = 0. */
class NormalMapImageTest {
    @Test
    void colourBecomesTheNormalAndTheTopRowTheLast() {
        BufferedImage image = new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, 128 << 16 | 128 << 8 | 255); // flat: (0, 0, 1)
        image.setRGB(1, 0, 218 << 16 | 128 << 8 | 218); // tilted towards +x by ~45 degrees
        image.setRGB(0, 1, 128 << 16 | 37 << 8 | 218);  // towards -y
        image.setRGB(1, 1, 0);                          // no outward normal: the mesh's own
        float[] map = NormalMapImage.frameMap(image);
        // image row 0 (top) is texture row 1
        assertEquals(0.0039, map[4 * 2], 0.005);
        assertEquals(0.0039, map[4 * 2 + 1], 0.005);
        double nx = 2 * 218 / 255.0 - 1;
        double nz = nx;
        double ny = 2 * 128 / 255.0 - 1;
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        assertEquals(nx / length, map[4 * 3], 1e-6);
        assertEquals(ny / length, map[4 * 3 + 1], 1e-6);
        assertEquals(1, map[4 * 3 + 2], 0);
        assertEquals(0, map[4 * 3 + 3], 0);
        assertEquals(-0.71, map[4 * 0 + 1], 0.02);
        assertEquals(0, map[4 * 1], 0);
        assertEquals(0, map[4 * 1 + 1], 0);
        assertEquals(1, map[4 * 1 + 2], 0);
    }
}
