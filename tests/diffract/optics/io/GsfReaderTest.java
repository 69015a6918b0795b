package diffract.optics.io;

import diffract.optics.patches.HeightField;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static diffract.optics.io.TestFiles.assertMeanSubtracted;
import static diffract.optics.io.TestFiles.assertUserError;
import static diffract.optics.io.TestFiles.gsf;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

class GsfReaderTest {
    // 3 columns x 2 rows, heights in metres (tens of nanometres, as an AFM scan)
    private static final float[] METRES = {1.0e-8f, 2.5e-8f, -3.0e-8f, 4.0e-8f, 0f, 7.5e-8f};

    @TempDir
    Path dir;

    private Path write(String name, byte[] bytes) throws IOException {
        Path file = dir.resolve(name);
        Files.write(file, bytes);
        return file;
    }

    private static double[] micrometres(float[] values, double factor) {
        double[] out = new double[values.length];
        for (int i = 0; i < values.length; i++) {
            out[i] = values[i] * factor;
        }
        return out;
    }

    @Test
    void readsEveryPaddingLengthWithNonSquarePixels() throws IOException {
        // Titles of 0..3 extra characters make the header need 4, 3, 2 and 1 NUL bytes (in some order).
        java.util.Set<Integer> paddings = new java.util.HashSet<>();
        for (String title : new String[] {"a", "ab", "abc", "abcd"}) {
            String header = "XRes = 3\nYRes = 2\nXReal = 6e-07\nYReal = 8.0E-7\nXYUnits = m\nZUnits = m\n"
                    + "Title = " + title + "\n";
            byte[] bytes = gsf(header, METRES, 0);
            paddings.add(bytes.length - 24 - ("Gwyddion Simple Field 1.0\n" + header).length());
            Path file = write("scan-" + title + ".gsf", bytes);

            HeightField field = HeightFieldReader.load(file, null, null, Reporter.SILENT);

            assertEquals(2, field.rows());
            assertEquals(3, field.cols());
            assertEquals(0.2, field.pixelSizeXUm(), 1e-12);
            assertEquals(0.4, field.pixelSizeYUm(), 1e-12);
            assertMeanSubtracted(micrometres(METRES, 1e6), field);
            // row 0 = the first stored row
            assertEquals(4.0e-8f * 1e6 - TestFiles.mean(micrometres(METRES, 1e6)), field.heightUm(1, 0), 1e-12);
        }
        assertEquals(java.util.Set.of(1, 2, 3, 4), paddings);
    }

    @Test
    void zUnitsNanometres() throws IOException {
        float[] nm = {10f, 20f, 30f, 45f};
        Path file = write("nm.gsf", gsf("XRes = 2\nYRes = 2\nXReal = 4e-7\nYReal = 4e-7\nZUnits = nm\n", nm, 0));
        HeightField field = HeightFieldReader.load(file, null, null, Reporter.SILENT);
        assertMeanSubtracted(micrometres(nm, 1e-3), field);
        assertEquals(0.2, field.pixelSizeXUm(), 1e-12);
    }

    @Test
    void pixelSizeOptionOverridesHeaderAndMaxHeightRescales() throws IOException {
        Path file = write("override.gsf", gsf("XRes = 3\nYRes = 2\nXReal = 3e-07\nYReal = 4e-7\n", METRES, 0));
        Reporter.Collecting reporter = new Reporter.Collecting();

        HeightField field = HeightFieldReader.load(file, 0.21, 0.25, reporter);

        assertEquals(0.25, field.pixelSizeXUm());
        assertEquals(0.25, field.pixelSizeYUm());
        assertEquals(0.21, field.maxHeightUm() - field.minHeightUm(), 1e-12);
        assertTrue(reporter.infos().stream().anyMatch(i -> i.contains("the given pixel size 0.25 um overrides")
                && i.contains("0.1 x 0.2 um")), reporter.infos().toString());
        assertTrue(reporter.infos().stream().anyMatch(i -> i.contains("rescaled")), reporter.infos().toString());
    }

    @Test
    void nanSamplesNameCountAndFirstPosition() throws IOException {
        float[] values = {1e-8f, 2e-8f, 3e-8f, Float.NaN, 5e-8f, Float.NaN};
        Path file = write("holes.gsf", gsf("XRes = 3\nYRes = 2\nXReal = 3e-7\nYReal = 2e-7\n", values, 0));
        assertUserError(file, () -> HeightFieldReader.load(file, null, null, Reporter.SILENT),
                "2 samples are NaN", "row 1, column 0");
    }

    @Test
    void truncatedDataNamesExpectedAndActualBytes() throws IOException {
        Path file = write("short.gsf", gsf("XRes = 3\nYRes = 2\nXReal = 3e-7\nYReal = 2e-7\n", METRES, 5));
        assertUserError(file, () -> HeightFieldReader.load(file, null, null, Reporter.SILENT),
                "truncated", "needs 24 bytes", "found 19");
    }

    @Test
    void headerProblemsAreUserErrors() throws IOException {
        Path noSize = write("nosize.gsf", gsf("XRes = 3\nYRes = 2\n", METRES, 0));
        assertUserError(noSize, () -> HeightFieldReader.load(noSize, null, null, Reporter.SILENT),
                "no XReal/YReal", "give the pixel size");
        // ... which the option fixes
        assertEquals(0.2, HeightFieldReader.load(noSize, null, 0.2, Reporter.SILENT).pixelSizeXUm());

        Path noRes = write("nores.gsf", gsf("XRes = 6\nXReal = 1e-6\nYReal = 1e-6\n", METRES, 0));
        assertUserError(noRes, () -> HeightFieldReader.load(noRes, null, null, Reporter.SILENT), "lacks", "YRes");

        Path zero = write("zero.gsf", gsf("XRes = 0\nYRes = 2\nXReal = 1e-6\nYReal = 1e-6\n", new float[0], 0));
        assertUserError(zero, () -> HeightFieldReader.load(zero, null, null, Reporter.SILENT), "zero samples");

        Path volts = write("volts.gsf", gsf("XRes = 3\nYRes = 2\nXReal = 3e-7\nYReal = 2e-7\nZUnits = V\n",
                METRES, 0));
        assertUserError(volts, () -> HeightFieldReader.load(volts, null, null, Reporter.SILENT), "not a length");

        Path badReal = write("badreal.gsf", gsf("XRes = 3\nYRes = 2\nXReal = -3e-7\nYReal = 2e-7\n", METRES, 0));
        assertUserError(badReal, () -> HeightFieldReader.load(badReal, null, null, Reporter.SILENT),
                "XReal", "positive");

        Path wrongMagic = write("wrong.gsf", "Gwyddion Dump Field\nXRes = 1\n".getBytes(StandardCharsets.UTF_8));
        assertUserError(wrongMagic, () -> HeightFieldReader.load(wrongMagic, null, null, Reporter.SILENT),
                "Gwyddion Simple Field 1.0");

        Path noNul = write("nonul.gsf", "Gwyddion Simple Field 1.0\nXRes = 1\n".getBytes(StandardCharsets.UTF_8));
        assertUserError(noNul, () -> HeightFieldReader.load(noNul, null, null, Reporter.SILENT), "NUL");
    }

    @Test
    void gsfIsRecognisedByContentWhateverItsName() throws IOException {
        Path file = write("exported.dat", gsf("XRes = 3\nYRes = 2\nXReal = 6e-7\nYReal = 8e-7\n", METRES, 0));
        assertMeanSubtracted(micrometres(METRES, 1e6), HeightFieldReader.load(file, null, null, Reporter.SILENT));
    }

    @Test
    void pixelSizeInTheWrongUnitIsWarned() throws IOException {
        // XYUnits claims micrometres but the sizes were written in metres-as-micrometres: 0.3 um / 3 = 1e-7 um
        Path file = write("units.gsf", gsf("XRes = 3\nYRes = 2\nXReal = 3e-7\nYReal = 2e-7\nXYUnits = um\n",
                METRES, 0));
        Reporter.Collecting reporter = new Reporter.Collecting();
        // so small a scan diffracts nothing and is refused; the warning before says why it is so small
        assertUserError(file, () -> HeightFieldReader.load(file, null, null, reporter), "or check the pixel size");
        assertTrue(reporter.warnings().stream().anyMatch(w -> w.contains("looks like metres")
                && w.contains("did you mean 0.1?") && w.contains("XReal/XRes")), reporter.warnings().toString());
    }
}
