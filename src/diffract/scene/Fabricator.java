package diffract.scene;

import diffract.jrtr.Shape;
import diffract.util.Reporter;
import diffract.viewer.TermSource;
import diffract.viewer.ViewerModel;
import diffract.viewer.ViewerSetup;

import java.nio.file.Path;

/**
 * Builds what the viewer draws from a scene file, as the thesis' Fabricator does (003 sec. 1.2): each constants
 * manager turns its part of the scene into what the renderer needs (camera: {@link CameraManager}, light:
 * {@link LightManager}, patch and shader constants: {@link MaterialManager}, geometry: {@link ShapeManager}), and
 * the Fabricator puts them together into one {@link ViewerSetup}. Taylor terms come from the user cache; the first
 * use of a patch and N precomputes them, with progress on the reporter (stderr for the CLI).
 */
public final class Fabricator {
    /**
     * A scene ready to draw.
     *
     * @param setup the viewer's setup
     * @param image the picture's (or window's) size from the scene
     * @param terms where the Taylor terms of {@code setup.patch()} come from
     */
    public record Fabricated(Scene scene, ViewerSetup setup, Scene.ImageSize image, TermSource terms) {
        /** Loads (or precomputes) the terms the setup asks for and builds the viewer's model. */
        public ViewerModel model(Reporter reporter) {
            return ViewerModel.load(setup, terms, reporter);
        }
    }

    private Fabricator() {
    }

    public static Fabricated fabricate(Path sceneFile, Reporter reporter) {
        return fabricate(SceneFile.load(sceneFile), reporter);
    }

    public static Fabricated fabricate(Scene scene, Reporter reporter) {
        MaterialManager material = new MaterialManager(scene.material(), reporter);
        Shape shape = ShapeManager.shape(scene.shape());
        Scene.MaterialSpec m = scene.material();
        var species = m.pigmentation().species();
        var pigmentation = species != null ? StageManager.speciesPigment(scene, species) : material.pigmentation();
        ViewerSetup setup = new ViewerSetup(material.patch(), material.patchName(), shape, pigmentation,
                m.diffuseWeight(), material.settings(), CameraManager.orbit(scene.camera()),
                LightManager.light(scene.light()), m.exposure(), scene.mode(), m.pigmentationOn() && pigmentation != null,
                scene.camera().fieldOfViewDeg(), StageManager.stage(scene));
        return new Fabricated(scene, setup, scene.image(), material.termSource());
    }
}
