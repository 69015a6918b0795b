package diffract.jrtr.textures;

import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import diffract.util.TestReport;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * {@code shaders/engine/mip_footprint.glsl} on the driver: a line of unit mass, looked up over a footprint of covariance
 * C, spreads across the line with C's variance along x, averaged over where the line falls in the levels' cells (each
 * layer holds the line one texel further on, so the layers together cover every alignment with a level's cells).
 */
@Tag("gl")
class MipFootprintTest {
    private static final int WIDTH = 128;
    private static final int HEIGHT = 4;
    private static final int LAYERS = 16;        // alignments: exact for levels below 4, variances below 64
    private static final int FIRST_LINE = 48;
    private static final int SAMPLES_PER_TEXEL = 4;
    private static Renderer renderer;
    private static OffscreenTarget target;
    private static Material material;

    @TempDir
    static Path shaderDir;

    @BeforeAll
    static void createTarget() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        GlTestSupport.write(shaderDir, "pass.vert", GlTestSupport.PASS_THROUGH_VERTEX);
        GlTestSupport.write(shaderDir, "engine/mip_footprint.glsl",
                Files.readString(Path.of("shaders/engine/mip_footprint.glsl")));
        // pixel (x, layer) looks up x / SAMPLES_PER_TEXEL texels (plus half a sample) along the layer's middle row
        GlTestSupport.write(shaderDir, "footprint.frag", String.join("\n",
                "#version 330 core",
                "#include \"/engine/mip_footprint.glsl\"",
                "uniform sampler2DArray lines;",
                "uniform vec3 covarianceTexels;",
                "out vec4 fragColor;",
                "void main() {",
                "    float u = (floor(gl_FragCoord.x) + 0.5) / " + SAMPLES_PER_TEXEL + ".0;",
                "    vec2 tc = vec2(u / " + WIDTH + ".0, 0.5);",
                "    float layer = floor(gl_FragCoord.y);",
                "    fragColor = vec4(textureFootprint(lines, tc, layer, mipFootprint(covarianceTexels)).r, 0.0, 0.0, 1.0);",
                "}",
                ""));
        float[] rgb = new float[3 * WIDTH * HEIGHT * LAYERS];
        for (int layer = 0; layer < LAYERS; layer++) {
            for (int row = 0; row < HEIGHT; row++) {
                rgb[3 * ((layer * HEIGHT + row) * WIDTH + FIRST_LINE + layer)] = 1f; // a line along y: unit mass in x
            }
        }
        material = new Material(ShaderProgram.fromDirectory(shaderDir, "pass.vert", "footprint.frag", Map.of()))
                .setTexture("lines", new FloatTexture3D(WIDTH, HEIGHT, LAYERS, rgb, FloatTexture3D.Precision.FLOAT32,
                        true));
        renderer = new Renderer(new Group("root").add(new ShapeNode(Shapes.fullScreenQuad(), material)),
                GlTestSupport.unitCamera(), GlTestSupport.rightAngleFrustum());
        target = new OffscreenTarget(renderer);
    }

    @AfterAll
    static void closeTarget() {
        if (target != null) {
            target.close();
        }
    }

    /** {mass, variance about the line} of the lookups across the line, over the layers' alignments. */
    private static double[] spreadAcrossTheLine(double xx, double xy, double yy) {
        material.setVec3("covarianceTexels", (float) xx, (float) xy, (float) yy);
        int width = WIDTH * SAMPLES_PER_TEXEL;
        float[] rgba = target.renderRgba(width, LAYERS);
        double massSum = 0;
        double varianceSum = 0;
        for (int layer = 0; layer < LAYERS; layer++) {
            double centre = FIRST_LINE + layer + 0.5;
            double mass = 0;
            double moment = 0;
            for (int x = 0; x < width; x++) {
                double value = GlTestSupport.pixel(rgba, width, x, LAYERS - 1 - layer)[0] / SAMPLES_PER_TEXEL;
                double u = (x + 0.5) / SAMPLES_PER_TEXEL;
                mass += value;
                moment += value * (u - centre) * (u - centre);
            }
            massSum += mass;
            varianceSum += moment / mass;
        }
        return new double[] {massSum / LAYERS, varianceSum / LAYERS};
    }

    /**
     * The spread a footprint of variance v gives here: at least level 0's own (1/4), less the 1/12 of a texel's box
     * that a sampled line lacks (a table's texels are cell averages, this line is one texel), plus the 1/12 of the
     * read-back's sample spacing squared.
     */
    private static double expectedSpread(double v) {
        return Math.max(v, 0.25) - 1.0 / 12 + 1.0 / (12.0 * SAMPLES_PER_TEXEL * SAMPLES_PER_TEXEL);
    }

    @Test
    void anIsotropicFootprintSpreadsWithItsVariance() {
        // level 0's own spread (a texel's box and its bilinear tent) is 1/4: smaller footprints cannot be sharper
        for (double variance : new double[] {0.25, 0.5, 1, 2, 3, 6, 12, 24, 48}) {
            double[] spread = spreadAcrossTheLine(variance, 0, variance);
            TestReport.printf(MipFootprintTest.class, Locale.ROOT, "variance %5.2f texels^2: mass %.4f, spread %.3f%n",
                    variance, spread[0], spread[1]);
            assertEquals(1, spread[0], 1e-3, "the lookup keeps the mass");
            assertEquals(expectedSpread(variance), spread[1], 0.03 * variance, "variance " + variance);
        }
    }

    @Test
    void anElongatedFootprintSpreadsAlongItsLongAxisOnly() {
        assertEquals(expectedSpread(16), spreadAcrossTheLine(16, 0, 1)[1], 0.03 * 16, "long axis across the line");
        assertEquals(expectedSpread(1), spreadAcrossTheLine(1, 0, 16)[1], 0.03, "long axis along the line");
        // eigenvalues 17 and 1 along the diagonals: the variance across the line is the xx entry
        assertEquals(expectedSpread(9), spreadAcrossTheLine(9, 8, 9)[1], 0.03 * 9, "a rotated footprint");
    }
}
