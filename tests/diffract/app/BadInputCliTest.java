package diffract.app;

import diffract.optics.io.GwyTestWriter;
import diffract.optics.io.IbwTestWriter;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The bad-input list through the real command line: each case ends with exit code 2 and one line that names
 * the problem and the fix, without a stack trace; {@code --debug} adds the trace. (A broken OBJ: {@link SceneCliTest};
 * {@code view} without a display: {@link ViewerCliTest}; an OpenGL context that is too old:
 * {@code GLVersionCheckTest}; the parsers under random input: {@code ReaderFuzzTest}, {@code SceneFuzzTest}.)
 */
class BadInputCliTest {
    @TempDir
    static Path dir;

    @BeforeAll
    static void writeFiles() throws IOException {
        Files.write(dir.resolve("empty.png"), new byte[0]);
        Files.writeString(dir.resolve("corrupt.png"), "not a PNG at all");
        Files.writeString(dir.resolve("heights.xyz"), "x y z\n0 0 1\n");
        Files.writeString(dir.resolve("matrix.txt"), "0 0.1 0.2\n0.1 0.2 0\n0.2 0 0.1\n");
        Files.write(dir.resolve("nan.gsf"), gsfWithNaN());
        Files.writeString(dir.resolve("single.txt"), "0.1\n");
        writeScans();
        Files.writeString(dir.resolve("typo.json"), """
                {
                  "camera": {"eye": [0, 0, 3]},
                  "light": {"thetaDeg": 30},
                  "shape": {"kind": "plane"},
                  "material": {"patch": {"procedural": "blazed"}, "exposre": 10}
                }
                """);
        Files.writeString(dir.resolve("no-camera.json"), """
                {
                  "light": {"thetaDeg": 30},
                  "shape": {"kind": "plane"},
                  "material": {"patch": {"procedural": "blazed"}}
                }
                """);
        Files.writeString(dir.resolve("wrong-type.json"), """
                {
                  "camera": {"eye": [0, 0, 3]},
                  "light": {"thetaDeg": "thirty"},
                  "shape": {"kind": "plane"},
                  "material": {"patch": {"procedural": "blazed"}}
                }
                """);
    }

    /** Gwyddion files and Igor waves of 8 x 8 samples of 0.1 um: sound, damaged and without heights. */
    private static void writeScans() throws IOException {
        double[] metres = new double[64];
        java.util.Arrays.setAll(metres, i -> (i % 8) * 1e-8);
        byte[] phase = GwyTestWriter.dataField(8, 8, 8e-7, 8e-7, "m", "deg", metres);
        byte[] height = GwyTestWriter.dataField(8, 8, 8e-7, 8e-7, "m", "m", metres);
        byte[] channels = GwyTestWriter.container(GwyTestWriter.channel(0, "Phase", phase),
                GwyTestWriter.channel(1, "Height", height));
        Files.write(dir.resolve("channels.gwy"), channels);
        Files.write(dir.resolve("truncated.gwy"), java.util.Arrays.copyOf(channels, channels.length - 100));
        byte[] magic = channels.clone();
        magic[3] = 'X';
        Files.write(dir.resolve("magic.gwy"), magic);
        Files.write(dir.resolve("xres.gwy"), GwyTestWriter.container(GwyTestWriter.objectComponent("/0/data",
                GwyTestWriter.object("GwyDataField", GwyTestWriter.float64("xres", 8), GwyTestWriter.int32("yres", 8),
                        GwyTestWriter.float64("xreal", 8e-7), GwyTestWriter.float64("yreal", 8e-7),
                        GwyTestWriter.doubles("data", metres)))));
        Files.write(dir.resolve("phase.gwy"), GwyTestWriter.container(GwyTestWriter.channel(0, "Phase", phase)));
        double[] holes = metres.clone();
        holes[9] = Double.NaN;
        holes[60] = Double.NaN;
        Files.write(dir.resolve("nan.gwy"), GwyTestWriter.heightsInMetres(8, 8, 1e-7, holes));

        double[] layers = new double[128];
        java.util.Arrays.setAll(layers, i -> (i % 8) * 1e-8);
        byte[] asylum = IbwTestWriter.wave(8, 8, 2, layers).step(1e-7, 1e-7, "m")
                .layers("HeightRetrace", "PhaseRetrace").note("ScanSize: 8e-07\r").bytes();
        Files.write(dir.resolve("asylum.ibw"), asylum);
        Files.write(dir.resolve("truncated.ibw"), java.util.Arrays.copyOf(asylum, 500));
        byte[] checksum = asylum.clone();
        checksum[100] ^= 1;
        Files.write(dir.resolve("checksum.ibw"), checksum);
    }

    /** A 2 x 2 Gwyddion Simple Field whose second sample is NaN (missing AFM data). */
    private static byte[] gsfWithNaN() {
        byte[] header = "Gwyddion Simple Field 1.0\nXRes = 2\nYRes = 2\nXReal = 2e-07\nYReal = 2e-07\n"
                .getBytes(StandardCharsets.US_ASCII);
        int padding = 4 - header.length % 4; // 1..4 NULs, so the data start on a multiple of 4 (the format's rule)
        ByteBuffer file = ByteBuffer.allocate(header.length + padding + 16).order(ByteOrder.LITTLE_ENDIAN);
        file.put(header).put(new byte[padding]).putFloat(0).putFloat(Float.NaN).putFloat(1e-7f).putFloat(0);
        return file.array();
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', textBlock = """
            missing height field     | brdfmap --theta-i 10 --patch DIR/nope.png --max-height 0.3 --pixel-size 0.1                 | nope.png: no such file; check the path
            empty height field       | brdfmap --theta-i 10 --patch DIR/empty.png --max-height 0.3 --pixel-size 0.1                | the file is empty (0 bytes)
            corrupt image            | brdfmap --theta-i 10 --patch DIR/corrupt.png --max-height 0.3 --pixel-size 0.1              | not a readable image
            unsupported file type    | brdfmap --theta-i 10 --patch DIR/heights.xyz --max-height 0.3 --pixel-size 0.1              | not a height-field file diffract reads (its content matches none of them and '.xyz' is not their extension); read are:
            NaN in a .gsf            | brdfmap --theta-i 10 --patch DIR/nan.gsf                                                    | 1 sample is NaN or infinite (missing data), at row 0, column 1
            negative maxH            | precompute --patch DIR/matrix.txt --pixel-size 0.1 --max-height -1 --terms 2   | --max-height: DIR/matrix.txt: the height of the brightest grey value -1.0 is not valid
            negative pixel size      | precompute --patch DIR/matrix.txt --pixel-size -0.1 --terms 2                  | --pixel-size: DIR/matrix.txt: the pixel size -0.1 is not valid
            scene key with a typo    | render DIR/typo.json                                                           | typo.json:5: material.exposre: unknown key (did you mean "exposure"?)
            scene without a camera   | render DIR/no-camera.json                                                      | no-camera.json:1: camera: missing
            scene value of wrong type| render DIR/wrong-type.json                                                     | wrong-type.json:3: light.thetaDeg:
            unknown variant          | brdfmap --theta-i 10 --patch DIR/matrix.txt --pixel-size 0.1 --variant fastest              | unknown variant 'fastest'
            truncated .gwy           | brdfmap --theta-i 10 --patch DIR/truncated.gwy                                  | truncated.gwy: truncated or damaged .gwy: GwyContainer at byte 4 says it holds
            not a .gwy               | brdfmap --theta-i 10 --patch DIR/magic.gwy                                      | magic.gwy: not a Gwyddion file (it must begin with GWYP)
            .gwy of wrong types      | brdfmap --theta-i 10 --patch DIR/xres.gwy                                       | xres.gwy: '/0/data/xres' is of type 'd' (a double), expected 'i' (a 32-bit integer)
            unknown channel          | brdfmap --theta-i 10 --patch DIR/channels.gwy --channel Amplitude               | --channel: DIR/channels.gwy: no channel 'Amplitude'; channels: 0 'Phase' (deg, 8 x 8), 1 'Height' (m, 8 x 8); give a title or an index of these
            channel of no heights    | brdfmap --theta-i 10 --patch DIR/channels.gwy --channel 0                       | --channel: DIR/channels.gwy: channel 0 'Phase' is in deg, not a length
            .gwy without heights     | brdfmap --theta-i 10 --patch DIR/phase.gwy                                      | --channel: DIR/phase.gwy: no channel holds heights (values in a length unit such as m); channels: 0 'Phase' (deg, 8 x 8)
            NaN in a .gwy            | brdfmap --theta-i 10 --patch DIR/nan.gwy                                        | nan.gwy: channel 'Height' has 2 missing samples (NaN or infinite), the first at row 1, column 1; fill them in Gwyddion
            truncated .ibw           | brdfmap --theta-i 10 --patch DIR/truncated.ibw                                  | truncated.ibw: truncated Igor binary wave: 8 x 8 x 2 points of float32 need 512 bytes after the headers, found 116
            damaged .ibw             | brdfmap --theta-i 10 --patch DIR/checksum.ibw                                   | checksum.ibw: the Igor header's checksum does not add up
            unknown .ibw channel     | render --patch DIR/asylum.ibw --channel Height                                  | --channel: DIR/asylum.ibw: no channel 'Height'; channels: 0 'HeightRetrace' (m, 8 x 8), 1 'PhaseRetrace' (deg, 8 x 8)
            channel of a text matrix | brdfmap --theta-i 10 --patch DIR/matrix.txt --pixel-size 0.2 --channel 1        | --channel: DIR/matrix.txt: a text matrix holds one height field, no channels to choose from
            1 x 1 scan               | precompute --patch DIR/single.txt --pixel-size 1 --terms 2                      | single.txt: the scan is 1 x 1 samples (columns x rows); its transform needs at least 2 samples along an axis with structure
            scan narrower than light | brdfmap --theta-i 10 --patch DIR/matrix.txt --pixel-size 0.1                    | matrix.txt: the scan is 0.3 x 0.3 um (3 x 3 samples (columns x rows) of 0.1 x 0.1 um), narrower than the shortest visible wavelength 0.38 um along x
            unknown levelling        | brdfmap --theta-i 10 --patch DIR/matrix.txt --pixel-size 0.2 --level tilt      | Invalid value for option '--level': must be plane, rows or none, got 'tilt'
            levelling a named patch  | brdfmap --theta-i 10 --synthetic blazed --level rows                            | --channel and --level read a --patch FILE; a --synthetic patch is made level
            """)
    void badInputGetsOneLineAndExitCode2(String what, String command, String expected) {
        Object[] result = CliTest.run(args(command, "-o", dir.resolve("out.png").toString()));
        String err = ((String) result[2]).strip();
        assertEquals(2, result[0], what + ": " + err);
        String[] lines = err.split("\n");
        String refusal = lines[lines.length - 1];
        assertTrue(refusal.startsWith("diffract: ") && refusal.contains(expected.strip().replace("DIR", dir.toString())), what + ": " + err);
        assertFalse(err.contains("\tat "), what + ": a stack trace without --debug: " + err);
    }

    @Test
    void channelsListsWhatAScanFileHoldsAndMarksTheDefault() {
        Object[] result = CliTest.run("channels", dir.resolve("channels.gwy").toString());
        assertEquals(0, result[0], (String) result[2]);
        assertEquals(dir.resolve("channels.gwy") + ": a Gwyddion file, 2 channels\n  0 'Phase' (deg, 8 x 8), 0.8 x 0.8 um\n"
                + "* 1 'Height' (m, 8 x 8), 0.8 x 0.8 um\n", ((String) result[1]).replace("\r\n", "\n"));
        Object[] none = CliTest.run("channels", dir.resolve("phase.gwy").toString());
        assertTrue(((String) none[1]).startsWith(dir.resolve("phase.gwy") + ": a Gwyddion file, 1 channel; none holds heights"),
                (String) none[1]);
        Object[] broken = CliTest.run("channels", dir.resolve("truncated.ibw").toString());
        assertEquals(2, broken[0]);
        assertTrue(((String) broken[2]).strip().startsWith("diffract: " + dir.resolve("truncated.ibw")
                + ": truncated Igor binary wave"), (String) broken[2]);
    }

    @Test
    void debugShowsTheStackTrace() {
        Object[] result = CliTest.run(args("--debug brdfmap --theta-i 10 --patch DIR/nope.png --max-height 0.3 --pixel-size 0.1",
                "-o", dir.resolve("out.png").toString()));
        String err = (String) result[2];
        assertEquals(2, result[0], err);
        assertTrue(err.contains("nope.png: no such file") && err.contains("\tat diffract."), err);
    }

    @Test
    void aPixelSizeThatLooksLikeNanometresIsNamedWithTheLikelyValue() {
        Object[] result = CliTest.run(args("precompute --patch DIR/matrix.txt --pixel-size 68.6 --max-height 0.3 --terms 2",
                "-o", dir.resolve("terms").toString()));
        String err = (String) result[2];
        assertEquals(0, result[0], "a warning, not a refusal: the value may be meant");
        assertTrue(err.contains("the pixel size looks like nanometres: 68.6 um per pixel") && err.contains("did you mean 0.0686?"),
                err);
    }

    private static String[] args(String command, String... more) {
        String[] words = command.strip().replace("DIR", dir.toString()).split("\\s+");
        String[] all = new String[words.length + more.length];
        System.arraycopy(words, 0, all, 0, words.length);
        System.arraycopy(more, 0, all, words.length, more.length);
        return all;
    }
}
