package diffract.app;

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
        Files.writeString(dir.resolve("heights.xyz"), "0 0 1\n");
        Files.writeString(dir.resolve("matrix.txt"), "0 0.1 0.2\n0.1 0.2 0\n0.2 0 0.1\n");
        Files.write(dir.resolve("nan.gsf"), gsfWithNaN());
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
            unsupported file type    | brdfmap --theta-i 10 --patch DIR/heights.xyz --max-height 0.3 --pixel-size 0.1              | unsupported file type '.xyz'; supported:
            NaN in a .gsf            | brdfmap --theta-i 10 --patch DIR/nan.gsf                                                    | 1 sample is NaN or infinite (missing data), at row 0, column 1
            negative maxH            | precompute --patch DIR/matrix.txt --pixel-size 0.1 --max-height -1 --terms 2   | --max-height: DIR/matrix.txt: the height of the brightest grey value -1.0 is not valid
            negative pixel size      | precompute --patch DIR/matrix.txt --pixel-size -0.1 --terms 2                  | --pixel-size: DIR/matrix.txt: the pixel size -0.1 is not valid
            scene key with a typo    | render DIR/typo.json                                                           | typo.json:5: material.exposre: unknown key (did you mean "exposure"?)
            scene without a camera   | render DIR/no-camera.json                                                      | no-camera.json:1: camera: missing
            scene value of wrong type| render DIR/wrong-type.json                                                     | wrong-type.json:3: light.thetaDeg:
            unknown variant          | brdfmap --theta-i 10 --patch DIR/matrix.txt --pixel-size 0.1 --variant fastest              | unknown variant 'fastest'
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
