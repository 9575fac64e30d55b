package ifold.geom;

/**
 * An oriented plane {@code normal · p = offset} with a unit normal, and the one place where
 * points are sorted to its sides. A point within {@code tolerance} of the plane is
 * {@link Side#ON} it: fold lines pass exactly through the vertices they were meant to.
 *
 * @param nx x of the unit normal
 * @param ny y of the unit normal
 * @param nz z of the unit normal
 * @param offset the normal's dot product with any point of the plane
 * @param tolerance how far from the plane a point still counts as on it
 */
public record Plane(double nx, double ny, double nz, double offset, double tolerance) {

    /** Which side of a plane a point lies on. */
    public enum Side { ABOVE, ON, BELOW }

    /** The plane through {@code (px, py, pz)} with normal {@code (nx, ny, nz)} (normalised here). */
    public static Plane through(double px, double py, double pz, double nx, double ny, double nz, double scale) {
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(length > 0)) {
            throw new IllegalArgumentException("a plane needs a non-zero normal");
        }
        nx /= length;
        ny /= length;
        nz /= length;
        return new Plane(nx, ny, nz, nx * px + ny * py + nz * pz, Tolerance.ON_PLANE * Math.max(scale, 1e-300));
    }

    /** Signed distance of a point: positive above, along the normal. */
    public double distance(double x, double y, double z) {
        return nx * x + ny * y + nz * z - offset;
    }

    public Side side(double x, double y, double z) {
        double d = distance(x, y, z);
        return d > tolerance ? Side.ABOVE : d < -tolerance ? Side.BELOW : Side.ON;
    }
}
