package diffract.viewer.frame;

import diffract.scene.DisplayMode;
import diffract.scene.OrbitCamera;
import diffract.scene.Scene;
import diffract.viewer.ViewerState;

import java.awt.Dimension;

/**
 * The scene that draws what the view shows: the scene the view was opened from with the view's state in place of its
 * own (the settings, the orbit camera, the light, the exposure, the pigment switch, the mode) and the view's size as
 * its image, so that {@code render} of it draws the view's refined picture ({@code ViewerFrameTest}).
 */
final class ViewScene {
    private ViewScene() {
    }

    static Scene of(Scene base, ViewerState state, Dimension viewSize) {
        OrbitCamera orbit = state.view().camera();
        Scene.CameraSpec camera = new Scene.CameraSpec(orbit.eye(),
                new double[] {orbit.targetX(), orbit.targetY(), orbit.targetZ()}, base.camera().up(),
                base.camera().fieldOfViewDeg());
        var d = state.view().light().direction();
        Scene.LightSpec light = new Scene.LightSpec(new double[] {d.x(), d.y(), d.z()}, base.light().spectrum());
        Scene.MaterialSpec m = base.material();
        boolean pigment = state.view().pigmentationOn() && m.pigmentation().present();
        Scene.MaterialSpec material = new Scene.MaterialSpec(m.patch(), state.settings(), null, m.pigmentation(),
                pigment, m.diffuseWeight(), state.view().exposure());
        Scene.ImageSize image = new Scene.ImageSize(Math.max(1, viewSize.width), Math.max(1, viewSize.height));
        DisplayMode mode = state.view().mode();
        return new Scene(base.source(), image, camera, light, base.shape(), material, mode, base.stage());
    }
}
