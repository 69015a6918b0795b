package diffract.render;

import diffract.colour.ToneMapping;
import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.scene.Fabricator;
import diffract.scene.SceneSetup;
import diffract.util.Reporter;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerRenderer;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The staged surface evaluates the same BRDF as the thesis' surface shader: with a frame map that tilts nothing
 * (every scale flat, its axis the mesh's tangent), no environment, no ground and clipping tone mapping, the picture
 * of the blazed grating on a plane equals the unstaged one (per-fragment frame against per-vertex tangent-space
 * directions, the same on a flat mesh up to float rounding); a frame map that tilts changes it.
 */
@Tag("gl")
@Tag(diffract.jrtr.GlTestSupport.LONG_TAG) // whole staged frames: a long test
class StagedSurfaceTest {
    static final int W = 96;
    static final int H = 60;

    static float[] render(SceneSetup setup) {
        ViewerModel model = ViewerModel.load(setup, Reporter.SILENT);
        try (OffscreenTarget target = new OffscreenTarget(new ViewerRenderer(model))) {
            return target.renderRgb(W, H);
        }
    }

    static Stage.ScaleFrames frames(float nx) {
        int w = 8;
        int h = 8;
        float[] rgba = new float[4 * w * h];
        for (int i = 0; i < w * h; i++) {
            rgba[4 * i] = nx;
            rgba[4 * i + 2] = 1; // axis along the tangent
        }
        return new Stage.ScaleFrames(w, h, rgba);
    }

    @Test
    void flatScalesGiveThePlainSurfaceAndTiltedOnesDoNot() {
        GlTestSupport.assumeOffscreenGl();
        // FLSS at 10 um under a point light: the grating's orders are a few pixels wide, so a tilt moves many values
        SceneSetup scene = Fabricator.fabricate(Path.of("assets", "scenes", "blazed-grating-plane.json"),
                Reporter.SILENT);
        SceneSetup plain = scene.withSettings(scene.settings().with(b -> b.coherenceLengthUm(10)
                .variant(diffract.optics.Variant.FLSS).lightSizeDeg(0)));
        float[] reference = render(plain);
        float[] flat = render(plain.withStage(new Stage(frames(0), null, null, ToneMapping.clip())));
        float[] tilted = render(plain.withStage(new Stage(frames(0.2f), null, null, ToneMapping.clip())));
        int lit = 0;
        int differing = 0;
        int moved = 0;
        for (int i = 0; i < reference.length; i++) {
            if (reference[i] > 0.02f) {
                lit++;
            }
            if (Math.abs(reference[i] - flat[i]) > 2 / 255f) {
                differing++;
            }
            if (Math.abs(reference[i] - tilted[i]) > 0.05f) {
                moved++;
            }
        }
        assertTrue(lit > 300, "the grating's orders light " + lit + " channel values");
        assertTrue(differing <= 0.005 * reference.length, differing + " channel values differ with flat scales");
        assertTrue(moved > 100, "a tilt of the scales moves the orders: " + moved + " values changed");
    }

    /**
     * At a silhouette a scale tilted away from the view would show its back: no reflection and no light let out of
     * the skin, a black pixel among lit ones. The staged Elaphe scene (its sky lights every surface, so no pixel of
     * it may be black) at 320 x 200 shows none: the normal is turned towards the view.
     */
    @Test
    void noScaleAtASilhouetteTurnsItsBackToTheView() {
        GlTestSupport.assumeOffscreenGl();
        SceneSetup scene = Fabricator.fabricate(Path.of("assets", "scenes", "snake-elaphe.json"), Reporter.SILENT);
        SceneSetup baked = scene.withSettings(scene.settings().with(b -> b.variant(diffract.optics.Variant.BAKED)));
        float[] rgb;
        ViewerModel model = ViewerModel.load(baked, Reporter.SILENT);
        try (OffscreenTarget target = new OffscreenTarget(new ViewerRenderer(model))) {
            rgb = target.renderRgb(320, 200);
        }
        int black = 0;
        for (int p = 0; p < rgb.length / 3; p++) {
            if (Math.max(rgb[3 * p], Math.max(rgb[3 * p + 1], rgb[3 * p + 2])) <= 0f) {
                black++;
            }
        }
        assertTrue(black == 0, black + " black pixels");
    }
}
