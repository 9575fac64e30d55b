package ifold.check;

import java.util.Arrays;
import java.util.List;

/** The model: its triangles, their unit outward normals, areas, a grid of them and its size. */
final class TruthModel {
    /** x y z of the three corners of each triangle, 9 per triangle. */
    final double[] corners;
    /** Unit outward normals, 3 per triangle (NaN for a degenerate triangle). */
    private final double[] normals;
    /** Running sum of the areas, to pick triangles by area. */
    private final double[] cumulativeArea;
    /** The bounding-box diagonal. */
    final double size;
    final TruthGrid grid;

    TruthModel(List<double[]> triangles) {
        int n = triangles.size();
        if (n == 0) {
            throw new IllegalArgumentException("no model triangles");
        }
        corners = new double[9 * n];
        normals = new double[3 * n];
        cumulativeArea = new double[n];
        double[] boxes = new double[6 * n];
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double area = 0;
        for (int t = 0; t < n; t++) {
            double[] tri = triangles.get(t);
            if (tri.length != 9 || !Arrays.stream(tri).allMatch(Double::isFinite)) {
                throw new IllegalArgumentException("model triangle " + (t + 1) + " is not 9 finite numbers");
            }
            System.arraycopy(tri, 0, corners, 9 * t, 9);
            double[] e1 = {tri[3] - tri[0], tri[4] - tri[1], tri[5] - tri[2]};
            double[] e2 = {tri[6] - tri[0], tri[7] - tri[1], tri[8] - tri[2]};
            double nx = e1[1] * e2[2] - e1[2] * e2[1];
            double ny = e1[2] * e2[0] - e1[0] * e2[2];
            double nz = e1[0] * e2[1] - e1[1] * e2[0];
            double twice = Math.sqrt(nx * nx + ny * ny + nz * nz);
            normals[3 * t] = nx / twice;
            normals[3 * t + 1] = ny / twice;
            normals[3 * t + 2] = nz / twice;
            area += twice / 2;
            cumulativeArea[t] = area;
            for (int d = 0; d < 3; d++) {
                boxes[6 * t + d] = Math.min(tri[d], Math.min(tri[3 + d], tri[6 + d]));
                boxes[6 * t + 3 + d] = Math.max(tri[d], Math.max(tri[3 + d], tri[6 + d]));
                min[d] = Math.min(min[d], boxes[6 * t + d]);
                max[d] = Math.max(max[d], boxes[6 * t + 3 + d]);
            }
        }
        size = Math.sqrt((max[0] - min[0]) * (max[0] - min[0]) + (max[1] - min[1]) * (max[1] - min[1])
                + (max[2] - min[2]) * (max[2] - min[2]));
        if (!(size > 0) || !(area > 0)) {
            throw new IllegalArgumentException("the model has no size or no area");
        }
        grid = new TruthGrid(boxes, n, TruthGrid.cellFor(boxes, n, WrapTruths.LEAST_CELL * size));
    }

    double[] normal(int t) {
        return Arrays.copyOfRange(normals, 3 * t, 3 * t + 3);
    }

    /** The triangle whose share of the total area holds r in [0, 1). */
    int pick(double r) {
        double target = r * cumulativeArea[cumulativeArea.length - 1];
        int i = Arrays.binarySearch(cumulativeArea, target);
        i = i >= 0 ? i + 1 : -i - 1;
        return Math.min(i, cumulativeArea.length - 1);
    }

    /** The height of point p[i..i+2] above triangle t's plane, along its outward normal. */
    double height(int t, double[] p, int i) {
        return normals[3 * t] * (p[i] - corners[9 * t]) + normals[3 * t + 1] * (p[i + 1] - corners[9 * t + 1])
                + normals[3 * t + 2] * (p[i + 2] - corners[9 * t + 2]);
    }

    /** The barycentric coordinates, in t, of p[i..i+2] projected onto t's plane. */
    void barycentric(int t, double[] p, int i, double[] out) {
        double[] n = normal(t);
        for (int k = 0; k < 3; k++) {
            int a = 9 * t + 3 * ((k + 1) % 3);
            int b = 9 * t + 3 * ((k + 2) % 3);
            // Twice the area of (p, a, b) over twice the triangle's area, both along n.
            double ex = corners[b] - corners[a];
            double ey = corners[b + 1] - corners[a + 1];
            double ez = corners[b + 2] - corners[a + 2];
            double rx = p[i] - corners[a];
            double ry = p[i + 1] - corners[a + 1];
            double rz = p[i + 2] - corners[a + 2];
            out[k] = (ey * rz - ez * ry) * n[0] + (ez * rx - ex * rz) * n[1] + (ex * ry - ey * rx) * n[2];
        }
        double total = out[0] + out[1] + out[2];
        for (int k = 0; k < 3; k++) {
            out[k] /= total;
        }
    }

    double longestEdge(int t) {
        double longest = 0;
        for (int k = 0; k < 3; k++) {
            longest = Math.max(longest, WrapTruths.distance(corners, 9 * t + 3 * k, corners, 9 * t + 3 * ((k + 1) % 3)));
        }
        return longest;
    }

    /** The distance from (x, y, z) to triangle t (Ericson, Real-Time Collision Detection, 5.1.5). */
    double distanceTo(int t, double x, double y, double z) {
        int i = 9 * t;
        double[] a = {corners[i], corners[i + 1], corners[i + 2]};
        double[] b = {corners[i + 3], corners[i + 4], corners[i + 5]};
        double[] c = {corners[i + 6], corners[i + 7], corners[i + 8]};
        double[] p = {x, y, z};
        double[] ab = TruthIsometry.minus(b, a);
        double[] ac = TruthIsometry.minus(c, a);
        double[] ap = TruthIsometry.minus(p, a);
        double d1 = dot(ab, ap);
        double d2 = dot(ac, ap);
        if (d1 <= 0 && d2 <= 0) {
            return length(ap);
        }
        double[] bp = TruthIsometry.minus(p, b);
        double d3 = dot(ab, bp);
        double d4 = dot(ac, bp);
        if (d3 >= 0 && d4 <= d3) {
            return length(bp);
        }
        double vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            return length(TruthIsometry.minus(ap, scale(ab, d1 / (d1 - d3))));
        }
        double[] cp = TruthIsometry.minus(p, c);
        double d5 = dot(ab, cp);
        double d6 = dot(ac, cp);
        if (d6 >= 0 && d5 <= d6) {
            return length(cp);
        }
        double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            return length(TruthIsometry.minus(ap, scale(ac, d2 / (d2 - d6))));
        }
        double va = d3 * d6 - d5 * d4;
        if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
            return length(TruthIsometry.minus(bp, scale(TruthIsometry.minus(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)))));
        }
        double denominator = 1 / (va + vb + vc);
        double v = vb * denominator;
        double w = vc * denominator;
        return length(TruthIsometry.minus(ap, plus(scale(ab, v), scale(ac, w))));
    }

    private static double[] plus(double[] a, double[] b) {
        return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    }

    private static double[] scale(double[] a, double s) {
        return new double[] {a[0] * s, a[1] * s, a[2] * s};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double length(double[] a) {
        return Math.sqrt(dot(a, a));
    }
}
