package diffract.util;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * OpenEXR files read back by a reader that shares no code with the writer: the OpenEXR library itself, through its
 * Python binding ({@code pip install OpenEXR}, which .ci/install-deps --tests installs), skipped where this machine
 * lacks it; and tinyexr's own loader, always. The floats equal the PFM written from the same data bit for bit; the
 * header says linear Rec. 709 / D65.
 */
class OpenExrTest {
    @TempDir
    Path dir;

    /** Values a map holds: zeros, a spread over many decades, negatives (unclipped linear sRGB), extremes. */
    private static float[] values(int count, long seed) {
        Random random = new Random(seed);
        float[] v = new float[count];
        for (int i = 0; i < count; i++) {
            v[i] = switch (i % 7) {
                case 0 -> 0f;
                case 1 -> -random.nextFloat() * 0.01f;
                case 2 -> Float.MIN_VALUE * (1 + random.nextInt(100));
                case 3 -> 3.0e38f * random.nextFloat();
                default -> (float) Math.pow(10, random.nextDouble() * 20 - 10);
            };
        }
        return v;
    }

    /** The two readers: tinyexr's loader (always here), and the OpenEXR library (where Python has it). */
    enum Reader { TINYEXR, OPENEXR_LIBRARY }

    @ParameterizedTest
    @EnumSource(Reader.class)
    void colourFloatsEqualThePfmsBitForBit(Reader reader) throws Exception {
        int width = 13;
        int height = 7;
        float[] rgb = values(width * height * 3, 1);
        Path exr = dir.resolve("map.exr");
        Path pfm = dir.resolve("map.pfm");
        OpenExr.write(exr, rgb, width, height, 3, OpenExr.Precision.FLOAT, "linear sRGB");
        ImageFiles.writePfm(pfm, rgb, width, height, 3);
        float[] fromPfm = ImageFiles.readPfm(pfm, new int[3]);
        Read read = read(reader, exr, "R", "G", "B");
        assertEquals(List.of("B:FLOAT", "G:FLOAT", "R:FLOAT"), read.channels);
        assertArrayEquals(OpenExr.REC709_D65_CHROMATICITIES, read.chromaticities);
        assertBitEqual(fromPfm, read.pixels, reader);
        if (reader == Reader.OPENEXR_LIBRARY) {
            assertEquals("linear sRGB", read.comments);
        }
    }

    @ParameterizedTest
    @EnumSource(Reader.class)
    void oneChannelIsYWithoutChromaticities(Reader reader) throws Exception {
        int width = 5;
        int height = 9;
        float[] grey = values(width * height, 2);
        Path exr = dir.resolve("grey.exr");
        Path pfm = dir.resolve("grey.pfm");
        OpenExr.write(exr, grey, width, height, 1, OpenExr.Precision.FLOAT, null);
        ImageFiles.writePfm(pfm, grey, width, height, 1);
        Read read = read(reader, exr, "Y");
        assertEquals(List.of("Y:FLOAT"), read.channels);
        assertNull(read.chromaticities);
        assertBitEqual(ImageFiles.readPfm(pfm, new int[3]), read.pixels, reader);
    }

    /** Halves: each value rounded to 11 significant bits (relative 2^-11), subnormal halves to 2^-24. */
    @ParameterizedTest
    @EnumSource(Reader.class)
    void halfRoundsEachValueToElevenBits(Reader reader) throws Exception {
        int width = 8;
        int height = 4;
        float[] rgb = new float[width * height * 3];
        Random random = new Random(3);
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = (float) Math.pow(10, random.nextDouble() * 8 - 4); // 1e-4 .. 1e4, inside the half range
        }
        Path exr = dir.resolve("half.exr");
        OpenExr.write(exr, rgb, width, height, 3, OpenExr.Precision.HALF, null);
        Read read = read(reader, exr, "R", "G", "B");
        if (reader == Reader.OPENEXR_LIBRARY) { // tinyexr widens halves to floats as it loads them
            assertEquals(List.of("B:HALF", "G:HALF", "R:HALF"), read.channels);
        }
        assertNear(rgb, read.pixels, reader);
    }

    /** What a reader found: channels (name:type, in file order), chromaticities, comments, pixels interleaved. */
    private record Read(List<String> channels, float[] chromaticities, String comments, float[] pixels) {
    }

    private Read read(Reader reader, Path exr, String... names) throws Exception {
        if (reader == Reader.OPENEXR_LIBRARY) {
            return readWithOpenExrLibrary(exr, names);
        }
        OpenExr.Image image = OpenExr.read(exr);
        List<String> channels = image.channelNames().stream().map(n -> n + ":FLOAT").toList();
        return new Read(channels, image.chromaticities(), null, interleave(image, names));
    }

    private static void assertNear(float[] expected, float[] actual, Reader reader) {
        assertEquals(expected.length, actual.length);
        for (int i = 0; i < expected.length; i++) {
            double tolerance = Math.abs(expected[i]) * Math.scalb(1.0, -11) + Math.scalb(1.0, -24);
            assertEquals(expected[i], actual[i], tolerance, reader + ": value " + i);
        }
    }

    private static void assertBitEqual(float[] expected, float[] actual, Reader reader) {
        assertEquals(expected.length, actual.length, reader.name());
        for (int i = 0; i < expected.length; i++) {
            assertEquals(Float.floatToRawIntBits(expected[i]), Float.floatToRawIntBits(actual[i]),
                    reader + ": value " + i + " (" + expected[i] + " against " + actual[i] + ")");
        }
    }

    private static float[] interleave(OpenExr.Image image, String... names) {
        int n = image.width() * image.height();
        float[] out = new float[n * names.length];
        for (int c = 0; c < names.length; c++) {
            float[] plane = image.channel(names[c]);
            assertNotNull(plane, names[c]);
            for (int p = 0; p < n; p++) {
                out[p * names.length + c] = plane[p];
            }
        }
        return out;
    }

    /**
     * Python's OpenEXR binding reads the file, prints the header's channels, chromaticities and comments, one per
     * line, and writes the named channels' floats, interleaved, little-endian, as raw bytes. Skips where the binding
     * is missing.
     */
    private Read readWithOpenExrLibrary(Path exr, String... names) throws Exception {
        assumeTrue(pythonOpenExr(), "Python's OpenEXR binding is not installed (pip install OpenEXR)");
        Path raw = dir.resolve(exr.getFileName() + ".raw");
        String script = String.join("\n",
                "import sys, OpenEXR, numpy",
                "f = OpenEXR.File(sys.argv[1], separate_channels=True)",
                "h = f.header()",
                "ch = f.channels()",
                "types = {'float32': 'FLOAT', 'float16': 'HALF', 'uint32': 'UINT'}",
                "print(' '.join(n + ':' + types[str(ch[n].pixels.dtype)] for n in sorted(ch)))",
                "print(' '.join(repr(float(v)) for v in h['chromaticities']) if 'chromaticities' in h else '-')",
                "print(h.get('comments', '-'))",
                "planes = [ch[n].pixels.astype(numpy.float32) for n in sys.argv[3:]]",
                "numpy.stack(planes, axis=-1).astype('<f4').tofile(sys.argv[2])");
        List<String> command = new ArrayList<>(List.of("python3", "-c", script, exr.toString(), raw.toString()));
        command.addAll(List.of(names));
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "python3 did not finish");
        assertEquals(0, p.exitValue(), output);
        TestReport.line(OpenExrTest.class, exr.getFileName() + " as the OpenEXR library reads it:\n" + output);
        List<String> lines = output.lines().toList();
        float[] chromaticities = null;
        if (!lines.get(1).equals("-")) {
            String[] xy = lines.get(1).split(" ");
            chromaticities = new float[xy.length];
            for (int i = 0; i < xy.length; i++) {
                chromaticities[i] = Float.parseFloat(xy[i]); // the float32 the file holds, printed as a double
            }
        }
        ByteBuffer bytes = ByteBuffer.wrap(Files.readAllBytes(raw)).order(ByteOrder.LITTLE_ENDIAN);
        float[] pixels = new float[bytes.remaining() / 4];
        bytes.asFloatBuffer().get(pixels);
        return new Read(List.of(lines.get(0).split(" ")), chromaticities,
                lines.get(2).equals("-") ? null : lines.get(2), pixels);
    }

    private static Boolean available;

    private static synchronized boolean pythonOpenExr() {
        if (available == null) {
            try {
                Process p = new ProcessBuilder("python3", "-c", "import OpenEXR, numpy").redirectErrorStream(true)
                        .start();
                p.getInputStream().readAllBytes();
                available = p.waitFor(60, TimeUnit.SECONDS) && p.exitValue() == 0;
            } catch (IOException | InterruptedException e) {
                available = false;
            }
        }
        return available;
    }
}
