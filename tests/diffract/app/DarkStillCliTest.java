package diffract.app;

import diffract.jrtr.GlTestSupport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * A still whose structural colour comes out black says so and names what shows it: the grating plane's scene with
 * the Elaphe-like patch, whose ridges' period lies across the scene's light, sends no order to the camera; the light
 * the warning names brings the first order into the picture, and {@code --exposure auto} shows the orders' tails.
 */
@Tag("gl")
class DarkStillCliTest {
    @TempDir
    Path dir;

    private static final String SCENE = Path.of("assets", "scenes", "blazed-grating-plane.json").toString();

    @Test
    void aBlackStillNamesTheLightThatShowsItsColour() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path black = dir.resolve("black.png");
        Object[] r = CliTest.run("render", SCENE, "--synthetic", "elaphe-like", "--size", "64x40", "-o",
                black.toString());
        assertEquals(0, r[0], (String) r[2]);
        String err = (String) r[2];
        assertTrue(err.contains("warning: the structural colour is black at exposure 400"), err);
        Matcher named = Pattern.compile("under --theta-i ([0-9.]+) --phi-i ([0-9]+)").matcher(err);
        assertTrue(named.find(), err);
        assertTrue(meanShapeValue(black) < 4, "the picture is black: " + meanShapeValue(black));

        Path lit = dir.resolve("lit.png");
        r = CliTest.run("render", SCENE, "--synthetic", "elaphe-like", "--size", "64x40", "--theta-i", named.group(1),
                "--phi-i", named.group(2), "-o", lit.toString());
        assertEquals(0, r[0], (String) r[2]);
        assertFalse(((String) r[2]).contains("structural colour is"), (String) r[2]);
        assertTrue(brightestShapeValue(lit) > 200, "the named light shows the first order");

        Path auto = dir.resolve("auto.png");
        r = CliTest.run("render", SCENE, "--synthetic", "elaphe-like", "--size", "64x40", "--exposure", "auto",
                "-o", auto.toString());
        assertEquals(0, r[0], (String) r[2]);
        assertTrue(((String) r[2]).contains("auto exposure"), (String) r[2]);
        assertFalse(((String) r[2]).contains("structural colour is"), (String) r[2]);
        assertTrue(brightestShapeValue(auto) > 200, "auto shows the orders' tails");
    }

    @Test
    void aStillInColourSaysNothingAndAutoCannotBeDumped() {
        GlTestSupport.assumeOffscreenGl();
        Object[] r = CliTest.run("render", SCENE, "--size", "64x40", "-o", dir.resolve("grating.png").toString());
        assertEquals(0, r[0], (String) r[2]);
        assertFalse(((String) r[2]).contains("structural colour is"), (String) r[2]);
        r = CliTest.run("render", SCENE, "--exposure", "auto", "--dump-scene");
        assertEquals(2, r[0]);
        assertTrue(((String) r[2]).contains("--exposure auto measures the picture"), (String) r[2]);
        assertEquals(1, ((String) r[2]).strip().lines().count(), (String) r[2]);
    }

    /** The mean of the pixels' largest channel (0..255) over the picture's middle third, where the plane is. */
    private static double meanShapeValue(Path png) throws Exception {
        BufferedImage image = ImageIO.read(png.toFile());
        double sum = 0;
        int count = 0;
        for (int y = image.getHeight() / 3; y < 2 * image.getHeight() / 3; y++) {
            for (int x = image.getWidth() / 3; x < 2 * image.getWidth() / 3; x++) {
                int rgb = image.getRGB(x, y);
                sum += Math.max((rgb >> 16) & 255, Math.max((rgb >> 8) & 255, rgb & 255));
                count++;
            }
        }
        return sum / count;
    }

    /** The largest channel value (0..255) of the picture's middle third, where the plane is. */
    private static int brightestShapeValue(Path png) throws Exception {
        BufferedImage image = ImageIO.read(png.toFile());
        int best = 0;
        for (int y = image.getHeight() / 3; y < 2 * image.getHeight() / 3; y++) {
            for (int x = image.getWidth() / 3; x < 2 * image.getWidth() / 3; x++) {
                int rgb = image.getRGB(x, y);
                best = Math.max(best, Math.max((rgb >> 16) & 255, Math.max((rgb >> 8) & 255, rgb & 255)));
            }
        }
        return best;
    }
}
