package diffract.jrtr.scenegraph;

import javax.vecmath.Matrix4f;
import javax.vecmath.Vector3f;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.List;

/**
 * The scene graph flattened for drawing: shapes with world matrices, in traversal order, and the lights in
 * world space. Built fresh each frame (cheap for scenes of a few nodes), so moving a TransformGroup needs no
 * notification.
 */
public final class RenderList {
    private final List<RenderItem> items;
    private final List<DirectionalLight> lights;

    private RenderList(List<RenderItem> items, List<DirectionalLight> lights) {
        this.items = Collections.unmodifiableList(items);
        this.lights = Collections.unmodifiableList(lights);
    }

    /** Walks the graph from {@code root}, accumulating transforms. */
    public static RenderList collect(Node root) {
        Collector collector = new Collector();
        root.accept(collector);
        return new RenderList(collector.items, collector.lights);
    }

    public List<RenderItem> items() {
        return items;
    }

    public List<DirectionalLight> lights() {
        return lights;
    }

    private static final class Collector implements NodeVisitor {
        private final List<RenderItem> items = new ArrayList<>();
        private final List<DirectionalLight> lights = new ArrayList<>();
        private final Deque<Matrix4f> stack = new ArrayDeque<>();
        // guards against a group that (indirectly) contains itself, which would recurse forever
        private final Deque<Group> path = new ArrayDeque<>();

        Collector() {
            Matrix4f identity = new Matrix4f();
            identity.setIdentity();
            stack.push(identity);
        }

        @Override
        public void visitGroup(Group group) {
            descend(group);
        }

        @Override
        public void visitTransformGroup(TransformGroup group) {
            Matrix4f world = new Matrix4f(stack.peek());
            world.mul(group.transform());
            stack.push(world);
            try {
                descend(group);
            } finally {
                stack.pop();
            }
        }

        private void descend(Group group) {
            for (Group ancestor : path) {
                if (ancestor == group) {
                    throw new IllegalStateException("scene graph cycle through " + group);
                }
            }
            path.push(group);
            try {
                for (Node child : group.children()) {
                    child.accept(this);
                }
            } finally {
                path.pop();
            }
        }

        @Override
        public void visitShape(ShapeNode shape) {
            items.add(new RenderItem(shape, stack.peek()));
        }

        @Override
        public void visitLight(LightNode light) {
            Vector3f direction = light.direction();
            stack.peek().transform(direction); // a direction: rotation/scale only, no translation
            if (direction.lengthSquared() == 0) {
                throw new IllegalStateException("light " + light.name() + " collapsed by a singular transform");
            }
            direction.normalize();
            lights.add(new DirectionalLight(direction, light.radiance()));
        }
    }
}
