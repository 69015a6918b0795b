package diffract.app;

import diffract.util.TestReport;
import diffract.jrtr.GlTestSupport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** {@code view} and {@code render} as a user meets them: files, exit codes, one-line refusals. */
class ViewerCliTest {
    @TempDir
    static Path dir;

    @Test
    @Tag("gl")
    void renderWritesAPictureOfTheShapeAtTheRequestedSize() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path png = dir.resolve("sphere.png");
        Object[] result = CliTest.run("render", "--synthetic", "elaphe-like", "--variant", "flss", "--terms", "8",
                "--lambda-step", "20", "--coherence-length", "10", "--size", "96x64", "-o", png.toString());
        assertEquals(0, result[0], (String) result[2]);
        assertTrue(((String) result[1]).contains("wrote " + png), (String) result[1]);
        assertTrue(((String) result[2]).matches("(?s).*diffract: OpenGL \\d\\.\\d.*, GLSL .*"),
                "render names the OpenGL it draws with: " + result[2]);
        BufferedImage image = ImageIO.read(png.toFile());
        assertEquals(96, image.getWidth());
        assertEquals(64, image.getHeight());
        int centre = image.getRGB(48, 32) & 0xffffff;
        assertNotEquals(Pictures.clearColour(), centre, "the centre shows the background, not the sphere");
        int coloured = Pictures.count(image, Pictures.COLOURED);
        TestReport.line(ViewerCliTest.class, "render 96x64: " + coloured + " coloured pixels");
        assertTrue(coloured >= 5, "only " + coloured + " coloured pixels: no structural colour on the sphere");
    }

    /** The demo's view: the procedural snake, its structural colour alone (no pigmentation), has rainbow pixels. */
    @Test
    @Tag("gl")
    void theSnakeIsIridescent() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        Path png = dir.resolve("snake.png");
        // fewer terms: llvmpipe is slow, and the patch needs only ~12 at 380 nm
        String[] args = {"render", DemoCommand.defaultScene(dir).toString(), "--terms", "12", "--size", "160x100",
            "-o", png.toString()};
        Object[] result = CliTest.run(args);
        assertEquals(0, result[0], (String) result[2]);
        BufferedImage image = ImageIO.read(png.toFile());
        int red = Pictures.count(image, (r, g, b) -> r > g + 30 && r > b + 30);
        int green = Pictures.count(image, (r, g, b) -> g > r + 30 && g > b + 30);
        int blue = Pictures.count(image, (r, g, b) -> b > r + 30 && b > g + 30);
        TestReport.printf(ViewerCliTest.class, "snake 160x100: %d red, %d green, %d blue pixels%n", red, green, blue);
        assertTrue(red >= 3 && green >= 3 && blue >= 3, "not a rainbow: " + red + " red, " + green + " green, "
                + blue + " blue pixels");
    }

    @Test
    void badUsageEndsWithOneLineAndExitCode2() {
        String out = dir.resolve("x.png").toString();
        assertOneLine(CliTest.run("view", "scene.json"), "cannot read scene file scene.json: no such file");
        assertOneLine(CliTest.run("render", "scene.json", "-o", out), "cannot read scene file scene.json");
        assertOneLine(CliTest.run("render", "assets/scenes/snake-elaphe.json", "--shape", "sphere", "-o", out),
                "--shape cannot be combined with a SCENE");
        assertOneLine(CliTest.run("render", "--variant", "reference", "-o", out), "the GPU renders flss, nmm, pq, baked and lobes");
        assertOneLine(CliTest.run("render", "--shape", "teapot", "-o", out), "sphere, plane, cylinder or snake");
        assertOneLine(CliTest.run("render", "--size", "12x9000", "-o", out), "--size");
        assertOneLine(CliTest.run("render", "--tangent", "0,0,0", "-o", out), "--tangent");
        assertOneLine(CliTest.run("render", "--species", "xenopeltisUnicolor", "-o", out),
                "--species dresses a snake, and the shape is a sphere: add --shape snake");
        assertOneLine(CliTest.run("render", "--synthetic", "zebra", "-o", out), "unknown patch 'zebra': use blazed, sinusoid");
        assertOneLine(CliTest.run("render", "--patch", "missing.png", "--synthetic", "blazed", "-o", out), "not both");
        assertOneLine(CliTest.run("render", "-o", dir.resolve("x.jpg").toString()), "-o writes .png or .exr");
        assertOneLine(CliTest.run("view", "--terms", "500"), "--terms: the highest Taylor order N must be in 0..100, got 500");
        Object[] missingOutput = CliTest.run("render");
        assertEquals(2, missingOutput[0]);
    }

    @Test
    void helpAnswersWithExitCode0() {
        for (String command : new String[] {"view", "render"}) {
            Object[] help = CliTest.run(command, "--help");
            assertEquals(0, help[0]);
            assertTrue(((String) help[1]).contains("--variant"), (String) help[1]);
        }
    }

    @Test
    void viewWithoutAVisibleDisplaySuggestsRender() {
        String linux = "Linux";
        assertTrue(ViewCommand.noDisplayProblem(Map.of(), linux).orElseThrow().contains("./diffract render"));
        assertTrue(ViewCommand.noDisplayProblem(Map.of("DISPLAY", ":99", "DIFFRACT_PRIVATE_XVFB", "1"), linux)
                .orElseThrow().contains("./diffract render"));
        assertTrue(ViewCommand.noDisplayProblem(Map.of("DISPLAY", ":0"), linux).isEmpty());
    }

    private static void assertOneLine(Object[] result, String expected) {
        String err = (String) result[2];
        assertEquals(2, result[0], err);
        assertEquals(1, err.strip().lines().count(), err);
        assertTrue(err.contains(expected), err);
    }
}
