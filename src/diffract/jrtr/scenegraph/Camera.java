package diffract.jrtr.scenegraph;

import javax.vecmath.Matrix4f;
import javax.vecmath.Point3f;
import javax.vecmath.Vector3f;

/**
 * A pinhole camera placed by eye point, look-at point and up vector (Single 2014, eq. 1.3-1.4): the camera
 * frame is w = (eye - lookAt)/|eye - lookAt|, u = (up x w)/|up x w|, v = w x u, and the camera matrix
 * C = [u v w eye; 0 0 0 1] maps camera to world coordinates. The view matrix is C^-1; the camera looks down
 * its -w axis.
 */
public final class Camera {
    private final Point3f eye = new Point3f();
    private final Point3f lookAt = new Point3f();
    private final Vector3f up = new Vector3f();

    public Camera(Point3f eye, Point3f lookAt, Vector3f up) {
        set(eye, lookAt, up);
    }

    /** Default jrtr camera: eye (0,0,40), looking at the origin, y up. */
    public Camera() {
        this(new Point3f(0, 0, 40), new Point3f(0, 0, 0), new Vector3f(0, 1, 0));
    }

    /** Moves the camera; throws if eye == lookAt or up is parallel to the viewing direction. */
    public void set(Point3f newEye, Point3f newLookAt, Vector3f newUp) {
        Vector3f w = new Vector3f();
        w.sub(newEye, newLookAt);
        if (w.lengthSquared() == 0) {
            throw new IllegalArgumentException("eye and look-at point coincide: " + newEye);
        }
        Vector3f u = new Vector3f();
        u.cross(newUp, w);
        if (u.lengthSquared() == 0) {
            throw new IllegalArgumentException("up vector " + newUp + " is parallel to the viewing direction");
        }
        eye.set(newEye);
        lookAt.set(newLookAt);
        up.set(newUp);
    }

    public Point3f eye() {
        return new Point3f(eye);
    }

    public Point3f lookAt() {
        return new Point3f(lookAt);
    }

    public Vector3f up() {
        return new Vector3f(up);
    }

    /** C = [u v w eye; 0 0 0 1]: camera coordinates to world coordinates. */
    public Matrix4f cameraMatrix() {
        Vector3f w = new Vector3f();
        w.sub(eye, lookAt);
        w.normalize();
        Vector3f u = new Vector3f();
        u.cross(up, w);
        u.normalize();
        Vector3f v = new Vector3f();
        v.cross(w, u);
        return new Matrix4f(
                u.x, v.x, w.x, eye.x,
                u.y, v.y, w.y, eye.y,
                u.z, v.z, w.z, eye.z,
                0, 0, 0, 1);
    }

    /**
     * C^-1, computed in closed form (rotation transposed, translation -R^T eye) rather than by a general
     * inverse, so it stays exactly orthonormal.
     */
    public Matrix4f viewMatrix() {
        Matrix4f c = cameraMatrix();
        float tx = -(c.m00 * eye.x + c.m10 * eye.y + c.m20 * eye.z);
        float ty = -(c.m01 * eye.x + c.m11 * eye.y + c.m21 * eye.z);
        float tz = -(c.m02 * eye.x + c.m12 * eye.y + c.m22 * eye.z);
        return new Matrix4f(
                c.m00, c.m10, c.m20, tx,
                c.m01, c.m11, c.m21, ty,
                c.m02, c.m12, c.m22, tz,
                0, 0, 0, 1);
    }
}
