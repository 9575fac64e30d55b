package ifold.mesh;

/**
 * Whether a surface of triangles runs through itself: two of its triangles that cross, or lie
 * over each other in one plane, beyond the corners and edges they share. Topology cannot see it
 * (a quad with a wrong corner can make a valid, even manifold, mesh that folds back over its
 * neighbours), and no paper can be laid on such a surface without passing through itself.
 *
 * <p>Each pair of triangles whose boxes meet is tested with both shrunk towards their centres
 * by a millionth: triangles that only share a corner or an edge then part, and any that cross
 * or overlap still meet. The test itself is exact in its signs up to rounding: a segment crosses
 * a triangle where it changes side of the triangle's plane within it; triangles in one plane
 * overlap where no axis of their edges separates them.
 */
public final class SelfCrossings {
    private SelfCrossings() {
    }

    /** The sizes checked, across the surface's box: products of four lengths stay within doubles (geom.Tolerance's range). */
    private static final double SMALLEST = 1e-60;
    private static final double LARGEST = 1e60;

    /** How far each triangle is shrunk towards its centre before the test, as a fraction of it. */
    private static final double SHRINK = 1e-6;

    /**
     * The first two triangles (faces of three corners) that cross or overlap, by face index, or
     * null where none does. Faces that are not triangles are passed over. Linear in the faces
     * for a surface whose triangles are about the same size (a grid of cells about their size).
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
        if (!(across >= SMALLEST && across <= LARGEST)) {
            return null; // beyond the sizes iFold computes with: the wrap refuses such a model for its size
        }
        // Cells about a triangle's mean size, at most CELLS along an axis.
        double cell = Math.max(sizes / Math.max(1, triangles), across / (CELLS - 1));
        if (triangles < 2 || !(cell > 0) || !Double.isFinite(cell)) {
            return null;
        }
        // Each triangle in each cell its box meets, as (cell << 32 | face), sorted: a cell's
        // triangles then lie side by side, without a map of lists (a 1.4M-triangle model's
        // grid of boxed lists took 19 s and 120 MB more than its wrap's refusal).
        long[] entries = new long[Math.max(16, 2 * triangles)];
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
                        if (count == entries.length) {
                            entries = java.util.Arrays.copyOf(entries, 2 * entries.length);
                        }
                        entries[count++] = ((((long) i * CELLS + j) * CELLS + k) << 32) | f;
                    }
                }
            }
        }
        java.util.Arrays.sort(entries, 0, count);
        double[] a = new double[9];
        double[] b = new double[9];
        int[] best = null;
        for (int start = 0; start < count; ) {
            int end = start + 1;
            while (end < count && entries[end] >>> 32 == entries[start] >>> 32) {
                end++;
            }
            for (int x = start; x < end; x++) {
                int f = (int) entries[x];
                shrunk(mesh, f, a);
                for (int y = x + 1; y < end; y++) {
                    int g = (int) entries[y];
                    if (best != null && f >= best[0] && (f > best[0] || g >= best[1])) {
                        break; // in the cell's order of faces: every pair after this one comes later
                    }
                    shrunk(mesh, g, b);
                    if (boxesMeet(a, b) && meet(a, b)) {
                        best = new int[] {f, g}; // f < g: entries of a cell are sorted by face
                        break;
                    }
                }
            }
            start = end;
        }
        return best;
    }

    /** The most cells along an axis: a cell number then fits in 30 bits. */
    private static final int CELLS = 1024;

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

    /** Triangle f's corners, each moved a millionth of the way to its centre. */
    private static void shrunk(IndexedPolygons mesh, int f, double[] out) {
        double[] centre = new double[3];
        for (int k = 0; k < 3; k++) {
            for (int axis = 0; axis < 3; axis++) {
                out[3 * k + axis] = mesh.coordinate(mesh.faceVertex(f, k), axis);
                centre[axis] += out[3 * k + axis] / 3;
            }
        }
        for (int k = 0; k < 9; k++) {
            out[k] += (centre[k % 3] - out[k]) * SHRINK;
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

    /** Whether two triangles (9 numbers each) share a point. */
    static boolean meet(double[] a, double[] b) {
        double[] n = normal(a);
        double[] m = normal(b);
        double scale = Math.max(length(n), length(m));
        if (!(scale > 0)) {
            return false; // a triangle without area holds no paper
        }
        double sa = side(a, 0, m, b);
        double sb = side(a, 3, m, b);
        double sc = side(a, 6, m, b);
        double tolerance = 1e-9 * length(m) * span(a, b); // corners within a billionth of the size of b's plane
        if (Math.abs(sa) <= tolerance && Math.abs(sb) <= tolerance && Math.abs(sc) <= tolerance) {
            return coplanarOverlap(a, b, m);
        }
        for (int e = 0; e < 3; e++) {
            if (segmentCrosses(a, e, (e + 1) % 3, b) || segmentCrosses(b, e, (e + 1) % 3, a)) {
                return true;
            }
        }
        return false;
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

    /** Whether edge (p, q) of triangle s crosses triangle t, not in its plane. */
    private static boolean segmentCrosses(double[] s, int p, int q, double[] t) {
        double[] n = normal(t);
        double hp = side(s, 3 * p, n, t);
        double hq = side(s, 3 * q, n, t);
        if (hp > 0 && hq > 0 || hp < 0 && hq < 0 || hp == hq) {
            return false;
        }
        double w = hp / (hp - hq);
        double[] x = new double[3];
        for (int axis = 0; axis < 3; axis++) {
            x[axis] = s[3 * p + axis] + w * (s[3 * q + axis] - s[3 * p + axis]);
        }
        // Inside t: on the same side of each of its edges as its normal says.
        for (int e = 0; e < 3; e++) {
            int i = 3 * e;
            int j = 3 * ((e + 1) % 3);
            double ex = t[j] - t[i];
            double ey = t[j + 1] - t[i + 1];
            double ez = t[j + 2] - t[i + 2];
            double dx = x[0] - t[i];
            double dy = x[1] - t[i + 1];
            double dz = x[2] - t[i + 2];
            double cx = ey * dz - ez * dy;
            double cy = ez * dx - ex * dz;
            double cz = ex * dy - ey * dx;
            if (cx * n[0] + cy * n[1] + cz * n[2] < 0) {
                return false;
            }
        }
        return true;
    }

    /** Whether two triangles of one plane (normal n) overlap: no edge's normal in the plane separates them. */
    private static boolean coplanarOverlap(double[] a, double[] b, double[] n) {
        // Drop the axis the normal is longest along: the triangles' shadows keep their overlap.
        int drop = Math.abs(n[0]) >= Math.abs(n[1]) && Math.abs(n[0]) >= Math.abs(n[2]) ? 0 : Math.abs(n[1]) >= Math.abs(n[2]) ? 1 : 2;
        int u = (drop + 1) % 3;
        int v = (drop + 2) % 3;
        double[] p = {a[u], a[v], a[3 + u], a[3 + v], a[6 + u], a[6 + v]};
        double[] q = {b[u], b[v], b[3 + u], b[3 + v], b[6 + u], b[6 + v]};
        return !separates(p, q) && !separates(q, p);
    }

    private static boolean separates(double[] p, double[] q) {
        for (int e = 0; e < 3; e++) {
            int i = 2 * e;
            int j = 2 * ((e + 1) % 3);
            double nx = p[j + 1] - p[i + 1];
            double ny = p[i] - p[j];
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
            if (pMax < qMin || qMax < pMin) {
                return true;
            }
        }
        return false;
    }
}
