package diffract.scene;

import diffract.optics.patches.Direction;

/**
 * The direction towards the (distant) light in world coordinates: polar angle theta_i from the world +z axis (the
 * side the camera starts on) and azimuth phi_i from +x towards +y. A plane facing +z with tangents along +x has its
 * tangent frame equal to the world frame, so there these angles are exactly {@code brdfmap}'s --theta-i/--phi-i,
 * and the BRDF-map mode uses them as tangent-frame angles.
 */
public record LightDirection(double thetaDeg, double phiDeg) {
    /** Grazing light gives a zero gain factor; stop just short of the horizon. */
    public static final double MAX_THETA_DEG = 89.0;
    /** {@link #MAX_THETA_DEG} as options' help and messages write it. */
    public static final String MAX_THETA_DEG_TEXT = "89";

    public LightDirection {
        if (!Double.isFinite(thetaDeg) || !Double.isFinite(phiDeg)) {
            throw new IllegalArgumentException("light angles must be finite");
        }
        thetaDeg = Math.max(0.0, Math.min(MAX_THETA_DEG, thetaDeg));
        phiDeg = OrbitCamera.wrapDegrees(phiDeg);
    }

    public LightDirection movedBy(double deltaThetaDeg, double deltaPhiDeg) {
        return new LightDirection(thetaDeg + deltaThetaDeg, phiDeg + deltaPhiDeg);
    }

    /** The unit vector towards the light, (sin theta cos phi, sin theta sin phi, cos theta). */
    public Direction direction() {
        return Direction.fromSphericalDeg(thetaDeg, phiDeg);
    }
}
