package diffract.optics.io;

import diffract.optics.HeightField;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static diffract.optics.io.TestFiles.assertUserError;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Format-independent behaviour of {@link HeightFieldReader#load}: file problems, option checks, warnings. */
class HeightFieldReaderTest {
    @TempDir
    Path dir;

    private Path matrix(String name) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, "0 0.2\n0.4 0.6\n");
        return file;
    }

    @Test
    void fileProblemsAreOneLineUserErrors() throws IOException {
        Path missing = dir.resolve("missing.png");
        assertUserError(missing, () -> HeightFieldReader.load(missing, 1.0, 0.1, Reporter.SILENT), "no such file");

        Path folder = Files.createDirectory(dir.resolve("folder.txt"));
        assertUserError(folder, () -> HeightFieldReader.load(folder, 1.0, 0.1, Reporter.SILENT), "is a directory");

        Path empty = Files.createFile(dir.resolve("empty.gsf"));
        assertUserError(empty, () -> HeightFieldReader.load(empty, 1.0, 0.1, Reporter.SILENT), "empty");

        Path jpeg = dir.resolve("photo.jpg");
        Files.writeString(jpeg, "not really a jpeg");
        assertUserError(jpeg, () -> HeightFieldReader.load(jpeg, 1.0, 0.1, Reporter.SILENT),
                "unsupported file type '.jpg'", ".png", ".tiff", ".csv", ".gsf");

        Path bare = dir.resolve("heights");
        Files.writeString(bare, "1 2\n");
        assertUserError(bare, () -> HeightFieldReader.load(bare, 1.0, 0.1, Reporter.SILENT), "no extension");
    }

    @Test
    void badOptionValuesAreUserErrors() throws IOException {
        Path file = matrix("opts.txt");
        assertUserError(file, () -> HeightFieldReader.load(file, -1.0, 0.1, Reporter.SILENT), "the height of the brightest grey value -1.0");
        assertUserError(file, () -> HeightFieldReader.load(file, 0.0, 0.1, Reporter.SILENT), "the height of the brightest grey value 0.0");
        assertUserError(file, () -> HeightFieldReader.load(file, null, 0.0, Reporter.SILENT), "the pixel size 0.0");
        assertUserError(file, () -> HeightFieldReader.load(file, null, -0.1, Reporter.SILENT), "the pixel size -0.1");
        assertUserError(file, () -> HeightFieldReader.load(file, null, Double.NaN, Reporter.SILENT),
                "the pixel size NaN", "positive");
        assertUserError(file, () -> HeightFieldReader.load(file, Double.POSITIVE_INFINITY, 0.1, Reporter.SILENT),
                "the height of the brightest grey value Infinity");
    }

    @Test
    void implausiblePixelSizesAndHeightsAreWarned() throws IOException {
        Path file = matrix("plausible.txt");

        Reporter.Collecting nanometres = new Reporter.Collecting();
        HeightFieldReader.load(file, null, 68.6, nanometres);
        assertWarned(nanometres.warnings(), "looks like nanometres: 68.6 um per pixel", "did you mean 0.0686?");

        Reporter.Collecting metres = new Reporter.Collecting();
        HeightFieldReader.load(file, null, 6.86e-8, metres);
        assertWarned(metres.warnings(), "looks like metres", "did you mean 0.0686?");

        Reporter.Collecting height = new Reporter.Collecting();
        HeightFieldReader.load(file, 500.0, 0.1, height);
        assertWarned(height.warnings(), "maximum height looks like nanometres: 500 um", "did you mean 0.5?");

        Reporter.Collecting fine = new Reporter.Collecting();
        HeightFieldReader.load(file, 0.5, 0.0686, fine);
        assertEquals(List.of(), fine.warnings());
    }

    @Test
    void flatFieldWarnsAboutSpecularReflection() throws IOException {
        Path file = dir.resolve("flat.csv");
        Files.writeString(file, "0.3,0.3\n0.3,0.3\n");
        Reporter.Collecting reporter = new Reporter.Collecting();

        HeightField field = HeightFieldReader.load(file, 1.0, 0.1, reporter);

        assertEquals(0.0, field.maxAbsHeightUm());
        assertWarned(reporter.warnings(), "flat", "specularly");
    }

    private static void assertWarned(List<String> warnings, String... phrases) {
        assertTrue(warnings.stream().anyMatch(w -> {
            for (String phrase : phrases) {
                if (!w.contains(phrase)) {
                    return false;
                }
            }
            return true;
        }), "expected " + List.of(phrases) + " in " + warnings);
    }
}
