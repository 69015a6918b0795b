package diffract.scene;


import java.util.Locale;

/**
 * The camera's constants manager (thesis 003 sec. 1.2): turns the scene's pinhole camera (eye, look-at, up, field of
 * view) into the viewer's {@link OrbitCamera}. With d = eye - lookAt: distance = |d|, elevation = asin(d_y / |d|),
 * azimuth = atan2(d_x, d_z) (0 on the +z side, as {@link OrbitCamera#eye()} defines them), target = lookAt.
 * The orbit camera's up is the world y axis, so the scene's up must agree with it once both are projected off the
 * view direction (no roll); a camera that needs roll is refused, and the shape's transform can turn the scene.
 */
final class CameraManager {
    /** Up vectors within this angle of the orbit camera's (after projection) give the same picture to a pixel. */
    static final double MAX_ROLL_DEG = 0.5;

    private CameraManager() {
    }

    static OrbitCamera orbit(Scene.CameraSpec camera) {
        double[] d = offset(camera);
        double distance = length(d);
        return new OrbitCamera(Math.toDegrees(Math.atan2(d[0], d[2])), Math.toDegrees(Math.asin(d[1] / distance)),
                distance, camera.lookAt()[0], camera.lookAt()[1], camera.lookAt()[2]);
    }

    /** Why the eye cannot be an orbit camera's position, or null. */
    static String problem(Scene.CameraSpec camera) {
        double distance = length(offset(camera));
        if (!(distance >= OrbitCamera.MIN_DISTANCE && distance <= OrbitCamera.MAX_DISTANCE)) {
            return String.format(Locale.ROOT, "the eye is %.4g from lookAt; the viewer's camera keeps between %s and %s "
                    + "(scale the shape with \"transform\" instead)", distance, OrbitCamera.MIN_DISTANCE,
                    OrbitCamera.MAX_DISTANCE);
        }
        double elevation = Math.toDegrees(Math.asin(offset(camera)[1] / distance));
        if (Math.abs(elevation) > OrbitCamera.MAX_ELEVATION_DEG) {
            return String.format(Locale.ROOT, "the eye is %.2f degrees above or below lookAt; the viewer's camera keeps "
                    + "within +-%.0f degrees of the horizon (its up is the y axis)", elevation,
                    OrbitCamera.MAX_ELEVATION_DEG);
        }
        return null;
    }

    /** Why {@code up} would roll the camera away from the world y axis, or null. */
    static String upProblem(Scene.CameraSpec camera) {
        double[] view = normalized(offset(camera));
        double[] upSide = projectedOff(camera.up(), view);
        double[] ySide = projectedOff(new double[] {0, 1, 0}, view);
        if (length(upSide) < 1e-9) {
            return "is parallel to the view direction; use [0, 1, 0]";
        }
        double cos = dot(normalized(upSide), normalized(ySide));
        double rollDeg = Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, cos))));
        if (rollDeg > MAX_ROLL_DEG) {
            return String.format(Locale.ROOT, "rolls the camera by %.1f degrees; the viewer's camera keeps the world "
                    + "y axis up: use [0, 1, 0] and turn the shape with \"transform\" instead", rollDeg);
        }
        return null;
    }

    private static double[] offset(Scene.CameraSpec camera) {
        return new double[] {camera.eye()[0] - camera.lookAt()[0], camera.eye()[1] - camera.lookAt()[1],
            camera.eye()[2] - camera.lookAt()[2]};
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double length(double[] v) {
        return Math.sqrt(dot(v, v));
    }

    static double[] normalized(double[] v) {
        double l = length(v);
        return new double[] {v[0] / l, v[1] / l, v[2] / l};
    }

    private static double[] projectedOff(double[] v, double[] unit) {
        double d = dot(v, unit);
        return new double[] {v[0] - d * unit[0], v[1] - d * unit[1], v[2] - d * unit[2]};
    }
}
