package ifold.mesh;

/**
 * Whether a surface of triangles runs through itself: two of its triangles that cross, or lie
 * over each other in one plane, beyond the corners and edges they share. Topology cannot see it
 * (a quad with a wrong corner can make a valid, even manifold, mesh that folds back over its
 * neighbours), and no paper can be laid on such a surface without passing through itself.
 *
 * <p>Triangles are told apart by what they share, not by moving them: two that share an edge
 * cross only where they lie in one plane on the same side of it (folded flat onto each other);
 * two that share a corner cross where an edge away from that corner passes through the other, or,
 * in one plane, where no axis of their edges parts them but at the corner; two that share nothing
 * cross where an edge of one passes through the other, or, in one plane, where their shadows
 * overlap. Touching is not crossing: a crossing must be more than a billionth of the triangles'
 * size inside both, so that a corner on another's edge (a T-junction) is not one.
 */
public final class SelfCrossings {
    private SelfCrossings() {
    }

    /** The sizes checked, across the surface's box: products of four lengths stay within doubles (geom.Tolerance's range). */
    private static final double SMALLEST = 1e-60;
    private static final double LARGEST = 1e60;

    /** The most cells along an axis: a cell number then fits in 30 bits. */
    private static final int CELLS = 1024;

    /** How far inside, relative to the triangles' size, a crossing must lie: less is touching. */
    private static final double INSIDE = 1e-9;

    /**
     * The first two triangles (faces of three corners) that cross or overlap, by face index, or
     * null where none does. Faces that are not triangles are passed over. The triangles are
     * filed in a grid of cells about their mean size, grown until they fill at most eight cells
     * each on average, so that its memory is linear in the triangles whatever their sizes.
     */
    public static int[] first(IndexedPolygons mesh) {
        int n = mesh.faceCount();
        double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double sizes = 0;
        int triangles = 0;
        for (int f = 0; f < n; f++) {
            if (mesh.faceSize(f) != 3) {
                continue;
            }
            triangles++;
            double[] b = box(mesh, f);
            for (int axis = 0; axis < 3; axis++) {
                box[axis] = Math.min(box[axis], b[axis]);
                box[3 + axis] = Math.max(box[3 + axis], b[3 + axis]);
            }
            sizes += Math.max(b[3] - b[0], Math.max(b[4] - b[1], b[5] - b[2]));
        }
        double across = Math.max(box[3] - box[0], Math.max(box[4] - box[1], box[5] - box[2]));
        if (triangles < 2 || !(across >= SMALLEST && across <= LARGEST)) {
            return null; // beyond the sizes iFold computes with: the wrap refuses such a model for its size
        }
        double cell = Math.max(sizes / triangles, across / (CELLS - 1));
        // One big triangle among many small ones would fill a cube of cells: the cells grow
        // until the entries are few (a 200,000-triangle model with one across it ran out of memory).
        long budget = 8L * triangles + 64;
        while (entries(mesh, box, cell, budget) > budget) {
            cell *= 2;
        }
        // Each triangle in each cell its box meets, as (cell << 32 | face), sorted: a cell's
        // triangles then lie side by side, without a map of lists.
        long[] entries = new long[(int) Math.min(Integer.MAX_VALUE - 8, Math.max(16, entries(mesh, box, cell, budget)))];
        int count = 0;
        for (int f = 0; f < n; f++) {
            if (mesh.faceSize(f) != 3) {
                continue;
            }
            double[] b = box(mesh, f);
            int[] from = cellOf(b, 0, box, cell);
            int[] to = cellOf(b, 3, box, cell);
            for (int i = from[0]; i <= to[0]; i++) {
                for (int j = from[1]; j <= to[1]; j++) {
                    for (int k = from[2]; k <= to[2]; k++) {
                        entries[count++] = ((((long) i * CELLS + j) * CELLS + k) << 32) | f;
                    }
                }
            }
        }
        java.util.Arrays.sort(entries, 0, count);
        double[] a = new double[9];
        double[] b = new double[9];
        int[] va = new int[3];
        int[] vb = new int[3];
        int[] best = null;
        for (int start = 0; start < count; ) {
            int end = start + 1;
            while (end < count && entries[end] >>> 32 == entries[start] >>> 32) {
                end++;
            }
            for (int x = start; x < end; x++) {
                int f = (int) entries[x];
                corners(mesh, f, a, va);
                for (int y = x + 1; y < end; y++) {
                    int g = (int) entries[y];
                    if (best != null && f >= best[0] && (f > best[0] || g >= best[1])) {
                        break; // in the cell's order of faces: every pair after this one comes later
                    }
                    corners(mesh, g, b, vb);
                    if (boxesMeet(a, b) && cross(a, va, b, vb)) {
                        best = new int[] {f, g}; // f < g: entries of a cell are sorted by face
                        break;
                    }
                }
            }
            start = end;
        }
        return best;
    }

    /** The entries a grid of this cell size holds, counted up to just past {@code stop}. */
    private static long entries(IndexedPolygons mesh, double[] box, double cell, long stop) {
        long total = 0;
        for (int f = 0; f < mesh.faceCount() && total <= stop; f++) {
            if (mesh.faceSize(f) == 3) {
                double[] b = box(mesh, f);
                int[] from = cellOf(b, 0, box, cell);
                int[] to = cellOf(b, 3, box, cell);
                total += (long) (to[0] - from[0] + 1) * (to[1] - from[1] + 1) * (to[2] - from[2] + 1);
            }
        }
        return total;
    }

    private static double[] box(IndexedPolygons mesh, int f) {
        double[] b = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int k = 0; k < 3; k++) {
            int v = mesh.faceVertex(f, k);
            for (int axis = 0; axis < 3; axis++) {
                double c = mesh.coordinate(v, axis);
                b[axis] = Math.min(b[axis], c);
                b[3 + axis] = Math.max(b[3 + axis], c);
            }
        }
        return b;
    }

    private static int[] cellOf(double[] b, int at, double[] box, double cell) {
        int[] c = new int[3];
        for (int axis = 0; axis < 3; axis++) {
            c[axis] = (int) Math.min(CELLS - 1, Math.max(0, Math.floor((b[at + axis] - box[axis]) / cell)));
        }
        return c;
    }

    /** Triangle f's corners (9 numbers) and their vertices. */
    private static void corners(IndexedPolygons mesh, int f, double[] out, int[] vertices) {
        for (int k = 0; k < 3; k++) {
            vertices[k] = mesh.faceVertex(f, k);
            for (int axis = 0; axis < 3; axis++) {
                out[3 * k + axis] = mesh.coordinate(vertices[k], axis);
            }
        }
    }

    private static boolean boxesMeet(double[] a, double[] b) {
        for (int axis = 0; axis < 3; axis++) {
            double aMin = Math.min(a[axis], Math.min(a[3 + axis], a[6 + axis]));
            double aMax = Math.max(a[axis], Math.max(a[3 + axis], a[6 + axis]));
            double bMin = Math.min(b[axis], Math.min(b[3 + axis], b[6 + axis]));
            double bMax = Math.max(b[axis], Math.max(b[3 + axis], b[6 + axis]));
            if (aMax < bMin || bMax < aMin) {
                return false;
            }
        }
        return true;
    }

    /** Whether triangles a and b (9 numbers each, vertices va and vb) cross beyond what they share. */
    static boolean cross(double[] a, int[] va, double[] b, int[] vb) {
        double[] n = normal(a);
        double[] m = normal(b);
        if (!(length(n) > 0) || !(length(m) > 0)) {
            return false; // a triangle without area holds no paper
        }
        int shared = 0;
        int sharedA = -1;
        int sharedB = -1;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                if (va[i] == vb[j]) {
                    shared++;
                    sharedA = i;
                    sharedB = j;
                }
            }
        }
        double span = span(a, b);
        boolean coplanar = coplanar(a, b, m, span) && coplanar(b, a, n, span);
        if (shared == 3) {
            return true; // the same triangle twice
        }
        if (shared == 2) {
            // Folded flat onto each other: one plane, the two far corners on one side of the edge.
            if (!coplanar) {
                return false;
            }
            int farA = farCorner(va, vb);
            int farB = farCorner(vb, va);
            int e0 = sharedVertexIndex(va, vb, 0);
            int e1 = sharedVertexIndex(va, vb, 1);
            double sa = sideOfEdge(a, 3 * e0, 3 * e1, a, 3 * farA, n);
            double sb = sideOfEdge(a, 3 * e0, 3 * e1, b, 3 * farB, n);
            return sa * sb > 0;
        }
        if (coplanar) {
            return overlapInPlane(a, b, n, span);
        }
        if (shared == 1) {
            // Planes meet in a line through the shared corner: only an edge away from it can pass through the other.
            return segmentCrosses(a, (sharedA + 1) % 3, (sharedA + 2) % 3, b, span)
                    || segmentCrosses(b, (sharedB + 1) % 3, (sharedB + 2) % 3, a, span);
        }
        for (int e = 0; e < 3; e++) {
            if (segmentCrosses(a, e, (e + 1) % 3, b, span) || segmentCrosses(b, e, (e + 1) % 3, a, span)) {
                return true;
            }
        }
        return false;
    }

    /** The corner of {@code v} that {@code w} does not have. */
    private static int farCorner(int[] v, int[] w) {
        for (int i = 0; i < 3; i++) {
            if (v[i] != w[0] && v[i] != w[1] && v[i] != w[2]) {
                return i;
            }
        }
        return 0;
    }

    /** The corner (of {@code v}) of the k-th vertex {@code v} shares with {@code w}. */
    private static int sharedVertexIndex(int[] v, int[] w, int k) {
        for (int i = 0; i < 3; i++) {
            if (v[i] == w[0] || v[i] == w[1] || v[i] == w[2]) {
                if (k-- == 0) {
                    return i;
                }
            }
        }
        return 0;
    }

    /** Which side of the line from p to q (corners of t) point r of s lies, in the plane of normal n. */
    private static double sideOfEdge(double[] t, int p, int q, double[] s, int r, double[] n) {
        double ex = t[q] - t[p];
        double ey = t[q + 1] - t[p + 1];
        double ez = t[q + 2] - t[p + 2];
        double dx = s[r] - t[p];
        double dy = s[r + 1] - t[p + 1];
        double dz = s[r + 2] - t[p + 2];
        return (ey * dz - ez * dy) * n[0] + (ez * dx - ex * dz) * n[1] + (ex * dy - ey * dx) * n[2];
    }

    /** Whether every corner of {@code t} lies within a billionth of the size of the plane of {@code plane} (normal n). */
    private static boolean coplanar(double[] t, double[] plane, double[] n, double span) {
        double tolerance = INSIDE * length(n) * span;
        for (int k = 0; k < 9; k += 3) {
            if (Math.abs(side(t, k, n, plane)) > tolerance) {
                return false;
            }
        }
        return true;
    }

    private static double span(double[] a, double[] b) {
        double s = 0;
        for (int k = 0; k < 9; k++) {
            s = Math.max(s, Math.max(Math.abs(a[k] - a[k % 3]), Math.abs(b[k] - b[k % 3])));
        }
        return Math.max(s, Double.MIN_NORMAL);
    }

    private static double[] normal(double[] t) {
        double ux = t[3] - t[0];
        double uy = t[4] - t[1];
        double uz = t[5] - t[2];
        double vx = t[6] - t[0];
        double vy = t[7] - t[1];
        double vz = t[8] - t[2];
        return new double[] {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
    }

    private static double length(double[] v) {
        return Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }

    /** The height of corner {@code at} of {@code t} over the plane of {@code plane} (normal {@code n}), times |n|. */
    private static double side(double[] t, int at, double[] n, double[] plane) {
        return n[0] * (t[at] - plane[0]) + n[1] * (t[at + 1] - plane[1]) + n[2] * (t[at + 2] - plane[2]);
    }

    /**
     * Whether edge (p, q) of triangle s passes through triangle t: from one side of its plane to
     * the other, each end more than a billionth of the size away, at a point more than that inside
     * every edge of t.
     */
    private static boolean segmentCrosses(double[] s, int p, int q, double[] t, double span) {
        double[] n = normal(t);
        double nl = length(n);
        double tolerance = INSIDE * nl * span;
        double hp = side(s, 3 * p, n, t);
        double hq = side(s, 3 * q, n, t);
        if (!(hp > tolerance && hq < -tolerance || hp < -tolerance && hq > tolerance)) {
            return false;
        }
        double w = hp / (hp - hq);
        double[] x = new double[3];
        for (int axis = 0; axis < 3; axis++) {
            x[axis] = s[3 * p + axis] + w * (s[3 * q + axis] - s[3 * p + axis]);
        }
        for (int e = 0; e < 3; e++) {
            int i = 3 * e;
            int j = 3 * ((e + 1) % 3);
            double edge = Math.sqrt((t[j] - t[i]) * (t[j] - t[i]) + (t[j + 1] - t[i + 1]) * (t[j + 1] - t[i + 1])
                    + (t[j + 2] - t[i + 2]) * (t[j + 2] - t[i + 2]));
            // (edge × (x − corner)) · n / (|edge| |n|): how far inside that edge x lies.
            if (sideOfEdge(t, i, j, x, 0, n) <= INSIDE * span * edge * nl) {
                return false;
            }
        }
        return true;
    }

    /** Whether two triangles of one plane (normal n) overlap by more than touching: no edge's normal in the plane parts them. */
    private static boolean overlapInPlane(double[] a, double[] b, double[] n, double span) {
        // Drop the axis the normal is longest along: the triangles' shadows keep their overlap.
        int drop = Math.abs(n[0]) >= Math.abs(n[1]) && Math.abs(n[0]) >= Math.abs(n[2]) ? 0 : Math.abs(n[1]) >= Math.abs(n[2]) ? 1 : 2;
        int u = (drop + 1) % 3;
        int v = (drop + 2) % 3;
        double[] p = {a[u], a[v], a[3 + u], a[3 + v], a[6 + u], a[6 + v]};
        double[] q = {b[u], b[v], b[3 + u], b[3 + v], b[6 + u], b[6 + v]};
        return !separates(p, q, span) && !separates(q, p, span);
    }

    private static boolean separates(double[] p, double[] q, double span) {
        for (int e = 0; e < 3; e++) {
            int i = 2 * e;
            int j = 2 * ((e + 1) % 3);
            double nx = p[j + 1] - p[i + 1];
            double ny = p[i] - p[j];
            double touch = INSIDE * span * Math.sqrt(nx * nx + ny * ny);
            double pMin = Double.POSITIVE_INFINITY;
            double pMax = Double.NEGATIVE_INFINITY;
            double qMin = Double.POSITIVE_INFINITY;
            double qMax = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < 3; k++) {
                double dp = nx * p[2 * k] + ny * p[2 * k + 1];
                double dq = nx * q[2 * k] + ny * q[2 * k + 1];
                pMin = Math.min(pMin, dp);
                pMax = Math.max(pMax, dp);
                qMin = Math.min(qMin, dq);
                qMax = Math.max(qMax, dq);
            }
            if (pMax <= qMin + touch || qMax <= pMin + touch) {
                return true; // apart, or touching along a line or at a point
            }
        }
        return false;
    }
}
