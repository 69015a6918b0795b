package diffract.render;

import diffract.jrtr.scenegraph.Camera;
import diffract.jrtr.scenegraph.Frustum;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.OffscreenTarget;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.shaders.ShaderSourceRoot;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;

import java.util.Map;
import java.util.TreeMap;
import java.util.function.DoubleBinaryOperator;

/**
 * Evaluates one GLSL expression of the shaders' functions on a grid of inputs, on the GPU, for comparison with the
 * function's Java twin: a fragment shader that includes the file under test computes {@code expression} of
 * {@code x} (along the grid's columns) and {@code y} (along its rows) per pixel and writes the result beside the
 * inputs it used, read back as float32. The twin is then evaluated at exactly those float32 inputs, so what is
 * compared is the function, not the grid's rounding.
 */
final class GlslFunctions {
    /** One evaluation: the inputs as the shader saw them and its result. */
    record Sample(double x, double y, double glsl) {
    }

    /** A grid's comparison with the Java twin: the largest absolute difference and where it was. */
    record Comparison(double maxAbsError, Sample worst, double twinAtWorst, int samples) {
        @Override
        public String toString() {
            return String.format(java.util.Locale.ROOT, "max |glsl - java| %.3g at (%.6g, %.6g): glsl %.9g, java %.9g,"
                    + " over %d samples", maxAbsError, worst.x(), worst.y(), worst.glsl(), twinAtWorst, samples);
        }
    }

    private GlslFunctions() {
    }

    /**
     * {@code expression} (GLSL, of {@code float x, y}) on an {@code nx} x {@code ny} grid spanning [x0, x1] x [y0, y1]
     * from pixel centre to pixel centre, with {@code include} (a path under {@code shaders/}) and {@code defines}.
     */
    static Sample[] evaluate(String include, Map<String, String> defines, String expression, int nx, int ny,
                             double x0, double x1, double y0, double y1) {
        String harness = "harness/function.frag";
        String fragment = "#version 330 core\n"
                + "#include \"/" + include + "\"\n"
                + "uniform vec4 grid;   // x0, x1, y0, y1\n"
                + "uniform vec2 counts; // nx, ny\n"
                + "out vec4 fragColor;\n"
                + "void main() {\n"
                + "    vec2 t = (gl_FragCoord.xy - 0.5) / max(counts - 1.0, vec2(1.0));\n"
                + "    float x = mix(grid.x, grid.y, t.x);\n"
                + "    float y = mix(grid.z, grid.w, t.y);\n"
                + "    fragColor = vec4(" + expression + ", x, y, 1.0);\n"
                + "}\n";
        ShaderSourceRoot classpath = ShaderSourceRoot.classpath();
        ShaderSourceRoot root = new ShaderSourceRoot() {
            @Override
            public String read(String path) {
                return ShaderSourceRoot.normalize(path).equals(harness) ? fragment : classpath.read(path);
            }

            @Override
            public String describe() {
                return "the function harness over " + classpath.describe();
            }
        };
        Map<String, String> all = new TreeMap<>(defines);
        ShaderProgram program = ShaderProgram.load(root, "diffraction/brdfmap.vert", harness, all);
        Material m = new Material(program).setVec4("grid", (float) x0, (float) x1, (float) y0, (float) y1)
                .setVec2("counts", nx, ny);
        ShapeNode quad = new ShapeNode(Shapes.fullScreenQuad(), m);
        float[] rgba;
        try (OffscreenTarget target = new OffscreenTarget(new Renderer(new Group("harness").add(quad), new Camera(),
                new Frustum()))) {
            rgba = target.renderRgba(nx, ny);
        }
        Sample[] samples = new Sample[nx * ny];
        for (int p = 0; p < samples.length; p++) {
            samples[p] = new Sample(rgba[4 * p + 1], rgba[4 * p + 2], rgba[4 * p]);
        }
        return samples;
    }

    /** The samples against the twin, evaluated in double at the shader's float32 inputs. */
    static Comparison compare(Sample[] samples, DoubleBinaryOperator twin) {
        double max = -1;
        Sample worst = null;
        double twinAtWorst = Double.NaN;
        for (Sample s : samples) {
            double expected = twin.applyAsDouble(s.x(), s.y());
            double error = Math.abs(s.glsl() - expected);
            if (!(error <= max)) { // NaN counts as the worst
                max = Double.isNaN(error) ? Double.POSITIVE_INFINITY : error;
                worst = s;
                twinAtWorst = expected;
            }
        }
        return new Comparison(max, worst, twinAtWorst, samples.length);
    }
}
