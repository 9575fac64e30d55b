package ifold.scene;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.function.Consumer;

/** An inner node: groups spatials under one transform. */
public class Node extends Spatial {
    private final List<Spatial> children = new ArrayList<>();

    public Node(String name) {
        super(name);
    }

    public List<Spatial> children() {
        return Collections.unmodifiableList(children);
    }

    /** Attaches {@code child}, detaching it first from any other parent. */
    public void attach(Spatial child) {
        if (child == this || isAncestor(child)) {
            throw new IllegalArgumentException("attaching " + child.name() + " under " + name() + " would make a cycle");
        }
        markChanged();
        if (child.parent() != null) {
            child.parent().detach(child);
        }
        children.add(child);
        child.setParent(this);
    }

    public void detach(Spatial child) {
        if (children.remove(child)) {
            markChanged();
            child.setParent(null);
        }
    }

    private boolean isAncestor(Spatial candidate) {
        for (Node n = parent(); n != null; n = n.parent()) {
            if (n == candidate) {
                return true;
            }
        }
        return false;
    }

    @Override
    void invalidateWorld() {
        if (isWorldDirty()) {
            return; // everything below is already marked: children are marked with their parent
        }
        super.invalidateWorld();
        for (Spatial child : children) {
            child.invalidateWorld();
        }
    }

    @Override
    public void addWorldBounds(Bounds bounds) {
        if (isVisible()) {
            for (Spatial child : children) {
                child.addWorldBounds(bounds);
            }
        }
    }

    @Override
    public void visitGeometry(Consumer<Geometry> visitor) {
        if (isVisible()) {
            for (Spatial child : children) {
                child.visitGeometry(visitor);
            }
        }
    }
}
