package diffract.scene;


/**
 * The light's constants manager: the scene's direction towards the light becomes the viewer's
 * {@link LightDirection}, theta = acos(z / |d|) from the world +z axis and phi = atan2(y, x) from +x towards +y
 * (0 when the light is on the z axis), the inverse of {@link LightDirection#direction()}.
 */
final class LightManager {
    private LightManager() {
    }

    static LightDirection light(Scene.LightSpec light) {
        return new LightDirection(thetaDeg(light.towardsLight()), phiDeg(light.towardsLight()));
    }

    static double thetaDeg(double[] towards) {
        double cos = towards[2] / CameraManager.length(towards);
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, cos))));
    }

    static double phiDeg(double[] towards) {
        return Math.hypot(towards[0], towards[1]) < 1e-12 * CameraManager.length(towards) ? 0
                : Math.toDegrees(Math.atan2(towards[1], towards[0]));
    }
}
