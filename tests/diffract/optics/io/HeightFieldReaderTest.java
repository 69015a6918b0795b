package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.patches.Levelling;
import diffract.optics.settings.Quantity;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static diffract.optics.io.TestFiles.assertUserError;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Format-independent behaviour of {@link HeightFieldReader#load}: file problems, option checks, warnings. */
class HeightFieldReaderTest {
    @TempDir
    Path dir;

    /** 8 x 8 heights from 0 to 0.49 um: 0.55 um wide at the Elaphe patch's 0.0686 um pixels. */
    private Path matrix(String name) throws IOException {
        StringBuilder text = new StringBuilder();
        for (int r = 0; r < 8; r++) {
            for (int c = 0; c < 8; c++) {
                text.append(c == 0 ? "" : " ").append((r * 8 + c) / 100.0);
            }
            text.append('\n');
        }
        Path file = dir.resolve(name);
        Files.writeString(file, text);
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
                "not a height-field file diffract reads (its content matches none of them and '.jpg' is not their"
                        + " extension); read are: ", ".png", ".tiff", ".csv", ".gsf", ".jpk", ".nid");

        Path bare = dir.resolve("heights");
        Files.writeString(bare, "heights\n");
        assertUserError(bare, () -> HeightFieldReader.load(bare, 1.0, 0.1, Reporter.SILENT),
                "its content matches none of them); read are: ");
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

        // metres make the scan too small to use: the warning comes first and names the likely value
        Reporter.Collecting metres = new Reporter.Collecting();
        assertUserError(file, () -> HeightFieldReader.load(file, null, 6.86e-8, metres), "or check the pixel size");
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
        Files.writeString(file, "0.5,0.5,0.5,0.5\n".repeat(4));
        Reporter.Collecting reporter = new Reporter.Collecting();

        HeightField field = HeightFieldReader.load(file, 1.0, 0.1, reporter);

        assertEquals(0.0, field.maxAbsHeightUm());
        assertWarned(reporter.warnings(), "flat", "specularly");
    }

    @Test
    void aScanTooSmallToDiffractIsRefusedWithItsSize() throws IOException {
        Path single = dir.resolve("single.txt");
        Files.writeString(single, "0.1\n");
        assertUserError(single, () -> HeightFieldReader.load(single, null, 5.0, Reporter.SILENT), "the scan is 1 x 1"
                + " samples (columns x rows); its transform needs at least 2 samples along an axis with structure");
        // one scan line is a 1-D profile (a grating's grooves along y): nothing along y to resolve
        Path line = dir.resolve("line.txt");
        Files.writeString(line, "0 0.1 0.2 0.1 0 0.1\n");
        assertEquals(6, HeightFieldReader.load(line, null, 1.0, Reporter.SILENT).sampleCount());
        // the same profile on three rows 0.1 um apart is too: constant along y; too short along x, refused
        Path grooves = dir.resolve("grooves.txt");
        Files.writeString(grooves, "0 0.1 0.2\n0 0.1 0.2\n0 0.1 0.2\n");
        assertEquals(9, HeightFieldReader.load(grooves, null, 0.2, Reporter.SILENT).sampleCount());
        assertUserError(grooves, () -> HeightFieldReader.load(grooves, null, 0.1, Reporter.SILENT),
                "the scan is 0.3 x 0.3 um", "along x");

        // 3 x 3 samples of 0.1 um: 0.3 um, below the shortest visible wavelength
        Path small = dir.resolve("small.txt");
        Files.writeString(small, "0 0.1 0.2\n0.1 0.2 0\n0.2 0 0.1\n");
        assertUserError(small, () -> HeightFieldReader.load(small, null, 0.1, Reporter.SILENT), "the scan is 0.3 x 0.3"
                + " um (3 x 3 samples (columns x rows) of 0.1 x 0.1 um), narrower than the shortest visible"
                + " wavelength 0.38 um along x: its first diffraction order (sin theta = lambda / width > 1) lies"
                + " beyond the horizon");
        // 0.4 um wide and 0.38 um high is enough
        assertEquals(9, HeightFieldReader.load(small, null, 0.4 / 3, Reporter.SILENT).sampleCount());
        Path narrow = dir.resolve("narrow.txt");
        Files.writeString(narrow, "0 0.1 0.2 0.3 0.2\n0.1 0.2 0 0.1 0.3\n");
        assertUserError(narrow, () -> HeightFieldReader.load(narrow, null, 0.15, Reporter.SILENT),
                "the scan is 0.75 x 0.3 um", "along y");
        assertEquals(10, HeightFieldReader.load(narrow, null, 0.19, Reporter.SILENT).sampleCount());
    }

    @Test
    void aChannelOfAFileWithoutChannelsIsRefused() throws IOException {
        Path file = matrix("one.txt");
        InvalidSettingException e = assertThrows(InvalidSettingException.class, () -> HeightFieldReader.load(file,
                null, 0.1, "Height", Levelling.PLANE, Reporter.SILENT));
        assertEquals(Quantity.CHANNEL, e.quantity());
        assertEquals(file + ": a text matrix holds one height field, no channels to choose from (only the instruments'"
                + " files have channels); leave the channel out", e.getMessage());
        assertEquals(List.of(), HeightFieldReader.channels(file, Reporter.SILENT));
    }

    @Test
    void theLevellingIsAppliedBeforeTheRescaleAndTheMean() throws IOException {
        // a tilted plane under ridges along y: 0.02 um per column and 0.05 um per row, ridges of 0.1 um
        double[] ridges = {0.1, -0.1, 0.1, -0.1, 0.1, -0.1};
        StringBuilder text = new StringBuilder();
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 6; c++) {
                text.append(c == 0 ? "" : " ").append(0.02 * c + 0.05 * r + ridges[c]);
            }
            text.append('\n');
        }
        Path file = dir.resolve("tilted.txt");
        Files.writeString(file, text);

        HeightField plane = HeightFieldReader.load(file, null, 0.1, null, Levelling.PLANE, Reporter.SILENT);
        HeightField rows = HeightFieldReader.load(file, null, 0.1, null, Levelling.ROWS, Reporter.SILENT);
        HeightField none = HeightFieldReader.load(file, null, 0.1, null, Levelling.NONE, Reporter.SILENT);
        // the ridges alternate about their mean, so the plane fit sees the tilt plus a small x slope of theirs:
        // sum((c - 2.5) ridges[c]) / sum((c - 2.5)^2) = -0.3 / 17.5 per column
        double ridgeSlope = -0.3 / 17.5;
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 6; c++) {
                assertEquals(ridges[c] - ridgeSlope * (c - 2.5), plane.heightUm(r, c), 1e-12);
                assertEquals(0.02 * (c - 2.5) + ridges[c], rows.heightUm(r, c), 1e-12);
                assertEquals(0.02 * (c - 2.5) + 0.05 * (r - 1.5) + ridges[c], none.heightUm(r, c), 1e-12);
            }
        }
        // a given peak-to-valley height rescales the levelled field, not the tilted one
        HeightField rescaled = HeightFieldReader.load(file, 0.1, 0.1, null, Levelling.ROWS, Reporter.SILENT);
        assertEquals(0.1, rescaled.maxHeightUm() - rescaled.minHeightUm(), 1e-12);
        assertEquals(rows.heightUm(0, 0) * 0.1 / (rows.maxHeightUm() - rows.minHeightUm()), rescaled.heightUm(0, 0),
                1e-12);
    }

    @Test
    void aPlaneThatLevellingFlattensIsWarned() throws IOException {
        Path file = dir.resolve("plane.txt");
        Files.writeString(file, "0 0.1 0.2 0.3\n0.1 0.2 0.3 0.4\n0.2 0.3 0.4 0.5\n0.3 0.4 0.5 0.6\n");
        Reporter.Collecting reporter = new Reporter.Collecting();
        HeightFieldReader.load(file, null, 0.2, null, Levelling.PLANE, reporter);
        assertWarned(reporter.warnings(), "levelling (plane) leaves the height field flat: it is a tilted plane");
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
