package ifold.geom;

/**
 * Measures of triangles given by the positions of their corners in an interleaved coordinate
 * array ({@code xyz[3 * v]}, {@code xyz[3 * v + 1]}, {@code xyz[3 * v + 2]}). Nothing here
 * allocates, so it can run in the loops over millions of faces.
 */
public final class Triangles {
    private Triangles() {
    }

    /** Twice the area of triangle (a, b, c): the length of the cross product of its edges. */
    public static double twiceArea(double[] xyz, int a, int b, int c) {
        double ux = xyz[3 * b] - xyz[3 * a];
        double uy = xyz[3 * b + 1] - xyz[3 * a + 1];
        double uz = xyz[3 * b + 2] - xyz[3 * a + 2];
        double vx = xyz[3 * c] - xyz[3 * a];
        double vy = xyz[3 * c + 1] - xyz[3 * a + 1];
        double vz = xyz[3 * c + 2] - xyz[3 * a + 2];
        double nx = uy * vz - uz * vy;
        double ny = uz * vx - ux * vz;
        double nz = ux * vy - uy * vx;
        return Math.sqrt(nx * nx + ny * ny + nz * nz);
    }

    /** The dot product of the edges from a to b and from a to c. */
    private static double dot(double[] xyz, int a, int b, int c) {
        return (xyz[3 * b] - xyz[3 * a]) * (xyz[3 * c] - xyz[3 * a])
                + (xyz[3 * b + 1] - xyz[3 * a + 1]) * (xyz[3 * c + 1] - xyz[3 * a + 1])
                + (xyz[3 * b + 2] - xyz[3 * a + 2]) * (xyz[3 * c + 2] - xyz[3 * a + 2]);
    }

    public static double distanceSquared(double[] xyz, int a, int b) {
        double dx = xyz[3 * b] - xyz[3 * a];
        double dy = xyz[3 * b + 1] - xyz[3 * a + 1];
        double dz = xyz[3 * b + 2] - xyz[3 * a + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    public static double distance(double[] xyz, int a, int b) {
        return Math.sqrt(distanceSquared(xyz, a, b));
    }

    /** Whether triangle (a, b, c) has no area in the sense of {@link Tolerance#DEGENERATE_AREA}. */
    public static boolean isDegenerate(double[] xyz, int a, int b, int c) {
        double longest = Math.max(distanceSquared(xyz, a, b),
                Math.max(distanceSquared(xyz, b, c), distanceSquared(xyz, c, a)));
        return Tolerance.isDegenerateTriangle(twiceArea(xyz, a, b, c), longest);
    }

    /**
     * The angle at corner {@code a} of triangle (a, b, c), in radians. Computed with atan2 of the
     * cross and dot products, which stays accurate for angles near 0 and near pi where acos
     * does not.
     */
    public static double angleAt(double[] xyz, int a, int b, int c) {
        return Math.atan2(twiceArea(xyz, a, b, c), dot(xyz, a, b, c));
    }

    /** The smallest of the three angles of triangle (a, b, c), in radians. */
    public static double minAngle(double[] xyz, int a, int b, int c) {
        return Math.min(angleAt(xyz, a, b, c), Math.min(angleAt(xyz, b, c, a), angleAt(xyz, c, a, b)));
    }

    /**
     * Writes the incentre of triangle (a, b, c) to {@code dest[destOffset..+2]}: the corners
     * weighted by the lengths of the opposite sides. It lies on all three angle bisectors, which
     * is why the sub-triangles of the Hamiltonian refinement keep at least half of each angle.
     */
    public static void incenter(double[] xyz, int a, int b, int c, double[] dest, int destOffset) {
        double la = distance(xyz, b, c);
        double lb = distance(xyz, c, a);
        double lc = distance(xyz, a, b);
        double sum = la + lb + lc;
        for (int axis = 0; axis < 3; axis++) {
            dest[destOffset + axis] =
                    (la * xyz[3 * a + axis] + lb * xyz[3 * b + axis] + lc * xyz[3 * c + axis]) / sum;
        }
    }
}
