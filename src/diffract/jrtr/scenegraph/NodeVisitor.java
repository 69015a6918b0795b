package diffract.jrtr.scenegraph;

/** Visits scene graph nodes by type; a {@link Group}'s visitor decides whether and how to descend. */
public interface NodeVisitor {
    void visitGroup(Group group);

    void visitTransformGroup(TransformGroup group);

    void visitShape(ShapeNode shape);

    void visitLight(LightNode light);
}
