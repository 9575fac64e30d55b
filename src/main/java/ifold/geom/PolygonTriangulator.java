package ifold.geom;

/**
 * Splits a simple polygon, planar or nearly so, into triangles by ear clipping on its projection
 * along the Newell normal. At each step it clips, among all valid ears, the one whose smallest
 * angle is largest, so that fans of slivers are avoided; a vertex that lies on a straight side
 * (collinear with its neighbours) is never clipped as an ear, so no zero-area triangle comes out
 * of a polygon that has area. Non-convex polygons come out right as long as their projection is
 * simple (does not cross itself).
 *
 * <p>Running time is cubic in the polygon's size in the worst case, which is fine for the faces
 * of real models (tens of vertices); above {@link #BEST_EAR_LIMIT} vertices it takes the first
 * valid ear instead, which is quadratic.
 */
public final class PolygonTriangulator {
    private static final int BEST_EAR_LIMIT = 64;

    private PolygonTriangulator() {
    }

    /**
     * Triangulates the polygon whose corners are {@code polygon[0..size-1]} (indices into the
     * interleaved {@code xyz}) and writes {@code size - 2} triangles, as indices into
     * {@code polygon}'s vertex ids, to {@code triangles[0..3 * (size - 2) - 1]}, each oriented
     * like the polygon.
     *
     * @return the number of triangles written: {@code size - 2}, or 0 when the polygon has no
     *     area ({@link Polygons#hasArea}), in which case nothing can be said about it
     */
    public static int triangulate(double[] xyz, int[] polygon, int size, int[] triangles) {
        if (size == 3) {
            triangles[0] = polygon[0];
            triangles[1] = polygon[1];
            triangles[2] = polygon[2];
            return 1;
        }
        double[] normal = new double[3];
        if (!Polygons.newellNormal(xyz, polygon, size, normal)) {
            return 0;
        }
        double nx = normal[0];
        double ny = normal[1];
        double nz = normal[2];
        // Project by dropping the dominant axis, choosing the other two so the polygon stays
        // counter-clockwise in the plane.
        int drop = Math.abs(nx) >= Math.abs(ny) && Math.abs(nx) >= Math.abs(nz) ? 0
                : Math.abs(ny) >= Math.abs(nz) ? 1 : 2;
        double sign = drop == 0 ? nx : drop == 1 ? ny : nz;
        int axisU = (drop + 1) % 3;
        int axisV = (drop + 2) % 3;
        if (sign < 0) {
            int swap = axisU;
            axisU = axisV;
            axisV = swap;
        }
        double[] u = new double[size];
        double[] v = new double[size];
        int[] nextOf = new int[size];
        int[] prevOf = new int[size];
        // Relative to the first corner and scaled to order 1: ears are judged the same way on a
        // model of side 1e-100 or 1e154 (no product underflows or overflows).
        double scale = 0;
        for (int i = 0; i < size; i++) {
            scale = Math.max(scale, Math.abs(xyz[3 * polygon[i] + axisU] * 0.5 - xyz[3 * polygon[0] + axisU] * 0.5));
            scale = Math.max(scale, Math.abs(xyz[3 * polygon[i] + axisV] * 0.5 - xyz[3 * polygon[0] + axisV] * 0.5));
        }
        if (!(scale > 0) || !Double.isFinite(scale)) {
            return 0;
        }
        for (int i = 0; i < size; i++) {
            u[i] = (xyz[3 * polygon[i] + axisU] * 0.5 - xyz[3 * polygon[0] + axisU] * 0.5) / scale;
            v[i] = (xyz[3 * polygon[i] + axisV] * 0.5 - xyz[3 * polygon[0] + axisV] * 0.5) / scale;
            nextOf[i] = (i + 1) % size;
            prevOf[i] = (i + size - 1) % size;
        }
        int remaining = size;
        int written = 0;
        int start = 0;
        while (remaining > 3) {
            int best = -1;
            double bestQuality = -1;
            int i = start;
            for (int step = 0; step < remaining; step++, i = nextOf[i]) {
                double quality = earQuality(u, v, prevOf[i], i, nextOf[i], nextOf);
                if (quality > bestQuality) {
                    bestQuality = quality;
                    best = i;
                    if (size > BEST_EAR_LIMIT) {
                        break;
                    }
                }
            }
            if (best < 0) {
                // No valid ear: the projection crosses itself. Clip the most convex corner so the
                // loop ends; a degenerate result is caught by the caller's area check.
                best = mostConvex(u, v, start, remaining, prevOf, nextOf);
            }
            int p = prevOf[best];
            int n = nextOf[best];
            triangles[written++] = polygon[p];
            triangles[written++] = polygon[best];
            triangles[written++] = polygon[n];
            nextOf[p] = n;
            prevOf[n] = p;
            start = n;
            remaining--;
        }
        triangles[written++] = polygon[prevOf[start]];
        triangles[written++] = polygon[start];
        triangles[written++] = polygon[nextOf[start]];
        return written / 3;
    }

    /** The smallest angle of ear (p, i, n), or -1 if it is not a valid ear. */
    private static double earQuality(double[] u, double[] v, int p, int i, int n, int[] nextOf) {
        double cross = cross(u, v, p, i, n);
        double longest = Math.max(dist2(u, v, p, i), Math.max(dist2(u, v, i, n), dist2(u, v, n, p)));
        if (cross <= 0 || Tolerance.isDegenerateTriangle(cross, longest)) {
            return -1; // reflex or straight corner
        }
        for (int j = nextOf[n]; j != p; j = nextOf[j]) {
            if (insideOrOn(u, v, p, i, n, j)) {
                return -1;
            }
        }
        return Math.min(angle(u, v, p, i, n), Math.min(angle(u, v, i, n, p), angle(u, v, n, p, i)));
    }

    private static int mostConvex(double[] u, double[] v, int start, int remaining, int[] prevOf, int[] nextOf) {
        int best = start;
        double bestCross = Double.NEGATIVE_INFINITY;
        int i = start;
        for (int step = 0; step < remaining; step++, i = nextOf[i]) {
            double c = cross(u, v, prevOf[i], i, nextOf[i]);
            if (c > bestCross) {
                bestCross = c;
                best = i;
            }
        }
        return best;
    }

    /** Whether point j lies inside or on triangle (a, b, c), which is counter-clockwise; points equal to a corner do not count. */
    private static boolean insideOrOn(double[] u, double[] v, int a, int b, int c, int j) {
        if (same(u, v, j, a) || same(u, v, j, b) || same(u, v, j, c)) {
            return false;
        }
        return cross(u, v, a, b, j) >= 0 && cross(u, v, b, c, j) >= 0 && cross(u, v, c, a, j) >= 0;
    }

    private static boolean same(double[] u, double[] v, int a, int b) {
        return u[a] == u[b] && v[a] == v[b];
    }

    private static double cross(double[] u, double[] v, int a, int b, int c) {
        return (u[b] - u[a]) * (v[c] - v[a]) - (v[b] - v[a]) * (u[c] - u[a]);
    }

    private static double dist2(double[] u, double[] v, int a, int b) {
        double du = u[b] - u[a];
        double dv = v[b] - v[a];
        return du * du + dv * dv;
    }

    /** The angle at a of triangle (a, b, c). */
    private static double angle(double[] u, double[] v, int a, int b, int c) {
        double bu = u[b] - u[a];
        double bv = v[b] - v[a];
        double cu = u[c] - u[a];
        double cv = v[c] - v[a];
        return Math.atan2(Math.abs(bu * cv - bv * cu), bu * cu + bv * cv);
    }
}
