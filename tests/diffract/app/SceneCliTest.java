package diffract.app;

import diffract.util.TestReport;
import diffract.jrtr.GlTestSupport;
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
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Scene files through the CLI: an OBJ mesh end to end, options that override the scene, a broken OBJ. */
class SceneCliTest {
    @TempDir
    static Path dir;

    /**
     * A 2 x 2 square in the xy plane facing the camera, as an OBJ with explicit {@code tg} tangents along x (the
     * grating's period across the picture), written as 8 x 8 quads so the mesh has interior vertices.
     */
    private static Path squareObj(String name, boolean badIndex) throws IOException {
        int cells = 8;
        StringBuilder obj = new StringBuilder("# a test square\n");
        for (int j = 0; j <= cells; j++) {
            for (int i = 0; i <= cells; i++) {
                obj.append(String.format(Locale.ROOT, "v %.4f %.4f 0%n", -1 + 2.0 * i / cells, -1 + 2.0 * j / cells));
                obj.append("vn 0 0 1\ntg 1 0 0\n");
            }
        }
        for (int j = 0; j < cells; j++) {
            for (int i = 0; i < cells; i++) {
                int a = j * (cells + 1) + i + 1;
                int b = a + 1;
                int c = a + cells + 2;
                int d = a + cells + 1;
                obj.append(String.format("f %d//%d %d//%d %d//%d %d//%d%n", a, a, b, b, c, c, d, d));
            }
        }
        if (badIndex) {
            obj.append("f 1 2 999\n");
        }
        Path path = dir.resolve(name);
        Files.writeString(path, obj);
        return path;
    }

    /** The blazed-grating plane scene, its shape replaced by an OBJ given by a path relative to the scene. */
    private static Path sceneWithObj(String sceneName, String objName) throws IOException {
        String scene = """
                {
                  "image": {"width": 64, "height": 48},
                  "camera": {"eye": [0, 0, 3.5], "lookAt": [0, 0, 0], "fieldOfViewDeg": 45},
                  "light": {"thetaDeg": 30, "phiDeg": 0},
                  "shape": {"kind": "obj", "file": "%s", "tangents": "explicit"},
                  "material": {
                    "patch": {"procedural": "blazed", "periodUm": 2.5, "heightUm": 0.2, "periods": 26,
                              "samplesPerPeriod": 25, "rows": 16},
                    "taylorTerms": 12, "lambdaStepNm": 20, "sigmaSpatialUm": 2.5, "exposure": 10
                  }
                }
                """.formatted(objName);
        Path path = dir.resolve(sceneName);
        Files.writeString(path, scene);
        return path;
    }

    /**
     * The OBJ square seen head-on under light from 30 degrees: the blazed grating's first orders leave at
     * sin(theta_r) = sin(30 deg) - lambda / 2.5 um, i.e. between -0.01 and 0.35 for 380..780 nm, so the camera's
     * +-22 degree view sees coloured orders on the square, and the background around it stays the clear colour.
     */
    @Test
    @Tag("gl")
    void anObjMeshFromASceneRendersWithItsExplicitTangents() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        squareObj("square.obj", false);
        Path scene = sceneWithObj("square.json", "square.obj");
        Path png = dir.resolve("square.png");
        Object[] result = CliTest.run("render", scene.toString(), "-o", png.toString());
        assertEquals(0, result[0], (String) result[2]);
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(64, image.getWidth());
        assertEquals(48, image.getHeight());
        assertEquals(Pictures.clearColour(), image.getRGB(0, 0) & 0xffffff, "the corner is background");
        int coloured = Pictures.count(image, Pictures.COLOURED);
        TestReport.line(SceneCliTest.class, "OBJ square 64x48: " + coloured + " coloured pixels");
        assertTrue(coloured >= 20, "only " + coloured + " coloured pixels on the OBJ square");
    }

    @Test
    @Tag("gl")
    void commandLineOptionsOverrideTheScene() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path png = dir.resolve("override.png");
        Object[] result = CliTest.run("render", "assets/scenes/blazed-grating-plane.json", "--variant", "pq",
                "--terms", "6", "--lambda-step", "40", "--size", "48x32", "-o", png.toString());
        assertEquals(0, result[0], (String) result[2]);
        String out = (String) result[1];
        assertTrue(out.contains("48x32") && out.contains("pq N=6") && out.contains("lambda step 40.0 nm"), out);
        // the scene's sun is drawn as a point light by a variant that samples the light at its centre, with a notice
        assertTrue(((String) result[2]).contains("pq samples the light at its centre"), (String) result[2]);
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(48, image.getWidth());
        assertEquals(32, image.getHeight());
    }

    /** --synthetic (or --patch) beside a scene replaces the scene's patch: the picture is another grating's. */
    @Test
    @Tag("gl")
    void aPatchGivenBesideASceneReplacesItsPatch() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path own = dir.resolve("own.png");
        Path other = dir.resolve("other.png");
        Object[] a = CliTest.run("render", "assets/scenes/blazed-grating-plane.json", "--size", "48x32", "-o",
                own.toString());
        assertEquals(0, a[0], (String) a[2]);
        Object[] b = CliTest.run("render", "assets/scenes/blazed-grating-plane.json", "--synthetic", "elaphe-like",
                "--size", "48x32", "-o", other.toString());
        assertEquals(0, b[0], (String) b[2]);
        int differing = differingPixels(own, other);
        assertTrue(differing > 48, "the Elaphe-like patch's orders are not the blazed grating's: " + differing);
    }

    /**
     * The staged snake with its lobes taking the rigorous orders (a cheap table: one 20 nm step, few harmonics and
     * slabs) renders: the environment's lights, which read a baked table, keep the scalar orders instead of refusing
     * the scene, and the key light's lobes take the rigorous ones, so the picture differs from the scalar orders'.
     */
    @Test
    @Tag("gl")
    void aStagedSnakeTakesTheRigorousOrdersForItsKeyLight() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        String[] cheap = {"assets/scenes/snake-elaphe.json", "--synthetic", "elaphe-ridge", "--lambda-min", "500",
                "--lambda-max", "520", "--harmonics", "8", "--layers", "4", "--size", "64x40"};
        Path scalar = dir.resolve("scalar.png");
        Path rigorous = dir.resolve("rigorous.png");
        Object[] a = CliTest.run(concat(new String[] {"render"}, cheap, "-o", scalar.toString()));
        assertEquals(0, a[0], (String) a[2]);
        Object[] b = CliTest.run(concat(new String[] {"render"}, cheap, "--orders", "rigorous", "-o",
                rigorous.toString()));
        assertEquals(0, b[0], (String) b[2]);
        assertTrue(differingPixels(scalar, rigorous) > 0, "the rigorous orders change the key light's lobes");
    }

    /** How many pixels of two pictures of the same size differ. */
    private static int differingPixels(Path a, Path b) throws java.io.IOException {
        BufferedImage x = ImageIO.read(a.toFile());
        BufferedImage y = ImageIO.read(b.toFile());
        int differing = 0;
        for (int j = 0; j < x.getHeight(); j++) {
            for (int i = 0; i < x.getWidth(); i++) {
                differing += x.getRGB(i, j) != y.getRGB(i, j) ? 1 : 0;
            }
        }
        return differing;
    }

    private static String[] concat(String[] first, String[] second, String... rest) {
        String[] all = java.util.Arrays.copyOf(first, first.length + second.length + rest.length);
        System.arraycopy(second, 0, all, first.length, second.length);
        System.arraycopy(rest, 0, all, first.length + second.length, rest.length);
        return all;
    }

    /**
     * A snake whose scales wear a scan as wide as the coherence window (the 52 um elaphe-scan, sigma_f = 0.5 texels)
     * renders with the lobes method under the scene's sun: no notice that it falls back to another method or a
     * point light, and the snake shows structural colour (a lit pixel's channels differ).
     */
    @Test
    @Tag("gl")
    void aScanAsWideAsTheWindowRendersWithTheLobesMethod() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path png = dir.resolve("scan.png");
        Object[] result = CliTest.run("render", "assets/scenes/viewer-snake-scan.json", "--variant", "lobes",
                "--size", "80x60", "-o", png.toString());
        String err = (String) result[2];
        assertEquals(0, result[0], err);
        assertFalse(err.contains("instead") || err.contains("as a point light"), err);
        assertTrue(((String) result[1]).contains("lobes"), (String) result[1]);
        BufferedImage image = ImageIO.read(png.toFile());
        int coloured = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                int rgb = image.getRGB(x, y);
                int r = rgb >> 16 & 255;
                int g = rgb >> 8 & 255;
                int b = rgb & 255;
                coloured += Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) > 40 ? 1 : 0;
            }
        }
        assertTrue(coloured > 20, "the snake shows colour: " + coloured + " pixels");
    }

    @Test
    void anObjWithABadIndexIsRefusedWithItsFileAndLine() throws Exception {
        Path obj = squareObj("broken.obj", true);
        Path scene = sceneWithObj("broken.json", "broken.obj");
        Object[] result = CliTest.run("render", scene.toString(), "-o", dir.resolve("b.png").toString());
        String err = (String) result[2];
        assertEquals(2, result[0], err);
        // the patch's warnings may come first; the refusal is one line, the last, naming the file and line
        String[] lines = err.strip().split("\n");
        assertEquals(1, err.lines().filter(l -> l.startsWith("diffract:")).count(), err);
        int objLines = Files.readAllLines(obj).size();
        assertTrue(lines[lines.length - 1].contains("broken.obj:" + objLines + ": vertex index 999"), err);
    }
}
