package diffract.jrtr.scenegraph;

import org.junit.jupiter.api.Test;

import javax.vecmath.Matrix4f;
import javax.vecmath.Point3f;
import javax.vecmath.Vector3f;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

/** Scene graph traversal: transforms accumulate parent-first, lights come out in world space. */
class RenderListTest {
    private static Matrix4f translation(float x, float y, float z) {
        Matrix4f m = new Matrix4f();
        m.setIdentity();
        m.setTranslation(new Vector3f(x, y, z));
        return m;
    }

    private static Matrix4f scale(float s) {
        Matrix4f m = new Matrix4f();
        m.setIdentity();
        m.setScale(s);
        return m;
    }

    @Test
    void transformsAccumulateFromRootToLeaf() {
        Shape shape = Shapes.cube(1);
        ShapeNode deep = new ShapeNode(shape, null);
        ShapeNode shallow = new ShapeNode(shape, null);
        TransformGroup outer = new TransformGroup("move", translation(10, 0, 0));
        TransformGroup inner = new TransformGroup("scale", scale(2));
        inner.add(deep);
        outer.add(inner, shallow);
        RenderList list = RenderList.collect(new Group("root").add(outer));
        List<RenderItem> items = list.items();
        assertEquals(2, items.size());
        assertSame(deep, items.get(0).node());
        // world = move * scale: point (1, 1, 1) -> (12, 2, 2), i.e. scaled first, then moved
        Point3f p = new Point3f(1, 1, 1);
        items.get(0).modelMatrix().transform(p);
        assertEquals(new Point3f(12, 2, 2), p);
        Point3f q = new Point3f(1, 1, 1);
        items.get(1).modelMatrix().transform(q);
        assertEquals(new Point3f(11, 1, 1), q);
    }

    @Test
    void lightDirectionsAreRotatedNotTranslatedAndNormalized() {
        Matrix4f turn = new Matrix4f();
        turn.rotZ((float) Math.toRadians(90));
        turn.setTranslation(new Vector3f(5, 5, 5));
        TransformGroup turned = new TransformGroup("turned", turn);
        turned.add(new LightNode("sun", new Vector3f(3, 0, 0), new Vector3f(1, 2, 3)));
        RenderList list = RenderList.collect(new Group("root").add(turned));
        assertEquals(1, list.lights().size());
        Vector3f direction = list.lights().get(0).direction();
        assertEquals(0, direction.x, 1e-6);
        assertEquals(1, direction.y, 1e-6);
        assertEquals(0, direction.z, 1e-6);
        assertEquals(new Vector3f(1, 2, 3), list.lights().get(0).radiance());
    }

    @Test
    void cyclesAreReportedInsteadOfOverflowingTheStack() {
        Group a = new Group("a");
        Group b = new Group("b");
        a.add(b);
        b.add(a);
        assertThrows(IllegalStateException.class, () -> RenderList.collect(a));
    }

    @Test
    void vertexDataChecksSizes() {
        assertThrows(IllegalArgumentException.class, () -> VertexData.builder(3).positions(0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> VertexData.builder(3).indices(0, 1, 3));
        assertThrows(IllegalStateException.class, () -> VertexData.builder(3).indices(0, 1, 2).build());
        VertexData cube = Shapes.cube(1).vertexData();
        assertEquals(24, cube.vertexCount());
        assertEquals(36, cube.indexCount());
    }
}
