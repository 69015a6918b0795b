package diffract.app;

import diffract.optics.patches.SyntheticPatches;
import diffract.optics.io.GsfWriter;
import diffract.util.ImageFiles;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** brdfmap's filtering options: --variant lobes, --light-size-deg, --fresnel, and their one-line errors. */
class FilteringCliTest {
    @TempDir
    static Path dir;
    static Path grating;

    @BeforeAll
    static void writeGrating() throws Exception {
        grating = dir.resolve("blazed.gsf");
        GsfWriter.write(grating, SyntheticPatches.blazed(2.5, 0.2, 20, 4, 16));
    }

    @Test
    void lobesWithALightAndTheThesisFresnelWriteAMap() throws Exception {
        Path pfm = dir.resolve("lobes.pfm");
        Object[] result = CliTest.run("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant", "lobes",
                "--light-size-deg", "2", "--fresnel", "thesis", "--size", "16", "-o", dir.resolve("lobes.png").toString(),
                "--pfm", pfm.toString());
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(Files.isRegularFile(dir.resolve("lobes.png")));
        int[] whc = new int[3];
        float[] map = ImageFiles.readPfm(pfm, whc);
        double sum = 0;
        for (float v : map) {
            assertTrue(Float.isFinite(v));
            sum += Math.abs(v);
        }
        assertTrue(sum > 0, "the map is lit");
    }

    /** A disc light on the lobes method draws on the CPU and the GPU alike; FLSS refuses it, naming who takes it. */
    @Test
    void lobesTakeADiscOnEitherEngineAndFlssSaysWhoDoes() throws Exception {
        float[][] maps = new float[2][];
        String[] engines = {"cpu", "gpu"};
        for (int e = 0; e < 2; e++) {
            if (e == 1 && diffract.jrtr.contexts.HeadlessGL.problem().isPresent()) {
                continue;
            }
            Path pfm = dir.resolve("disc-" + engines[e] + ".pfm");
            Object[] result = CliTest.run("brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--variant",
                    "lobes", "--light-size-deg", "10", "--light-profile", "disc", "--engine", engines[e], "--size",
                    "16", "-o", dir.resolve("disc-" + engines[e] + ".png").toString(), "--pfm", pfm.toString());
            assertEquals(0, result[0], (String) result[2]);
            maps[e] = ImageFiles.readPfm(pfm, new int[3]);
        }
        double largest = 0;
        for (float v : maps[0]) {
            largest = Math.max(largest, v);
        }
        assertTrue(largest > 0, "the map is lit");
        if (maps[1] != null) {
            for (int k = 0; k < maps[0].length; k++) {
                assertEquals(maps[0][k], maps[1][k], 1e-4 * largest, "value " + k);
            }
        }
        assertOneLine(run("--variant", "flss", "--light-size-deg", "10", "--light-profile", "disc"),
                "(disc) needs a method that averages over it, reference, baked, lobes or rigorous (or a point light");
    }

    @Test
    void badFilteringOptionsEndWithOneLine() {
        assertOneLine(run("--variant", "flss", "--light-size-deg", "2", "--light-profile", "gaussian"),
                "(gaussian) needs a method that averages over it");
        assertOneLine(run("--variant", "lobes", "--fresnel", "squared"), "--fresnel");
        assertOneLine(run("--variant", "lobes", "--light-size-deg", "25"), "angular diameter");
        assertOneLine(run("--variant", "lobes", "--light-size-deg", "1", "--lambda", "550"), "--light-size-deg");
    }

    private static Object[] run(String... extra) {
        String[] base = {"brdfmap", "--patch", grating.toString(), "--theta-i", "30", "--size", "8", "-o",
            dir.resolve("bad.png").toString()};
        String[] args = new String[base.length + extra.length];
        System.arraycopy(base, 0, args, 0, base.length);
        System.arraycopy(extra, 0, args, base.length, extra.length);
        return CliTest.run(args);
    }

    private static void assertOneLine(Object[] result, String mentions) {
        String err = (String) result[2];
        assertEquals(2, result[0], err);
        assertEquals(1, err.strip().lines().count(), err);
        assertTrue(err.startsWith("diffract: ") && err.contains(mentions), err);
    }
}
