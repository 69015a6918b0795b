package diffract.jrtr.scenegraph;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

/** A node with ordered children; it adds no transform of its own. */
public class Group extends Node {
    private final List<Node> children = new ArrayList<>();

    public Group(String name) {
        super(name);
    }

    /** Appends children; returns this group so scenes can be built in one expression. */
    public Group add(Node... nodes) {
        for (Node node : nodes) {
            if (node == this) {
                throw new IllegalArgumentException("a group cannot contain itself");
            }
            children.add(node);
        }
        return this;
    }

    public boolean remove(Node node) {
        return children.remove(node);
    }

    public List<Node> children() {
        return Collections.unmodifiableList(children);
    }

    @Override
    public void accept(NodeVisitor visitor) {
        visitor.visitGroup(this);
    }
}
