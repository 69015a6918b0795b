package diffract.jrtr;

import diffract.jrtr.contexts.DisplayCheck;
import diffract.jrtr.contexts.HeadlessGL;
import diffract.jrtr.scenegraph.Camera;
import diffract.jrtr.scenegraph.Frustum;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.ShaderProgram;
import org.junit.jupiter.api.Assumptions;

import javax.vecmath.Point3f;
import javax.vecmath.Vector3f;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Optional;

/**
 * Shared helpers for the GL tests. The two assumptions are what every GL test in every package starts with:
 * {@link #assumeOffscreenGl()} for anything drawn offscreen (headless EGL, no X server needed; {@link HeadlessGL}
 * chooses the context exactly as the commands do), {@link #assumeWindow()} for tests that open a window (tag them
 * {@value #WINDOW_TAG}: {@code .ci/run} runs that tag again under Xvfb). Also a standard camera, pixel access and
 * shader files for the engine's own tests.
 */
public final class GlTestSupport {
    /** JUnit tag of the tests that need a window, hence an X display. */
    public static final String WINDOW_TAG = "window";
    /**
     * JUnit tag of the sweeps and reports that take a minute on a software rasteriser: README's test command leaves
     * them out (pom.xml's {@code diffract.excludedGroups}) and {@code .ci/run} runs them after it.
     */
    public static final String LONG_TAG = "long";

    private GlTestSupport() {
    }

    /** Skips (does not fail) the test where no offscreen GL context can be made, saying why and what to install. */
    public static void assumeOffscreenGl() {
        Optional<String> problem = HeadlessGL.problem();
        Assumptions.assumeTrue(problem.isEmpty(), () -> "skipping GL test: " + problem.orElse(""));
    }

    /** Skips the test where no X display exists for a window (e.g. outside {@code xvfb-run}). */
    public static void assumeWindow() {
        Assumptions.assumeTrue(DisplayCheck.problem().isEmpty(),
                () -> "skipping window test: " + DisplayCheck.NO_DISPLAY_MESSAGE);
    }

    /** Eye (0,0,1) looking at the origin: with a 90 degree frustum, z = 0 shows exactly [-1,1] x [-1,1]. */
    public static Camera unitCamera() {
        return new Camera(new Point3f(0, 0, 1), new Point3f(0, 0, 0), new Vector3f(0, 1, 0));
    }

    public static Frustum rightAngleFrustum() {
        return new Frustum(0.1f, 10f, 1f, 90f);
    }

    public static Material unlit(float r, float g, float b) {
        return new Material(ShaderProgram.fromClasspath("engine/unlit.vert", "engine/unlit.frag", Map.of()))
                .setVec4("color", r, g, b, 1);
    }

    /** RGBA of pixel (x, y), y counted from the top. */
    public static float[] pixel(float[] rgba, int width, int x, int y) {
        int i = (y * width + x) * 4;
        return new float[] {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }

    public static void write(Path dir, String relative, String text) throws IOException {
        Path file = dir.resolve(relative);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
    }

    /** Vertex shader that puts the [-1,1]^2 quad straight into clip space: covers the viewport exactly. */
    public static final String PASS_THROUGH_VERTEX = String.join("\n",
            "#version 330 core",
            "in vec3 position;",
            "void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }",
            "");
}
