package diffract.jrtr.scenegraph;

import javax.vecmath.Matrix4f;

/** A group whose children are placed by {@code transform} (child coordinates to parent coordinates). */
public class TransformGroup extends Group {
    private final Matrix4f transform = new Matrix4f();

    public TransformGroup(String name) {
        super(name);
        transform.setIdentity();
    }

    public TransformGroup(String name, Matrix4f transform) {
        super(name);
        this.transform.set(transform);
    }

    /** A copy of the child-to-parent matrix. */
    public Matrix4f transform() {
        return new Matrix4f(transform);
    }

    public void setTransform(Matrix4f matrix) {
        transform.set(matrix);
    }

    @Override
    public TransformGroup add(Node... nodes) {
        super.add(nodes);
        return this;
    }

    @Override
    public void accept(NodeVisitor visitor) {
        visitor.visitTransformGroup(this);
    }
}
