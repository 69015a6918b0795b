package diffract.jrtr;

import com.jogamp.opengl.GL3;
import diffract.jrtr.contexts.GLInfo;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.scenegraph.Shape;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.IntBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The depth pre-pass of {@link GLRenderContext#draw}: a far quad covering the frame drawn before a near quad over a
 * quarter of it. Each fragment shader run adds one to an atomic counter, so the count is the shading work: without the
 * pre-pass the hidden quarter of the far quad is shaded too (1.25 frames of fragments), with it each pixel once (one
 * frame), and the picture is the same. A program whose positions do not come from the pre-pass's expression is drawn
 * as without it.
 */
@Tag("gl")
class DepthPrepassTest {
    private static final int SIZE = 32;
    private static final int ATOMIC_COUNTER_BUFFER = 0x92C0; // GL 4.2
    private static Renderer renderer;
    private static OffscreenTarget target;

    @TempDir
    static Path shaders;

    @BeforeAll
    static void createTarget() {
        GlTestSupport.assumeOffscreenGl();
        renderer = new Renderer(new Group("empty"), GlTestSupport.unitCamera(), GlTestSupport.rightAngleFrustum());
        target = new OffscreenTarget(renderer);
        boolean atomics = target.withContext(gl -> {
            int[] version = GLInfo.parseVersion(gl.glGetString(GL3.GL_VERSION));
            return version[0] > 4 || version[0] == 4 && version[1] >= 2;
        });
        Assumptions.assumeTrue(atomics, "atomic counters need OpenGL 4.2");
        target.renderRgba(SIZE, SIZE); // the renderer's context exists from its first frame on
    }

    @AfterAll
    static void closeTarget() {
        if (target != null) {
            target.close();
        }
    }

    private static Material counting(boolean invariant, float r, float g, float b) throws IOException {
        String vertex = "#version 450 core\n"
                + "in vec3 position;\n"
                + "uniform mat4 model;\nuniform mat4 view;\nuniform mat4 projection;\n"
                + (invariant ? "invariant gl_Position;\n" : "")
                + "void main() {\n"
                + "    vec4 worldPosition = model * vec4(position, 1.0);\n"
                + "    gl_Position = projection * view * worldPosition;\n"
                + "}\n";
        String fragment = "#version 450 core\n"
                // a shader with side effects is run before the depth test unless it asks otherwise; the materials have
                // none, and the driver tests their depth first on its own
                + "layout(early_fragment_tests) in;\n"
                + "layout(binding = 0, offset = 0) uniform atomic_uint shaded;\n"
                + "uniform vec4 color;\n"
                + "out vec4 fragColor;\n"
                + "void main() {\n"
                + "    atomicCounterIncrement(shaded);\n"
                + "    fragColor = color;\n"
                + "}\n";
        String name = invariant ? "invariant" : "plain";
        Files.writeString(shaders.resolve(name + ".vert"), vertex);
        Files.writeString(shaders.resolve(name + ".frag"), fragment);
        return new Material(ShaderProgram.fromDirectory(shaders, name + ".vert", name + ".frag", Map.of()))
                .setVec4("color", r, g, b, 1);
    }

    private record Frame(float[] rgba, int shaded) {
    }

    private static Frame draw(boolean prepass, boolean invariant) throws IOException {
        Shape far = Shapes.rectangle("far", -2f, -2f, 2f, 2f, -0.5f);
        Shape near = Shapes.rectangle("near", -0.5f, -0.5f, 0.5f, 0.5f, 0);
        renderer.setRoot(new Group("root").add(new ShapeNode(far, counting(invariant, 0, 1, 0)),
                new ShapeNode(near, counting(invariant, 1, 0, 0))));
        int buffer = target.withContext(gl -> {
            renderer.context().setDepthPrepass(prepass);
            int[] name = new int[1];
            gl.glGenBuffers(1, name, 0);
            gl.glBindBuffer(ATOMIC_COUNTER_BUFFER, name[0]);
            gl.glBufferData(ATOMIC_COUNTER_BUFFER, 4, IntBuffer.wrap(new int[] {0}), GL3.GL_DYNAMIC_DRAW);
            gl.glBindBufferBase(ATOMIC_COUNTER_BUFFER, 0, name[0]);
            return name[0];
        });
        float[] rgba = target.renderRgba(SIZE, SIZE);
        int shaded = target.withContext(gl -> {
            int[] count = new int[1];
            gl.glBindBuffer(ATOMIC_COUNTER_BUFFER, buffer);
            gl.glGetBufferSubData(ATOMIC_COUNTER_BUFFER, 0, 4, IntBuffer.wrap(count));
            gl.glDeleteBuffers(1, new int[] {buffer}, 0);
            renderer.context().setDepthPrepass(true);
            return count[0];
        });
        return new Frame(rgba, shaded);
    }

    @Test
    void eachPixelIsShadedOnceAndThePictureIsTheSame() throws IOException {
        Frame without = draw(false, true);
        Frame with = draw(true, true);
        int pixels = SIZE * SIZE;
        // the near quad spans NDC [-0.5, 0.5]: 16 x 16 pixels of 32 x 32, drawn over the far quad's
        assertEquals(pixels + pixels / 4, without.shaded(), "without the pre-pass the hidden quarter is shaded too");
        assertEquals(pixels, with.shaded(), "with it each pixel once");
        assertArrayEquals(without.rgba(), with.rgba(), "the same picture");
        assertArrayEquals(new float[] {1, 0, 0, 1}, GlTestSupport.pixel(with.rgba(), SIZE, SIZE / 2, SIZE / 2));
        assertArrayEquals(new float[] {0, 1, 0, 1}, GlTestSupport.pixel(with.rgba(), SIZE, 2, 2));
    }

    @Test
    void aProgramPlacingItsVerticesAnotherWayIsDrawnAsWithoutThePrepass() throws IOException {
        Frame plain = draw(true, false);
        assertEquals(SIZE * SIZE + SIZE * SIZE / 4, plain.shaded(), "no pre-pass for a program not declaring it");
        assertArrayEquals(new float[] {1, 0, 0, 1}, GlTestSupport.pixel(plain.rgba(), SIZE, SIZE / 2, SIZE / 2));
    }

    @Test
    void theEnginesOwnSurfaceProgramsMatchThePrepass() {
        assertTrue(ShaderProgram.fromClasspath("engine/unlit.vert", "engine/unlit.frag", Map.of())
                .matchesDepthPrepass());
        assertTrue(ShaderProgram.fromClasspath("lighting/ground.vert", "lighting/ground.frag", Map.of())
                .matchesDepthPrepass());
        assertFalse(ShaderProgram.fromClasspath("engine/shadow_depth.vert", "engine/shadow_depth.frag", Map.of())
                .matchesDepthPrepass());
    }
}
