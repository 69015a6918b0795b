package diffract.render;

import diffract.colour.DeltaEStatistics;
import diffract.colour.Srgb;
import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.optics.BakedGrid;
import diffract.optics.Variant;
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
import java.util.Arrays;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The staged baked surface under the demo scene's 15-degree key light read from the table spread by the disc
 * ({@link DiscTable}) against the same table integrated over the disc per pixel, row by row ({@code baked_disc.glsl}),
 * at 320 x 200 with the sky taken out, so that the comparison sees the key light alone: mean CIEDE2000 over the frame
 * at most 0.5 (measured 0.27, p95 1.7; at 800 x 600 with the sky, against the lobes method's picture, the GPU suite
 * measures 0.76 where the rows measure 0.54, docs/design/viewer.md). The comparison sees the disc: the spread table of a disc
 * a third narrower differs from the rows by more than 2.5 times as much (measured 0.97).
 */
@Tag("gl")
@Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // whole staged frames: a long test
class DiscTableSceneTest {
    static final int W = 320;
    static final int H = 200;

    @TempDir
    Path dir;

    @Test
    void theKeyLightFromTheSpreadTableStaysCloseToTheRowsIntegral() throws IOException {
        GlTestSupport.assumeOffscreenGl();
        float[] rows;
        DiscTable.enabled = false;
        try {
            rows = render(scene(15));
        } finally {
            DiscTable.enabled = true;
        }
        assertTrue(DiscTable.applies(scene(15).settings(), new BakedGrid(512, 2)));
        DeltaEStatistics same = difference(render(scene(15)), rows);
        DeltaEStatistics narrower = difference(render(scene(10)), rows);
        TestReport.printf(DiscTableSceneTest.class, Locale.ROOT, "15-degree disc, spread table vs rows: CIEDE2000 "
                + "mean %.3f, p95 %.3f; a 10-degree disc's spread table against the rows: mean %.3f%n", same.mean(),
                same.p95(), narrower.mean());
        assertTrue(same.mean() <= 0.5, "mean " + same.mean());
        assertTrue(narrower.mean() > 2.5 * same.mean(), "the comparison sees the disc: " + narrower.mean());
    }

    private SceneSetup scene(double keyLightDeg) throws IOException {
        String text = Files.readString(Path.of("assets", "scenes", "snake-elaphe.json"))
                .replace("\"angularDiameterDeg\": 15", "\"angularDiameterDeg\": " + keyLightDeg)
                .replace("\"environment\": {\"sky\": {\"irradianceRatio\": 0.3}, \"lights\": 8},", "");
        Path file = dir.resolve("disc-" + keyLightDeg + ".json");
        Files.writeString(file, text);
        SceneSetup setup = Fabricator.fabricate(file, Reporter.SILENT);
        assertTrue(setup.stage().environment() == null, "the sky is out");
        return setup.withSettings(setup.settings().with(b -> b.variant(Variant.BAKED)));
    }

    private static float[] render(SceneSetup setup) {
        ViewerModel model = ViewerModel.load(setup, Reporter.SILENT);
        try (OffscreenTarget target = new OffscreenTarget(new ViewerRenderer(model))) {
            return target.renderRgb(W, H);
        }
    }

    private static DeltaEStatistics difference(float[] a, float[] b) {
        float[] xyzA = Srgb.xyzOfDisplayRgb(a);
        float[] xyzB = Srgb.xyzOfDisplayRgb(b);
        boolean[] all = new boolean[xyzA.length / 3];
        Arrays.fill(all, true);
        return DeltaEStatistics.of(xyzA, xyzB, all);
    }
}
