package diffract.jrtr.scenegraph;

import javax.vecmath.Vector3f;

/**
 * A directional light: a direction (in the node's coordinates, pointing from the surface TOWARDS the light)
 * and an RGB radiance. The engine only transports these numbers to the shaders; what they mean physically is
 * up to the shaders.
 */
public class LightNode extends Node {
    private final Vector3f direction = new Vector3f();
    private final Vector3f radiance = new Vector3f();

    public LightNode(String name, Vector3f towardsLight, Vector3f radiance) {
        super(name);
        setDirection(towardsLight);
        this.radiance.set(radiance);
    }

    /** A copy of the unit direction towards the light, in this node's coordinates. */
    public Vector3f direction() {
        return new Vector3f(direction);
    }

    public void setDirection(Vector3f towardsLight) {
        if (towardsLight.lengthSquared() == 0) {
            throw new IllegalArgumentException("light direction must not be zero");
        }
        direction.normalize(towardsLight);
    }

    public Vector3f radiance() {
        return new Vector3f(radiance);
    }

    public void setRadiance(Vector3f rgb) {
        radiance.set(rgb);
    }

    @Override
    public void accept(NodeVisitor visitor) {
        visitor.visitLight(this);
    }
}
