package diffract.render;

import diffract.colour.ColourPath;
import diffract.colour.Xyz;
import diffract.jrtr.scenegraph.Camera;
import diffract.jrtr.textures.FloatTextureArray;
import diffract.jrtr.scenegraph.Frustum;
import diffract.jrtr.GlTestSupport;
import diffract.jrtr.scenegraph.Group;
import diffract.jrtr.scenegraph.LightNode;
import diffract.jrtr.scenegraph.Material;
import diffract.jrtr.OffscreenTarget;
import diffract.jrtr.Renderer;
import diffract.jrtr.scenegraph.Shape;
import diffract.jrtr.scenegraph.ShapeNode;
import diffract.jrtr.scenegraph.Shapes;
import diffract.jrtr.textures.Texture2D;
import diffract.jrtr.scenegraph.TransformGroup;
import diffract.jrtr.scenegraph.VertexData;
import diffract.optics.BrdfSettings;
import diffract.optics.DiffractionBrdf;
import diffract.optics.patches.Direction;
import diffract.optics.patches.HeightField;
import diffract.optics.spectra.TaylorTerms;
import diffract.optics.Variant;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;

import javax.vecmath.AxisAngle4f;
import javax.vecmath.Matrix4f;
import javax.vecmath.Point3f;
import javax.vecmath.Vector3f;
import java.awt.image.BufferedImage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * No pixel is ever NaN or Inf: grazing light (theta_i = 89.9 degrees), the exact specular direction (where
 * (u, v) = 0: NMM's fallback, PQ's 0/0 Dirichlet quotient, sinc(0)) and degenerate tangent frames; and the mesh
 * path (003 Algorithm 2) sees the same BRDF as the maps.
 */
@Tag("gl")
class GpuFinitenessTest {
    static java.util.stream.Stream<Variant> thesisMethods() {
        return java.util.stream.Stream.of(Variant.FLSS, Variant.NMM, Variant.PQ);
    }


    /**
     * Odd map sizes put a pixel centre exactly on the mirror direction: S = 33 has x = y = 0 at pixel (16, 16)
     * (normal incidence) and x = -16/33 at column 8, the mirror direction of sin theta_i = 16/33 (theta_i = 29
     * degrees; in float32 u is then 0 or an ulp, 3e-8).
     */
    @ParameterizedTest
    @org.junit.jupiter.params.provider.MethodSource("thesisMethods")
    void everyPixelIsFiniteAtGrazingLightAndAtTheExactSpecularDirection(Variant variant) {
        GlTestSupport.assumeOffscreenGl();
        for (HeightField patch : new HeightField[] {RenderTestSupport.BLAZED, RenderTestSupport.ELAPHE_LIKE}) {
            TaylorTerms terms = RenderTestSupport.terms(patch);
            BrdfSettings settings = RenderTestSupport.settings(variant);
            DiffractionBrdf cpu = DiffractionBrdf.create(settings, patch, terms);
            try (GpuBrdfMap gpu = new GpuBrdfMap(terms, settings)) {
                String where = variant + " " + RenderTestSupport.name(patch);
                assertFiniteAndNonNegative(gpu.xyz(Direction.fromSphericalDeg(89.9, 0), 32), where + " at 89.9 deg");
                assertFiniteAndNonNegative(gpu.xyz(Direction.fromSphericalDeg(89.9, 90), 32), where + " at 89.9 deg");
                assertFiniteAndNonNegative(gpu.monochromatic(Direction.fromSphericalDeg(89.9, 0), 550, 32),
                        where + " at 89.9 deg, 550 nm");

                Direction normal = Direction.fromSphericalDeg(0, 0);
                float[] centre = gpu.xyz(normal, 33);
                assertFiniteAndNonNegative(centre, where + " at normal incidence");
                assertSpecularPixel(centre, 33, 16, 16, cpu.xyz(normal, new Direction(0, 0, 1)), where);
                assertFiniteAndNonNegative(gpu.monochromatic(normal, 550, 33), where + " at normal incidence, 550 nm");

                Direction oblique = Direction.fromSphericalDeg(Math.toDegrees(Math.asin(16.0 / 33)), 0);
                float[] map = gpu.xyz(oblique, 33);
                assertFiniteAndNonNegative(map, where + " at 29 deg");
                assertSpecularPixel(map, 33, 8, 16, cpu.xyz(oblique, Direction.fromProjected(-16.0 / 33, 0)),
                        where + " at 29 deg");
            }
        }
    }

    private static void assertSpecularPixel(float[] xyz, int size, int column, int row, Xyz expected, String where) {
        int p = 3 * (row * size + column);
        assertTrue(expected.y() > 1e-3, where + ": the CPU's specular pixel is dark: " + expected);
        assertEquals(expected.y(), xyz[p + 1], 1e-3 * expected.y(), where + ": specular pixel (" + column + ", " + row
                + ")");
    }

    private static void assertFiniteAndNonNegative(float[] values, String where) {
        for (int i = 0; i < values.length; i++) {
            assertTrue(Float.isFinite(values[i]) && values[i] >= 0, where + ": value " + i + " is " + values[i]);
        }
    }

    /**
     * A square [-1, 1]^2 seen from (0, 0, 1) through a 90 degree frustum fills a 33 x 33 image; pixel (i, j)
     * shows world point (x, y, 0) with x = 2 (i + 0.5) / 33 - 1, y = 1 - 2 (j + 0.5) / 33. Rotated by 90 degrees
     * about z, its tangent (the height field's x axis) points along world y, so a light from world +x lies along
     * the tangent frame's -y. The fragments' display sRGB must be the CPU's XYZ of the same (omega_i, omega_r)
     * through ColourPath.SRGB (to 2/255), which checks Algorithm 2's frame, signs and interpolation.
     */
    @Test
    void meshPathShowsTheSameBrdfAsTheCpuInTheTangentFrame() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.ELAPHE_LIKE;
        TaylorTerms terms = RenderTestSupport.terms(patch);
        BrdfSettings settings = RenderTestSupport.settings(Variant.FLSS);
        DiffractionTextures textures = DiffractionTextures.of(terms, settings);
        float exposure = 20;
        Material material = DiffractionMaterials.surface(textures, settings, exposure, null, 0);
        Vector3f towardsLight = new Vector3f(0.5f, 0, 1);
        towardsLight.normalize();
        int size = 33;
        float[] rgba = render(material, towardsLight, Shapes.rectangle("square", -1, -1, 1, 1, 0), size);
        // tangent frame: T = world y, B = N x T = world -x, N = world z
        Direction wi = new Direction(0, -towardsLight.x, towardsLight.z);
        DiffractionBrdf cpu = DiffractionBrdf.create(settings, patch, terms);
        int lit = assertCpuColours(rgba, size, 4, cpu, wi, exposure);
        assertTrue(lit >= 3, "only " + lit + " of the checked pixels are lit");
    }

    /**
     * Every {@code step}-th pixel of {@link #render}'s square (rotated 90 degrees about z) shows the CPU's display
     * sRGB of its (omega_i, omega_r) to 2/255; returns how many of them are lit (G above 0.05).
     */
    static int assertCpuColours(float[] rgba, int size, int step, DiffractionBrdf cpu, Direction wi, double exposure) {
        int lit = 0;
        for (int j = 0; j < size; j += step) {
            for (int i = 0; i < size; i += step) {
                double x = 2.0 * (i + 0.5) / size - 1;
                double y = 1 - 2.0 * (j + 0.5) / size;
                double len = Math.sqrt(x * x + y * y + 1);
                Direction wr = new Direction(-y / len, x / len, 1 / len); // (-x, -y, 1) in (T, B, N)
                float[] expected = ColourPath.SRGB.displayRgb(cpu.xyz(wi, wr).scaled(exposure));
                int p = 4 * (j * size + i);
                for (int k = 0; k < 3; k++) {
                    assertEquals(expected[k], rgba[p + k], 2.0 / 255, "pixel (" + i + ", " + j + ") channel " + k);
                }
                lit += expected[1] > 0.05 ? 1 : 0;
            }
        }
        return lit;
    }

    /** Pigmentation blending and a degenerate frame (tangent parallel to the normal) stay finite and in [0, 1]. */
    @Test
    void meshPathWithPigmentationAndDegenerateTangentsStaysFinite() {
        GlTestSupport.assumeOffscreenGl();
        HeightField patch = RenderTestSupport.BLAZED;
        BrdfSettings settings = RenderTestSupport.settings(Variant.NMM);
        DiffractionTextures textures = DiffractionTextures.of(RenderTestSupport.terms(patch), settings);
        BufferedImage pigment = new BufferedImage(4, 4, BufferedImage.TYPE_INT_ARGB);
        for (int y = 0; y < 4; y++) {
            for (int x = 0; x < 4; x++) {
                pigment.setRGB(x, y, 0xff000000 | (60 * x) << 16 | (60 * y) << 8 | 0x40);
            }
        }
        Material blended = DiffractionMaterials.surface(textures, settings, 10, new Texture2D(pigment), 0.3f);
        Vector3f light = new Vector3f(0, 0, 1); // towards the camera: the centre is the exact specular direction
        float[] withPigment = render(blended, light, Shapes.rectangle("square", -1, -1, 1, 1, 0), 33);
        assertDisplayRange(withPigment, "pigmentation");
        int p = 4 * (16 * 33 + 16);
        assertTrue(withPigment[p] + withPigment[p + 1] + withPigment[p + 2] > 0.1, "the specular centre is dark");

        Shape degenerate = new Shape("degenerate", VertexData.builder(4)
                .positions(-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0)
                .normals(0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1)
                .tangents(0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1)
                .texcoords(0, 0, 1, 0, 1, 1, 0, 1)
                .indices(0, 1, 2, 0, 2, 3).build());
        float[] black = render(DiffractionMaterials.surface(textures, settings, 10, null, 0), light, degenerate, 16);
        assertDisplayRange(black, "degenerate tangent frame");
    }

    private static void assertDisplayRange(float[] rgba, String where) {
        for (int i = 0; i < rgba.length; i++) {
            assertTrue(Float.isFinite(rgba[i]) && rgba[i] >= 0 && rgba[i] <= 1, where + ": value " + i + " is "
                    + rgba[i]);
        }
    }

    static float[] render(Material material, Vector3f towardsLight, Shape shape, int size) {
        Matrix4f quarterTurn = new Matrix4f();
        quarterTurn.set(new AxisAngle4f(0, 0, 1, (float) (Math.PI / 2)));
        Group root = new Group("scene").add(
                new TransformGroup("turned", quarterTurn).add(new ShapeNode(shape, material)),
                new LightNode("sun", towardsLight, new Vector3f(1, 1, 1)));
        Camera camera = new Camera(new Point3f(0, 0, 1), new Point3f(0, 0, 0), new Vector3f(0, 1, 0));
        try (OffscreenTarget target = new OffscreenTarget(new Renderer(root, camera, new Frustum(0.1f, 10f, 1f, 90f)))) {
            return target.renderRgba(size, size);
        }
    }
}
