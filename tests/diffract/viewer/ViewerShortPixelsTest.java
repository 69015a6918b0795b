package diffract.viewer;

import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.scene.Fabricator;
import diffract.scene.SceneSetup;
import diffract.util.Reporter;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The viewer says in its title when the refined picture's pixels were left short (the GL ended the lobes shader's
 * loops early, {@link diffract.render.ShortPixels}), as {@code render} says it on the console: a 32 x 32 sphere with
 * a 37 um patch (256 texels, 32 periods) under the sun's disc whose every lobe is marched (no cutoff, no texel sums,
 * 4 nodes per sigma, 1 nm at most) leaves pixels short on llvmpipe; with the default quadrature the title says
 * nothing of it.
 */
@Tag("gl")
class ViewerShortPixelsTest {
    private static final int MAX_DISPLAYS = 2000;
    private static final String EVERY_LOBE = "{\"cutoff\": 0, \"sumNodesPerBox\": 0, \"nodesPerSigma\": 4, "
            + "\"maxStepNm\": 1}";

    @TempDir
    Path dir;

    /** The sphere's scene with the quadrature {@code knobs} (a JSON object). */
    private SceneSetup sphere(String knobs) throws IOException {
        Path scene = dir.resolve("sphere.json");
        Files.writeString(scene, "{\"camera\": {\"eye\": [0, 1.2, 3.3], \"lookAt\": [0, 0, 0], \"fieldOfViewDeg\": 45},"
                + " \"light\": {\"thetaDeg\": 30, \"phiDeg\": 90, \"angularDiameterDeg\": 0.53},"
                + " \"shape\": {\"kind\": \"sphere\", \"tangents\": {\"project\": [1, 0, 0]}},"
                + " \"material\": {\"patch\": {\"procedural\": \"elaphe-like\", \"periods\": 32, \"sizePx\": 256},"
                + " \"variant\": \"lobes\", \"taylorTerms\": 20, \"exposure\": 400,"
                + " \"lobeQuadrature\": " + knobs + "}}");
        return Fabricator.fabricate(scene, Reporter.SILENT);
    }

    /** The notice the title shows once the picture of {@code setup} is refined, and the GL's name. */
    private static String[] noticeOnceRefined(SceneSetup setup) throws InterruptedException {
        ViewerModel model = ViewerModel.load(setup, Reporter.SILENT);
        try (TableBaker baker = new TableBaker(model)) {
            RefiningRenderer refining = new RefiningRenderer(model, new ViewerRenderer(model), baker);
            refining.drawOn(Thread.currentThread());
            try (OffscreenTarget target = new OffscreenTarget(refining)) {
                for (int i = 0; i < MAX_DISPLAYS; i++) {
                    target.renderRgba(32, 32);
                    assertFalse(refining.status().stage() == RefinementStatus.Stage.FAILED,
                            () -> String.valueOf(model.state().notice()));
                    if (refining.status().isRefined(model.state()) && !refining.needsDisplay()) {
                        Notice notice = model.state().notice();
                        return new String[] {notice == null ? "" : notice.text(), target.info().renderer()};
                    }
                }
            }
        }
        throw new AssertionError("the picture was not refined in " + MAX_DISPLAYS + " displays");
    }

    @Test
    void theTitleNamesThePixelsLeftShort() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        String[] marched = noticeOnceRefined(sphere(EVERY_LOBE));
        if (marched[1].contains("llvmpipe")) {
            assertTrue(marched[0].matches("\\d+ px left short \\(the GL ended their loops early\\).*"), marched[0]);
        }
        String[] plain = noticeOnceRefined(sphere("{}"));
        assertFalse(plain[0].contains("left short"), "the default quadrature: " + plain[0]);
    }
}
