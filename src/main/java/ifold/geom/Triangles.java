package ifold.geom;

/**
 * Measures of triangles given by the positions of their corners in an interleaved coordinate
 * array ({@code xyz[3 * v]}, {@code xyz[3 * v + 1]}, {@code xyz[3 * v + 2]}). Shapes (no area,
 * angles) are measured on edges scaled to order 1, so that models of any size, 1e-100 to 1e300,
 * give the same answers.
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

    public static double distanceSquared(double[] xyz, int a, int b) {
        double dx = xyz[3 * b] - xyz[3 * a];
        double dy = xyz[3 * b + 1] - xyz[3 * a + 1];
        double dz = xyz[3 * b + 2] - xyz[3 * a + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    /** The distance from a to b, without overflow or underflow whatever the model's size. */
    public static double distance(double[] xyz, int a, int b) {
        double dx = xyz[3 * b] * 0.5 - xyz[3 * a] * 0.5;
        double dy = xyz[3 * b + 1] * 0.5 - xyz[3 * a + 1] * 0.5;
        double dz = xyz[3 * b + 2] * 0.5 - xyz[3 * a + 2] * 0.5;
        double scale = Math.max(Math.abs(dx), Math.max(Math.abs(dy), Math.abs(dz)));
        if (scale == 0) {
            return 0;
        }
        dx /= scale;
        dy /= scale;
        dz /= scale;
        return 2 * scale * Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * Whether triangle (a, b, c) has no area in the sense of {@link Tolerance#DEGENERATE_AREA}.
     * Measured on its edges scaled to the largest coordinate difference: a triangle of side
     * 1e-100 or 1e154 is the same shape as one of side 1, and its squares neither underflow nor
     * overflow.
     */
    public static boolean isDegenerate(double[] xyz, int a, int b, int c) {
        // Measured from the corner of lowest index, whichever corner a face's loop starts at
        // and whichever way round it runs: a sliver at the threshold is judged the same by
        // the builder, which reads the input's order, and the validator, which walks the mesh.
        if (b < a && b < c) {
            return isDegenerate(xyz, b, c, a);
        }
        if (c < a && c < b) {
            return isDegenerate(xyz, c, a, b);
        }
        // The arithmetic of scaledEdges and crossLength, spelled out in locals: this runs for
        // every triangle of every model loaded, and arrays per call cost a third of a load.
        int pa = 3 * a;
        int pb = 3 * b;
        int pc = 3 * c;
        double ux = xyz[pb] * 0.5 - xyz[pa] * 0.5;
        double uy = xyz[pb + 1] * 0.5 - xyz[pa + 1] * 0.5;
        double uz = xyz[pb + 2] * 0.5 - xyz[pa + 2] * 0.5;
        double vx = xyz[pc] * 0.5 - xyz[pa] * 0.5;
        double vy = xyz[pc + 1] * 0.5 - xyz[pa + 1] * 0.5;
        double vz = xyz[pc + 2] * 0.5 - xyz[pa + 2] * 0.5;
        double scale = Math.max(Math.max(Math.abs(ux), Math.abs(vx)),
                Math.max(Math.max(Math.abs(uy), Math.abs(vy)), Math.max(Math.abs(uz), Math.abs(vz))));
        if (!(scale > 0) || !Double.isFinite(scale)) {
            return true; // all three corners at one point
        }
        ux /= scale;
        uy /= scale;
        uz /= scale;
        vx /= scale;
        vy /= scale;
        vz /= scale;
        double wx = vx - ux;
        double wy = vy - uy;
        double wz = vz - uz;
        double longest = Math.max(ux * ux + uy * uy + uz * uz,
                Math.max(vx * vx + vy * vy + vz * vz, wx * wx + wy * wy + wz * wz));
        double nx = uy * vz - uz * vy;
        double ny = uz * vx - ux * vz;
        double nz = ux * vy - uy * vx;
        return Tolerance.isDegenerateTriangle(Math.sqrt(nx * nx + ny * ny + nz * nz), longest);
    }

    /**
     * The edges from a to b and from a to c, u then v, divided by their largest coordinate
     * difference; null if that is zero (or not finite).
     */
    private static double[] scaledEdges(double[] xyz, int a, int b, int c) {
        double[] e = new double[6];
        double scale = 0;
        for (int axis = 0; axis < 3; axis++) {
            // Halved before subtracting: coordinates near 1e308 differ by more than a double holds.
            e[axis] = xyz[3 * b + axis] * 0.5 - xyz[3 * a + axis] * 0.5;
            e[3 + axis] = xyz[3 * c + axis] * 0.5 - xyz[3 * a + axis] * 0.5;
            scale = Math.max(scale, Math.max(Math.abs(e[axis]), Math.abs(e[3 + axis])));
        }
        if (!(scale > 0) || !Double.isFinite(scale)) {
            return null;
        }
        for (int k = 0; k < 6; k++) {
            e[k] /= scale;
        }
        return e;
    }

    private static double crossLength(double[] e) {
        double nx = e[1] * e[5] - e[2] * e[4];
        double ny = e[2] * e[3] - e[0] * e[5];
        double nz = e[0] * e[4] - e[1] * e[3];
        return Math.sqrt(nx * nx + ny * ny + nz * nz);
    }

    /**
     * The angle at corner {@code a} of triangle (a, b, c), in radians. Computed with atan2 of the
     * cross and dot products, which stays accurate for angles near 0 and near pi where acos
     * does not.
     */
    public static double angleAt(double[] xyz, int a, int b, int c) {
        // On the edges scaled to order 1: the angle is the same, and tiny or huge models keep it.
        double[] e = scaledEdges(xyz, a, b, c);
        if (e == null) {
            return 0;
        }
        return Math.atan2(crossLength(e), e[0] * e[3] + e[1] * e[4] + e[2] * e[5]);
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
        // Weights first, then the corners: products of two huge (or tiny) numbers would overflow.
        double wa = la / sum;
        double wb = lb / sum;
        double wc = lc / sum;
        for (int axis = 0; axis < 3; axis++) {
            dest[destOffset + axis] = wa * xyz[3 * a + axis] + wb * xyz[3 * b + axis] + wc * xyz[3 * c + axis];
        }
    }
}
