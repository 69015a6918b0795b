package diffract.jrtr;

import diffract.jrtr.scenegraph.Camera;
import diffract.jrtr.scenegraph.Frustum;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.LightNode;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.Node;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.scenegraph.Shape;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import diffract.jrtr.scenegraph.TransformGroup;
import diffract.util.ImageFiles;
import diffract.util.TestReport;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import javax.vecmath.Matrix4f;
import javax.vecmath.Point3f;
import javax.vecmath.Vector3f;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;

import static diffract.jrtr.GlTestSupport.pixel;
import static diffract.jrtr.GlTestSupport.unlit;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** Renders small scenes offscreen and checks pixels against what the geometry and matrices predict. */
@Tag("gl")
class OffscreenRenderTest {
    private static final int SIZE = 64;
    private static Renderer renderer;
    private static OffscreenTarget target;

    @BeforeAll
    static void createTarget() {
        GlTestSupport.assumeOffscreenGl();
        renderer = new Renderer(new Group("empty"), GlTestSupport.unitCamera(), GlTestSupport.rightAngleFrustum());
        renderer.setClearColor(0.1f, 0.2f, 0.3f, 1f);
        target = new OffscreenTarget(renderer);
        TestReport.line(OffscreenRenderTest.class, "GL under test: " + target.info());
    }

    @AfterAll
    static void closeTarget() {
        if (target != null) {
            target.close();
        }
    }

    private float[] render(Node root) {
        renderer.setRoot(root);
        renderer.setCamera(GlTestSupport.unitCamera());
        return target.renderRgba(SIZE, SIZE);
    }

    @Test
    void quadHasItsColourAtTheCentreAndTheClearColourAtACorner() {
        Shape quad = Shapes.rectangle("half quad", -0.5f, -0.5f, 0.5f, 0.5f, 0);
        float[] rgba = render(new Group("root").add(new ShapeNode(quad, unlit(0.25f, 0.5f, 0.75f))));
        // RGBA32F target: the uniform colour arrives without any rounding
        assertArrayEquals(new float[] {0.25f, 0.5f, 0.75f, 1f}, pixel(rgba, SIZE, SIZE / 2, SIZE / 2));
        assertArrayEquals(new float[] {0.1f, 0.2f, 0.3f, 1f}, pixel(rgba, SIZE, 0, 0));
        assertArrayEquals(new float[] {0.1f, 0.2f, 0.3f, 1f}, pixel(rgba, SIZE, SIZE - 1, SIZE - 1));
        // the quad spans NDC [-0.5, 0.5]: pixels 16..47 inclusive
        assertArrayEquals(new float[] {0.25f, 0.5f, 0.75f, 1f}, pixel(rgba, SIZE, 16, 47));
        assertArrayEquals(new float[] {0.1f, 0.2f, 0.3f, 1f}, pixel(rgba, SIZE, 15, 32));
        assertArrayEquals(new float[] {0.1f, 0.2f, 0.3f, 1f}, pixel(rgba, SIZE, 32, 48));
    }

    @Test
    void nearQuadHidesFarQuadWhateverTheDrawOrder() {
        Shape near = Shapes.rectangle("near", -0.5f, -0.5f, 0.5f, 0.5f, 0);
        Shape far = Shapes.rectangle("far", -2f, -2f, 2f, 2f, -0.5f);
        Material red = unlit(1, 0, 0);
        Material green = unlit(0, 1, 0);
        for (boolean nearFirst : new boolean[] {true, false}) {
            Group root = new Group("root");
            if (nearFirst) {
                root.add(new ShapeNode(near, red), new ShapeNode(far, green));
            } else {
                root.add(new ShapeNode(far, green), new ShapeNode(near, red));
            }
            float[] rgba = render(root);
            assertArrayEquals(new float[] {1, 0, 0, 1}, pixel(rgba, SIZE, SIZE / 2, SIZE / 2),
                    "near first: " + nearFirst);
            assertArrayEquals(new float[] {0, 1, 0, 1}, pixel(rgba, SIZE, 2, 2), "near first: " + nearFirst);
        }
    }

    @Test
    void perspectiveCubeLandsWhereTheProjectionPredicts() {
        // camera at (1, 2, 6) looking at (0.5, 0, 0), 50 degree field of view, cube rotated and moved
        Point3f eye = new Point3f(1, 2, 6);
        Point3f lookAt = new Point3f(0.5f, 0, 0);
        Camera camera = new Camera(eye, lookAt, new Vector3f(0, 1, 0));
        Matrix4f placement = new Matrix4f();
        placement.rotY((float) Math.toRadians(30));
        placement.setTranslation(new Vector3f(0.8f, 0.2f, -0.5f));
        TransformGroup placed = new TransformGroup("placed", placement);
        placed.add(new ShapeNode(Shapes.cube(0.75f), unlit(1, 1, 1)));
        renderer.setRoot(new Group("root").add(placed));
        renderer.setCamera(camera);
        renderer.setFrustum(new Frustum(0.5f, 50f, 1f, 50f));
        float[] rgba;
        try {
            rgba = target.renderRgba(SIZE, SIZE);
        } finally {
            renderer.setFrustum(GlTestSupport.rightAngleFrustum());
        }

        // prediction, written out independently of Camera/Frustum: project the 8 corners by hand
        double[] w = normalized(eye.x - lookAt.x, eye.y - lookAt.y, eye.z - lookAt.z);
        double[] u = normalized(cross(new double[] {0, 1, 0}, w));
        double[] v = cross(w, u);
        double focal = 1 / Math.tan(Math.toRadians(25));
        double minX = Double.MAX_VALUE, maxX = -Double.MAX_VALUE, minY = Double.MAX_VALUE, maxY = -Double.MAX_VALUE;
        double c = Math.cos(Math.toRadians(30)), s = Math.sin(Math.toRadians(30));
        for (int corner = 0; corner < 8; corner++) {
            double x = (corner & 1) == 0 ? -0.75 : 0.75;
            double y = (corner & 2) == 0 ? -0.75 : 0.75;
            double z = (corner & 4) == 0 ? -0.75 : 0.75;
            double[] world = {c * x + s * z + 0.8, y + 0.2, -s * x + c * z - 0.5};
            double[] d = {world[0] - eye.x, world[1] - eye.y, world[2] - eye.z};
            double cu = dot(d, u), cv = dot(d, v), cw = dot(d, w);
            double ndcX = focal * cu / -cw;
            double ndcY = focal * cv / -cw;
            double px = (ndcX + 1) / 2 * SIZE;
            double py = (1 - ndcY) / 2 * SIZE; // image rows count from the top
            minX = Math.min(minX, px);
            maxX = Math.max(maxX, px);
            minY = Math.min(minY, py);
            maxY = Math.max(maxY, py);
        }
        int[] box = coveredBox(rgba);
        // a pixel is covered when its centre (i + 0.5) is inside: first covered = round(min), last = round(max) - 1
        assertEquals(minX, box[0] + 0.5, 1.0, "left edge");
        assertEquals(maxX, box[2] + 0.5, 1.0, "right edge");
        assertEquals(minY, box[1] + 0.5, 1.0, "top edge");
        assertEquals(maxY, box[3] + 0.5, 1.0, "bottom edge");
        assertTrue(box[2] - box[0] > 10 && box[3] - box[1] > 10, "cube should cover a visible area");
    }

    @Test
    void defineInjectionChangesTheOutput() {
        Shape quad = Shapes.fullScreenQuad();
        Material plain = unlit(0.25f, 0.5f, 0.75f);
        Material normals = new Material(ShaderProgram.fromClasspath("engine/unlit.vert", "engine/unlit.frag",
                Map.of("OUTPUT_NORMAL", "1"))).setVec4("color", 0.25f, 0.5f, 0.75f, 1);
        float[] withoutDefine = render(new Group("root").add(new ShapeNode(quad, plain)));
        float[] withDefine = render(new Group("root").add(new ShapeNode(quad, normals)));
        assertArrayEquals(new float[] {0.25f, 0.5f, 0.75f, 1}, pixel(withoutDefine, SIZE, SIZE / 2, SIZE / 2));
        // normal (0, 0, 1) encoded as n / 2 + 1/2
        assertArrayEquals(new float[] {0.5f, 0.5f, 1f, 1f}, pixel(withDefine, SIZE, SIZE / 2, SIZE / 2));
    }

    @Test
    void aShapeDrawnTwiceIsUploadedOnceAndTransformsAccumulate() {
        Shape small = Shapes.rectangle("small", -0.25f, -0.25f, 0.25f, 0.25f, 0);
        Matrix4f left = new Matrix4f();
        left.setIdentity();
        left.setTranslation(new Vector3f(-0.5f, 0, 0));
        Matrix4f up = new Matrix4f();
        up.setIdentity();
        up.setTranslation(new Vector3f(0, 0.5f, 0));
        TransformGroup outer = new TransformGroup("left", left);
        TransformGroup inner = new TransformGroup("left and up", up);
        inner.add(new ShapeNode(small, unlit(0, 0, 1)));
        outer.add(inner);
        int before = renderer.context() == null ? 0 : renderer.context().uploadedShapeCount();
        float[] rgba = render(new Group("root").add(outer, new ShapeNode(small, unlit(1, 1, 0))));
        assertEquals(before + 1, renderer.context().uploadedShapeCount());
        assertArrayEquals(new float[] {1, 1, 0, 1}, pixel(rgba, SIZE, 32, 32));
        // centre (-0.5, 0.5) in NDC is pixel (16, 16) from the top-left
        assertArrayEquals(new float[] {0, 0, 1, 1}, pixel(rgba, SIZE, 16, 16));
        assertArrayEquals(new float[] {0.1f, 0.2f, 0.3f, 1f}, pixel(rgba, SIZE, 16, 48));
    }

    @Test
    void lightsReachTheShaderInWorldSpace(@TempDir Path dir) throws Exception {
        GlTestSupport.write(dir, "light.frag", String.join("\n",
                "#version 330 core",
                "uniform int lightCount;",
                "uniform vec3 lightDirection[8];",
                "uniform vec3 lightRadiance[8];",
                "out vec4 fragColor;",
                "void main() { fragColor = vec4(lightDirection[1] * lightRadiance[1].x, float(lightCount)); }",
                ""));
        GlTestSupport.write(dir, "pass.vert", GlTestSupport.PASS_THROUGH_VERTEX);
        Matrix4f turn = new Matrix4f();
        turn.rotZ((float) Math.toRadians(90)); // +x becomes +y
        TransformGroup turned = new TransformGroup("turned", turn);
        turned.add(new LightNode("second", new Vector3f(2, 0, 0), new Vector3f(0.5f, 7, 7)));
        Node root = new Group("root").add(
                new LightNode("first", new Vector3f(0, 0, 1), new Vector3f(1, 1, 1)),
                turned,
                new ShapeNode(Shapes.fullScreenQuad(),
                        new Material(ShaderProgram.fromDirectory(dir, "pass.vert", "light.frag", Map.of()))));
        float[] p = pixel(render(root), SIZE, 5, 5);
        assertEquals(0, p[0], 1e-6);
        assertEquals(0.5, p[1], 1e-6);
        assertEquals(0, p[2], 1e-6);
        assertEquals(2, p[3], 0);
    }

    @Test
    void writesPngAndPfm(@TempDir Path dir) throws Exception {
        renderer.setRoot(new Group("root").add(new ShapeNode(Shapes.rectangle("q", -0.5f, -0.5f, 0.5f, 0.5f, 0),
                unlit(2f, 0.5f, 0f))));
        renderer.setCamera(GlTestSupport.unitCamera());
        Path png = dir.resolve("frame.png");
        Path pfm = dir.resolve("frame.pfm");
        target.writePng(png, SIZE, SIZE);
        target.writePfm(pfm, SIZE, SIZE);
        assertTrue(Files.size(png) > 0);
        int[] whc = new int[3];
        float[] rgb = ImageFiles.readPfm(pfm, whc);
        assertArrayEquals(new int[] {SIZE, SIZE, 3}, whc);
        // PFM keeps values above 1 (float target, no clamping); row 0 of the file is the top row
        int centre = (SIZE / 2 * SIZE + SIZE / 2) * 3;
        assertArrayEquals(new float[] {2f, 0.5f, 0f}, new float[] {rgb[centre], rgb[centre + 1], rgb[centre + 2]});
        java.awt.image.BufferedImage image = javax.imageio.ImageIO.read(png.toFile());
        assertEquals(0xFFFF8000, image.getRGB(SIZE / 2, SIZE / 2));
        assertEquals(0xFF1A334D, image.getRGB(0, 0));
    }

    /** Bounding box {minX, minY, maxX, maxY} of pixels that differ from the clear colour. */
    private static int[] coveredBox(float[] rgba) {
        int[] box = {Integer.MAX_VALUE, Integer.MAX_VALUE, -1, -1};
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                if (pixel(rgba, SIZE, x, y)[0] == 1f) {
                    box[0] = Math.min(box[0], x);
                    box[1] = Math.min(box[1], y);
                    box[2] = Math.max(box[2], x);
                    box[3] = Math.max(box[3], y);
                }
            }
        }
        return box;
    }

    private static double[] normalized(double... v) {
        double n = Math.sqrt(dot(v, v));
        return new double[] {v[0] / n, v[1] / n, v[2] / n};
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }
}
