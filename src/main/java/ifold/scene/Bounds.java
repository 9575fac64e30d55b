package ifold.scene;

import org.joml.Vector3d;

/** An axis-aligned box that grows to hold points; empty until the first point. */
public final class Bounds {
    private final Vector3d min = new Vector3d(Double.POSITIVE_INFINITY);
    private final Vector3d max = new Vector3d(Double.NEGATIVE_INFINITY);

    public void add(double x, double y, double z) {
        min.set(Math.min(min.x, x), Math.min(min.y, y), Math.min(min.z, z));
        max.set(Math.max(max.x, x), Math.max(max.y, y), Math.max(max.z, z));
    }

    public boolean isEmpty() {
        return min.x > max.x;
    }

    public Vector3d center(Vector3d dest) {
        return isEmpty() ? dest.zero() : dest.set(min).add(max).mul(0.5);
    }

    /** Half the diagonal: the radius of a sphere around the centre that holds the box. */
    public double radius() {
        return isEmpty() ? 0 : 0.5 * max.distance(min);
    }

    public Vector3d min() {
        return new Vector3d(min);
    }

    public Vector3d max() {
        return new Vector3d(max);
    }
}
