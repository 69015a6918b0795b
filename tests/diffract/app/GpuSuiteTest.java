package diffract.app;

import diffract.jrtr.contexts.GLInfo;
import diffract.jrtr.GlTestSupport;
import diffract.optics.BrdfSettings;
import diffract.optics.illumination.LightSource;
import diffract.scene.SceneFile;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code bench --gpu-suite} at a tiny size: its rows, its numbers and the OpenGL it names. */
class GpuSuiteTest {
    @Test
    void theSuiteRunsAtFullSizeOnGpusAndAnEighthOnSoftwareRasterisers() {
        GLInfo llvmpipe = new GLInfo("4.5 (Core Profile) Mesa 22.3.6", "llvmpipe (LLVM 15.0.6, 256 bits)", "Mesa/X.org",
                "4.50", true, "EGL surfaceless");
        GLInfo nvidia = new GLInfo("4.6.0 NVIDIA 550.54.15", "NVIDIA H200/PCIe/SSE2", "NVIDIA Corporation", "4.60 NVIDIA",
                true, "EGL device 0 of 1 (NVIDIA CUDA device)");
        assertArrayEquals(new int[] {240, 135}, GpuSuite.size(null, llvmpipe));
        assertArrayEquals(new int[] {1920, 1080}, GpuSuite.size(null, nvidia));
        assertArrayEquals(new int[] {64, 36}, GpuSuite.size(new int[] {64, 36}, llvmpipe));
        assertTrue(GpuSuite.isSoftware(llvmpipe));
        assertFalse(GpuSuite.isSoftware(nvidia));
    }

    /**
     * The map rows' light: the scene's up to the sun's disc, the sun's disc beyond (a CPU reference map under the
     * staged scene's 15-degree key light would take days), the profile kept.
     */
    @Test
    void theMapsTakeTheScenesLightUpToTheSunsDisc() {
        BrdfSettings staged = SceneFile.load(Path.of("assets/scenes/snake-elaphe.json"))
                .material().settings();
        assertEquals(15, staged.illumination().light().angularDiameterDeg());
        BrdfSettings maps = GpuSuite.mapSettings(staged);
        assertEquals(LightSource.SUN_DEG, maps.illumination().light().angularDiameterDeg());
        assertEquals(staged.illumination().light().profile(), maps.illumination().light().profile());
        assertEquals(staged.with(b -> b.lightSizeDeg(LightSource.SUN_DEG)), maps);
        for (double deg : new double[] {0, 0.3, LightSource.SUN_DEG}) {
            BrdfSettings narrow = staged.with(b -> b.lightSizeDeg(deg));
            assertEquals(narrow, GpuSuite.mapSettings(narrow), deg + " degrees");
        }
    }

    @Test
    @Tag("gl")
    @Tag(GlTestSupport.LONG_TAG)
    void aTinySuiteWritesOneRowPerConfigurationWithTheRenderer(@TempDir Path dir) throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Object[] result = CliTest.run("bench", "--gpu-suite", "--variants", "flss", "--suite-size", "48x27",
                "--error-size", "16", "-o", dir.toString());
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[2]).contains("diffract: OpenGL "), "the GL in use is named: " + result[2]);
        List<String> lines = Files.readAllLines(dir.resolve("gpu-suite.csv"));
        List<String> header = List.of(lines.get(0).split(","));
        assertEquals(GpuSuite.COLUMNS, header);
        // flss with the scene's settings and the thesis' configuration, each as a scene and as a BRDF map, and the
        // staged scene with a glossy material in place of the diffraction, for its cost
        assertEquals(1 + 5, lines.size(), String.join("\n", lines));
        for (String line : lines.subList(1, lines.size())) {
            String[] f = line.split(",", -1);
            assertEquals(header.size(), f.length, line);
            if (f[1].equals(GpuSuite.GLOSSY_CONFIGURATION)) {
                assertTrue(Double.parseDouble(f[header.indexOf("ms_per_frame")]) > 0, line);
                assertEquals("0", f[header.indexOf("compared_pixels")], line);
                continue;
            }
            double ms = Double.parseDouble(f[header.indexOf("ms_per_frame")]);
            double mean = Double.parseDouble(f[header.indexOf("deltaE_mean")]);
            assertTrue(ms > 0 && Double.isFinite(ms), line);
            assertTrue(Integer.parseInt(f[header.indexOf("compared_pixels")]) > 0, line);
            assertFalse(f[header.indexOf("gl_renderer")].isBlank(), line);
            boolean scene = f[0].equals("scene");
            assertEquals(scene ? "48" : "27", f[header.indexOf("width")], line);
            if (f[1].equals("scene settings")) {
                // FLSS at N = 20 against its converged self (scene) or the exact model at 1 nm (map): close; at the
                // scene's 65 um the map's orders are narrower than FLSS' 5 nm step, which costs about 3.5 here (a
                // wrong colour costs tens)
                assertTrue(mean < (scene ? 0.5 : 5.0), "CIEDE2000 " + mean + ": " + line);
            }
        }
        BufferedImage picture = ImageIO.read(dir.resolve("scene-flss.png").toFile());
        assertEquals(48, picture.getWidth());
        assertEquals(27, picture.getHeight());
        String markdown = Files.readString(dir.resolve("gpu-suite.md"));
        assertTrue(markdown.startsWith("GPU suite on OpenGL "));
        assertTrue(markdown.contains("times the time of the same scene with a glossy GGX material"), markdown);
        BufferedImage glossy = ImageIO.read(dir.resolve("scene-glossy.png").toFile());
        assertEquals(48, glossy.getWidth());
    }

    /**
     * The viewer's sphere under the sun's disc at 800 x 600: the lobes method's baked table against the lobes method
     * itself. A surface's pixel blends the disc's Gaussian into its rows as the lobes method does
     * (BakedDisc.gaussianBelow): mean 0.26, p95 1.27 (target/test-reports/GpuSuiteTest.txt); blended as a BRDF map's
     * box is, 0.41 and 1.88. And the viewer's first look ({@code viewer-sphere.json}: a 15-degree soft light, the
     * camera closer), whose disc the table spread by it draws (DiscTable): mean 0.86, p95 3.9 (the disc's edges at
     * oblique light, an ellipse that the spread's round discs and a Gaussian approximate).
     */
    @Test
    @Tag("gl")
    @Tag(GlTestSupport.LONG_TAG)
    void theViewersSphereDrawsTheTableCloseToTheLobesMethod(@TempDir Path dir) throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path sun = dir.resolve("sphere-sun.json");
        Files.writeString(sun, """
                {
                  "image": {"width": 800, "height": 600},
                  "camera": {"eye": [0, 1.19707, 3.28892], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fieldOfViewDeg": 45},
                  "light": {"thetaDeg": 30, "phiDeg": 90},
                  "shape": {"kind": "sphere"},
                  "material": {"patch": {"procedural": "elaphe-like"}, "variant": "baked", "coherenceLengthUm": 65,
                    "diffuseWeight": 0.2, "exposure": 400},
                  "mode": "surface"
                }
                """);
        double[] underTheSun = sphereRow(sun, dir.resolve("sun"));
        assertTrue(underTheSun[0] <= 0.33 && underTheSun[1] <= 1.6, "under the sun: " + underTheSun[0] + ", "
                + underTheSun[1]);
        double[] firstLook = sphereRow(Path.of("assets", "scenes", "viewer-sphere.json"), dir.resolve("first"));
        assertTrue(firstLook[0] <= 1.0 && firstLook[1] <= 4.5, "the first look: " + firstLook[0] + ", "
                + firstLook[1]);
    }

    /** The scene's baked row of the suite at 800 x 600: CIEDE2000 mean and p95 against the lobes method. */
    private static double[] sphereRow(Path scene, Path dir) throws Exception {
        Object[] result = CliTest.run("bench", "--gpu-suite", "--suite-scenes-only", "--suite-size", "800x600",
                "--variants", "baked", "--suite-scene", scene.toString(), "-o", dir.toString());
        assertEquals(0, result[0], (String) result[2]);
        List<String> lines = Files.readAllLines(dir.resolve("gpu-suite.csv"));
        List<String> header = List.of(lines.get(0).split(","));
        String row = lines.stream().filter(l -> l.startsWith("scene,scene settings,")).findFirst().orElseThrow();
        String[] f = row.split(",", -1);
        double mean = Double.parseDouble(f[header.indexOf("deltaE_mean")]);
        double p95 = Double.parseDouble(f[header.indexOf("deltaE_p95")]);
        TestReport.line(GpuSuiteTest.class, scene.getFileName() + ", baked against lobes at 800 x 600: "
                + "CIEDE2000 mean " + mean + ", p95 " + p95);
        assertTrue(Integer.parseInt(f[header.indexOf("compared_pixels")]) > 100_000, row);
        return new double[] {mean, p95};
    }
}
