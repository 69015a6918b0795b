package diffract.optics.io;

import diffract.util.UserInputException;
import org.junit.jupiter.api.function.Executable;

import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Helpers for the reader tests: GSF bytes built by hand, and checks on one-line error messages. */
final class TestFiles {
    private TestFiles() {
    }

    /**
     * A GSF file: the magic line, the given header lines, 1..4 NUL bytes up to a multiple of 4, then the floats
     * little-endian; {@code dropBytes} cuts that many bytes off the end (truncation).
     */
    static byte[] gsf(String headerLines, float[] values, int dropBytes) {
        byte[] header = ("Gwyddion Simple Field 1.0\n" + headerLines).getBytes(StandardCharsets.UTF_8);
        int padding = 4 - header.length % 4;
        ByteBuffer data = ByteBuffer.allocate(values.length * 4).order(ByteOrder.LITTLE_ENDIAN);
        for (float v : values) {
            data.putFloat(v);
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(header);
        out.writeBytes(new byte[padding]);
        out.writeBytes(data.array());
        byte[] all = out.toByteArray();
        return java.util.Arrays.copyOf(all, all.length - dropBytes);
    }

    /** Asserts a one-line UserInputException naming the file and containing each phrase. */
    static String assertUserError(Path file, Executable load, String... phrases) {
        UserInputException e = assertThrows(UserInputException.class, load);
        String message = e.getMessage();
        assertFalse(message.contains("\n") || message.contains("\r"), "one line: " + message);
        assertTrue(message.contains(file.getFileName().toString()), "names the file: " + message);
        for (String phrase : phrases) {
            assertTrue(message.contains(phrase), "'" + phrase + "' in: " + message);
        }
        return message;
    }

    static double mean(double[] values) {
        double sum = 0;
        for (double v : values) {
            sum += v;
        }
        return sum / values.length;
    }

    /** Asserts that the loaded field holds expectedRaw (row-major) minus its mean. */
    static void assertMeanSubtracted(double[] expectedRaw, diffract.optics.patches.HeightField field) {
        double mean = mean(expectedRaw);
        assertEquals(expectedRaw.length, field.sampleCount());
        for (int i = 0; i < expectedRaw.length; i++) {
            assertEquals(expectedRaw[i] - mean, field.heightUm(i / field.cols(), i % field.cols()), 1e-12,
                    "sample " + i);
        }
        assertEquals(0.0, field.meanUm(), 1e-12);
    }
}
