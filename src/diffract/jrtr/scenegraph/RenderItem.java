package diffract.jrtr.scenegraph;

import javax.vecmath.Matrix4f;

/** One shape to draw: the scene graph leaf and its object-to-world matrix at traversal time. */
public record RenderItem(ShapeNode node, Matrix4f modelMatrix) {
    public RenderItem {
        modelMatrix = new Matrix4f(modelMatrix);
    }

    public Shape shape() {
        return node.shape();
    }

    public Material material() {
        return node.material();
    }

    @Override
    public Matrix4f modelMatrix() {
        return new Matrix4f(modelMatrix);
    }
}
