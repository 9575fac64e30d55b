package ifold.scene;

import java.util.function.Consumer;
import org.joml.Matrix4dc;
import org.joml.Vector3d;

/**
 * A leaf that draws a {@link SceneMesh} with a {@link Material}. The renderer uploads the mesh
 * once per {@link #version()}; revealing part of it (the path animation) changes only a
 * number the shader reads, so it costs no upload.
 */
public final class Geometry extends Spatial {
    /** Reveal every triangle. */
    public static final int ALL = Integer.MAX_VALUE;

    private SceneMesh mesh;
    private Material material;
    private int version;
    private int revealed = ALL;
    private int hiddenColor = 0xFFF3F3F3;
    private boolean closed;
    private boolean seenThrough;
    private boolean under;

    public Geometry(String name, SceneMesh mesh, Material material) {
        super(name);
        this.mesh = mesh;
        this.material = material;
    }

    public SceneMesh mesh() {
        return mesh;
    }

    /** Replaces the mesh; the renderer uploads it again. */
    public void setMesh(SceneMesh mesh) {
        markChanged();
        this.mesh = mesh;
        version++;
    }

    /** Increases whenever the mesh's data changed and must be uploaded again. */
    public int version() {
        return version;
    }

    public Material material() {
        return material;
    }

    public void setMaterial(Material material) {
        markChanged();
        this.material = material;
    }

    /** How many triangles, in mesh order, show their own colour; the rest show {@link #hiddenColor()}. */
    public int revealed() {
        return revealed;
    }

    public void setRevealed(int count) {
        if (count != revealed) {
            markChanged();
            revealed = count;
        }
    }

    /**
     * Whether the mesh is a closed surface seen only from outside, so that the renderer may skip
     * the triangles facing away (about half, and on a software renderer the cost is per
     * triangle). Paper is never closed: both its sides show.
     */
    public boolean isClosed() {
        return closed;
    }

    public void setClosed(boolean closed) {
        markChanged();
        this.closed = closed;
    }

    /**
     * Whether the geometry is drawn over everything, as if the paper before it were glass:
     * paper crossing paper lies between layers, where the layers above would hide it.
     */
    public boolean isSeenThrough() {
        return seenThrough;
    }

    public void setSeenThrough(boolean seenThrough) {
        markChanged();
        this.seenThrough = seenThrough;
    }

    /**
     * Whether the geometry lies under others (the model under its paper): it is drawn after
     * them, so that where they cover it a software renderer skips its pixels before shading
     * them, rather than shading them twice.
     */
    public boolean isUnder() {
        return under;
    }

    public void setUnder(boolean under) {
        markChanged();
        this.under = under;
    }

    /** The colour of triangles not yet revealed. */
    public int hiddenColor() {
        return hiddenColor;
    }

    public void setHiddenColor(int argb) {
        markChanged();
        hiddenColor = argb;
    }

    @Override
    public void addWorldBounds(Bounds bounds) {
        Bounds local = mesh.bounds();
        if (!isVisible() || local.isEmpty()) {
            return;
        }
        Matrix4dc world = worldTransform();
        Vector3d min = local.min();
        Vector3d max = local.max();
        Vector3d corner = new Vector3d();
        for (int i = 0; i < 8; i++) {
            corner.set((i & 1) == 0 ? min.x : max.x, (i & 2) == 0 ? min.y : max.y, (i & 4) == 0 ? min.z : max.z);
            world.transformPosition(corner);
            bounds.add(corner.x, corner.y, corner.z);
        }
    }

    /** The largest distance from {@code center} to a vertex of the mesh, in world coordinates. */
    public double worldDistanceFrom(Vector3d center) {
        Matrix4dc world = worldTransform();
        double[] xyz = mesh.positions();
        Vector3d p = new Vector3d();
        double max = 0;
        for (int i = 0; i < xyz.length; i += 3) {
            world.transformPosition(p.set(xyz[i], xyz[i + 1], xyz[i + 2]));
            max = Math.max(max, p.distance(center));
        }
        return max;
    }

    @Override
    public void visitGeometry(Consumer<Geometry> visitor) {
        if (isVisible()) {
            visitor.accept(this);
        }
    }
}
