package diffract.optics.patches;

/**
 * A unit direction in the patch's tangent frame: x along the height field's columns, y along its rows, z the
 * surface normal. Both omega_i (towards the light) and omega_r (towards the viewer) point away from the surface.
 */
public record Direction(double x, double y, double z) {

    /** (sin theta cos phi, sin theta sin phi, cos theta), angles in degrees (004 appendix, spherical coordinates). */
    public static Direction fromSphericalDeg(double thetaDeg, double phiDeg) {
        double theta = Math.toRadians(thetaDeg);
        double phi = Math.toRadians(phiDeg);
        return new Direction(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta));
    }

    /** The unit vector (x, y, sqrt(1 - x^2 - y^2)) above the surface; requires x^2 + y^2 <= 1. */
    public static Direction fromProjected(double x, double y) {
        double zz = 1.0 - x * x - y * y;
        if (zz < 0) {
            throw new IllegalArgumentException("(" + x + ", " + y + ") lies outside the unit disk");
        }
        return new Direction(x, y, Math.sqrt(zz));
    }

    /** The mirror direction about the normal: where a flat surface reflects light arriving from this direction. */
    public Direction specular() {
        return new Direction(-x, -y, z);
    }

    public double dot(Direction o) {
        return x * o.x + y * o.y + z * o.z;
    }
}
