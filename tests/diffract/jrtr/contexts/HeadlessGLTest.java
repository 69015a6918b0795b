package diffract.jrtr.contexts;

import com.jogamp.opengl.GL3;
import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.Group;
import diffract.util.UserInputException;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** How offscreen contexts are chosen: EGL without an X server, the GPU by index, one-line refusals. */
class HeadlessGLTest {
    @Test
    void badSettingsAreRefusedInOneLineNamingTheVariable() {
        UserInputException gpu = assertThrows(UserInputException.class,
                () -> HeadlessGL.problem(Map.of(HeadlessGL.GPU_VARIABLE, "first")));
        assertEquals("DIFFRACT_GPU=first is not a device index (0, 1, ...)", gpu.getMessage());
        assertThrows(UserInputException.class, () -> HeadlessGL.problem(Map.of(HeadlessGL.GPU_VARIABLE, "-1")));
        UserInputException platform = assertThrows(UserInputException.class,
                () -> HeadlessGL.problem(Map.of(HeadlessGL.PLATFORM_VARIABLE, "wayland")));
        assertEquals("DIFFRACT_GL=wayland: use egl or x11", platform.getMessage());
        assertThrows(UserInputException.class, () -> HeadlessGL.useGpu(-2));
    }

    @Test
    void versionStringsOfTheDriversParse() {
        assertArrayEquals(new int[] {4, 5}, GLInfo.parseVersion("4.5 (Core Profile) Mesa 22.3.6"));
        assertArrayEquals(new int[] {4, 6}, GLInfo.parseVersion("4.6.0 NVIDIA 550.54.15"));
        assertArrayEquals(new int[] {3, 3}, GLInfo.parseVersion("3.3.0 Core Profile Context 23.10.1"));
        assertArrayEquals(new int[] {0, 0}, GLInfo.parseVersion(null));
    }

    /** Without an X display (DISPLAY unset), the offscreen context is EGL: no Xvfb is needed. */
    @Test
    @Tag("gl")
    void withoutAnXDisplayOffscreenTargetsRunOnEglWithACoreContext() {
        GlTestSupport.assumeOffscreenGl();
        try (OffscreenTarget target = new OffscreenTarget(new Renderer(new Group("empty"), GlTestSupport.unitCamera(),
                GlTestSupport.rightAngleFrustum()))) {
            GLInfo info = target.info();
            if (DisplayCheck.problem().isPresent()) {
                assertTrue(info.platform().startsWith("EGL"), info.toString());
            }
            assertTrue(GLInfo.parseVersion(info.version())[0] >= 3, info.toString());
            if (info.platform().startsWith("EGL")) {
                assertTrue(info.coreProfile(), info + " is not a core profile context");
                assertNull(HeadlessGL.currentContext(), "nothing stays current outside withContext");
                Object inside = target.withContext(gl -> HeadlessGL.currentContext());
                assertNotNull(inside);
            }
            // JOGL's extension query answers on either context: a listed extension is there, a made-up one is not
            boolean[] answers = target.withContext(gl -> {
                int[] count = new int[1];
                gl.glGetIntegerv(GL3.GL_NUM_EXTENSIONS, count, 0);
                assertTrue(count[0] > 0, "no extensions listed by " + info);
                String last = gl.glGetStringi(GL3.GL_EXTENSIONS, count[0] - 1);
                return new boolean[] {gl.isExtensionAvailable(last), gl.isExtensionAvailable("GL_DIFFRACT_none")};
            });
            assertTrue(answers[0], "a listed extension is available");
            assertFalse(answers[1], "a made-up extension is not");
        }
    }

    @Test
    @Tag("gl")
    void aGpuIndexPastTheDevicesNamesTheDevicesFound() {
        GlTestSupport.assumeOffscreenGl();
        UserInputException e = assertThrows(UserInputException.class,
                () -> HeadlessGL.problem(Map.of(HeadlessGL.GPU_VARIABLE, "97")));
        assertTrue(e.getMessage().startsWith("GPU 97 not found: "), e.getMessage());
        assertTrue(e.getMessage().endsWith("give no GPU index (neither the option nor DIFFRACT_GPU) for the automatic choice"),
                e.getMessage());
    }
}
