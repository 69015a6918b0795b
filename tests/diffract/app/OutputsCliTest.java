package diffract.app;

import diffract.optics.patches.SyntheticPatches;
import diffract.optics.io.GsfWriter;
import diffract.util.DiskCache;
import diffract.util.ImageFiles;
import diffract.util.OpenExr;
import diffract.util.SpecialFiles;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * Outputs through the real command line: each command refuses, before any work, an output that is a device, a
 * pipe, a folder, a kernel file, the same file as another output or of a format it cannot write, with exit code 2
 * and one line, and leaves the special file as it was; brdfmap writes OpenEXR maps equal to its PFMs.
 *
 * <p>No work ran: the patch is real, so the work would start (and print its notes and results) if the check did not
 * come first; the refusal must be the only line, nothing is printed on standard output, and the private term cache
 * stays absent.
 */
class OutputsCliTest {
    @TempDir
    static Path shared;
    static Path grating;

    @TempDir
    Path dir;

    static final Path DEV_NULL = Path.of("/dev/null");

    @BeforeAll
    static void writeGrating() throws IOException {
        grating = shared.resolve("blazed.gsf");
        GsfWriter.write(grating, SyntheticPatches.blazed(2.5, 0.13, 10, 8, 4));
    }

    private String suiteCache;

    @BeforeEach
    void privateCache() {
        suiteCache = System.getProperty(DiskCache.ROOT_PROPERTY);
        System.setProperty(DiskCache.ROOT_PROPERTY, dir.resolve("cache").toString());
    }

    @AfterEach
    void suiteCacheAgain() {
        if (suiteCache != null) {
            System.setProperty(DiskCache.ROOT_PROPERTY, suiteCache);
        } else {
            System.clearProperty(DiskCache.ROOT_PROPERTY);
        }
    }

    /** Exit code 2, exactly {@code "diffract: " + expected} on standard error, nothing else, no work done. */
    private void assertRefused(String expected, String... args) {
        Object[] result = CliTest.run(args);
        String err = ((String) result[2]).strip();
        assertEquals("diffract: " + expected, err, String.join(" ", args));
        assertEquals(2, result[0], err);
        assertEquals("", result[1], "nothing on standard output");
        assertFalse(Files.exists(dir.resolve("cache")), "no terms were computed");
    }

    private String[] brdfmap(String... outputs) {
        List<String> args = new ArrayList<>(List.of("brdfmap", "--patch", grating.toString(), "--theta-i", "30",
                "--variant", "flss", "--terms", "6", "--size", "16"));
        args.addAll(List.of(outputs));
        return args.toArray(String[]::new);
    }

    private static void assertCharacterDevice(Path path) {
        assumeTrue(Files.exists(path), path + " is missing here");
        assertFalse(Files.isRegularFile(path), path + " is still no regular file");
        assertTrue(Files.exists(path), path + " is still there");
    }

    private static void assertFifo(Path fifo) {
        assertFalse(Files.isRegularFile(fifo) || Files.isDirectory(fifo), fifo + " is still a fifo");
        assertTrue(Files.exists(fifo));
    }

    @Test
    void aDeviceIsRefusedByEveryCommandThatWrites() {
        assertCharacterDevice(DEV_NULL);
        String file = "-o /dev/null is a character device, not a regular file; name a file to write, e.g. ";
        String folder = " /dev/null is a character device, not a folder; name a folder to write into";
        assertRefused(file + "map.png", brdfmap("-o", "/dev/null"));
        assertRefused("--exr" + file.substring(2) + "map.exr",
                brdfmap("-o", dir.resolve("m.png").toString(), "--exr", "/dev/null"));
        assertRefused(file + "render.png", "render", "--synthetic", "blazed", "--size", "16x16", "-o", "/dev/null");
        assertRefused(file + "patch.gsf", "patch", "blazed", "-o", "/dev/null");
        assertRefused("-o" + folder, "demo", "-o", "/dev/null");
        assertRefused("-o" + folder, "precompute", "--patch", grating.toString(), "--terms", "3", "-o", "/dev/null");
        assertRefused("--to" + folder, "convert-terms", "--from", dir.toString(), "--to", "/dev/null");
        assertRefused("-o" + folder, "bench", "--quick", "-o", "/dev/null");
        assertRefused("--save" + folder, "measure", "--synthetic", "blazed", "--size", "16x16", "--save",
                "/dev/null");
        assertRefused("--screenshot-dir" + folder, "view", "--synthetic", "blazed", "--screenshot-dir", "/dev/null");
        assertCharacterDevice(DEV_NULL);
    }

    @Test
    void aFifoIsRefusedAndStaysAFifo() throws Exception {
        Path pfm = SpecialFiles.fifo(dir.resolve("m.pfm"));
        assertRefused("--pfm " + pfm + " is a named pipe (fifo), not a regular file; name a file to write, e.g. "
                + "map.pfm", brdfmap("-o", dir.resolve("m.png").toString(), "--pfm", pfm.toString()));
        assertFifo(pfm);

        // a turntable's PNG sequence: every frame's name is checked
        Path frame = SpecialFiles.fifo(dir.resolve("turn-002.png"));
        assertRefused("-o " + frame + " is a named pipe (fifo), not a regular file; name a file to write, e.g. "
                        + "turntable-000.png", "render", "--synthetic", "blazed", "--size", "16x16", "--turntable",
                "4", "-o", dir.resolve("turn.png").toString());
        assertFifo(frame);

        // the bench's files of fixed name in its folder
        Path results = SpecialFiles.fifo(dir.resolve("bench").resolve("results.md"));
        assertRefused("-o " + results + " is a named pipe (fifo), not a regular file; name a file to write, e.g. "
                + "results.md", "bench", "--quick", "-o", dir.resolve("bench").toString());
        assertFifo(results);

        // the files of fixed name measure --save and the demo write into their folders
        Path mask = SpecialFiles.fifo(dir.resolve("saved").resolve("mask.png"));
        assertRefused("--save " + mask + " is a named pipe (fifo), not a regular file; name a file to write, e.g. "
                + "mask.png", "measure", "--synthetic", "blazed", "--size", "16x16", "--save",
                dir.resolve("saved").toString());
        assertFifo(mask);
        Path demo = SpecialFiles.fifo(dir.resolve("demo").resolve("demo.png"));
        assertRefused("-o " + demo + " is a named pipe (fifo), not a regular file; name a file to write, e.g. "
                + "demo.png", "demo", "-o", dir.resolve("demo").toString());
        assertFifo(demo);
    }

    @Test
    void theKernelsFilesAreRefused() {
        assumeTrue(Files.isDirectory(Path.of("/proc/self")), "no /proc here");
        String proc = " holds the kernel's own files (proc), not files to write; choose another place";
        assertRefused("-o /proc/x.png: /proc" + proc, brdfmap("-o", "/proc/x.png"));
        assertRefused("--pfm /proc/x.pfm: /proc" + proc,
                brdfmap("-o", dir.resolve("m.png").toString(), "--pfm", "/proc/x.pfm"));
        assertRefused("-o /proc/terms: /proc" + proc, "precompute", "--patch", grating.toString(), "--terms", "3",
                "-o", "/proc/terms");
        assertRefused("-o /proc/x.png: /proc" + proc, "render", "--synthetic", "blazed", "--size", "16x16", "-o",
                "/proc/x.png");
        assertFalse(Files.exists(Path.of("/proc/x.png")));
    }

    @Test
    void aFolderIsRefusedWhereAFileIsMeant() throws IOException {
        Path folder = Files.createDirectories(dir.resolve("sub.exr"));
        assertRefused("-o " + folder + " is a folder; name the file to write, e.g. " + folder.resolve("map.png"),
                brdfmap("-o", folder.toString()));
        assertRefused("--exr " + folder + " is a folder; name the file to write, e.g. " + folder.resolve("map.exr"),
                brdfmap("-o", dir.resolve("m.png").toString(), "--exr", folder.toString()));
        assertTrue(Files.isDirectory(folder));
    }

    @Test
    void twoOutputsOnOnePathAreRefused() {
        Path map = dir.resolve("m.exr");
        String same = dir + "/sub/../m.exr";
        assertRefused("-o " + map + " and --exr " + same + " are the same file; give each output its own name",
                brdfmap("-o", map.toString(), "--exr", same));
        Path png = dir.resolve("m.png");
        assertRefused("-o " + png + " and --pfm " + png + " are the same file; give each output its own name",
                brdfmap("-o", png.toString(), "--pfm", png.toString()));
        assertFalse(Files.exists(map) || Files.exists(png));
    }

    @Test
    void anExtensionACommandCannotWriteIsRefusedWithTheOnesItCan() {
        Path jpg = dir.resolve("x.jpg");
        assertRefused("-o " + jpg + ": cannot write .jpg files; -o writes .png or .exr (e.g. map.png)",
                brdfmap("-o", jpg.toString()));
        Path exr = dir.resolve("x.exr");
        assertRefused("--pfm " + exr + ": cannot write .exr files; --pfm writes .pfm (e.g. map.pfm)",
                brdfmap("-o", dir.resolve("m.png").toString(), "--pfm", exr.toString()));
        assertRefused("-o " + jpg + ": cannot write .jpg files; -o writes .png or .exr (e.g. render.png)",
                "render", "--synthetic", "blazed", "--size", "16x16", "-o", jpg.toString());
        assertRefused("-o " + exr + ": cannot write .exr files; -o writes .gif or .png (e.g. turntable.gif)",
                "render", "--synthetic", "blazed", "--size", "16x16", "--turntable", "4", "-o", exr.toString());
        assertRefused("--exr-half goes with an OpenEXR output: -o OUT.exr", "render", "--synthetic", "blazed",
                "--size", "16x16", "--exr-half", "-o", dir.resolve("r.png").toString());
        assertRefused("-o " + jpg + ": cannot write .jpg files; -o writes .gif or .png (e.g. turntable.gif)",
                "render", "--synthetic", "blazed", "--size", "16x16", "--turntable", "4", "-o", jpg.toString());
        Path png = dir.resolve("x.png");
        assertRefused("-o " + png + ": cannot write .png files; -o writes .gsf (e.g. patch.gsf)",
                "patch", "blazed", "-o", png.toString());
        assertRefused("--exr-half goes with an OpenEXR output: --exr MAP.exr or -o MAP.exr",
                brdfmap("-o", dir.resolve("m.png").toString(), "--exr-half"));
        assertFalse(Files.exists(jpg) || Files.exists(exr) || Files.exists(png));
    }

    /** -o MAP.exr and --exr hold the floats of --pfm, bit for bit, with linear Rec. 709 / D65 in the header. */
    @Test
    void openExrMapsHoldThePfmsFloats() throws IOException {
        Path mapExr = dir.resolve("m.exr");
        Path alsoExr = dir.resolve("also.exr");
        Path pfm = dir.resolve("m.pfm");
        Object[] result = CliTest.run(brdfmap("-o", mapExr.toString(), "--exr", alsoExr.toString(), "--pfm",
                pfm.toString()));
        assertEquals(0, result[0], (String) result[2]);
        float[] floats = ImageFiles.readPfm(pfm, new int[3]);
        for (Path exr : List.of(mapExr, alsoExr)) {
            OpenExr.Image image = OpenExr.read(exr);
            assertEquals(16, image.width());
            assertEquals(16, image.height());
            assertArrayEquals(OpenExr.REC709_D65_CHROMATICITIES, image.chromaticities());
            assertBitEqual(floats, interleaved(image, "R", "G", "B"));
        }
        assertTrue(max(floats) > 0, "the map is lit");
    }

    @Test
    void aMonochromaticMapIsOneChannelY() throws IOException {
        Path exr = dir.resolve("mono.exr");
        Path pfm = dir.resolve("mono.pfm");
        Object[] result = CliTest.run(brdfmap("--lambda", "550", "-o", dir.resolve("mono.png").toString(), "--exr",
                exr.toString(), "--pfm", pfm.toString()));
        assertEquals(0, result[0], (String) result[2]);
        OpenExr.Image image = OpenExr.read(exr);
        assertEquals(List.of("Y"), image.channelNames());
        assertBitEqual(ImageFiles.readPfm(pfm, new int[3]), image.channel("Y"));
    }

    @Test
    void halfFloatsAreTheFloatsRoundedToElevenBits() throws IOException {
        Path exr = dir.resolve("half.exr");
        Path pfm = dir.resolve("half.pfm");
        Object[] result = CliTest.run(brdfmap("-o", exr.toString(), "--exr-half", "--pfm", pfm.toString()));
        assertEquals(0, result[0], (String) result[2]);
        float[] floats = ImageFiles.readPfm(pfm, new int[3]);
        float[] halves = interleaved(OpenExr.read(exr), "R", "G", "B");
        for (int i = 0; i < floats.length; i++) {
            float f = floats[i];
            double tolerance = Math.abs(f) * Math.scalb(1.0, -11) + Math.scalb(1.0, -24);
            assertEquals(f, halves[i], Math.abs(f) < 65504 ? tolerance : Double.POSITIVE_INFINITY, "value " + i);
        }
    }

    private static float[] interleaved(OpenExr.Image image, String... names) {
        int n = image.width() * image.height();
        float[] out = new float[n * names.length];
        for (int c = 0; c < names.length; c++) {
            float[] plane = image.channel(names[c]);
            for (int p = 0; p < n; p++) {
                out[p * names.length + c] = plane[p];
            }
        }
        return out;
    }

    private static void assertBitEqual(float[] expected, float[] actual) {
        assertEquals(expected.length, actual.length);
        for (int i = 0; i < expected.length; i++) {
            assertEquals(Float.floatToRawIntBits(expected[i]), Float.floatToRawIntBits(actual[i]), "value " + i);
        }
    }

    private static double max(float[] values) {
        double max = 0;
        for (float v : values) {
            max = Math.max(max, v);
        }
        return max;
    }
}
