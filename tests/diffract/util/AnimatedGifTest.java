package diffract.util;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Animated GIFs: every frame, its size, colours within the palette's reach, the looping extension. */
class AnimatedGifTest {
    @TempDir
    Path dir;

    @Test
    void framesSizeColoursAndLoopSurviveTheRoundTrip() throws Exception {
        int w = 37;
        int h = 21;
        List<float[]> frames = new ArrayList<>();
        for (int f = 0; f < 5; f++) {
            float[] rgb = new float[3 * w * h];
            for (int p = 0; p < w * h; p++) {
                rgb[3 * p] = (float) (p % w) / w;
                rgb[3 * p + 1] = f / 4f;
                rgb[3 * p + 2] = (float) (p / w) / h;
            }
            frames.add(rgb);
        }
        Path gif = dir.resolve("turn.gif");
        AnimatedGif.write(gif, frames, w, h, 80);
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReaders(in).next();
            reader.setInput(in);
            assertEquals(5, reader.getNumImages(true));
            for (int f = 0; f < 5; f++) {
                BufferedImage image = reader.read(f);
                assertEquals(w, image.getWidth());
                assertEquals(h, image.getHeight());
                // 5 x 37 x 21 colours share 256 entries: each channel within a few steps of the original
                int rgb = image.getRGB(20, 10);
                assertEquals(Math.round(20f / w * 255), (rgb >> 16) & 0xFF, 24);
                assertEquals(Math.round(f / 4f * 255), (rgb >> 8) & 0xFF, 24);
            }
            reader.dispose();
        }
        String bytes = new String(Files.readAllBytes(gif), java.nio.charset.StandardCharsets.ISO_8859_1);
        assertTrue(bytes.contains("NETSCAPE2.0"), "the looping extension");
    }
}
