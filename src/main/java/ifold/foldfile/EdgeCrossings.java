package ifold.foldfile;

import java.util.Arrays;
import java.util.Locale;

/**
 * Whether a crease pattern's edges form a planar graph: no two cross, and no vertex lies on a
 * crease or flat edge without splitting it (a crease drawn across another, or ending on it,
 * with no vertex where they meet, cuts no face). Found by sweeping the edges' boxes along x.
 */
final class EdgeCrossings {
    private EdgeCrossings() {
    }

    /**
     * @throws CreasePattern.Refused naming the two edges that cross, or the vertex on an edge
     */
    static void refuse(double[][] vertices, int[][] edges, char[] assignments) throws CreasePattern.Refused {
        int n = edges.length;
        double[][] box = new double[n][];
        Integer[] byX = new Integer[n];
        double size = 0;
        for (int e = 0; e < n; e++) {
            double[] a = vertices[edges[e][0]];
            double[] b = vertices[edges[e][1]];
            box[e] = new double[] {Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[0], b[0]), Math.max(a[1], b[1])};
            size = Math.max(size, Math.max(box[e][2] - box[e][0], box[e][3] - box[e][1]));
            byX[e] = e;
        }
        double tolerance = 1e-9 * Math.max(size, Double.MIN_NORMAL);
        Arrays.sort(byX, (p, q) -> Double.compare(box[p][0], box[q][0]));
        for (int i = 0; i < n; i++) {
            int e = byX[i];
            for (int j = i + 1; j < n && box[byX[j]][0] <= box[e][2] + tolerance; j++) {
                int f = byX[j];
                if (box[f][1] > box[e][3] + tolerance || box[e][1] > box[f][3] + tolerance) {
                    continue;
                }
                check(vertices, edges, assignments, e, f, tolerance);
            }
        }
    }

    private static void check(double[][] vertices, int[][] edges, char[] assignments, int e, int f, double tolerance)
            throws CreasePattern.Refused {
        int a = edges[e][0];
        int b = edges[e][1];
        int c = edges[f][0];
        int d = edges[f][1];
        for (int[] pair : new int[][] {{c, e}, {d, e}, {a, f}, {b, f}}) {
            int v = pair[0];
            int[] edge = edges[pair[1]];
            // A crease may end on a border edge given whole (the line-by-line folder reads such
            // files); on a crease or a flat edge, a vertex must split it.
            if (assignments[pair[1]] != 'B' && v != edge[0] && v != edge[1] && inside(vertices[v], vertices[edge[0]], vertices[edge[1]],
                    tolerance)) {
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "vertex %d (%s, %s) lies on edge %d without splitting it: give"
                        + " the edge two pieces, each ending there", v, CreasePattern.fmt(vertices[v][0]), CreasePattern.fmt(vertices[v][1]),
                        pair[1]));
            }
        }
        if (a == c || a == d || b == c || b == d) {
            return;
        }
        double d1 = side(vertices[c], vertices[d], vertices[a]);
        double d2 = side(vertices[c], vertices[d], vertices[b]);
        double d3 = side(vertices[a], vertices[b], vertices[c]);
        double d4 = side(vertices[a], vertices[b], vertices[d]);
        if (((d1 > tolerance && d2 < -tolerance) || (d1 < -tolerance && d2 > tolerance))
                && ((d3 > tolerance && d4 < -tolerance) || (d3 < -tolerance && d4 > tolerance))) {
            throw new CreasePattern.Refused(String.format(Locale.ROOT, "edges %d and %d cross with no vertex where they meet: give each"
                    + " two pieces, ending at a vertex there", e, f));
        }
    }

    /** Which side of the line p → q point r lies on, as a distance (positive: left). */
    private static double side(double[] p, double[] q, double[] r) {
        double dx = q[0] - p[0];
        double dy = q[1] - p[1];
        double length = Math.hypot(dx, dy);
        return length > 0 ? (dx * (r[1] - p[1]) - dy * (r[0] - p[0])) / length : 0;
    }

    /** Whether point r lies on the segment p-q, away from its ends. */
    private static boolean inside(double[] r, double[] p, double[] q, double tolerance) {
        double dx = q[0] - p[0];
        double dy = q[1] - p[1];
        double length = Math.hypot(dx, dy);
        if (!(length > 0)) {
            return false;
        }
        double along = ((r[0] - p[0]) * dx + (r[1] - p[1]) * dy) / length;
        return Math.abs(side(p, q, r)) <= tolerance && along > tolerance && along < length - tolerance;
    }
}
