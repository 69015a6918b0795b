package diffract.scene;

import diffract.geometry.SnakeMesh;
import diffract.geometry.SnakeSpecies;
import diffract.geometry.TangentSource;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.Levelling;
import diffract.optics.patches.ProceduralPatches;

import java.nio.file.Path;

/**
 * A scene file, parsed and checked (every range, every file): what {@link Fabricator} turns into a viewer setup.
 * The schema is {@code docs/guide/scene-format.md}; {@link SceneFile} reads it.
 *
 * @param source the file it was read from (messages name it)
 */
public record Scene(Path source, ImageSize image, CameraSpec camera, LightSpec light, ShapeSpec shape,
                    MaterialSpec material, DisplayMode mode, StageSpec stage) {
    /** The same scene with another material. */
    public Scene withMaterial(MaterialSpec m) {
        return new Scene(source, image, camera, light, shape, m, mode, stage);
    }

    /** Pixels of the rendered picture (the window's size for {@code view}). */
    public record ImageSize(int width, int height) {
        /** Pixels per side a picture may have, in scene files and on every command ({@code --size}). */
        public static final int MIN_PX = 1;
        public static final int MAX_PX = 8192;
    }

    /** A pinhole camera: eye point, the point it looks at, the up direction, the vertical field of view. */
    public record CameraSpec(double[] eye, double[] lookAt, double[] up, double fieldOfViewDeg) {
    }

    /** A distant light: the world direction towards it (any length) and its spectrum (D65 only). */
    public record LightSpec(double[] towardsLight, String spectrum) {
    }

    /** Translation, rotation (degrees about x, then y, then z) and uniform scale, applied scale first. */
    public record Transform(double[] translate, double[] rotateDeg, double scale) {
        public static Transform identity() {
            return new Transform(new double[3], new double[3], 1.0);
        }
    }

    /** The shape kinds by their scene-file spelling. */
    public enum ShapeKind {
        SNAKE, OBJ, PLANE, SPHERE, CYLINDER;

        public String sceneName() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /**
     * @param file     the OBJ file (kind obj), else null
     * @param tangents where the patch's x axis on the surface comes from (obj, plane, sphere, cylinder)
     * @param ridges    how the patch lies on the snake (kind snake)
     * @param pose      the snake's pose (kind snake)
     * @param scales    the scale lattice laid on the snake, or null for a smooth skin
     * @param normalMap an OBJ shape's tangent-space normal map, or null
     */
    public record ShapeSpec(ShapeKind kind, Path file, TangentSource tangents, SnakeMesh.RidgeDirection ridges,
                            Transform transform, SnakeMesh.Pose pose, StageSpec.ScalesSpec scales,
                            StageSpec.NormalMapSpec normalMap) {
    }

    /** A height field: a file, or a procedural patch. */
    public sealed interface PatchSpec {
    }

    /**
     * A height-field file (PNG/BMP/TIFF, text matrix, .gsf, .gwy, .ibw) with the sizes images and text need, the
     * channel of a multi-channel file (null: the first in a length unit) and the levelling before use.
     */
    public record FilePatch(Path file, Double maxHeightUm, Double pixelSizeUm, String channel, Levelling levelling)
            implements PatchSpec {
    }

    /**
     * A patch made by code.
     *
     * @param name the catalogue name it starts from ({@link diffract.optics.patches.PatchCatalogue})
     */
    public record ProceduralPatch(String name, ProceduralPatches.Spec spec) implements PatchSpec {
    }

    /**
     * The pigmentation image: none, the procedural corn-snake pattern, an sRGB image file, or a species' pattern
     * painted on the snake's scales.
     */
    public record PigmentationSpec(boolean procedural, Path file, SnakeSpecies species) {
        public static PigmentationSpec none() {
            return new PigmentationSpec(false, null, null);
        }

        public static PigmentationSpec proceduralPattern() {
            return new PigmentationSpec(true, null, null);
        }

        public static PigmentationSpec imageFile(Path image) {
            return new PigmentationSpec(false, image, null);
        }

        public static PigmentationSpec ofSpecies(SnakeSpecies s) {
            return new PigmentationSpec(false, null, s);
        }

        public boolean present() {
            return procedural || file != null || species != null;
        }
    }

    /**
     * Everything about the surface's reflectance and its display.
     *
     * @param settings       the BRDF settings
     * @param orderTolerance when not null, N is the smallest order whose Lagrange bound meets it for the patch at
     *                       the shortest wavelength (001 sec. 3.3.3), instead of the settings' N
     */
    public record MaterialSpec(PatchSpec patch, BrdfSettings settings, Double orderTolerance,
                               PigmentationSpec pigmentation, boolean pigmentationOn, double diffuseWeight,
                               double exposure) {
        public MaterialSpec withSettings(BrdfSettings s) {
            return new MaterialSpec(patch, s, orderTolerance, pigmentation, pigmentationOn, diffuseWeight, exposure);
        }

        public MaterialSpec withExposure(double e) {
            return new MaterialSpec(patch, settings, orderTolerance, pigmentation, pigmentationOn, diffuseWeight, e);
        }
    }
}
