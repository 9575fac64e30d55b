package ifold.scene;

import org.joml.Matrix4d;
import org.joml.Matrix4dc;

/**
 * A thing in the scene with a local transform (relative to its parent) and a world transform
 * (relative to the scene), computed on demand and cached until something above it moves.
 */
public abstract class Spatial {
    private final String name;
    private Node parent;
    private final Matrix4d local = new Matrix4d();
    private final Matrix4d world = new Matrix4d();
    private boolean worldDirty = true;
    private boolean visible = true;

    protected Spatial(String name) {
        this.name = name;
    }

    public String name() {
        return name;
    }

    public Node parent() {
        return parent;
    }

    void setParent(Node parent) {
        this.parent = parent;
        invalidateWorld();
    }

    public Matrix4dc localTransform() {
        return local;
    }

    /** Sets the transform relative to the parent; the world transforms below follow. */
    public void setLocalTransform(Matrix4dc transform) {
        markChanged();
        local.set(transform);
        invalidateWorld();
    }

    /** The transform from this spatial's coordinates to the scene's. */
    public Matrix4dc worldTransform() {
        if (worldDirty) {
            if (parent == null) {
                world.set(local);
            } else {
                parent.worldTransform().mul(local, world);
            }
            worldDirty = false;
        }
        return world;
    }

    boolean isWorldDirty() {
        return worldDirty;
    }

    /** Marks this world transform, and those below, for recomputation. */
    void invalidateWorld() {
        worldDirty = true;
    }

    public boolean isVisible() {
        return visible;
    }

    public void setVisible(boolean visible) {
        if (this.visible != visible) {
            markChanged();
            this.visible = visible;
        }
    }

    /**
     * Records that something here changed, on the way up to the root, which checks the thread
     * and remembers to redraw.
     */
    protected void markChanged() {
        if (parent != null) {
            parent.markChanged();
        }
    }

    /** Grows {@code bounds} by this spatial's world-space extent (nothing if invisible). */
    public abstract void addWorldBounds(Bounds bounds);

    /** Calls {@code visitor} on every visible geometry at or below this spatial. */
    public abstract void visitGeometry(java.util.function.Consumer<Geometry> visitor);
}
