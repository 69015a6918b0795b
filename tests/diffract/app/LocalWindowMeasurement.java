package diffract.app;

import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.scene.Fabricator;
import diffract.util.ImageFiles;
import diffract.util.Reporter;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * The measurements of docs/measurements/scans.md, "Close-ups: the window under each surface point" (not a test: it asserts
 * nothing and runs only with {@code -Ddiffract.measure=glints}; {@code bash docs/measurements/local-window.sh} runs it). The scene
 * of {@link LocalWindowSceneTest} (the 52 um scan on a plane between the mirror and the first order, FLSS, the
 * automatic window radius): the viewer's GPU time per frame (GL timer queries, median of 10 frames after a warm-up)
 * of the close-up under the local window against the same view under the averaged window, in alternating rounds so
 * that the machine's load moves both, and a picture of the close-up under both windows and of the local window where
 * a pixel covers two scans. Writes {@code target/local-window/local-window.md} and {@code local-window.png}.
 */
class LocalWindowMeasurement {
    static final Path OUT = Path.of("target", "local-window");
    static final int TIMED_PX = 64;
    static final int PICTURE_PX = 128;
    static final int ROUNDS = 2;

    @Test
    void measure() throws IOException {
        Assumptions.assumeTrue("glints".equals(System.getProperty("diffract.measure")), "measurement only on request");
        GlTestSupport.assumeOffscreenGl();
        Files.createDirectories(OUT);
        // label, window, scans per pixel (0: the close-up, 250 um of skin per unit of texture coordinate)
        String[][] views = {
            {"averaged window", "averaged", "0"},
            {"local window, close-up (4.2 scans across the view)", "local", "0"},
            {"local window, a pixel as wide as the scan", "local", "1"},
            {"local window, 4 scans per pixel (the averaged window's sum)", "local", "4"},
        };
        double[][] ms = new double[views.length][ROUNDS];
        float[][] pictures = new float[views.length][];
        String gl = "";
        for (int round = 0; round < ROUNDS; round++) {
            for (int v = 0; v < views.length; v++) {
                double scansPerPixel = Double.parseDouble(views[v][2]);
                if (round == 0) {
                    pictures[v] = render(views[v][1], PICTURE_PX, scansPerPixel, null);
                }
                double[] timed = new double[1];
                render(views[v][1], TIMED_PX, scansPerPixel, timed);
                ms[v][round] = timed[0];
                gl = renderer;
            }
        }
        List<String> lines = new ArrayList<>();
        lines.add("# The local window's cost");
        lines.add("");
        lines.add("Written by `bash docs/measurements/local-window.sh` (`tests/diffract/app/LocalWindowMeasurement.java`) on " + gl
                + ": the close-up scene of `LocalWindowSceneTest` (the 52 um `elaphe-scan` on a plane, FLSS, N = 30,"
                + " 5 nm, 65 um, window radius auto), GPU ms per " + TIMED_PX + " x " + TIMED_PX + " frame (median of"
                + " 10 frames), " + ROUNDS + " alternating rounds.");
        lines.add("");
        lines.add("| view | --window | --skin-um-per-texcoord at " + TIMED_PX + " px | ms per frame (rounds) |"
                + " against the averaged window |");
        lines.add("|---|---|---|---|---|");
        double averaged = mean(ms[0]);
        for (int v = 0; v < views.length; v++) {
            StringBuilder rounds = new StringBuilder();
            for (int r = 0; r < ROUNDS; r++) {
                rounds.append(r == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.0f", ms[v][r]));
            }
            lines.add(String.format(Locale.ROOT, "| %s | %s | %.0f | %s | %.2f |", views[v][0], views[v][1],
                    tilingUm(TIMED_PX, Double.parseDouble(views[v][2])), rounds, mean(ms[v]) / averaged));
        }
        Files.write(OUT.resolve("local-window.md"), lines, StandardCharsets.UTF_8);
        int gap = 4;
        int panels = 3;
        int width = panels * PICTURE_PX + (panels - 1) * gap;
        float[] composite = new float[width * PICTURE_PX * 3];
        int[] order = {1, 2, 0}; // close-up, a pixel as wide as the scan, averaged
        for (int k = 0; k < panels; k++) {
            float[] p = pictures[order[k]];
            for (int y = 0; y < PICTURE_PX; y++) {
                for (int x = 0; x < PICTURE_PX; x++) {
                    for (int c = 0; c < 3; c++) {
                        composite[(y * width + k * (PICTURE_PX + gap) + x) * 3 + c] = p[(y * PICTURE_PX + x) * 3 + c];
                    }
                }
            }
        }
        for (int k = 1; k < panels; k++) { // white gaps between the panels
            for (int y = 0; y < PICTURE_PX; y++) {
                for (int x = 0; x < gap; x++) {
                    for (int c = 0; c < 3; c++) {
                        composite[(y * width + k * (PICTURE_PX + gap) - gap + x) * 3 + c] = 1f;
                    }
                }
            }
        }
        ImageFiles.writePng(OUT.resolve("local-window.png"), composite, width, PICTURE_PX, 3);
    }

    /**
     * um of skin per unit of texture coordinate for a pixel of {@code scansPerPixel} scans at this size (0: the
     * close-up's 250): the view is 2 x 50 tan(0.05 deg) = 0.0873 scene units wide and a unit of texture coordinate
     * 0.1 scene units, so a pixel spans 0.873 T / size um of skin; the scan is 52.4 um wide.
     */
    static double tilingUm(int sizePx, double scansPerPixel) {
        return scansPerPixel == 0 ? 250 : scansPerPixel * 52.4 * sizePx / 0.87266;
    }

    /** The GL renderer of the last frame. */
    private static String renderer = "";

    /** A frame of the scene, or with {@code ms} its median GPU ms per frame into ms[0] (and null). */
    private static float[] render(String window, int sizePx, double scansPerPixel, double[] ms) throws IOException {
        Path scene = OUT.resolve("scene-" + window + "-" + sizePx + "-" + scansPerPixel + ".json");
        Files.writeString(scene, scene(window, sizePx, tilingUm(sizePx, scansPerPixel)));
        try (OffscreenTarget target = new OffscreenTarget(new ViewerRenderer(ViewerModel.load(
                Fabricator.fabricate(scene, Reporter.SILENT), Reporter.SILENT)))) {
            renderer = target.info().renderer();
            if (ms != null) {
                ms[0] = target.measureMedianMs(sizePx, sizePx, 1, 10);
                return null;
            }
            return target.renderRgb(sizePx, sizePx);
        }
    }

    static String scene(String window, int sizePx, double tilingUm) {
        String material = "\"variant\": \"flss\", \"window\": \"" + window + "\", \"skinUmPerTexcoord\": " + tilingUm + ",";
        return LocalWindowSceneTest.SCENE.replace("\"variant\": \"flss\",", material)
                .replace("\"width\": 48, \"height\": 48", "\"width\": " + sizePx + ", \"height\": " + sizePx);
    }

    static double mean(double[] values) {
        double sum = 0;
        for (double v : values) {
            sum += v;
        }
        return sum / values.length;
    }
}
