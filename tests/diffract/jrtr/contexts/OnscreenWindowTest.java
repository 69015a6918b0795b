package diffract.jrtr.contexts;

import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

/** The renderer that draws offscreen also draws into a window (here on Xvfb), with the same result. */
@Tag("gl")
@Tag(GlTestSupport.WINDOW_TAG)
class OnscreenWindowTest {
    @Test
    void sameRendererDrawsTheSamePictureInAWindow() {
        GlTestSupport.assumeWindow();
        Group root = new Group("root").add(new ShapeNode(Shapes.rectangle("q", -0.5f, -0.5f, 0.5f, 0.5f, 0),
                GlTestSupport.unlit(1, 0.5f, 0)));
        Renderer renderer = new Renderer(root, GlTestSupport.unitCamera(), GlTestSupport.rightAngleFrustum());
        renderer.setClearColor(0, 0, 1, 1);
        float[] offscreen;
        try (OffscreenTarget target = new OffscreenTarget(renderer)) {
            offscreen = target.renderRgba(64, 64);
        }
        try (OnscreenWindow window = new OnscreenWindow("jrtr test", 64, 64, renderer)) {
            window.setTitle("jrtr test: drawn");
            float[] onscreen = window.renderRgba();
            assertEquals(64, window.surfaceWidth());
            assertEquals(64, window.surfaceHeight());
            float[] centre = GlTestSupport.pixel(onscreen, 64, 32, 32);
            // the window is 8-bit: 0.5 becomes 128/255
            assertArrayEquals(new float[] {1, 128 / 255f, 0, 1}, centre, 1e-6f);
            assertArrayEquals(new float[] {0, 0, 1, 1}, GlTestSupport.pixel(onscreen, 64, 2, 2), 1e-6f);
            for (int i = 0; i < offscreen.length; i++) {
                assertEquals(Math.round(offscreen[i] * 255) / 255f, onscreen[i], 1e-6f, "value " + i);
            }
        }
    }
}
