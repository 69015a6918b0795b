package diffract.app;

import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.optics.maps.AutoExposure;
import diffract.optics.maps.BrdfMapDifference;
import diffract.optics.patches.Direction;
import diffract.util.ImageFiles;
import diffract.util.NpyFile;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

/**
 * {@code export --mitsuba} end to end: the files it writes, its refusals, and a round trip through Mitsuba 3's Python
 * package: the plugin's BSDF, evaluated over the directions of a 64 x 64 BRDF map, reproduces {@code brdfmap}'s map of
 * the same patch and settings (skipped where {@code import mitsuba} fails).
 */
class MitsubaExportTest {
    private static final int SIZE = 64;
    private static final double THETA_I_DEG = 30;
    private static final double PHI_I_DEG = 90; // elaphe-like's period lies along y
    /** Mean CIEDE2000 over lit pixels allowed between Mitsuba's map and brdfmap's. */
    private static final double MAX_LIT_MEAN_DELTA_E = 2.0;

    @TempDir
    static Path dir;
    static Path header;

    @BeforeAll
    static void export() {
        header = dir.resolve("elaphe.json");
        Object[] result = CliTest.run("export", "--synthetic", "elaphe-like", "--mitsuba", header.toString(), "--quiet");
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[1]).startsWith("wrote "), (String) result[1]);
    }

    @Test
    void writesAHeaderAndAFloat32TableOfTheAutomaticGrid() throws IOException {
        String json = Files.readString(header);
        assertTrue(json.contains("\"format\" : \"diffract-brdf-table\""), json);
        assertTrue(json.contains("\"gain\" : \"rayleigh-rice\""), json);
        assertTrue(json.contains("\"normalisation\" : \"energy\""), json);
        int[][] shape = new int[1][];
        float[] data = NpyFile.readFloat32(dir.resolve("elaphe.npy"), shape);
        // elaphe-like at 65 um: 2 samples per sigma of the narrowest order exceed the cap of 512; along w 2 per
        // radian of a texel pair's largest phase, 2 x (2 pi / 380 nm) 2 x 0.1766 um = 11.68: 24 steps, 25 samples
        assertArrayEquals(new int[] {25, 512, 512, 3}, shape[0]);
        assertEquals(25 * 512 * 512 * 3, data.length);
    }

    @Test
    void refusesAnotherVariantAndAnExtendedLight() {
        Object[] variant = CliTest.run("export", "--synthetic", "blazed", "--variant", "flss", "--mitsuba",
                dir.resolve("x.json").toString());
        assertEquals(2, variant[0]);
        assertTrue(((String) variant[2]).contains("lobes method"), (String) variant[2]);
        Object[] light = CliTest.run("export", "--synthetic", "blazed", "--light-size-deg", "0.53", "--mitsuba",
                dir.resolve("x.json").toString());
        assertEquals(2, light[0]);
        assertTrue(((String) light[2]).contains("point light"), (String) light[2]);
    }

    @Test
    void mitsubaReproducesBrdfMap() throws Exception {
        assumeTrue(mitsubaImports(), "Mitsuba 3's Python package is not installed (pip install mitsuba)");
        Path reference = dir.resolve("brdfmap.pfm");
        Object[] map = CliTest.run("brdfmap", "--synthetic", "elaphe-like", "--variant", "lobes", "--normalisation",
                "energy", "--theta-i", "30", "--phi-i", "90", "--size", String.valueOf(SIZE), "--quiet",
                "-o", dir.resolve("brdfmap.png").toString(), "--pfm", reference.toString());
        assertEquals(0, map[0], (String) map[2]);
        Path mitsuba = dir.resolve("mitsuba.pfm");
        Process p = new ProcessBuilder("python3", "python/mitsuba_brdfmap.py", header.toString(), "--theta-i",
                String.valueOf(THETA_I_DEG), "--phi-i", String.valueOf(PHI_I_DEG), "--size", String.valueOf(SIZE), "-o",
                mitsuba.toString()).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "python3 did not finish");
        assertEquals(0, p.exitValue(), output);
        float[] a = xyz(mitsuba);
        float[] b = xyz(reference);
        Direction wi = Direction.fromSphericalDeg(THETA_I_DEG, PHI_I_DEG);
        double exposure = AutoExposure.ofXyz(b, wi, SIZE); // brdfmap --exposure auto's
        BrdfMapDifference d = BrdfMapDifference.of(a, b, SIZE, exposure);
        System.out.println("Mitsuba 3 against brdfmap: " + d.summary());
        assertTrue(d.lit() != null && d.lit().pixels() > 50, d.summary());
        assertTrue(d.lit().mean() <= MAX_LIT_MEAN_DELTA_E, d.summary());
    }

    private static float[] xyz(Path pfm) throws IOException {
        int[] whc = new int[3];
        float[] rgb = ImageFiles.readPfm(pfm, whc);
        assertEquals(SIZE, whc[0]);
        assertEquals(3, whc[2]);
        float[] out = new float[rgb.length];
        for (int q = 0; q < rgb.length; q += 3) {
            Xyz c = Srgb.xyzFromLinear(new double[] {rgb[q], rgb[q + 1], rgb[q + 2]});
            out[q] = (float) c.x();
            out[q + 1] = (float) c.y();
            out[q + 2] = (float) c.z();
        }
        return out;
    }

    private static boolean mitsubaImports() {
        try {
            Process p = new ProcessBuilder("python3", "-c", "import mitsuba as mi; mi.set_variant('scalar_rgb')")
                    .redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(120, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }
}
