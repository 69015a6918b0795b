package diffract.viewer;

import diffract.jrtr.Shape;
import diffract.jrtr.VertexAttribute;
import diffract.optics.BrdfSettings;
import diffract.optics.HeightField;
import diffract.optics.Variant;
import diffract.render.DiffractionShaders;
import diffract.render.Stage;
import diffract.util.UserInputException;

import java.awt.image.BufferedImage;
import java.util.Objects;

/**
 * What the viewer starts with, the one thing a scene file has to produce: the patch and the shape covered with it,
 * an optional pigmentation image, the BRDF settings, the camera, the light and the display choices. The command
 * line fills it from options today; a scene loader fills it from a file later (and options may then override).
 *
 * @param patch          the height field, mean-subtracted (its Taylor terms are what the shaders read)
 * @param patchName      where the patch came from (a file name, "elaphe-like"), for titles and the term cache
 * @param shape          a mesh with position, normal, tangent and texcoord attributes; the tangent is the
 *                       height field's column (x) direction on the surface
 * @param pigmentation   display-encoded sRGB pigment colours over the texcoords, or null
 * @param diffuseWeight  w_d of 003 Algorithm 4: how much pigment is mixed in as ambient light
 * @param exposure       multiplies linear XYZ before display encoding
 * @param verticalFovDeg the camera's vertical field of view in degrees, in (0, 180)
 * @param stage          scales, environment light, ground and tone mapping around the surface
 *                       ({@link Stage#none()}: the plain surface)
 */
public record ViewerSetup(HeightField patch, String patchName, Shape shape, BufferedImage pigmentation,
                          double diffuseWeight, BrdfSettings settings, OrbitCamera camera, LightDirection light,
                          double exposure, DisplayMode mode, boolean pigmentationOn,
                          double verticalFovDeg, Stage stage) {
    /** A setup without staging ({@link Stage#none()}). */
    public ViewerSetup(HeightField patch, String patchName, Shape shape, BufferedImage pigmentation,
                       double diffuseWeight, BrdfSettings settings, OrbitCamera camera, LightDirection light,
                       double exposure, DisplayMode mode, boolean pigmentationOn, double verticalFovDeg) {
        this(patch, patchName, shape, pigmentation, diffuseWeight, settings, camera, light, exposure, mode,
                pigmentationOn, verticalFovDeg, Stage.none());
    }

    /** This setup on another stage. */
    public ViewerSetup withStage(Stage newStage) {
        return new ViewerSetup(patch, patchName, shape, pigmentation, diffuseWeight, settings, camera, light, exposure,
                mode, pigmentationOn, verticalFovDeg, newStage);
    }

    /** The field of view the viewer had before scene files could choose one. */
    public static final double DEFAULT_VERTICAL_FOV_DEG = 45;

    /** A setup with the default field of view ({@value #DEFAULT_VERTICAL_FOV_DEG} degrees). */
    public ViewerSetup(HeightField patch, String patchName, Shape shape, BufferedImage pigmentation,
                       double diffuseWeight, BrdfSettings settings, OrbitCamera camera, LightDirection light,
                       double exposure, DisplayMode mode, boolean pigmentationOn) {
        this(patch, patchName, shape, pigmentation, diffuseWeight, settings, camera, light, exposure, mode,
                pigmentationOn, DEFAULT_VERTICAL_FOV_DEG);
    }

    public ViewerSetup {
        Objects.requireNonNull(stage, "stage");
        Objects.requireNonNull(patch, "patch");
        Objects.requireNonNull(patchName, "patchName");
        Objects.requireNonNull(shape, "shape");
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(camera, "camera");
        Objects.requireNonNull(light, "light");
        Objects.requireNonNull(mode, "mode");
        if (Math.abs(patch.meanUm()) > 1e-9 * Math.max(1.0, patch.maxAbsHeightUm())) {
            throw new IllegalArgumentException("the viewer needs a mean-subtracted patch (HeightField.meanSubtracted)");
        }
        for (VertexAttribute attribute : VertexAttribute.values()) {
            if (!shape.vertexData().has(attribute)) {
                throw new UserInputException("shape '" + shape.name() + "' has no " + attribute.glslName()
                        + " attribute; the diffraction shader needs positions, normals, tangents and texcoords");
            }
        }
        if (settings.variant() == Variant.REFERENCE) {
            throw new UserInputException(DiffractionShaders.REFERENCE_IS_CPU_ONLY);
        }
        if (!(exposure > 0) || !Double.isFinite(exposure)) {
            throw new UserInputException("exposure must be a positive number, got " + exposure);
        }
        if (!(diffuseWeight >= 0 && diffuseWeight <= 1)) {
            throw new UserInputException("the diffuse weight w_d must be in [0, 1], got " + diffuseWeight);
        }
        if (!(verticalFovDeg > 0 && verticalFovDeg < 180)) {
            throw new UserInputException("the field of view must be in (0, 180) degrees, got " + verticalFovDeg);
        }
        if (pigmentationOn && pigmentation == null) {
            throw new UserInputException("pigmentation is switched on but no pigmentation image was given");
        }
    }
}
