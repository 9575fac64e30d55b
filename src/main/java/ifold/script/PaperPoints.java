package ifold.script;

import ifold.fold.Paper;
import org.joml.Vector3d;

/** Where a point of the unfolded sheet (u, v) is now, on the top layer that holds it. */
final class PaperPoints {
    private PaperPoints() {
    }

    /**
     * The 3D position of paper point (u, v): found in the paper face that contains it in paper
     * coordinates (the highest one along the paper's normal where layers share the point, as
     * on a crease), mapped by the face's own rigid placement. Null if no face contains it.
     */
    static Vector3d locate(Paper paper, double u, double v) {
        double tolerance = 1e-9 * Math.max(1, paper.size());
        Vector3d best = null;
        double bestHeight = Double.NEGATIVE_INFINITY;
        for (int f = 0; f < paper.faceCount(); f++) {
            if (paper.isCap(f)) {
                continue;
            }
            int[] face = paper.face(f);
            // A fan of triangles from the first corner; the point is in one of them.
            for (int i = 1; i + 1 < face.length; i++) {
                int a = face[0];
                int b = face[i];
                int c = face[i + 1];
                double[] w = barycentric(paper, a, b, c, u, v);
                if (w == null || w[0] < -tolerance || w[1] < -tolerance || w[2] < -tolerance) {
                    continue;
                }
                Vector3d p = new Vector3d(
                        w[0] * paper.x(a) + w[1] * paper.x(b) + w[2] * paper.x(c),
                        w[0] * paper.y(a) + w[1] * paper.y(b) + w[2] * paper.y(c),
                        w[0] * paper.z(a) + w[1] * paper.z(b) + w[2] * paper.z(c));
                double height = p.dot(paper.normal());
                if (height > bestHeight) {
                    bestHeight = height;
                    best = p;
                }
            }
        }
        return best;
    }

    /** Barycentric weights of (u, v) in paper triangle (a, b, c), or null if it has no area. */
    private static double[] barycentric(Paper paper, int a, int b, int c, double u, double v) {
        double x1 = paper.u(b) - paper.u(a);
        double y1 = paper.v(b) - paper.v(a);
        double x2 = paper.u(c) - paper.u(a);
        double y2 = paper.v(c) - paper.v(a);
        double det = x1 * y2 - x2 * y1;
        if (det == 0) {
            return null;
        }
        double px = u - paper.u(a);
        double py = v - paper.v(a);
        double wb = (px * y2 - x2 * py) / det;
        double wc = (x1 * py - px * y1) / det;
        return new double[] {1 - wb - wc, wb, wc};
    }
}
