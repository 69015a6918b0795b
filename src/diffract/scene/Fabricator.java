package diffract.scene;

import diffract.jrtr.scenegraph.Shape;
import diffract.optics.settings.OrderWeights;
import diffract.optics.validity.ScalarValidity;
import diffract.util.Reporter;

import java.nio.file.Path;

/**
 * Builds what a scene draws, as the thesis' Fabricator does (003 sec. 1.2): each constants manager turns its part
 * of the scene into what the renderer needs (camera: {@link CameraManager}, light: {@link LightManager}, patch and
 * shader constants: {@link MaterialManager}, geometry: {@link ShapeManager}), and the Fabricator puts them together
 * into one {@link SceneSetup}. Taylor terms come from the user cache; the first use of a patch and N precomputes
 * them, with progress on the reporter (stderr for the CLI).
 */
public final class Fabricator {
    private Fabricator() {
    }

    public static SceneSetup fabricate(Path sceneFile, Reporter reporter) {
        return fabricate(SceneFile.load(sceneFile), reporter);
    }

    /**
     * Where the patch lies outside the region where the scalar model is within a visible difference of Maxwell's
     * equations (docs/measurements/validity.md), one line says how far, and what solves it rigorously, at the light's polar angle.
     */
    private static void warnWhereTheScalarModelFails(MaterialManager material, Scene scene, Reporter reporter) {
        double[] d = scene.light().towardsLight();
        double thetaDeg = Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, d[2] / Math.sqrt(d[0] * d[0] + d[1] * d[1]
                + d[2] * d[2])))));
        if (material.settings().rigorous().orders() == OrderWeights.RIGOROUS) {
            return; // the lobes take their orders from Maxwell's equations
        }
        ScalarValidity.Estimate e = ScalarValidity.shipped().estimate(material.field(), Math.min(90, thetaDeg),
                material.settings().illumination().gain());
        if (e.visible()) {
            String fix = material.settings().variant().takesRigorousOrders() ? "; \"orders\": \"rigorous\" in the "
                    + "material takes the lobes' orders from Maxwell's equations (docs/design/rigorous.md)" : "";
            reporter.warn(e.describe() + ": the rigorous method (diffract orders, diffract brdfmap with the variant "
                    + "rigorous) solves 1-D patches such as the snake patches' ridges alone, elaphe-ridge and "
                    + "xenopeltis-ridge, and 2-D cells of about a micrometre" + fix);
        }
    }

    public static SceneSetup fabricate(Scene scene, Reporter reporter) {
        MaterialManager material = new MaterialManager(scene.material(), reporter);
        warnWhereTheScalarModelFails(material, scene, reporter);
        Shape shape = ShapeManager.shape(scene.shape());
        Scene.MaterialSpec m = scene.material();
        var species = m.pigmentation().species();
        var pigmentation = species != null ? StageManager.speciesPigment(scene, species) : material.pigmentation();
        return new SceneSetup(material.pipeline(), shape, pigmentation, m.diffuseWeight(), material.settings(),
                CameraManager.orbit(scene.camera()), LightManager.light(scene.light()), m.exposure(), scene.mode(),
                m.pigmentationOn() && pigmentation != null, scene.camera().fieldOfViewDeg(), StageManager.stage(scene));
    }
}
