package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.awt.image.WritableRaster;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import static diffract.optics.io.TestFiles.assertMeanSubtracted;
import static diffract.optics.io.TestFiles.assertUserError;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class ImageHeightFieldReaderTest {
    @TempDir
    Path dir;

    private Path write(BufferedImage image, String format, String name) throws IOException {
        Path file = dir.resolve(name);
        assertTrue(ImageIO.write(image, format, file.toFile()), "the JDK writes " + format);
        return file;
    }

    @Test
    void eightBitGreyPngKeepsOrientationAndScale() throws IOException {
        // 3 rows x 5 columns, every value distinct, so a transposed or flipped read cannot pass.
        BufferedImage image = new BufferedImage(5, 3, BufferedImage.TYPE_BYTE_GRAY);
        double[] expected = new double[15];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 5; c++) {
                int grey = 17 * (r * 5 + c);
                image.getRaster().setSample(c, r, 0, grey);
                expected[r * 5 + c] = grey / 255.0 * 1.5;
            }
        }
        Path file = write(image, "png", "grey8.png");
        Reporter.Collecting reporter = new Reporter.Collecting();

        HeightField field = HeightFieldReader.load(file, 1.5, 0.13, reporter);

        assertEquals(3, field.rows());
        assertEquals(5, field.cols());
        assertEquals(0.13, field.pixelSizeXUm());
        assertEquals(0.13, field.pixelSizeYUm());
        assertMeanSubtracted(expected, field);
        // row 0 is the top image row: its first sample is black, the bottom-right one is the brightest
        assertEquals(-TestFiles.mean(expected), field.heightUm(0, 0), 1e-12);
        assertEquals(238 / 255.0 * 1.5 - TestFiles.mean(expected), field.heightUm(2, 4), 1e-12);
        assertEquals(0, reporter.warnings().size(), reporter.warnings().toString());
    }

    private static BufferedImage sixteenBit() {
        BufferedImage image = new BufferedImage(2, 3, BufferedImage.TYPE_USHORT_GRAY);
        WritableRaster raster = image.getRaster();
        int[] values = {0, 1, 32768, 65535, 257, 40000};
        for (int i = 0; i < values.length; i++) {
            raster.setSample(i % 2, i / 2, 0, values[i]);
        }
        return image;
    }

    private static double[] sixteenBitExpected(double maxHeightUm) {
        int[] values = {0, 1, 32768, 65535, 257, 40000};
        return Arrays.stream(values).mapToDouble(v -> v / 65535.0 * maxHeightUm).toArray();
    }

    @Test
    void sixteenBitGreyPngIsReadExactly() throws IOException {
        Path file = write(sixteenBit(), "png", "grey16.png");

        HeightField field = HeightFieldReader.load(file, 2.0, 0.2, Reporter.SILENT);

        assertEquals(3, field.rows());
        assertEquals(2, field.cols());
        assertMeanSubtracted(sixteenBitExpected(2.0), field);
        // 32768 / 65535 * 2, not the 8-bit 128 / 255 * 2 that getRGB would give
        assertEquals(32768 / 65535.0 * 2 - TestFiles.mean(sixteenBitExpected(2.0)), field.heightUm(1, 0), 1e-12);
        // 1 and 0 differ in 16 bits
        assertTrue(field.heightUm(0, 1) > field.heightUm(0, 0));
    }

    @Test
    void sixteenBitGreyTiffIsReadExactly() throws IOException {
        for (String name : new String[] {"grey16.tif", "grey16.TIFF"}) {
            Path file = write(sixteenBit(), "tiff", name);
            HeightField field = HeightFieldReader.load(file, 0.7, 0.2, Reporter.SILENT);
            assertMeanSubtracted(sixteenBitExpected(0.7), field);
        }
    }

    @Test
    void rgbBmpUsesLuminanceOnStoredValues() throws IOException {
        BufferedImage image = new BufferedImage(2, 2, BufferedImage.TYPE_3BYTE_BGR);
        int[][] rgb = {{100, 100, 100}, {255, 0, 0}, {10, 20, 30}, {0, 0, 255}};
        double[] expected = new double[4];
        for (int i = 0; i < 4; i++) {
            image.getRaster().setPixel(i % 2, i / 2, rgb[i]);
            double r = rgb[i][0] / 255.0;
            double g = rgb[i][1] / 255.0;
            double b = rgb[i][2] / 255.0;
            expected[i] = (r == g && g == b ? r : 0.2126 * r + 0.7152 * g + 0.0722 * b) * 1.0;
        }
        Path file = write(image, "bmp", "colour.bmp");
        Reporter.Collecting reporter = new Reporter.Collecting();

        HeightField field = HeightFieldReader.load(file, 1.0, 0.2, reporter);

        assertMeanSubtracted(expected, field);
        assertEquals(100 / 255.0 - TestFiles.mean(expected), field.heightUm(0, 0), 1e-15, "grey stays exact");
        assertTrue(reporter.warnings().stream().anyMatch(w -> w.contains("colour pixels")), reporter.warnings().toString());
    }

    @Test
    void paletteImageGoesThroughItsPalette() throws IOException {
        byte[] r = {0, (byte) 255, (byte) 255, (byte) 128};
        byte[] g = {0, (byte) 255, 0, (byte) 128};
        byte[] b = {0, (byte) 255, 0, (byte) 128};
        IndexColorModel palette = new IndexColorModel(2, 4, r, g, b);
        BufferedImage image = new BufferedImage(4, 2, BufferedImage.TYPE_BYTE_BINARY, palette);
        for (int x = 0; x < 4; x++) {
            image.getRaster().setSample(x, 0, 0, x);
            image.getRaster().setSample(x, 1, 0, 3 - x);
        }
        Path file = write(image, "png", "palette.png");

        HeightField field = HeightFieldReader.load(file, 1.0, 0.2, Reporter.SILENT);

        assertMeanSubtracted(new double[] {0, 1, 0.2126, 128 / 255.0, 128 / 255.0, 0.2126, 1, 0}, field);
    }

    @Test
    void imagesNeedMaxHeightAndPixelSize() throws IOException {
        Path file = write(sixteenBit(), "png", "needs-options.png");
        assertUserError(file, () -> HeightFieldReader.load(file, null, 0.1, Reporter.SILENT), "the height in micrometres that white maps to");
        assertUserError(file, () -> HeightFieldReader.load(file, 1.0, null, Reporter.SILENT), "give the pixel size");
        assertUserError(file, () -> HeightFieldReader.load(file, null, null, Reporter.SILENT),
                "white maps to", "and the pixel size");
    }

    @Test
    void corruptAndTruncatedImagesAreUserErrors() throws IOException {
        Path good = write(sixteenBit(), "png", "good.png");
        byte[] bytes = Files.readAllBytes(good);

        Path truncated = dir.resolve("truncated.png");
        Files.write(truncated, Arrays.copyOf(bytes, bytes.length / 2));
        assertUserError(truncated, () -> HeightFieldReader.load(truncated, 1.0, 0.1, Reporter.SILENT), "corrupt");

        Path garbage = dir.resolve("garbage.png");
        byte[] junk = Arrays.copyOf(bytes, 40);
        Arrays.fill(junk, 8, 40, (byte) 0x5A); // PNG signature, then nonsense
        Files.write(garbage, junk);
        assertUserError(garbage, () -> HeightFieldReader.load(garbage, 1.0, 0.1, Reporter.SILENT), "corrupt");

        Path text = dir.resolve("text.bmp");
        Files.writeString(text, "this is not a bitmap");
        assertUserError(text, () -> HeightFieldReader.load(text, 1.0, 0.1, Reporter.SILENT), "not a readable image");
    }
}
