package diffract.jrtr.textures;

import diffract.jrtr.GlTestSupport;
import diffract.jrtr.OffscreenTarget;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.scenegraph.ShaderProgram;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Uploads known values and reads them back through {@code texelFetch} in a shader that writes them to the
 * RGBA32F target, one texel per pixel.
 */
@Tag("gl")
class TextureTest {
    private static final int WIDTH = 8;
    private static final int HEIGHT = 4;
    private static final int LAYERS = 3;
    private static Renderer renderer;
    private static OffscreenTarget target;

    @TempDir
    static Path shaderDir;

    @BeforeAll
    static void createTarget() throws Exception {
        GlTestSupport.assumeOffscreenGl();
        GlTestSupport.write(shaderDir, "pass.vert", GlTestSupport.PASS_THROUGH_VERTEX);
        // pixel (x, y) with y = layer * HEIGHT + row shows texel (x, row) of that layer
        GlTestSupport.write(shaderDir, "array.frag", String.join("\n",
                "#version 330 core",
                "uniform sampler2DArray table;",
                "uniform int layerHeight;",
                "out vec4 fragColor;",
                "void main() {",
                "    ivec2 p = ivec2(gl_FragCoord.xy);",
                "    int layer = p.y / layerHeight;",
                "    vec2 texel = texelFetch(table, ivec3(p.x, p.y % layerHeight, layer), 0).rg;",
                "    fragColor = vec4(texel, float(layer), 1.0);",
                "}",
                ""));
        GlTestSupport.write(shaderDir, "table1d.frag", String.join("\n",
                "#version 330 core",
                "uniform sampler1D table;",
                "out vec4 fragColor;",
                "void main() { fragColor = texelFetch(table, int(gl_FragCoord.x), 0); }",
                ""));
        GlTestSupport.write(shaderDir, "image.frag", String.join("\n",
                "#version 330 core",
                "uniform sampler2D image;",
                "out vec4 fragColor;",
                "void main() { fragColor = texelFetch(image, ivec2(gl_FragCoord.xy), 0); }",
                ""));
        GlTestSupport.write(shaderDir, "two1d.frag", String.join("\n",
                "#version 330 core",
                "uniform sampler1D first;",
                "uniform sampler1D second;",
                "out vec4 fragColor;",
                "void main() { fragColor = vec4(texelFetch(first, 0, 0).r, texelFetch(second, 0, 0).r, 0.0, 1.0); }",
                ""));
        renderer = new Renderer(new Group("empty"), GlTestSupport.unitCamera(), GlTestSupport.rightAngleFrustum());
        target = new OffscreenTarget(renderer);
    }

    @AfterAll
    static void closeTarget() {
        if (target != null) {
            target.close();
        }
    }

    private static Material material(String fragment) {
        return new Material(ShaderProgram.fromDirectory(shaderDir, "pass.vert", fragment, Map.of()));
    }

    private static float[] draw(Material material, int width, int height) {
        renderer.setRoot(new Group("root").add(new ShapeNode(Shapes.fullScreenQuad(), material)));
        return target.renderRgba(width, height);
    }

    /** Values over many magnitudes and both signs, plus edge cases that must survive unchanged. */
    private static List<float[]> layers(long seed, float scale) {
        Random random = new Random(seed);
        List<float[]> layers = new ArrayList<>();
        for (int layer = 0; layer < LAYERS; layer++) {
            float[] values = new float[WIDTH * HEIGHT * 2];
            for (int i = 0; i < values.length; i++) {
                values[i] = (float) ((random.nextDouble() * 2 - 1) * Math.pow(10, random.nextInt(7) - 3)) * scale;
            }
            layers.add(values);
        }
        if (scale == 1) {
            float[] first = layers.get(0);
            first[0] = -0.0f;
            first[1] = Float.MAX_VALUE;
            first[2] = Float.MIN_NORMAL;
            first[3] = 1.0f / 3.0f;
        }
        return layers;
    }

    /** The texel the readback pixel (x, top-down row) shows: {layer, x, row within layer}. */
    private static float[] fetched(float[] rgba, int x, int layer, int row) {
        int glRow = layer * HEIGHT + row;
        int imageRow = LAYERS * HEIGHT - 1 - glRow;
        return GlTestSupport.pixel(rgba, WIDTH, x, imageRow);
    }

    @Test
    void rg32fArrayRoundTripsBitExactly() {
        List<float[]> layers = layers(42, 1);
        FloatTextureArray texture = new FloatTextureArray(WIDTH, HEIGHT, layers,
                FloatTextureArray.Precision.FLOAT32);
        assertFalse(texture.isUploaded());
        float[] rgba = draw(material("array.frag").setTexture("table", texture).setInt("layerHeight", HEIGHT),
                WIDTH, HEIGHT * LAYERS);
        assertTrue(texture.isUploaded());
        for (int layer = 0; layer < LAYERS; layer++) {
            for (int y = 0; y < HEIGHT; y++) {
                for (int x = 0; x < WIDTH; x++) {
                    float[] p = fetched(rgba, x, layer, y);
                    int i = (y * WIDTH + x) * 2;
                    String at = "layer " + layer + " texel (" + x + ", " + y + ")";
                    assertEquals(Float.floatToRawIntBits(layers.get(layer)[i]), Float.floatToRawIntBits(p[0]), at);
                    assertEquals(Float.floatToRawIntBits(layers.get(layer)[i + 1]), Float.floatToRawIntBits(p[1]), at);
                    assertEquals(layer, p[2], at);
                }
            }
        }
    }

    @Test
    void rg16fArrayRoundTripsWithinHalfPrecision() {
        List<float[]> layers = layers(7, 0.1f);
        FloatTextureArray texture = new FloatTextureArray(WIDTH, HEIGHT, layers,
                FloatTextureArray.Precision.FLOAT16);
        float[] rgba = draw(material("array.frag").setTexture("table", texture).setInt("layerHeight", HEIGHT),
                WIDTH, HEIGHT * LAYERS);
        boolean anyRounded = false;
        for (int layer = 0; layer < LAYERS; layer++) {
            for (int y = 0; y < HEIGHT; y++) {
                for (int x = 0; x < WIDTH; x++) {
                    float[] p = fetched(rgba, x, layer, y);
                    for (int c = 0; c < 2; c++) {
                        float expected = layers.get(layer)[(y * WIDTH + x) * 2 + c];
                        // half: 11 significant bits, relative error <= 2^-11; subnormals below 2^-14 are absolute
                        double tolerance = Math.max(Math.abs(expected) * Math.pow(2, -11), Math.pow(2, -24));
                        assertEquals(expected, p[c], tolerance, "layer " + layer + " (" + x + ", " + y + ")");
                        anyRounded |= expected != p[c];
                    }
                }
            }
        }
        assertTrue(anyRounded, "RG16F storage should round some float32 values");
    }

    @Test
    void rgba32fTableRoundTripsBitExactly() {
        int entries = 16;
        float[] table = new float[entries * 4];
        Random random = new Random(3);
        for (int i = 0; i < table.length; i++) {
            table[i] = (float) (random.nextGaussian() * 1e3);
        }
        float[] rgba = draw(material("table1d.frag").setTexture("table", new FloatTexture1D(table)), entries, 1);
        for (int i = 0; i < table.length; i++) {
            assertEquals(Float.floatToRawIntBits(table[i]), Float.floatToRawIntBits(rgba[i]), "float " + i);
        }
    }

    @Test
    void imageTextureKeepsBytesAndOrientation() {
        BufferedImage image = new BufferedImage(4, 2, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 4; x++) {
                image.setRGB(x, y, (0xFF << 24) | (x * 60 << 16) | (y * 200 << 8) | 17);
            }
        }
        float[] rgba = draw(material("image.frag").setTexture("image", new Texture2D(image)), 4, 2);
        // with bottom-up upload and top-down readback, the rendered picture equals the image
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 4; x++) {
                float[] p = GlTestSupport.pixel(rgba, 4, x, y);
                assertEquals(x * 60 / 255f, p[0], 1e-6, "red at " + x + "," + y);
                assertEquals(y * 200 / 255f, p[1], 1e-6, "green at " + x + "," + y);
                assertEquals(17 / 255f, p[2], 1e-6);
                assertEquals(1f, p[3], 1e-6);
            }
        }
    }

    @Test
    void texturesUploadOnceAcrossFrames() {
        FloatTexture1D table = new FloatTexture1D(new float[] {1, 2, 3, 4});
        Material material = material("table1d.frag").setTexture("table", table);
        draw(material, 1, 1);
        int name = target.withContext(gl -> table.glTexture());
        assertTrue(name > 0);
        draw(material, 1, 1);
        assertEquals(name, (int) target.withContext(gl -> table.glTexture()), "same GL texture object, no re-upload");
    }

    /**
     * Two textures of one target, both uploaded by their first draw: the second's upload must not undo the first's
     * binding (an upload binds on unit 0, where the first texture already sits for this draw).
     */
    @Test
    void aFirstDrawUploadsEveryTextureWithoutLosingABinding() {
        Material material = material("two1d.frag").setTexture("first", new FloatTexture1D(new float[] {3, 0, 0, 0}))
                .setTexture("second", new FloatTexture1D(new float[] {5, 0, 0, 0}));
        float[] rgba = draw(material, 1, 1);
        assertEquals(3f, rgba[0], "the texture on unit 0");
        assertEquals(5f, rgba[1], "the texture on unit 1");
    }

    /** A material names only uniforms its program declares, and sets every uniform the program uses. */
    @Test
    void unknownAndUnsetUniformsAreRefused() {
        FloatTexture1D table = new FloatTexture1D(new float[] {1, 2, 3, 4});
        Material typo = material("table1d.frag").setTexture("table", table).setFloat("tabel", 1);
        assertThrows(IllegalArgumentException.class, () -> draw(typo, 1, 1));
        Material unset = material("two1d.frag").setTexture("first", table);
        assertThrows(IllegalStateException.class, () -> draw(unset, 1, 1));
    }
}
