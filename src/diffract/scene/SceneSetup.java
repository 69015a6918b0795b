package diffract.scene;

import diffract.jrtr.scenegraph.Shape;
import diffract.jrtr.scenegraph.VertexAttribute;
import diffract.optics.BrdfSettings;
import diffract.optics.patches.HeightField;
import diffract.optics.settings.InvalidSettingException;
import diffract.optics.settings.Quantity;
import diffract.pipeline.DiffractionPipeline;
import diffract.render.DiffractionShaders;
import diffract.render.Stage;
import diffract.util.UserInputException;

import java.awt.image.BufferedImage;

/**
 * What a scene draws, ready for the viewer and for {@code render}: the patch (as the pipeline that turns it into
 * terms, textures and materials), the shape covered with it, an optional pigmentation image, the BRDF settings, the
 * camera, the light and the display choices. The {@link Fabricator} makes it from a {@link Scene}.
 *
 * @param pipeline       the patch, mean-subtracted, and where its Taylor terms come from
 * @param shape          a mesh with position, normal, tangent and texcoord attributes; the tangent is the
 *                       height field's column (x) direction on the surface
 * @param pigmentation   display-encoded sRGB pigment colours over the texcoords, or null
 * @param diffuseWeight  w_d of 003 Algorithm 4: how much pigment is mixed in as ambient light
 * @param exposure       multiplies linear XYZ before display encoding
 * @param verticalFovDeg the camera's vertical field of view in degrees, in (0, 180)
 * @param stage          scales, environment light, ground and tone mapping around the surface
 *                       ({@link Stage#none()}: the plain surface)
 */
public record SceneSetup(DiffractionPipeline pipeline, Shape shape, BufferedImage pigmentation, double diffuseWeight,
                         BrdfSettings settings, OrbitCamera camera, LightDirection light, double exposure,
                         DisplayMode mode, boolean pigmentationOn, double verticalFovDeg, Stage stage) {
    /** The vertical field of view when a scene names none. */
    public static final double DEFAULT_VERTICAL_FOV_DEG = 45;

    public SceneSetup {
        if (pipeline == null || shape == null || settings == null || camera == null || light == null || mode == null
                || stage == null) {
            throw new NullPointerException("a setup needs a pipeline, shape, settings, camera, light, mode and stage");
        }
        for (VertexAttribute attribute : VertexAttribute.values()) {
            if (!shape.vertexData().has(attribute)) {
                throw new UserInputException("shape '" + shape.name() + "' has no " + attribute.glslName()
                        + " attribute; the diffraction shader needs positions, normals, tangents and texcoords");
            }
        }
        if (!settings.variant().runsOnGpu()) {
            throw new InvalidSettingException(Quantity.VARIANT, DiffractionShaders.cpuOnly(settings.variant()));
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

    /** The height field, mean-subtracted (its Taylor terms are what the shaders read). */
    public HeightField patch() {
        return pipeline.patch().meanSubtracted();
    }

    /** Where the patch came from (a file name, "elaphe-like"), for titles. */
    public String patchName() {
        return pipeline.patch().name();
    }

    /** The same setup with other settings (the command line's, or auto's choice). */
    public SceneSetup withSettings(BrdfSettings s) {
        return new SceneSetup(pipeline, shape, pigmentation, diffuseWeight, s, camera, light, exposure, mode,
                pigmentationOn, verticalFovDeg, stage);
    }

    /** The same setup shown at another exposure (the structural colour's gain). */
    public SceneSetup withExposure(double e) {
        return new SceneSetup(pipeline, shape, pigmentation, diffuseWeight, settings, camera, light, e, mode,
                pigmentationOn, verticalFovDeg, stage);
    }

    /** The same setup on another stage. */
    public SceneSetup withStage(Stage newStage) {
        return new SceneSetup(pipeline, shape, pigmentation, diffuseWeight, settings, camera, light, exposure, mode,
                pigmentationOn, verticalFovDeg, newStage);
    }
}
