package diffract.jrtr;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GL;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import diffract.jrtr.textures.DepthBounds;
import diffract.jrtr.textures.Texture;
import diffract.util.TestReport;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.vecmath.Matrix4f;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * {@code lighting/environment.glsl}'s soft shadow settles regions by the depth bounds without comparing their taps;
 * the answer must be the taps' own. Receivers over a map of blockers at many depths (discs, a ramp, single texels)
 * are lit once with the shortcuts and once comparing every tap ({@code SHADOW_TAPS_ONLY}): the visibilities agree
 * bit for bit, and the receivers cover lit, umbra and penumbra alike.
 */
@Tag("gl")
class ShadowBoundsTest {
    private static final int MAP = 256;
    private static final int OUT = 96;

    @TempDir
    Path dir;

    @Test
    void theBoundsShortcutsGiveWhatTheTapsGive() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        float[] depth = blockers();
        float[] withBounds = visibilities(depth, Map.of());
        float[] tapsOnly = visibilities(depth, Map.of("SHADOW_TAPS_ONLY", "1"));
        int lit = 0;
        int dark = 0;
        int between = 0;
        for (int p = 0; p < OUT * OUT; p++) {
            assertEquals(tapsOnly[4 * p], withBounds[4 * p], 0f, "receiver " + p);
            float v = withBounds[4 * p];
            if (v == 1f) {
                lit++;
            } else if (v == 0f) {
                dark++;
            } else {
                between++;
            }
        }
        TestReport.printf(ShadowBoundsTest.class, Locale.ROOT, "%d receivers: %d lit, %d in umbra, %d in penumbra%n",
                OUT * OUT, lit, dark, between);
        assertTrue(lit > OUT * OUT / 10 && dark > OUT * OUT / 40 && between > OUT * OUT / 10,
                "lit " + lit + ", umbra " + dark + ", penumbra " + between);
    }

    /** Depths in [0, 1] (1: nothing): discs of blockers at several depths, a ramp, scattered texels. */
    private static float[] blockers() {
        float[] depth = new float[MAP * MAP];
        java.util.Arrays.fill(depth, 1f);
        Random random = new Random(3);
        for (int d = 0; d < 12; d++) {
            double cx = random.nextDouble() * MAP;
            double cy = random.nextDouble() * MAP;
            double r = 6 + random.nextDouble() * 30;
            float z = 0.2f + 0.5f * random.nextFloat();
            for (int y = 0; y < MAP; y++) {
                for (int x = 0; x < MAP; x++) {
                    if ((x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r) {
                        depth[x + MAP * y] = Math.min(depth[x + MAP * y], z);
                    }
                }
            }
        }
        for (int y = 200; y < 240; y++) {
            for (int x = 10; x < 120; x++) {
                depth[x + MAP * y] = Math.min(depth[x + MAP * y], 0.3f + 0.006f * x);
            }
        }
        for (int t = 0; t < 300; t++) {
            depth[random.nextInt(MAP * MAP)] = 0.5f;
        }
        return depth;
    }

    /** keyLightVisibility over OUT^2 receivers at depths 0.55 to 0.95 across the map, RGBA floats (R). */
    private float[] visibilities(float[] depth, Map<String, String> defines) throws Exception {
        Path shaders = dir.resolve(defines.isEmpty() ? "bounds" : "taps");
        GlTestSupport.write(shaders, "pass.vert", GlTestSupport.PASS_THROUGH_VERTEX);
        GlTestSupport.write(shaders, "lighting/environment.glsl",
                Files.readString(Path.of("shaders/lighting/environment.glsl")));
        GlTestSupport.write(shaders, "visibility.frag", String.join("\n",
                "#version 330 core",
                "#define SHADOW_MAP 1",
                "#include \"/lighting/environment.glsl\"",
                "out vec4 fragColor;",
                "void main() {",
                "    vec2 st = gl_FragCoord.xy / " + OUT + ".0;",
                "    float z = 0.55 + 0.4 * fract(7.0 * st.x + 3.0 * st.y);",
                "    vec3 light = vec3(0.0, 0.0, 1.0);",
                "    fragColor = vec4(keyLightVisibility(vec3(st, z), light, light), 0.0, 0.0, 1.0);",
                "}",
                ""));
        DepthBounds bounds = new DepthBounds(MAP);
        bounds.update(null, depth);
        Material material = new Material(ShaderProgram.fromDirectory(shaders, "pass.vert", "visibility.frag",
                defines))
                .setTexture("shadowMap", new ComparedDepth(depth))
                .setTexture("shadowDepthBounds", bounds)
                .setMatrix("shadowMatrix", identity())
                .setFloat("shadowNormalOffset", 0f)
                .setFloat("shadowTexelWorld", 1f / MAP)
                .setFloat("shadowDepthRangeWorld", 1f)
                .setFloat("keyLightTanHalfAngle", (float) Math.tan(Math.toRadians(10)));
        Renderer renderer = new Renderer(new Group("root").add(new ShapeNode(Shapes.fullScreenQuad(), material)),
                GlTestSupport.unitCamera(), GlTestSupport.rightAngleFrustum());
        try (OffscreenTarget target = new OffscreenTarget(renderer)) {
            return target.renderRgba(OUT, OUT);
        }
    }

    private static Matrix4f identity() {
        Matrix4f m = new Matrix4f();
        m.setIdentity();
        return m;
    }

    /** A depth texture of given depths, sampled with comparisons as {@link ShadowMap} is. */
    private static final class ComparedDepth extends Texture {
        private final float[] depth;

        ComparedDepth(float[] depth) {
            this.depth = depth;
        }

        @Override
        public int glTarget() {
            return GL.GL_TEXTURE_2D;
        }

        @Override
        protected void fill(GL3 gl) {
            ShadowMap.depthImage(gl, MAP, depth);
        }
    }
}
