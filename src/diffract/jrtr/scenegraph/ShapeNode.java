package diffract.jrtr.scenegraph;

/** A leaf that draws a {@link Shape} with a {@link Material}. */
public class ShapeNode extends Node {
    private final Shape shape;
    private Material material;

    public ShapeNode(Shape shape, Material material) {
        super(shape.name());
        this.shape = shape;
        this.material = material;
    }

    public Shape shape() {
        return shape;
    }

    public Material material() {
        return material;
    }

    public void setMaterial(Material material) {
        this.material = material;
    }

    @Override
    public void accept(NodeVisitor visitor) {
        visitor.visitShape(this);
    }
}
