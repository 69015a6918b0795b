package diffract.scene;

/**
 * A camera on a sphere around a target point: azimuth about the world y axis (0 = on the +z side), elevation above
 * the x-z plane, distance from the target. Mouse drags change the two angles; the wheel changes the distance.
 * Elevation stays within +-{@value #MAX_ELEVATION_DEG} degrees so the world's y axis can serve as the up vector.
 */
public record OrbitCamera(double azimuthDeg, double elevationDeg, double distance,
                          double targetX, double targetY, double targetZ) {
    public static final double MAX_ELEVATION_DEG = 89.0;
    public static final double MIN_DISTANCE = 0.2;
    public static final double MAX_DISTANCE = 50.0;

    public OrbitCamera {
        if (!(distance > 0) || !Double.isFinite(distance)) {
            throw new IllegalArgumentException("camera distance must be positive and finite, got " + distance);
        }
        elevationDeg = Math.max(-MAX_ELEVATION_DEG, Math.min(MAX_ELEVATION_DEG, elevationDeg));
        azimuthDeg = wrapDegrees(azimuthDeg);
    }

    /** Looking at the origin from {@code distance} on the +z axis. */
    public static OrbitCamera facingOrigin(double distance) {
        return new OrbitCamera(0, 0, distance, 0, 0, 0);
    }

    /** The eye point (x, y, z) in world coordinates. */
    public double[] eye() {
        double az = Math.toRadians(azimuthDeg);
        double el = Math.toRadians(elevationDeg);
        return new double[] {
            targetX + distance * Math.cos(el) * Math.sin(az),
            targetY + distance * Math.sin(el),
            targetZ + distance * Math.cos(el) * Math.cos(az)};
    }

    public OrbitCamera orbitedBy(double deltaAzimuthDeg, double deltaElevationDeg) {
        return new OrbitCamera(azimuthDeg + deltaAzimuthDeg, elevationDeg + deltaElevationDeg, distance,
                targetX, targetY, targetZ);
    }

    /** Distance times {@code factor}, kept within [{@value #MIN_DISTANCE}, {@value #MAX_DISTANCE}]. */
    public OrbitCamera zoomedBy(double factor) {
        double d = Math.max(MIN_DISTANCE, Math.min(MAX_DISTANCE, distance * factor));
        return new OrbitCamera(azimuthDeg, elevationDeg, d, targetX, targetY, targetZ);
    }

    static double wrapDegrees(double deg) {
        double wrapped = deg % 360.0;
        if (wrapped > 180.0) {
            wrapped -= 360.0;
        } else if (wrapped <= -180.0) {
            wrapped += 360.0;
        }
        return wrapped;
    }
}
