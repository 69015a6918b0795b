package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import static diffract.optics.io.TestFiles.assertMeanSubtracted;
import static diffract.optics.io.TestFiles.assertUserError;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class TextMatrixReaderTest {
    @TempDir
    Path dir;

    private Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, text);
        return file;
    }

    @Test
    void readsCommasSpacesSemicolonsAndComments() throws IOException {
        Path file = write("matrix.csv", "# Gwyddion ASCII export\n# Width: 1 um\n"
                + "0.1, 0.2  0.3\n"
                + "\n"
                + "  0.4;0.5,\t0.6   # trailing comment\r\n"
                + "# between rows\n"
                + "-0.7 8e-1 +.9\n");
        Reporter.Collecting reporter = new Reporter.Collecting();

        HeightField field = HeightFieldReader.load(file, null, 0.15, reporter);

        assertEquals(3, field.rows());
        assertEquals(3, field.cols());
        assertEquals(0.15, field.pixelSizeXUm());
        assertEquals(0.15, field.pixelSizeYUm());
        assertMeanSubtracted(new double[] {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, -0.7, 0.8, 0.9}, field);
        assertEquals(0, reporter.warnings().size(), reporter.warnings().toString());
    }

    @Test
    void nonSquareMatrixKeepsRowsAsLines() throws IOException {
        Path file = write("wide.txt", "1 2 3 4 5\n6 7 8 9 10\n11 12 13 14 15\n");
        HeightField field = HeightFieldReader.load(file, null, 0.15, Reporter.SILENT);
        assertEquals(3, field.rows());
        assertEquals(5, field.cols());
        assertEquals(4 - 8.0, field.heightUm(0, 3), 1e-12);
        assertEquals(11 - 8.0, field.heightUm(2, 0), 1e-12);
    }

    @Test
    void maxHeightRescalesPeakToValley() throws IOException {
        Path file = write("rescale.dat", "0 1\n2 4\n");
        Reporter.Collecting reporter = new Reporter.Collecting();

        HeightField field = HeightFieldReader.load(file, 0.5, 0.2, reporter);

        assertMeanSubtracted(new double[] {0, 0.125, 0.25, 0.5}, field);
        assertEquals(0.5, field.maxHeightUm() - field.minHeightUm(), 1e-15);
        assertTrue(reporter.infos().stream().anyMatch(i -> i.contains("rescaled") && i.contains("0.125")
                && i.contains("4 um")), reporter.infos().toString());
    }

    @Test
    void raggedRowsNameTheLineAndBothLengths() throws IOException {
        Path file = write("ragged.txt", "# header\n1 2 3\n4 5\n");
        assertUserError(file, () -> HeightFieldReader.load(file, null, 0.1, Reporter.SILENT),
                "line 3 has 2 values", "line 2", "has 3");
    }

    @Test
    void badTokensNaNsAndEmptyFilesAreUserErrors() throws IOException {
        Path word = write("word.asc", "1 2\n3 abc\n");
        assertUserError(word, () -> HeightFieldReader.load(word, null, 0.1, Reporter.SILENT),
                "line 2", "'abc' is not a number");

        Path suffix = write("suffix.txt", "1 2d\n");
        assertUserError(suffix, () -> HeightFieldReader.load(suffix, null, 0.1, Reporter.SILENT), "'2d'");

        Path nan = write("nan.txt", "1 2 3\n4 NaN 6\nnan 8 -inf\n");
        assertUserError(nan, () -> HeightFieldReader.load(nan, null, 0.1, Reporter.SILENT),
                "3 samples are NaN or infinite", "row 1, column 1");

        Path comments = write("comments.txt", "# only\n\n# comments\n");
        assertUserError(comments, () -> HeightFieldReader.load(comments, null, 0.1, Reporter.SILENT), "no numbers");

        Path binary = dir.resolve("binary.dat");
        Files.write(binary, new byte[] {1, 2, 0, (byte) 0xFF, 7});
        assertUserError(binary, () -> HeightFieldReader.load(binary, null, 0.1, Reporter.SILENT), "not a number");
    }

    @Test
    void textNeedsPixelSize() throws IOException {
        Path file = write("nopixel.txt", "1 2\n3 4\n");
        assertUserError(file, () -> HeightFieldReader.load(file, null, null, Reporter.SILENT), "give the pixel size");
    }

    @Test
    void heightsThatLookLikeNanometresAreWarned() throws IOException {
        Path file = write("nm.txt", "0 350\n120 40\n");
        Reporter.Collecting reporter = new Reporter.Collecting();
        HeightFieldReader.load(file, null, 0.2, reporter);
        assertTrue(reporter.warnings().stream().anyMatch(w -> w.contains("looks like nanometres")
                && w.contains("did you mean 0.35")), reporter.warnings().toString());
    }
}
