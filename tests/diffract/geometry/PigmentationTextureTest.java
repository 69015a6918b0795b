package diffract.geometry;

import org.junit.jupiter.api.Test;

import java.awt.image.BufferedImage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The corn-snake pigmentation: deterministic per seed, with saddles, their black edges and a ground. */
class PigmentationTextureTest {

    private static int count(BufferedImage image, int rgb) {
        int n = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                n += (image.getRGB(x, y) & 0xffffff) == rgb ? 1 : 0;
            }
        }
        return n;
    }

    @Test
    void sameSeedSameImageOtherSeedOtherImage() {
        BufferedImage a = new PigmentationTexture(PigmentationTexture.Parameters.defaults(7)).image(64, 512);
        BufferedImage b = new PigmentationTexture(PigmentationTexture.Parameters.defaults(7)).image(64, 512);
        BufferedImage c = new PigmentationTexture(PigmentationTexture.Parameters.defaults(8)).image(64, 512);
        int differences = 0;
        for (int y = 0; y < 512; y++) {
            for (int x = 0; x < 64; x++) {
                assertEquals(a.getRGB(x, y), b.getRGB(x, y));
                differences += a.getRGB(x, y) != c.getRGB(x, y) ? 1 : 0;
            }
        }
        assertTrue(differences > 100, "seeds 7 and 8 differ in only " + differences + " pixels");
    }

    @Test
    void hasSaddlesBlackEdgesAndTheBackIsNotTheBelly() {
        BufferedImage image = new PigmentationTexture(PigmentationTexture.Parameters.defaults(2014)).image(128, 1024);
        int saddle = count(image, PigmentationTexture.SADDLE);
        int edge = count(image, PigmentationTexture.EDGE);
        int pixels = 128 * 1024;
        assertTrue(saddle > pixels / 50, "saddle pixels: " + saddle);
        assertTrue(edge > pixels / 200, "black pixels (saddle edges and belly checks): " + edge);
        // u = 0.5 (column 64) runs along the back through the saddles; u = 0 is the belly, never a saddle
        int backSaddles = 0;
        for (int y = 0; y < 1024; y++) {
            backSaddles += (image.getRGB(64, y) & 0xffffff) == PigmentationTexture.SADDLE ? 1 : 0;
            assertNotEquals(PigmentationTexture.SADDLE, image.getRGB(0, y) & 0xffffff, "saddle on the belly at " + y);
        }
        assertTrue(backSaddles > 100, "saddles along the back: " + backSaddles);
    }
}
