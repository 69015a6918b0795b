package diffract.app;

import diffract.jrtr.GlTestSupport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code render --turntable}: as many frames as asked, of the asked size, and the frames differ as things turn. */
@Tag("gl")
class TurntableCliTest {
    @TempDir
    Path dir;

    static final String SCENE = Path.of("assets", "scenes", "blazed-grating-plane.json").toString();

    @Test
    void aGifHasEveryFrameAtTheAskedSize() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path gif = dir.resolve("turn.gif");
        Object[] result = CliTest.run("render", SCENE, "--turntable", "4", "--size", "48x32", "-o", gif.toString());
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[1]).contains("4 frames of 48x32"), (String) result[1]);
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReaders(in).next();
            reader.setInput(in);
            assertEquals(4, reader.getNumImages(true));
            BufferedImage first = reader.read(0);
            BufferedImage second = reader.read(1);
            assertEquals(48, first.getWidth());
            assertEquals(32, first.getHeight());
            // a quarter turn of the camera shows the plane from the side: not the same picture
            assertNotEquals(java.util.Arrays.toString(first.getRGB(0, 0, 48, 32, null, 0, 48)),
                    java.util.Arrays.toString(second.getRGB(0, 0, 48, 32, null, 0, 48)));
            reader.dispose();
        }
    }

    @Test
    void aPngNameGivesANumberedSequenceAndTheLightCanGoRound() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path png = dir.resolve("light.png");
        Object[] result = CliTest.run("render", SCENE, "--turntable", "3", "--orbit-light", "--size", "40x24", "-o",
                png.toString());
        assertEquals(0, result[0], (String) result[2]);
        for (int k = 0; k < 3; k++) {
            Path frame = dir.resolve(String.format("light-%03d.png", k));
            assertTrue(Files.isRegularFile(frame), frame + " missing");
            BufferedImage image = ImageIO.read(frame.toFile());
            assertEquals(40, image.getWidth());
            assertEquals(24, image.getHeight());
        }
        assertTrue(!Files.exists(dir.resolve("light-003.png")));
    }

    @Test
    void badTurntableUsageIsOneLine() {
        Object[] result = CliTest.run("render", SCENE, "--turntable", "1", "-o", dir.resolve("x.gif").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("2..720"), (String) result[2]);
        result = CliTest.run("render", SCENE, "--orbit-light", "-o", dir.resolve("x.png").toString());
        assertEquals(2, result[0]);
        assertTrue(((String) result[2]).contains("--turntable"), (String) result[2]);
    }
}
