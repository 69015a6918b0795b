package diffract.jrtr.scenegraph;

import javax.vecmath.Vector3f;

/** A light after traversal: unit world-space direction towards the light, and radiance. */
public record DirectionalLight(Vector3f direction, Vector3f radiance) {
    public DirectionalLight {
        direction = new Vector3f(direction);
        radiance = new Vector3f(radiance);
    }

    @Override
    public Vector3f direction() {
        return new Vector3f(direction);
    }

    @Override
    public Vector3f radiance() {
        return new Vector3f(radiance);
    }
}
