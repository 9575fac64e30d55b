package ifold.check;

/**
 * The exact test of two triangles in space, and the checker's numerics in one place: whether
 * they cross, how deep, along which segment, or whether they overlap lying in one plane.
 *
 * <p><b>Depth.</b> The depth of two crossing triangles is their penetration depth: the shortest
 * distance one of them must move, in any direction, to come free of the other (to touch it at
 * most). By the separating-axis theorem it is the least, over the eleven axes that can separate
 * two triangles (both normals and the nine cross products of an edge of each), of the overlap of
 * their projections on the axis, {@code min(maxA - minB, maxB - minA)}. Along B's normal that
 * overlap is how far the part of A on its shorter side of B's plane reaches beyond it, and the
 * other way round along A's normal; an axis of two edges is less only where the triangles hook
 * each other near their edges. So a sheet poked 4 T deep through another crosses it 4 T deep,
 * two sheets crossed in an X as deep as the nearer of their corners to the other's plane, and
 * neighbours that share an edge or a corner (or meet within the touching distance) not at all.
 * The depth does not depend on how far the triangles reach elsewhere in the direction of the
 * segment: it measures a crossing, not its length. It is the depth of two triangles, not of
 * their faces: where a fan's diagonal crosses the other face, an axis across that diagonal may
 * free the pair a little sooner than the whole face would come free (by the cosine of the
 * diagonal's slant to the other face: 0.9998 T for a cap 2 T high across a strip as wide as 1).
 * The minimum over eleven axes is exact for two triangles: they are convex, and every facet of
 * their Minkowski difference is normal to one of those axes.
 *
 * <p><b>Coplanar overlap.</b> Two triangles that lie in one plane (each within the touching
 * distance of the other's plane) have no depth across it, yet two layers of paper at one height
 * that overlap are a collision. They are reported as {@link #COPLANAR} when their overlap in the
 * plane is deeper than the touching distance: the shortest slide in the plane that parts them
 * (the same separating-axis measure, over the six in-plane edge normals), so that neighbours in
 * one plane, which share an edge, do not count.
 *
 * <p>Allocation-free: an instance holds its scratch and its last answer, so each thread keeps one.
 * Not thread-safe.
 */
final class TriangleContact {
    /** The triangles are apart, or touch within the touching distance. */
    static final int APART = 0;
    /** They cross deeper than the touching distance: {@link #depth} and {@link #segment} say how. */
    static final int CROSSING = 1;
    /** They lie in one plane and overlap deeper than the touching distance: {@link #depth} is that overlap. */
    static final int COPLANAR = 2;

    /**
     * A triangle whose doubled area is at most this times its longest edge squared has no normal
     * worth the name (its smallest angle below about 1e-10 radians) and is skipped: it has no area
     * to cross with, and the fan it belongs to has triangles that do.
     */
    static final double DEGENERATE = 1e-10;
    /**
     * Two edges closer to parallel than this sine give no axis of their own: their cross product
     * is rounding. Leaving an axis out can only make a depth larger, never hide a crossing.
     */
    static final double PARALLEL_EDGES = 1e-6;

    /** After {@link #test}: the depth of a crossing, the in-plane overlap of a coplanar pair (same units as the input). */
    double depth;
    /** After a crossing: the segment the triangles share, x0 y0 z0 x1 y1 z1; after a coplanar overlap, the overlap's longest chord. */
    final double[] segment = new double[6];
    /** After a coplanar overlap: the area of the overlap. */
    double area;

    // Scratch: the corners of A and B (x y z each), their edges, unit normals, distances to the other's plane.
    private final double[] a = new double[9];
    private final double[] b = new double[9];
    private final double[] edgesA = new double[9];
    private final double[] edgesB = new double[9];
    private final double[] normalA = new double[3];
    private final double[] normalB = new double[3];
    /** dA[k]: corner k of A's signed distance to B's plane; dB the other way. */
    private final double[] dA = new double[3];
    private final double[] dB = new double[3];
    /** The coplanar case: both triangles in A's plane (u v each), and the clipped overlap polygon. */
    private final double[] flatA = new double[6];
    private final double[] flatB = new double[6];
    private final double[] polygon = new double[2 * 9];
    private final double[] clipped = new double[2 * 9];

    /**
     * Tests triangle (a0, a1, a2) against (b0, b1, b2), corners given as vertex indices into
     * {@code xyz} (x y z interleaved).
     *
     * @param touch the touching distance: pairs that meet no deeper than this are {@link #APART}
     * @return {@link #APART}, {@link #CROSSING} or {@link #COPLANAR}; the last two set {@link #depth}
     *     and {@link #segment}, a coplanar overlap also {@link #area}
     */
    int test(double[] xyz, int a0, int a1, int a2, int b0, int b1, int b2, double touch) {
        load(xyz, a0, a1, a2, a);
        load(xyz, b0, b1, b2, b);
        if (!frame(a, edgesA, normalA) || !frame(b, edgesB, normalB)) {
            return APART;
        }
        // Each triangle against the other's plane: how far it reaches to either side.
        double aAbove = Double.NEGATIVE_INFINITY;
        double aBelow = Double.NEGATIVE_INFINITY;
        double bAbove = Double.NEGATIVE_INFINITY;
        double bBelow = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            double d = normalB[0] * (a[3 * k] - b[0]) + normalB[1] * (a[3 * k + 1] - b[1]) + normalB[2] * (a[3 * k + 2] - b[2]);
            dA[k] = d;
            aAbove = Math.max(aAbove, d);
            aBelow = Math.max(aBelow, -d);
        }
        double reachA = Math.min(aAbove, aBelow);
        if (reachA <= touch && Math.max(aAbove, aBelow) > touch) {
            // A only touches B's plane from one side (the usual case: a layer above another).
            return APART;
        }
        for (int k = 0; k < 3; k++) {
            double d = normalA[0] * (b[3 * k] - a[0]) + normalA[1] * (b[3 * k + 1] - a[1]) + normalA[2] * (b[3 * k + 2] - a[2]);
            dB[k] = d;
            bAbove = Math.max(bAbove, d);
            bBelow = Math.max(bBelow, -d);
        }
        double reachB = Math.min(bAbove, bBelow);
        if (Math.max(aAbove, aBelow) <= touch && Math.max(bAbove, bBelow) <= touch) {
            return coplanar(touch);
        }
        double depth = Math.min(reachA, reachB);
        if (depth <= touch) {
            return APART;
        }
        // The nine axes of an edge of each.
        for (int i = 0; i < 3; i++) {
            double ex = edgesA[3 * i];
            double ey = edgesA[3 * i + 1];
            double ez = edgesA[3 * i + 2];
            double eLength = Math.sqrt(ex * ex + ey * ey + ez * ez);
            for (int j = 0; j < 3; j++) {
                double fx = edgesB[3 * j];
                double fy = edgesB[3 * j + 1];
                double fz = edgesB[3 * j + 2];
                double nx = ey * fz - ez * fy;
                double ny = ez * fx - ex * fz;
                double nz = ex * fy - ey * fx;
                double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
                if (!(length > PARALLEL_EDGES * eLength * Math.sqrt(fx * fx + fy * fy + fz * fz))) {
                    continue;
                }
                nx /= length;
                ny /= length;
                nz /= length;
                double minA = Double.POSITIVE_INFINITY;
                double maxA = Double.NEGATIVE_INFINITY;
                double minB = Double.POSITIVE_INFINITY;
                double maxB = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < 3; k++) {
                    double p = nx * a[3 * k] + ny * a[3 * k + 1] + nz * a[3 * k + 2];
                    minA = Math.min(minA, p);
                    maxA = Math.max(maxA, p);
                    double q = nx * b[3 * k] + ny * b[3 * k + 1] + nz * b[3 * k + 2];
                    minB = Math.min(minB, q);
                    maxB = Math.max(maxB, q);
                }
                depth = Math.min(depth, Math.min(maxA - minB, maxB - minA));
                if (depth <= touch) {
                    return APART;
                }
            }
        }
        this.depth = depth;
        segment();
        return CROSSING;
    }

    private static void load(double[] xyz, int v0, int v1, int v2, double[] out) {
        System.arraycopy(xyz, 3 * v0, out, 0, 3);
        System.arraycopy(xyz, 3 * v1, out, 3, 3);
        System.arraycopy(xyz, 3 * v2, out, 6, 3);
    }

    /**
     * Whether two triangles plainly do not cross: one lies on one side of the other's plane, no
     * deeper than the touching distance and not all of it within it. This is the first thing
     * {@link #test} decides, answered the same from normals computed beforehand by {@link #frame}
     * (most pairs whose boxes meet are layers of a stack, one above the other).
     *
     * @param normals unit normals, x y z of each triangle
     * @param tri the corners of each triangle, three vertex indices each
     */
    static boolean apart(double[] xyz, double[] normals, int[] tri, int i, int j, double touch) {
        return oneSided(xyz, normals, tri, i, j, touch) || oneSided(xyz, normals, tri, j, i, touch);
    }

    /** Whether triangle i lies on one side of triangle j's plane, as apart says. */
    private static boolean oneSided(double[] xyz, double[] normals, int[] tri, int i, int j, double touch) {
        int origin = 3 * tri[3 * j];
        double nx = normals[3 * j];
        double ny = normals[3 * j + 1];
        double nz = normals[3 * j + 2];
        double above = Double.NEGATIVE_INFINITY;
        double below = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            int v = 3 * tri[3 * i + k];
            double d = nx * (xyz[v] - xyz[origin]) + ny * (xyz[v + 1] - xyz[origin + 1]) + nz * (xyz[v + 2] - xyz[origin + 2]);
            above = Math.max(above, d);
            below = Math.max(below, -d);
        }
        return Math.min(above, below) <= touch && Math.max(above, below) > touch;
    }

    /**
     * The edges (corner k to k + 1, x y z each) and the unit normal of triangle t (its corners x y
     * z each); false when it is degenerate, as {@link #DEGENERATE} says.
     */
    static boolean frame(double[] t, double[] edges, double[] normal) {
        double longest = 0;
        for (int k = 0; k < 3; k++) {
            int next = (k + 1) % 3;
            double squared = 0;
            for (int axis = 0; axis < 3; axis++) {
                double e = t[3 * next + axis] - t[3 * k + axis];
                edges[3 * k + axis] = e;
                squared += e * e;
            }
            longest = Math.max(longest, squared);
        }
        double nx = edges[1] * edges[8] - edges[2] * edges[7];
        double ny = edges[2] * edges[6] - edges[0] * edges[8];
        double nz = edges[0] * edges[7] - edges[1] * edges[6];
        // Edge 2 runs from corner 2 to corner 0, so e0 x e2 points against e0 x (c2 - c0).
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(length > DEGENERATE * longest)) {
            return false;
        }
        normal[0] = -nx / length;
        normal[1] = -ny / length;
        normal[2] = -nz / length;
        return true;
    }

    /**
     * The segment of a crossing (Möller's intervals): where each triangle meets the other's plane
     * is a segment on the planes' common line; the crossing is where the two overlap.
     */
    private void segment() {
        double lx = normalA[1] * normalB[2] - normalA[2] * normalB[1];
        double ly = normalA[2] * normalB[0] - normalA[0] * normalB[2];
        double lz = normalA[0] * normalB[1] - normalA[1] * normalB[0];
        // A's two points on B's plane go to segment[0..5]; B's to scratch, then the overlap is kept.
        double[] ends = polygon;
        cut(a, dA, ends, 0);
        cut(b, dB, ends, 6);
        double tA0 = lx * ends[0] + ly * ends[1] + lz * ends[2];
        double tA1 = lx * ends[3] + ly * ends[4] + lz * ends[5];
        double tB0 = lx * ends[6] + ly * ends[7] + lz * ends[8];
        double tB1 = lx * ends[9] + ly * ends[10] + lz * ends[11];
        int loA = tA0 <= tA1 ? 0 : 3;
        int hiA = 3 - loA;
        int loB = tB0 <= tB1 ? 6 : 9;
        int hiB = 15 - loB;
        double tLoA = Math.min(tA0, tA1);
        double tHiA = Math.max(tA0, tA1);
        double tLoB = Math.min(tB0, tB1);
        double tHiB = Math.max(tB0, tB1);
        int from = tLoA >= tLoB ? loA : loB;
        int to = tHiA <= tHiB ? hiA : hiB;
        double x0 = ends[from];
        double y0 = ends[from + 1];
        double z0 = ends[from + 2];
        segment[3] = ends[to];
        segment[4] = ends[to + 1];
        segment[5] = ends[to + 2];
        segment[0] = x0;
        segment[1] = y0;
        segment[2] = z0;
    }

    /** The two points where triangle t's edges cross the plane its corners' distances d are to, into out[at .. at + 5]. */
    private static void cut(double[] t, double[] d, double[] out, int at) {
        int found = 0;
        for (int k = 0; k < 3 && found < 2; k++) {
            int next = (k + 1) % 3;
            if ((d[k] > 0) == (d[next] > 0)) {
                continue;
            }
            // d[k] and d[next] differ in sign (one may be 0), so the denominator is not 0.
            double s = d[k] / (d[k] - d[next]);
            for (int axis = 0; axis < 3; axis++) {
                out[at + 3 * found + axis] = t[3 * k + axis] + s * (t[3 * next + axis] - t[3 * k + axis]);
            }
            found++;
        }
    }

    /** Two triangles in A's plane: their overlap in it, as the class comment says. */
    private int coplanar(double touch) {
        // A basis of A's plane: u along A's first edge, v = n x u.
        double ux = edgesA[0];
        double uy = edgesA[1];
        double uz = edgesA[2];
        double length = Math.sqrt(ux * ux + uy * uy + uz * uz);
        ux /= length;
        uy /= length;
        uz /= length;
        double vx = normalA[1] * uz - normalA[2] * uy;
        double vy = normalA[2] * ux - normalA[0] * uz;
        double vz = normalA[0] * uy - normalA[1] * ux;
        for (int k = 0; k < 3; k++) {
            double ax = a[3 * k] - a[0];
            double ay = a[3 * k + 1] - a[1];
            double az = a[3 * k + 2] - a[2];
            flatA[2 * k] = ux * ax + uy * ay + uz * az;
            flatA[2 * k + 1] = vx * ax + vy * ay + vz * az;
            double bx = b[3 * k] - a[0];
            double by = b[3 * k + 1] - a[1];
            double bz = b[3 * k + 2] - a[2];
            flatB[2 * k] = ux * bx + uy * by + uz * bz;
            flatB[2 * k + 1] = vx * bx + vy * by + vz * bz;
        }
        double overlap = Math.min(flatOverlap(flatA, flatA, flatB), flatOverlap(flatB, flatA, flatB));
        if (!(overlap > touch)) {
            return APART;
        }
        depth = overlap;
        clip(ux, uy, uz, vx, vy, vz);
        return COPLANAR;
    }

    /** The least overlap of flat triangles p and q along the normals of the edges of {@code edgesOf}. */
    private static double flatOverlap(double[] edgesOf, double[] p, double[] q) {
        double least = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            int next = (k + 1) % 3;
            double nx = -(edgesOf[2 * next + 1] - edgesOf[2 * k + 1]);
            double ny = edgesOf[2 * next] - edgesOf[2 * k];
            double length = Math.sqrt(nx * nx + ny * ny);
            nx /= length;
            ny /= length;
            double minP = Double.POSITIVE_INFINITY;
            double maxP = Double.NEGATIVE_INFINITY;
            double minQ = Double.POSITIVE_INFINITY;
            double maxQ = Double.NEGATIVE_INFINITY;
            for (int c = 0; c < 3; c++) {
                double s = nx * p[2 * c] + ny * p[2 * c + 1];
                minP = Math.min(minP, s);
                maxP = Math.max(maxP, s);
                double t = nx * q[2 * c] + ny * q[2 * c + 1];
                minQ = Math.min(minQ, t);
                maxQ = Math.max(maxQ, t);
            }
            least = Math.min(least, Math.min(maxP - minQ, maxQ - minP));
        }
        return least;
    }

    /**
     * The overlap polygon of the flat triangles (B clipped by A's three half-planes,
     * Sutherland-Hodgman): its area, and its longest chord back in space as the segment.
     */
    private void clip(double ux, double uy, double uz, double vx, double vy, double vz) {
        double orientation = (flatA[2] - flatA[0]) * (flatA[5] - flatA[1]) - (flatA[3] - flatA[1]) * (flatA[4] - flatA[0]);
        double sign = orientation >= 0 ? 1 : -1;
        System.arraycopy(flatB, 0, polygon, 0, 6);
        double[] in = polygon;
        double[] out = clipped;
        int n = 3;
        for (int k = 0; k < 3 && n > 0; k++) {
            int next = (k + 1) % 3;
            double px = flatA[2 * k];
            double py = flatA[2 * k + 1];
            double ex = flatA[2 * next] - px;
            double ey = flatA[2 * next + 1] - py;
            int m = 0;
            for (int c = 0; c < n; c++) {
                int d = (c + 1) % n;
                double sc = sign * (ex * (in[2 * c + 1] - py) - ey * (in[2 * c] - px));
                double sd = sign * (ex * (in[2 * d + 1] - py) - ey * (in[2 * d] - px));
                if (sc >= 0) {
                    out[2 * m] = in[2 * c];
                    out[2 * m + 1] = in[2 * c + 1];
                    m++;
                }
                if ((sc >= 0) != (sd >= 0)) {
                    double s = sc / (sc - sd);
                    out[2 * m] = in[2 * c] + s * (in[2 * d] - in[2 * c]);
                    out[2 * m + 1] = in[2 * c + 1] + s * (in[2 * d + 1] - in[2 * c + 1]);
                    m++;
                }
            }
            double[] swap = in;
            in = out;
            out = swap;
            n = m;
        }
        double twice = 0;
        double longest = -1;
        int from = 0;
        int to = 0;
        for (int c = 0; c < n; c++) {
            int d = (c + 1) % n;
            twice += in[2 * c] * in[2 * d + 1] - in[2 * d] * in[2 * c + 1];
            for (int e = c + 1; e < n; e++) {
                double dx = in[2 * e] - in[2 * c];
                double dy = in[2 * e + 1] - in[2 * c + 1];
                if (dx * dx + dy * dy > longest) {
                    longest = dx * dx + dy * dy;
                    from = c;
                    to = e;
                }
            }
        }
        area = Math.abs(twice) / 2;
        for (int end = 0; end < 2; end++) {
            int c = end == 0 ? from : to;
            double s = n == 0 ? 0 : in[2 * c];
            double t = n == 0 ? 0 : in[2 * c + 1];
            segment[3 * end] = a[0] + s * ux + t * vx;
            segment[3 * end + 1] = a[1] + s * uy + t * vy;
            segment[3 * end + 2] = a[2] + s * uz + t * vz;
        }
    }
}
