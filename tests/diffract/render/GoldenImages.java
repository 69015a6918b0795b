package diffract.render;

import diffract.util.TestReport;
import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * Compares a rendered PNG with its golden: a pixel matches when no channel differs by more than
 * {@code channelTolerance} of 255, and at most {@code pixelBudgetPercent} % of the pixels may fail. On failure an
 * amplified difference (|a - b| x 16) goes next to the rendered picture. With {@code -Ddiffract.updateGoldens=true}
 * the rendered picture becomes the golden instead.
 */
public final class GoldenImages {
    public static final Path DIFFS = Path.of("target", "golden-diffs");

    private GoldenImages() {
    }

    /** @param actualPng the rendered picture, kept (under {@link #DIFFS}) for inspection */
    public static void assertMatches(String name, Path actualPng, Path golden, int channelTolerance,
                                     double pixelBudgetPercent) throws IOException {
        if (Boolean.getBoolean("diffract.updateGoldens")) {
            Files.createDirectories(golden.getParent());
            Files.copy(actualPng, golden, StandardCopyOption.REPLACE_EXISTING);
            TestReport.line(GoldenImages.class, "golden updated: " + golden);
            return;
        }
        if (!Files.isRegularFile(golden)) {
            fail("no golden " + golden + "; create it with -Ddiffract.updateGoldens=true");
        }
        BufferedImage expected = ImageIO.read(golden.toFile());
        BufferedImage actual = ImageIO.read(actualPng.toFile());
        assertEquals(expected.getWidth(), actual.getWidth(), name + ": width");
        assertEquals(expected.getHeight(), actual.getHeight(), name + ": height");
        int width = expected.getWidth();
        int height = expected.getHeight();
        BufferedImage diff = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        int failing = 0;
        int worst = 0;
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int a = expected.getRGB(x, y);
                int b = actual.getRGB(x, y);
                int pixelWorst = 0;
                int amplified = 0;
                for (int shift = 0; shift <= 16; shift += 8) {
                    int d = Math.abs(((a >> shift) & 0xff) - ((b >> shift) & 0xff));
                    pixelWorst = Math.max(pixelWorst, d);
                    amplified |= Math.min(255, 16 * d) << shift;
                }
                diff.setRGB(x, y, amplified);
                worst = Math.max(worst, pixelWorst);
                failing += pixelWorst > channelTolerance ? 1 : 0;
            }
        }
        double percent = 100.0 * failing / (width * height);
        String summary = String.format(Locale.ROOT, "%s: %d pixels (%.3f %%) differ by more than %d/255, largest "
                + "difference %d/255", name, failing, percent, channelTolerance, worst);
        TestReport.line(GoldenImages.class, "golden " + summary);
        if (percent > pixelBudgetPercent) {
            Files.createDirectories(DIFFS);
            Path diffPng = DIFFS.resolve(name + "-diff.png");
            ImageIO.write(diff, "png", diffPng.toFile());
            fail(summary + " (budget " + pixelBudgetPercent + " %); see " + actualPng + " and " + diffPng);
        }
    }
}
