package diffract.jrtr.scenegraph;

/**
 * A scene graph node. Traversal ({@link RenderList#collect}) walks the graph depth first, multiplying the
 * matrices of {@link TransformGroup}s on the way down, and records every {@link ShapeNode} and
 * {@link LightNode} with its world matrix.
 */
public abstract class Node {
    private final String name;

    protected Node(String name) {
        this.name = name;
    }

    public String name() {
        return name;
    }

    /** Double dispatch for traversals: calls the visitor method for this node's type. */
    public abstract void accept(NodeVisitor visitor);

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[" + name + "]";
    }
}
