package diffract.scene;

import diffract.geometry.SnakeMesh;
import diffract.geometry.TangentSource;
import diffract.optics.ProceduralPatches;
import diffract.optics.Variant;
import diffract.viewer.DisplayMode;

import java.nio.file.Path;

/**
 * A scene file, parsed and checked (every range, every file): what {@link Fabricator} turns into a viewer setup.
 * The schema is {@code docs/scene-format.md}; {@link SceneFile} reads it.
 *
 * @param source the file it was read from (messages name it)
 */
public record Scene(Path source, ImageSize image, CameraSpec camera, LightSpec light, ShapeSpec shape,
                    MaterialSpec material, DisplayMode mode, StageSpec stage) {
    /** A scene without staging keys. */
    public Scene(Path source, ImageSize image, CameraSpec camera, LightSpec light, ShapeSpec shape,
                 MaterialSpec material, DisplayMode mode) {
        this(source, image, camera, light, shape, material, mode, StageSpec.none());
    }

    /** Pixels of the rendered picture (the window's size for {@code view}). */
    public record ImageSize(int width, int height) {
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
     * @param ridges   how the patch lies on the snake (kind snake)
     */
    public record ShapeSpec(ShapeKind kind, Path file, TangentSource tangents, SnakeMesh.RidgeDirection ridges,
                            Transform transform, SnakeMesh.Pose pose, StageSpec.ScalesSpec scales,
                            StageSpec.NormalMapSpec normalMap) {
        /** A smooth snake in S-bends, or another kind, without a normal map. */
        public ShapeSpec(ShapeKind kind, Path file, TangentSource tangents, SnakeMesh.RidgeDirection ridges,
                         Transform transform) {
            this(kind, file, tangents, ridges, transform, SnakeMesh.Pose.S_CURVE, null, null);
        }
    }

    /** A height field: a file, or a procedural patch. */
    public sealed interface PatchSpec {
    }

    /** A height-field file (PNG/BMP/TIFF, text matrix, .gsf) with the sizes images and text need. */
    public record FilePatch(Path file, Double maxHeightUm, Double pixelSizeUm) implements PatchSpec {
    }

    /** A patch made by code. */
    public record ProceduralPatch(ProceduralPatches.Spec spec) implements PatchSpec {
    }

    /**
     * The pigmentation image: none, the procedural corn-snake pattern, an sRGB image file, or a species' pattern
     * painted on the snake's scales.
     */
    public record PigmentationSpec(boolean procedural, Path file, diffract.geometry.SnakeSpecies species) {
        public PigmentationSpec(boolean procedural, Path file) {
            this(procedural, file, null);
        }

        public static PigmentationSpec none() {
            return new PigmentationSpec(false, null);
        }

        public boolean present() {
            return procedural || file != null || species != null;
        }
    }

    /**
     * Everything about the surface's reflectance and its display. Exactly one of {@code taylorTerms} and
     * {@code tolerance} is set.
     */
    public record MaterialSpec(PatchSpec patch, Variant variant, Integer taylorTerms, Double tolerance,
                               double lambdaMinNm, double lambdaMaxNm, double lambdaStepNm, int windowRadius,
                               double sigmaSpatialUm, double refractiveIndex, PigmentationSpec pigmentation,
                               boolean pigmentationOn, double diffuseWeight, double exposure) {
    }
}
