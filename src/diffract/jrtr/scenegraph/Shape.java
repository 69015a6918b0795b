package diffract.jrtr.scenegraph;

/**
 * A named piece of geometry. The render context uploads its {@link VertexData} to the GPU the first time the
 * shape is drawn and reuses that copy (keyed by this object) until the context is disposed; the same shape
 * may appear in several {@link ShapeNode}s.
 */
public final class Shape {
    private final String name;
    private final VertexData vertexData;

    public Shape(String name, VertexData vertexData) {
        this.name = name;
        this.vertexData = vertexData;
    }

    public String name() {
        return name;
    }

    public VertexData vertexData() {
        return vertexData;
    }

    @Override
    public String toString() {
        return "Shape[" + name + ", " + vertexData.vertexCount() + " vertices]";
    }
}
