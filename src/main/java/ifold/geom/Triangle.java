package ifold.geom;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A triangle in space, as the zig-zag demo takes it: its corners named A, B and C (0, 1, 2), its
 * front the side from which they run counter-clockwise; the altitude from a start corner sets
 * the strip's widest width.
 */
public final class Triangle {
    private final Vector3d[] corners;

    public Triangle(Vector3dc a, Vector3dc b, Vector3dc c) {
        corners = new Vector3d[] {new Vector3d(a), new Vector3d(b), new Vector3d(c)};
        for (Vector3d corner : corners) {
            if (!corner.isFinite()) {
                throw new IllegalArgumentException("the triangle's corners must be finite numbers");
            }
        }
        // Measured as Triangles measures faces: on edges scaled to order 1, whatever the size.
        double[] xyz = {a.x(), a.y(), a.z(), b.x(), b.y(), b.z(), c.x(), c.y(), c.z()};
        if (Triangles.isDegenerate(xyz, 0, 1, 2)) {
            throw new IllegalArgumentException("the triangle has no area: its corners lie on one line");
        }
    }

    /** A triangle in the plane z = 0 from x1, y1, x2, y2, x3, y3. */
    public static Triangle planar(double x1, double y1, double x2, double y2, double x3, double y3) {
        return new Triangle(new Vector3d(x1, y1, 0), new Vector3d(x2, y2, 0), new Vector3d(x3, y3, 0));
    }

    public Vector3dc corner(int i) {
        return corners[i];
    }

    /** The corner's name: A, B or C. */
    public static String name(int corner) {
        return String.valueOf((char) ('A' + corner));
    }

    /** The unit normal of the front: corners counter-clockwise seen from it. */
    public Vector3d normal() {
        return new Vector3d(corners[1]).sub(corners[0]).cross(new Vector3d(corners[2]).sub(corners[0])).normalize();
    }

    public double area() {
        return new Vector3d(corners[1]).sub(corners[0]).cross(new Vector3d(corners[2]).sub(corners[0])).length() / 2;
    }

    /** The altitude from {@code start} onto the opposite edge. */
    public double height(int start) {
        return 2 * area() / opposite(start);
    }

    /** The length of the edge opposite {@code corner}. */
    public double opposite(int corner) {
        return corners[(corner + 1) % 3].distance(corners[(corner + 2) % 3]);
    }

    /** The angles at A, B and C, in degrees. */
    public double[] angles() {
        double[] angles = new double[3];
        for (int i = 0; i < 3; i++) {
            Vector3d u = new Vector3d(corners[(i + 1) % 3]).sub(corners[i]);
            Vector3d v = new Vector3d(corners[(i + 2) % 3]).sub(corners[i]);
            angles[i] = Math.toDegrees(u.angle(v));
        }
        return angles;
    }

    /** The smallest angle, in degrees. */
    public double smallestAngle() {
        double[] angles = angles();
        return Math.min(angles[0], Math.min(angles[1], angles[2]));
    }

    /** The largest angle, in degrees. */
    public double largestAngle() {
        double[] angles = angles();
        return Math.max(angles[0], Math.max(angles[1], angles[2]));
    }

    /** A line for reports: the corners, rounded. */
    @Override
    public String toString() {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < 3; i++) {
            s.append(i == 0 ? "" : ", ").append(name(i)).append(String.format(java.util.Locale.ROOT, " (%.4g, %.4g, %.4g)",
                    corners[i].x, corners[i].y, corners[i].z));
        }
        return s.toString();
    }
}
