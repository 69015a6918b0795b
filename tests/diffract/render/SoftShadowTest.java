package diffract.render;

import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.scene.Fabricator;
import diffract.scene.SceneSetup;
import diffract.util.Reporter;
import diffract.util.TestReport;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The key light's shadow has the penumbra of the light's size. A unit sphere rests on the ground (y = -1), lit from
 * theta = 36.9 degrees off the vertical towards -x (light direction (-0.6, 0.8, 0), and 2 degrees towards +z, which
 * the viewer asks of a light), seen from straight above (2 degrees off, along z), no sky, clipping tone mapping: the
 * ground's brightness along the x axis over a fully lit ground's is the key light's visibility. The shadow is the
 * sphere's cylinder along the light cut by the ground: its far edge lies at x = tan theta + 1 / cos theta = 2, cast by
 * the sphere's point (cos theta, sin theta, 0) a distance (1 + sin theta) / cos theta = 2 away along the light, so a
 * light of angular diameter D spreads it over a penumbra of radius rho = 2 tan(D / 2) / cos theta on the ground
 * (stretched along x by 1 / cos theta), in which the visible fraction of a disc light falls from 90 % to 10 % over
 * 1.374 rho. The depth map holds the sphere's side towards the light, not its silhouette, so the estimate of the
 * blockers' distance runs high: the width must lie within [0.6, 2] times the disc's. A light of the sun's size
 * leaves a sharp edge (a pixel or two).
 */
@Tag("gl")
class SoftShadowTest {
    private static final int SIZE = 256;
    private static final double EYE_HEIGHT = 6;
    private static final double FOV_DEG = 45;

    @TempDir
    Path dir;

    @Test
    void aTwentyDegreeLightSpreadsTheEdgeOverItsPenumbra() throws IOException {
        GlTestSupport.assumeOffscreenGl();
        double[] wide = edge(20);
        double[] sun = edge(0.53);
        double disc = 1.374 * 2 * Math.tan(Math.toRadians(10)) / 0.8;
        TestReport.printf(SoftShadowTest.class, Locale.ROOT,
                "20 degrees: 50 %% at x = %.3f, 90 %% -> 10 %% over %.3f (a disc light: %.3f); the sun: 50 %% at "
                        + "x = %.3f over %.3f%n", wide[0], wide[1], disc, sun[0], sun[1]);
        assertEquals(2.0, wide[0], 0.1, "half the light at the geometric edge");
        assertTrue(wide[1] > 0.6 * disc && wide[1] < 2 * disc, "penumbra " + wide[1] + ", a disc light's " + disc);
        assertEquals(2.0, sun[0], 0.05);
        assertTrue(sun[1] < 0.15 * disc, "the sun's edge stays sharp: " + sun[1]);
    }

    /** {x where the visibility crosses 0.5, the distance from 0.9 down to 0.1} along the ground's x axis. */
    private double[] edge(double lightDiameterDeg) throws IOException {
        Path scene = dir.resolve("sphere-" + lightDiameterDeg + ".json");
        Files.writeString(scene, String.format(Locale.ROOT, """
                {
                  "image": {"width": %d, "height": %d},
                  "camera": {"eye": [0, %s, 0.2], "lookAt": [0, 0, 0], "fieldOfViewDeg": %s},
                  "light": {"direction": [-0.6, 0.8, 0.035], "angularDiameterDeg": %s},
                  "ground": {"albedoSrgb": [0.5, 0.5, 0.5], "mottle": 0},
                  "toneMapping": {"operator": "clip"},
                  "shape": {"kind": "sphere"},
                  "material": {"patch": {"procedural": "blazed"}, "variant": "lobes", "exposure": 1}
                }
                """, SIZE, SIZE, EYE_HEIGHT, FOV_DEG, lightDiameterDeg));
        SceneSetup setup = Fabricator.fabricate(scene, Reporter.SILENT);
        float[] rgb;
        try (OffscreenTarget target = new OffscreenTarget(new ViewerRenderer(ViewerModel.load(setup,
                Reporter.SILENT)))) {
            rgb = target.renderRgb(SIZE, SIZE);
        }
        int row = SIZE / 2;
        double lit = linear(rgb, SIZE - 1, row);
        // ground x of column c: the ground lies EYE_HEIGHT + 1 below the camera
        double worldPerPx = 2 * (EYE_HEIGHT + 1) * Math.tan(Math.toRadians(FOV_DEG / 2)) / SIZE;
        double x50 = Double.NaN;
        double x90 = Double.NaN;
        double x10 = Double.NaN;
        double previous = 0;
        for (int c = SIZE / 2; c < SIZE; c++) {
            double x = (c + 0.5 - SIZE / 2.0) * worldPerPx;
            if (x < 1.3) {
                continue; // under the sphere, as the camera sees it
            }
            double v = linear(rgb, c, row) / lit;
            if (v >= 0.1 && previous < 0.1) {
                x10 = x;
            }
            if (v >= 0.5 && previous < 0.5) {
                x50 = x;
            }
            if (v >= 0.9 && previous < 0.9) {
                x90 = x;
            }
            previous = v;
        }
        assertTrue(lit > 0.1, "the lit ground: " + lit);
        assertTrue(!Double.isNaN(x10) && !Double.isNaN(x50) && !Double.isNaN(x90), "the edge crosses 10, 50 and 90 %");
        return new double[] {x50, Math.max(x90 - x10, worldPerPx)};
    }

    /** The luminance of pixel (column, row), display sRGB decoded to linear (rows from the bottom). */
    private static double linear(float[] rgb, int column, int row) {
        int p = 3 * (row * SIZE + column);
        return 0.2126 * decode(rgb[p]) + 0.7152 * decode(rgb[p + 1]) + 0.0722 * decode(rgb[p + 2]);
    }

    private static double decode(double c) {
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }
}
