package diffract.jrtr;

import diffract.jrtr.contexts.EglContext;
import diffract.jrtr.contexts.EglDisplay;
import diffract.jrtr.contexts.JoglOffscreenContext;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The same renderer on headless EGL and on JOGL's context on the X display (GLX under Xvfb) gives the same floats:
 * the GL3 calls the engine makes mean the same through LWJGL as through JOGL.
 */
@Tag("gl")
@Tag(GlTestSupport.WINDOW_TAG)
class EglGlxAgreementTest {
    @Test
    void eglAndGlxDrawTheSamePicture() {
        GlTestSupport.assumeWindow();
        GlTestSupport.assumeOffscreenGl();
        // a cube with its normals encoded as colours, in front of a coloured quad: vertex data, uniforms, depth
        Material normals = new Material(ShaderProgram.fromClasspath("engine/unlit.vert", "engine/unlit.frag",
                Map.of("OUTPUT_NORMAL", "1"))).setVec4("color", 0.25f, 0.5f, 0.75f, 1);
        Group root = new Group("root")
                .add(new ShapeNode(Shapes.cube(0.3f), normals))
                .add(new ShapeNode(Shapes.rectangle("q", -1f, -1f, 1f, -0.5f, -0.2f), GlTestSupport.unlit(0.25f, 0.5f, 1f)));
        float[] egl;
        float[] glx;
        String eglPlatform;
        try (OffscreenTarget target = new OffscreenTarget(new Renderer(root, GlTestSupport.unitCamera(),
                GlTestSupport.rightAngleFrustum()), new EglContext(eglDisplay()))) {
            eglPlatform = target.info().platform();
            egl = target.renderRgba(64, 48);
        }
        try (OffscreenTarget target = new OffscreenTarget(new Renderer(root, GlTestSupport.unitCamera(),
                GlTestSupport.rightAngleFrustum()), new JoglOffscreenContext())) {
            assertTrue(target.info().platform().startsWith("GLX"), target.info().toString());
            glx = target.renderRgba(64, 48);
        }
        assertTrue(eglPlatform.startsWith("EGL"), eglPlatform);
        int differing = 0;
        for (int i = 0; i < egl.length; i++) {
            assertEquals(glx[i], egl[i], 1e-5f, "value " + i);
            differing += glx[i] != egl[i] ? 1 : 0;
        }
        float[] centre = GlTestSupport.pixel(egl, 64, 32, 24);
        assertTrue(centre[2] > 0.9f, "the cube's front face looks at the camera: its encoded normal is blue");
        assertTrue(differing < egl.length / 100, differing + " values differ at all");
    }

    private static EglDisplay eglDisplay() {
        return EglDisplay.open(null);
    }
}
