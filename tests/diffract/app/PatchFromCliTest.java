package diffract.app;

import diffract.optics.patches.HeightField;
import diffract.optics.patches.Levelling;
import diffract.optics.io.HeightFieldReader;
import diffract.util.Reporter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code patch --from FILE} writes the height field exactly as the commands read it: the .gsf read back holds the
 * same samples (to float32), pixel size and levelling as {@code --patch FILE} gives every command.
 */
class PatchFromCliTest {
    private static final Path NANOSCOPE = Path.of("tests/fixtures/afm/di-3.di");

    @TempDir
    Path dir;

    @Test
    void theWrittenFieldIsWhatEveryCommandReads() {
        for (Levelling level : Levelling.values()) {
            Path out = dir.resolve("height-" + level.label() + ".gsf");
            Object[] result = CliTest.run("patch", "--from", NANOSCOPE.toString(), "--channel", "Height", "--level",
                    level.label(), "-o", out.toString());
            assertEquals(0, result[0], (String) result[2]);
            assertTrue(((String) result[1]).startsWith("wrote " + out + ": " + NANOSCOPE
                    + " read as a Bruker NanoScope file, 256 x 256 pixels of 0.0390625 x 0.0390625 um"),
                    (String) result[1]);
            HeightField read = HeightFieldReader.load(NANOSCOPE, null, null, "Height", level, Reporter.SILENT);
            HeightField written = HeightFieldReader.load(out, null, null, null, Levelling.NONE, Reporter.SILENT);
            assertEquals(read.cols(), written.cols());
            assertEquals(read.rows(), written.rows());
            assertEquals(read.pixelSizeXUm(), written.pixelSizeXUm(), 1e-12);
            assertEquals(read.pixelSizeYUm(), written.pixelSizeYUm(), 1e-12);
            double[] want = read.heightsUm();
            double[] got = written.heightsUm();
            double range = read.maxHeightUm() - read.minHeightUm();
            for (int i = 0; i < want.length; i++) {
                // float32 metres, and the mean of the rounded values subtracted again on reading
                assertEquals(want[i], got[i], 1e-6 * range, level + " sample " + i);
            }
        }
    }

    @Test
    void theDefaultChannelAndLevellingAreThoseOfTheCommands() {
        Path out = dir.resolve("default.gsf");
        Object[] result = CliTest.run("patch", "--from", NANOSCOPE.toString(), "-o", out.toString());
        assertEquals(0, result[0], (String) result[2]);
        HeightField read = HeightFieldReader.load(NANOSCOPE, null, null, null, null, Reporter.SILENT);
        HeightField written = HeightFieldReader.load(out, null, null, null, Levelling.NONE, Reporter.SILENT);
        assertEquals(read.maxHeightUm(), written.maxHeightUm(), 1e-6 * read.maxHeightUm());
        assertTrue(((String) result[2]).contains("channel 3 'Height' (m, 256 x 256), one of 4"), (String) result[2]);
        assertTrue(((String) result[2]).contains("plane levelled"), (String) result[2]);
    }

    @Test
    void badCombinationsAreOneLineRefusals() {
        String out = dir.resolve("x.gsf").toString();
        for (List<String> args : List.of(
                List.of("patch", "-o", out),
                List.of("patch", "blazed", "--from", NANOSCOPE.toString(), "-o", out),
                List.of("patch", "blazed", "--channel", "1", "-o", out),
                List.of("patch", "--from", NANOSCOPE.toString(), "--period", "2", "-o", out),
                List.of("patch", "--from", NANOSCOPE.toString(), "--channel", "Phase", "-o", out),
                List.of("patch", "--from", dir.resolve("missing.spm").toString(), "-o", out))) {
            Object[] result = CliTest.run(args.toArray(String[]::new));
            assertEquals(2, result[0], args.toString());
            String err = ((String) result[2]).strip();
            assertEquals(1, err.lines().filter(l -> l.startsWith("diffract: ")).count(), args + ": " + err);
            assertTrue(err.lines().noneMatch(l -> l.contains("\tat ")), args + ": " + err);
            assertTrue(err.lines().reduce((a, b) -> b).orElseThrow().startsWith("diffract: "), err);
        }
    }
}
