package diffract.app;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * brdfmap's point light goes up to the horizon, exclusive: the extremes' grazing light of 89.9 degrees makes a
 * finite map with lit orders (the mirror direction is at 89.9 degrees, the orders spread back towards the normal;
 * linear sRGB may be slightly negative for spectral colours outside its gamut); a disc of light must stay above the horizon, so the sun's 0.53 degrees
 * stop at 89.735; 90 and beyond are refused. The viewer and scenes keep their own limit of 89 degrees.
 */
class GrazingLightCliTest {
    @TempDir
    Path dir;

    @Test
    void aPointLightAt89point9DegreesMakesAFiniteMap() throws IOException {
        Path patch = dir.resolve("blazed.gsf");
        assertEquals(0, CliTest.run("patch", "blazed", "--period", "2.5", "--height", "0.2", "--periods", "4", "-o",
                patch.toString())[0]);
        Path pfm = dir.resolve("grazing.pfm");
        Object[] result = CliTest.run("brdfmap", "--patch", patch.toString(), "--theta-i", "89.9", "--size", "16",
                "--coherence-length", "10", "-o", dir.resolve("grazing.png").toString(), "--pfm", pfm.toString(), "-q");
        assertEquals(0, result[0], (String) result[2]);
        float[] values = pfm(pfm);
        double max = 0;
        double min = 0;
        for (float v : values) {
            assertTrue(Float.isFinite(v), "a map value " + v);
            max = Math.max(max, v);
            min = Math.min(min, v);
        }
        assertTrue(max > 0, "the grazing light's orders are lit");
        assertTrue(-min < 0.1 * max, "out-of-gamut negatives stay small: " + min + " against " + max);
    }

    @Test
    void theHorizonIsRefusedAndADiscMustStayAboveIt() {
        Path patch = dir.resolve("unused.gsf");
        Object[] horizon = CliTest.run("brdfmap", "--synthetic", "blazed", "--theta-i", "90", "-o",
                dir.resolve("x.png").toString());
        assertEquals(2, horizon[0]);
        assertTrue(((String) horizon[2]).contains("--theta-i must be in [0, 90) degrees"), (String) horizon[2]);
        Object[] disc = CliTest.run("brdfmap", "--synthetic", "blazed", "--theta-i", "89.9", "--light-size-deg",
                "0.53", "--variant", "lobes", "-o", dir.resolve("x.png").toString());
        assertEquals(2, disc[0]);
        assertEquals("diffract: --theta-i 89.9 with --light-size-deg 0.53 puts part of the light's disc below the"
                + " horizon (theta_i + D/2 = 90.165 degrees); a disc stays above it up to --theta-i below 89.735, a"
                + " point light (--light-size-deg 0) up to 90", ((String) disc[2]).strip());
        Object[] viewer = CliTest.run("view", "--synthetic", "blazed", "--theta-i", "89.9");
        assertEquals(2, viewer[0]);
        assertTrue(((String) viewer[2]).contains("--theta-i must be in [0, 89]"), (String) viewer[2]);
        assertTrue(!Files.exists(patch));
    }

    /** The floats of a PFM (header lines "PF" or "Pf", "W H", the scale; then little-endian floats). */
    private static float[] pfm(Path file) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        int lines = 0;
        int at = 0;
        while (lines < 3) {
            if (bytes[at++] == '\n') {
                lines++;
            }
        }
        ByteBuffer b = ByteBuffer.wrap(bytes, at, bytes.length - at).order(ByteOrder.LITTLE_ENDIAN);
        float[] out = new float[(bytes.length - at) / 4];
        for (int i = 0; i < out.length; i++) {
            out[i] = b.getFloat();
        }
        return out;
    }
}
