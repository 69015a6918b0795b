package diffract.scene;

import diffract.jrtr.Shape;
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

    public static SceneSetup fabricate(Scene scene, Reporter reporter) {
        MaterialManager material = new MaterialManager(scene.material(), reporter);
        Shape shape = ShapeManager.shape(scene.shape());
        Scene.MaterialSpec m = scene.material();
        var species = m.pigmentation().species();
        var pigmentation = species != null ? StageManager.speciesPigment(scene, species) : material.pigmentation();
        return new SceneSetup(material.pipeline(), shape, pigmentation, m.diffuseWeight(), material.settings(),
                CameraManager.orbit(scene.camera()), LightManager.light(scene.light()), m.exposure(), scene.mode(),
                m.pigmentationOn() && pigmentation != null, scene.camera().fieldOfViewDeg(), StageManager.stage(scene));
    }
}
