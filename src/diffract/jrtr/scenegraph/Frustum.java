package diffract.jrtr.scenegraph;

import javax.vecmath.Matrix4f;

/**
 * A symmetric perspective view volume: near and far plane distances (both positive), aspect ratio
 * (width / height) and vertical field of view in degrees. Its projection matrix maps camera coordinates to
 * clip coordinates as OpenGL expects (camera looking down -z, depth -near..-far to NDC -1..1).
 */
public final class Frustum {
    private float near;
    private float far;
    private float aspect;
    private float verticalFovDegrees;

    public Frustum(float near, float far, float aspect, float verticalFovDegrees) {
        if (!(near > 0) || !(far > near)) {
            throw new IllegalArgumentException("need 0 < near < far, got near " + near + ", far " + far);
        }
        if (!(verticalFovDegrees > 0 && verticalFovDegrees < 180)) {
            throw new IllegalArgumentException("vertical field of view must be in (0, 180) degrees, got "
                    + verticalFovDegrees);
        }
        this.near = near;
        this.far = far;
        this.verticalFovDegrees = verticalFovDegrees;
        setAspect(aspect);
    }

    /** Default jrtr frustum: near 1, far 100, aspect 1, 60 degrees. */
    public Frustum() {
        this(1, 100, 1, 60);
    }

    public float near() {
        return near;
    }

    public float far() {
        return far;
    }

    public float aspect() {
        return aspect;
    }

    public float verticalFovDegrees() {
        return verticalFovDegrees;
    }

    /** Called by the renderer when the viewport changes shape. */
    public void setAspect(float widthOverHeight) {
        if (!(widthOverHeight > 0) || Float.isInfinite(widthOverHeight)) {
            throw new IllegalArgumentException("aspect ratio must be positive and finite, got " + widthOverHeight);
        }
        this.aspect = widthOverHeight;
    }

    /**
     * P = [1/(a t), 0, 0, 0; 0, 1/t, 0, 0; 0, 0, (n+f)/(n-f), 2nf/(n-f); 0, 0, -1, 0] with t = tan(fov/2).
     */
    public Matrix4f projectionMatrix() {
        double t = Math.tan(Math.toRadians(verticalFovDegrees) / 2);
        return new Matrix4f(
                (float) (1 / (aspect * t)), 0, 0, 0,
                0, (float) (1 / t), 0, 0,
                0, 0, (near + far) / (near - far), 2 * near * far / (near - far),
                0, 0, -1, 0);
    }
}
