package ifold.check;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

/**
 * Whether points lie inside the solid a model bounds, by the parity of a ray's crossings with
 * its closed components. A component (triangles joined across edges, corners matched by equal
 * coordinates) is closed when each of its edges belongs to an even number of its triangles; only
 * those bound a solid. A point is inside when a ray from it crosses their triangles an odd number
 * of times, so a cavity (a closed shell inside another) is outside, as it is in the solid.
 *
 * <p>The ray leaves in a fixed direction of no special slant, so that it does not run along the
 * edges and faces of models built on the axes; the triangles are binned in a grid across it.
 * Where a ray passes within rounding of a triangle's edge, it is cast again in other directions
 * (against every triangle: it is rare). A point on the surface (within rounding) is not inside.
 * Immutable once built: threads may share it.
 */
final class SolidInside {
    /** Directions of the ray: the first is binned, the others tried in turn where it grazes an edge. */
    private static final double[][] DIRECTIONS = {
        {0.5183691, 0.3217514, 0.7923046}, {-0.6138432, 0.7071541, 0.3507217},
        {0.2718281, -0.8414709, 0.4668201}, {-0.3819660, -0.4142135, -0.8262144}};
    /** Relative to the model's size: a ray this close to an edge grazes it; a point this close to the surface lies on it. */
    private static final double GRAZE = 1e-12;
    /** The answers of one cast. */
    private static final int OUTSIDE = 0;
    private static final int INSIDE = 1;
    private static final int GRAZED = 2;

    /** The closed components' triangles, x1 y1 z1 x2 y2 z2 x3 y3 z3 each. */
    private final double[] closed;
    private final int count;
    /** The bounding box of the closed triangles: min x y z, max x y z. */
    private final double[] bounds = new double[6];
    private final double graze;
    /** Each direction's frame: e1, e2 across the ray and d along it (9 numbers). */
    private final double[][] frames = new double[DIRECTIONS.length][];
    /** The grid across the first direction: its cell, lowest corner and size in cells. */
    private final double cell;
    private final double s0;
    private final double t0;
    private final int ns;
    private final int nt;
    /** Cell k's triangles are cellTriangles[cellStart[k] .. cellStart[k + 1]). */
    private final int[] cellStart;
    private final int[] cellTriangles;

    /**
     * @param triangles the model's triangles, 9 numbers each (corners x y z), in any orientation
     * @param n how many
     */
    SolidInside(double[] triangles, int n) {
        closed = closedTriangles(triangles, n);
        count = closed.length / 9;
        Arrays.fill(bounds, 0, 3, Double.POSITIVE_INFINITY);
        Arrays.fill(bounds, 3, 6, Double.NEGATIVE_INFINITY);
        for (int i = 0; i < closed.length; i += 3) {
            for (int axis = 0; axis < 3; axis++) {
                bounds[axis] = Math.min(bounds[axis], closed[i + axis]);
                bounds[3 + axis] = Math.max(bounds[3 + axis], closed[i + axis]);
            }
        }
        double size = count == 0 ? 0 : Math.max(bounds[3] - bounds[0], Math.max(bounds[4] - bounds[1], bounds[5] - bounds[2]));
        graze = GRAZE * size;
        for (int k = 0; k < DIRECTIONS.length; k++) {
            frames[k] = frame(DIRECTIONS[k]);
        }
        double[] f = frames[0];
        // The projected boxes; a cell the median of their extents, at most about 4 cells a triangle.
        double[] boxes = new double[4 * count];
        double[] extents = new double[count];
        double sMin = Double.POSITIVE_INFINITY;
        double tMin = Double.POSITIVE_INFINITY;
        double sMax = Double.NEGATIVE_INFINITY;
        double tMax = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            double lo0 = Double.POSITIVE_INFINITY;
            double lo1 = Double.POSITIVE_INFINITY;
            double hi0 = Double.NEGATIVE_INFINITY;
            double hi1 = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < 3; k++) {
                int o = 9 * i + 3 * k;
                double s = f[0] * closed[o] + f[1] * closed[o + 1] + f[2] * closed[o + 2];
                double t = f[3] * closed[o] + f[4] * closed[o + 1] + f[5] * closed[o + 2];
                lo0 = Math.min(lo0, s);
                hi0 = Math.max(hi0, s);
                lo1 = Math.min(lo1, t);
                hi1 = Math.max(hi1, t);
            }
            boxes[4 * i] = lo0 - graze;
            boxes[4 * i + 1] = lo1 - graze;
            boxes[4 * i + 2] = hi0 + graze;
            boxes[4 * i + 3] = hi1 + graze;
            extents[i] = Math.max(hi0 - lo0, hi1 - lo1);
            sMin = Math.min(sMin, boxes[4 * i]);
            tMin = Math.min(tMin, boxes[4 * i + 1]);
            sMax = Math.max(sMax, boxes[4 * i + 2]);
            tMax = Math.max(tMax, boxes[4 * i + 3]);
        }
        Arrays.sort(extents);
        double c = count == 0 ? 1 : Math.max(extents[count / 2], size * 1e-6);
        while (count > 0 && ((sMax - sMin) / c + 1) * ((tMax - tMin) / c + 1) > 4.0 * count + 16) {
            c *= 1.5;
        }
        cell = c > 0 ? c : 1;
        s0 = count == 0 ? 0 : sMin;
        t0 = count == 0 ? 0 : tMin;
        ns = count == 0 ? 1 : (int) Math.floor((sMax - s0) / cell) + 1;
        nt = count == 0 ? 1 : (int) Math.floor((tMax - t0) / cell) + 1;
        int cells = ns * nt;
        int[] start = new int[cells + 1];
        for (int i = 0; i < count; i++) {
            for (int s = column(boxes[4 * i]); s <= column(boxes[4 * i + 2]); s++) {
                for (int t = row(boxes[4 * i + 1]); t <= row(boxes[4 * i + 3]); t++) {
                    start[s * nt + t + 1]++;
                }
            }
        }
        for (int k = 0; k < cells; k++) {
            start[k + 1] += start[k];
        }
        int[] next = Arrays.copyOf(start, cells);
        int[] lists = new int[start[cells]];
        for (int i = 0; i < count; i++) {
            for (int s = column(boxes[4 * i]); s <= column(boxes[4 * i + 2]); s++) {
                for (int t = row(boxes[4 * i + 1]); t <= row(boxes[4 * i + 3]); t++) {
                    lists[next[s * nt + t]++] = i;
                }
            }
        }
        cellStart = start;
        cellTriangles = lists;
    }

    /** The number of triangles in closed components. */
    int closedTriangleCount() {
        return count;
    }

    private int column(double s) {
        return Math.max(0, Math.min(ns - 1, (int) Math.floor((s - s0) / cell)));
    }

    private int row(double t) {
        return Math.max(0, Math.min(nt - 1, (int) Math.floor((t - t0) / cell)));
    }

    /** e1, e2, d: an orthonormal frame whose third axis is the (normalised) direction. */
    private static double[] frame(double[] direction) {
        double dx = direction[0];
        double dy = direction[1];
        double dz = direction[2];
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= length;
        dy /= length;
        dz /= length;
        // e1: d x (the axis d is least along), normalised; e2 = d x e1.
        double ax = Math.abs(dx) <= Math.abs(dy) && Math.abs(dx) <= Math.abs(dz) ? 1 : 0;
        double ay = ax == 0 && Math.abs(dy) <= Math.abs(dz) ? 1 : 0;
        double az = ax == 0 && ay == 0 ? 1 : 0;
        double e1x = dy * az - dz * ay;
        double e1y = dz * ax - dx * az;
        double e1z = dx * ay - dy * ax;
        double e1 = Math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z);
        e1x /= e1;
        e1y /= e1;
        e1z /= e1;
        return new double[] {e1x, e1y, e1z, dy * e1z - dz * e1y, dz * e1x - dx * e1z, dx * e1y - dy * e1x, dx, dy, dz};
    }

    /**
     * Whether (x, y, z) lies inside the solid: strictly, not on its surface (within rounding of
     * the model's size). False when the model has no closed component.
     */
    boolean inside(double x, double y, double z) {
        if (count == 0 || x < bounds[0] || y < bounds[1] || z < bounds[2] || x > bounds[3] || y > bounds[4] || z > bounds[5]) {
            return false;
        }
        double[] f = frames[0];
        double s = f[0] * x + f[1] * y + f[2] * z;
        double t = f[3] * x + f[4] * y + f[5] * z;
        double d = f[6] * x + f[7] * y + f[8] * z;
        if (s < s0 || t < t0 || s > s0 + ns * cell || t > t0 + nt * cell) {
            return false;
        }
        int k = column(s) * nt + row(t);
        int crossings = 0;
        boolean grazed = false;
        for (int c = cellStart[k]; c < cellStart[k + 1] && !grazed; c++) {
            int answer = cross(f, cellTriangles[c], s, t, d);
            grazed = answer == GRAZED;
            crossings += answer == INSIDE ? 1 : 0;
        }
        if (!grazed) {
            return (crossings & 1) == 1;
        }
        for (int r = 1; r < frames.length; r++) {
            double[] g = frames[r];
            double gs = g[0] * x + g[1] * y + g[2] * z;
            double gt = g[3] * x + g[4] * y + g[5] * z;
            double gd = g[6] * x + g[7] * y + g[8] * z;
            crossings = 0;
            grazed = false;
            for (int i = 0; i < count && !grazed; i++) {
                int answer = cross(g, i, gs, gt, gd);
                grazed = answer == GRAZED;
                crossings += answer == INSIDE ? 1 : 0;
            }
            if (!grazed) {
                return (crossings & 1) == 1;
            }
        }
        // Every ray grazed an edge: the point lies on the surface or as good as.
        return false;
    }

    /**
     * Whether the ray from (s, t, d) in frame f along +d crosses closed triangle i: {@link #INSIDE}
     * for a crossing, {@link #OUTSIDE} for none, {@link #GRAZED} where rounding cannot tell (the ray
     * passes within {@link #graze} of an edge, or the point lies on the triangle).
     */
    private int cross(double[] f, int i, double s, double t, double d) {
        int o = 9 * i;
        double s1 = f[0] * closed[o] + f[1] * closed[o + 1] + f[2] * closed[o + 2] - s;
        double t1 = f[3] * closed[o] + f[4] * closed[o + 1] + f[5] * closed[o + 2] - t;
        double s2 = f[0] * closed[o + 3] + f[1] * closed[o + 4] + f[2] * closed[o + 5] - s;
        double t2 = f[3] * closed[o + 3] + f[4] * closed[o + 4] + f[5] * closed[o + 5] - t;
        double s3 = f[0] * closed[o + 6] + f[1] * closed[o + 7] + f[2] * closed[o + 8] - s;
        double t3 = f[3] * closed[o + 6] + f[4] * closed[o + 7] + f[5] * closed[o + 8] - t;
        // Twice the signed areas of the point with each edge: the weights of the opposite corners.
        double w3 = s1 * t2 - s2 * t1;
        double w1 = s2 * t3 - s3 * t2;
        double w2 = s3 * t1 - s1 * t3;
        double l12 = Math.hypot(s2 - s1, t2 - t1);
        double l23 = Math.hypot(s3 - s2, t3 - t2);
        double l31 = Math.hypot(s1 - s3, t1 - t3);
        // A weight over its edge's length is the point's distance from the edge's line.
        boolean near3 = Math.abs(w3) <= graze * l12;
        boolean near1 = Math.abs(w1) <= graze * l23;
        boolean near2 = Math.abs(w2) <= graze * l31;
        boolean positive = w1 > 0 && w2 > 0 && w3 > 0;
        boolean negative = w1 < 0 && w2 < 0 && w3 < 0;
        if (!(near1 || near2 || near3)) {
            if (!positive && !negative) {
                return OUTSIDE;
            }
        } else if (!((w1 >= 0 || near1) && (w2 >= 0 || near2) && (w3 >= 0 || near3))
                && !((w1 <= 0 || near1) && (w2 <= 0 || near2) && (w3 <= 0 || near3))) {
            // Near an edge's line, but plainly outside across another edge.
            return OUTSIDE;
        } else {
            return GRAZED;
        }
        double total = w1 + w2 + w3;
        double d1 = f[6] * closed[o] + f[7] * closed[o + 1] + f[8] * closed[o + 2];
        double d2 = f[6] * closed[o + 3] + f[7] * closed[o + 4] + f[8] * closed[o + 5];
        double d3 = f[6] * closed[o + 6] + f[7] * closed[o + 7] + f[8] * closed[o + 8];
        double hit = (w1 * d1 + w2 * d2 + w3 * d3) / total;
        if (Math.abs(hit - d) <= graze) {
            return GRAZED;
        }
        return hit > d ? INSIDE : OUTSIDE;
    }

    /**
     * The triangles of the closed components, corners matched by equal coordinates; triangles
     * with two corners equal are left out (they bound nothing).
     */
    private static double[] closedTriangles(double[] triangles, int n) {
        Map<Corner, Integer> ids = new HashMap<>();
        int[] vertex = new int[3 * n];
        for (int c = 0; c < 3 * n; c++) {
            Corner key = new Corner(triangles[3 * c] + 0.0, triangles[3 * c + 1] + 0.0, triangles[3 * c + 2] + 0.0);
            Integer id = ids.get(key);
            if (id == null) {
                id = ids.size();
                ids.put(key, id);
            }
            vertex[c] = id;
        }
        // Union-find of triangles across their edges; each edge's count of triangles.
        int[] parent = new int[n];
        for (int i = 0; i < n; i++) {
            parent[i] = i;
        }
        boolean[] degenerate = new boolean[n];
        Map<Long, int[]> edges = new HashMap<>();
        for (int i = 0; i < n; i++) {
            int a = vertex[3 * i];
            int b = vertex[3 * i + 1];
            int c = vertex[3 * i + 2];
            degenerate[i] = a == b || b == c || c == a;
            if (degenerate[i]) {
                continue;
            }
            for (int k = 0; k < 3; k++) {
                int from = vertex[3 * i + k];
                int to = vertex[3 * i + (k + 1) % 3];
                long key = (long) Math.min(from, to) << 32 | Math.max(from, to);
                int[] edge = edges.get(key);
                if (edge == null) {
                    edges.put(key, new int[] {1, i});
                } else {
                    edge[0]++;
                    union(parent, edge[1], i);
                }
            }
        }
        boolean[] open = new boolean[n];
        for (int[] edge : edges.values()) {
            if ((edge[0] & 1) == 1) {
                open[find(parent, edge[1])] = true;
            }
        }
        int kept = 0;
        double[] out = new double[9 * n];
        for (int i = 0; i < n; i++) {
            if (!degenerate[i] && !open[find(parent, i)]) {
                System.arraycopy(triangles, 9 * i, out, 9 * kept++, 9);
            }
        }
        return Arrays.copyOf(out, 9 * kept);
    }

    /** The root of i's piece in a union-find parent array (the checkers keep their own: they share no code with the engine). */
    static int find(int[] parent, int i) {
        while (parent[i] != i) {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    }

    /** Joins the pieces of i and j, the lower root the root of both. */
    static void union(int[] parent, int i, int j) {
        int a = find(parent, i);
        int b = find(parent, j);
        if (a != b) {
            parent[Math.max(a, b)] = Math.min(a, b);
        }
    }

    /** A corner's coordinates, for matching corners (with +0.0 for -0.0). */
    private record Corner(double x, double y, double z) {
    }
}
