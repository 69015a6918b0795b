package diffract.app;

import diffract.colour.Ciede2000;
import diffract.colour.Lab;
import diffract.colour.Srgb;
import diffract.colour.Xyz;
import diffract.jrtr.GlTestSupport;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The local window in a scene, as a user renders it: the shipped 52 um scan ({@code elaphe-scan}, 52.4 x 50.8 um) on
 * a plane, FLSS, 48 x 48 pixels, the light at theta_i = 30 in the plane of the ridges' period and the camera 15
 * degrees off the normal on the mirror's side, between the mirror and the first order (v = -0.25), where many texels
 * of comparable power add: a 0.1-degree field of view, so every pixel sees the same direction and the averaged window
 * draws one colour (its lit pixels' spread is 0.15 CIEDE2000, 8-bit rounding). {@code --skin-um-per-texcoord T} sets
 * how much skin a pixel covers: its box spans 0.0182 T um, so T = 250 is a close-up (4.5 um pixels, a twelfth of the
 * scan) and T = 2880 a pixel as wide as the scan.
 *
 * <ul>
 *   <li>Close up, the local window's colours vary across the scan (each pixel sees the coherence area under it) far
 *       more than the averaged window's: their spread, the mean CIEDE2000 of the lit pixels from their mean colour, is
 *       more than 3 times larger (measured: 42 times), while their mean colour over the 4.2 scans in view stays within
 *       {@value #MEAN_OVER_SCANS_DELTA_E} of the averaged window's (over whole scans the mean of the window's
 *       positions is the averaged window exactly, {@code LocalWindowTest}; a fifth of a scan is counted twice here).</li>
 *   <li>As a pixel's footprint grows past the scan the picture converges to the averaged window's: the mean CIEDE2000
 *       between the local and the averaged pictures over the lit pixels falls with the footprint and is exactly 0 once
 *       the footprint's pair factors are all below 1e-7 (4 scans per pixel); at 2 scans per pixel (the nearest pairs
 *       damped to exp(-2 pi^2 (2 L)^2 / (12 L^2)) = 1.4e-3) it is below {@value #CONVERGED_DELTA_E}, a tenth of the
 *       smallest difference people see side by side (measured: 0.007), against 6.2 for the close-up.</li>
 * </ul>
 * The numbers are written to {@code target/test-reports/LocalWindowSceneTest.txt}.
 */
@Tag("gl")
class LocalWindowSceneTest {
    static final double CONVERGED_DELTA_E = 0.1;
    static final double MEAN_OVER_SCANS_DELTA_E = 1.0;
    static final int SIZE = 48;

    @TempDir
    Path dir;

    static final String SCENE = """
            {
              "image": {"width": 48, "height": 48},
              "camera": {"eye": [0, -12.5, 48.41], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fieldOfViewDeg": 0.1},
              "light": {"thetaDeg": 30, "phiDeg": 90, "angularDiameterDeg": 0},
              "shape": {"kind": "plane", "tangents": {"project": [1, 0, 0]}, "transform": {"scale": 0.05}},
              "material": {
                "patch": {"procedural": "elaphe-scan"},
                "variant": "flss",
                "windowRadius": "auto",
                "exposure": 3000
              }
            }
            """;

    @Test
    @Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // whole scenes: a long test
    void aCloseUpShowsTheCoherenceAreasAndAFarViewConvergesToTheAveragedWindow() throws IOException {
        GlTestSupport.assumeOffscreenGl();
        Path scene = dir.resolve("plane.json");
        Files.writeString(scene, SCENE);
        Xyz[] averaged = render(scene, "averaged", 250);
        Xyz[] closeUp = render(scene, "local", 250);
        boolean[] lit = lit(averaged, closeUp);
        int litCount = 0;
        for (boolean b : lit) {
            litCount += b ? 1 : 0;
        }
        double lightness = 0;
        for (int p = 0; p < lit.length; p++) {
            lightness += lit[p] ? lab(averaged[p]).l() / litCount : 0;
        }
        report(String.format(Locale.ROOT, "averaged window: mean L* %.1f over %d lit pixels", lightness, litCount));
        assertTrue(litCount > SIZE * SIZE / 2, "the view should be lit: " + litCount + " lit pixels");
        double spreadAveraged = spread(averaged, lit);
        double spreadLocal = spread(closeUp, lit);
        double closeUpDifference = meanDeltaE(closeUp, averaged, lit);
        report(String.format(Locale.ROOT, "close-up (4.6 um pixels on the 52 um scan), %d lit pixels: spread of the"
                + " colours (mean CIEDE2000 from their mean) local %.2f, averaged %.2f (ratio %.1f); local against"
                + " averaged, mean CIEDE2000 %.2f", litCount, spreadLocal, spreadAveraged, spreadLocal / spreadAveraged,
                closeUpDifference));
        double means = Ciede2000.deltaE(lab(mean(closeUp, lit)), lab(mean(averaged, lit)));
        report(String.format(Locale.ROOT, "close-up: the mean colour of its lit pixels (over 4.2 scans along each"
                + " axis) against the averaged window's, CIEDE2000 %.2f", means));
        assertTrue(means < MEAN_OVER_SCANS_DELTA_E, "the close-up's mean colour: " + means);
        assertTrue(spreadLocal > 3 * spreadAveraged, "the close-up should vary across the scan: " + spreadLocal
                + " against " + spreadAveraged);
        double previous = closeUpDifference;
        for (int scansPerPixel : new int[] {1, 2, 4}) {
            double tiling = 2880.0 * scansPerPixel;
            double d = meanDeltaE(render(scene, "local", tiling), averaged, lit);
            report(String.format(Locale.ROOT, "footprint %d scan(s) per pixel (--skin-um-per-texcoord %.0f): local"
                    + " against averaged, mean CIEDE2000 %.4f over the lit pixels", scansPerPixel, tiling, d));
            assertTrue(d <= previous, "the difference should fall as the footprint grows: " + d + " after " + previous);
            previous = d;
            if (scansPerPixel >= 2) {
                assertTrue(d < CONVERGED_DELTA_E, scansPerPixel + " scans per pixel: " + d);
            }
        }
        assertTrue(closeUpDifference > 10 * CONVERGED_DELTA_E, "the close-up should differ from the averaged window: "
                + closeUpDifference);
    }

    /** What cannot draw the local window says so in one line and exits 2. */
    @Test
    void whatCannotDrawTheLocalWindowRefusesItInOneLine() throws IOException {
        Path out = dir.resolve("refused.png");
        String[][] cases = {
            {"brdfmap", "--synthetic", "elaphe-like", "--variant", "flss", "--window", "local", "--size", "8", "-o",
                out.toString()},
            {"render", "--shape", "plane", "--variant", "lobes", "--window", "local", "--skin-um-per-texcoord", "100",
                "-o", out.toString()},
            {"render", "--shape", "plane", "--variant", "flss", "--window", "local", "-o", out.toString()},
        };
        String[] expected = {"--window: the local window follows the surface point", "--window: the local window is"
                + " drawn by flss and nmm", "--skin-um-per-texcoord: the local window needs"};
        for (int i = 0; i < cases.length; i++) {
            Object[] result = CliTest.run(cases[i]);
            String err = ((String) result[2]).strip();
            assertEquals(2, result[0], err);
            assertTrue(err.lines().count() == 1 && err.contains(expected[i]), err);
        }
        Path scene = dir.resolve("untiled.json");
        Files.writeString(scene, SCENE.replace("\"variant\": \"flss\",", "\"variant\": \"flss\", \"window\": \"local\","));
        Object[] result = CliTest.run("render", scene.toString(), "-o", out.toString());
        assertEquals(2, result[0], (String) result[2]);
        assertTrue(((String) result[2]).contains("material.window: \"local\" needs \"skinUmPerTexcoord\""),
                (String) result[2]);
    }

    private Xyz[] render(Path scene, String window, double tiling) throws IOException {
        Path png = dir.resolve(window + "-" + (long) tiling + ".png");
        Object[] result = CliTest.run("render", scene.toString(), "--window", window, "--skin-um-per-texcoord",
                Double.toString(tiling), "-o", png.toString());
        assertEquals(0, result[0], (String) result[2]);
        BufferedImage image = ImageIO.read(png.toFile());
        Xyz[] xyz = new Xyz[SIZE * SIZE];
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                int rgb = image.getRGB(x, y);
                double[] linear = {Srgb.decode(((rgb >> 16) & 255) / 255.0), Srgb.decode(((rgb >> 8) & 255) / 255.0),
                    Srgb.decode((rgb & 255) / 255.0)};
                xyz[y * SIZE + x] = Srgb.xyzFromLinear(linear);
            }
        }
        return xyz;
    }

    private static Lab lab(Xyz xyz) {
        return Lab.fromXyz(xyz, Srgb.whiteXyz());
    }

    /** Pixels of lightness above 5 in both pictures (the plane's own; the background is black). */
    private static boolean[] lit(Xyz[] a, Xyz[] b) {
        boolean[] lit = new boolean[a.length];
        for (int p = 0; p < a.length; p++) {
            lit[p] = lab(a[p]).l() > 5 && lab(b[p]).l() > 5;
        }
        return lit;
    }

    /** The mean XYZ of the lit pixels. */
    private static Xyz mean(Xyz[] xyz, boolean[] lit) {
        double[] sum = new double[3];
        int n = 0;
        for (int p = 0; p < xyz.length; p++) {
            if (lit[p]) {
                sum[0] += xyz[p].x();
                sum[1] += xyz[p].y();
                sum[2] += xyz[p].z();
                n++;
            }
        }
        return new Xyz(sum[0] / n, sum[1] / n, sum[2] / n);
    }

    /** The mean CIEDE2000 of the lit pixels from the Lab of their mean XYZ. */
    private static double spread(Xyz[] xyz, boolean[] lit) {
        Lab mean = lab(mean(xyz, lit));
        int n = 0;
        double total = 0;
        for (int p = 0; p < xyz.length; p++) {
            if (lit[p]) {
                total += Ciede2000.deltaE(lab(xyz[p]), mean);
                n++;
            }
        }
        return total / n;
    }

    private static double meanDeltaE(Xyz[] a, Xyz[] b, boolean[] lit) {
        double total = 0;
        int n = 0;
        for (int p = 0; p < a.length; p++) {
            if (lit[p]) {
                total += Ciede2000.deltaE(lab(a[p]), lab(b[p]));
                n++;
            }
        }
        return total / n;
    }

    private static void report(String line) {
        TestReport.line(LocalWindowSceneTest.class, line);
    }
}
