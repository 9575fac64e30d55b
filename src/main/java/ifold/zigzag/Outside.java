package ifold.zigzag;

import ifold.fold.Paper;
import org.joml.Matrix4dc;
import org.joml.Vector3d;

/**
 * How a folded paper sits on a triangle, measured in the triangle's plan frame: how far paper
 * reaches beyond each edge, how much of it lies outside, and how far any of it is from the
 * triangle in space.
 */
final class Outside {
    private Outside() {
    }

    /**
     * How far the paper faces (caps left out) reach beyond edge {@code edge} of the plan
     * triangle {@code plan} (x, y of three counter-clockwise corners; edge e runs from corner e to
     * corner e + 1): the largest outward distance of a vertex from the edge's line, or a negative
     * number if all lie inside it.
     */
    static double farthestBeyondEdge(Paper paper, Matrix4dc toPlan, double[] plan, int edge) {
        double ax = plan[2 * edge];
        double ay = plan[2 * edge + 1];
        double bx = plan[2 * ((edge + 1) % 3)];
        double by = plan[2 * ((edge + 1) % 3) + 1];
        double length = Math.hypot(bx - ax, by - ay);
        // Outward is to the right of a counter-clockwise edge.
        double nx = (by - ay) / length;
        double ny = (ax - bx) / length;
        double farthest = Double.NEGATIVE_INFINITY;
        Vector3d p = new Vector3d();
        boolean[] used = usedByPaper(paper);
        for (int v = 0; v < paper.vertexCount(); v++) {
            if (used[v]) {
                toPlan.transformPosition(p.set(paper.x(v), paper.y(v), paper.z(v)));
                farthest = Math.max(farthest, (p.x - ax) * nx + (p.y - ay) * ny);
            }
        }
        return farthest;
    }

    /** The paper area (caps left out) whose shadow on the triangle's plane lies outside the triangle. */
    static double area(Paper paper, Matrix4dc toPlan, double[] plan) {
        double outside = 0;
        Vector3d p = new Vector3d();
        for (int f = 0; f < paper.faceCount(); f++) {
            if (paper.isCap(f)) {
                continue;
            }
            int[] face = paper.face(f);
            double[] shadow = new double[2 * face.length];
            for (int i = 0; i < face.length; i++) {
                toPlan.transformPosition(p.set(paper.x(face[i]), paper.y(face[i]), paper.z(face[i])));
                shadow[2 * i] = p.x;
                shadow[2 * i + 1] = p.y;
            }
            double whole = Math.abs(signedArea(shadow));
            double[] inside = shadow;
            if (signedArea(inside) < 0) {
                inside = reversed(inside);
            }
            for (int e = 0; e < 3 && inside.length > 0; e++) {
                inside = clip(inside, plan[2 * e], plan[2 * e + 1], plan[2 * ((e + 1) % 3)], plan[2 * ((e + 1) % 3) + 1]);
            }
            outside += Math.max(0, whole - Math.abs(signedArea(inside)));
        }
        return outside;
    }

    /**
     * The farthest any vertex of the paper faces lies from the triangle in space: its height over
     * the triangle's plane and its distance beyond the edges together. Caps are left out: they are
     * the bend of a fold, bulging by half the gap between the layers they join.
     */
    static double farthestFromTriangle(Paper paper, Matrix4dc toPlan, double[] plan) {
        double farthest = 0;
        Vector3d p = new Vector3d();
        boolean[] used = usedByPaper(paper);
        for (int v = 0; v < paper.vertexCount(); v++) {
            if (!used[v]) {
                continue;
            }
            toPlan.transformPosition(p.set(paper.x(v), paper.y(v), paper.z(v)));
            double planar = distanceToTriangle(p.x, p.y, plan);
            farthest = Math.max(farthest, Math.hypot(planar, p.z));
        }
        return farthest;
    }

    /** Whether the vertex belongs to a paper face (not only to caps). */
    private static boolean[] usedByPaper(Paper paper) {
        boolean[] used = new boolean[paper.vertexCount()];
        for (int f = 0; f < paper.faceCount(); f++) {
            if (!paper.isCap(f)) {
                for (int v : paper.face(f)) {
                    used[v] = true;
                }
            }
        }
        return used;
    }

    /** Distance in the plane from (x, y) to the counter-clockwise triangle: 0 inside. */
    static double distanceToTriangle(double x, double y, double[] plan) {
        boolean inside = true;
        double nearest = Double.POSITIVE_INFINITY;
        for (int e = 0; e < 3; e++) {
            double ax = plan[2 * e];
            double ay = plan[2 * e + 1];
            double bx = plan[2 * ((e + 1) % 3)];
            double by = plan[2 * ((e + 1) % 3) + 1];
            inside &= (bx - ax) * (y - ay) - (by - ay) * (x - ax) >= 0;
            double dx = bx - ax;
            double dy = by - ay;
            double t = Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / (dx * dx + dy * dy)));
            nearest = Math.min(nearest, Math.hypot(x - ax - t * dx, y - ay - t * dy));
        }
        return inside ? 0 : nearest;
    }

    private static double signedArea(double[] polygon) {
        double twice = 0;
        int n = polygon.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            twice += polygon[2 * i] * polygon[2 * j + 1] - polygon[2 * j] * polygon[2 * i + 1];
        }
        return twice / 2;
    }

    private static double[] reversed(double[] polygon) {
        int n = polygon.length / 2;
        double[] r = new double[polygon.length];
        for (int i = 0; i < n; i++) {
            r[2 * i] = polygon[2 * (n - 1 - i)];
            r[2 * i + 1] = polygon[2 * (n - 1 - i) + 1];
        }
        return r;
    }

    /** Sutherland–Hodgman: the part of a convex polygon left of the line from a to b. */
    private static double[] clip(double[] polygon, double ax, double ay, double bx, double by) {
        int n = polygon.length / 2;
        double[] out = new double[4 * n + 4];
        int size = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double px = polygon[2 * i];
            double py = polygon[2 * i + 1];
            double qx = polygon[2 * j];
            double qy = polygon[2 * j + 1];
            double dp = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
            double dq = (bx - ax) * (qy - ay) - (by - ay) * (qx - ax);
            if (dp >= 0) {
                out[size++] = px;
                out[size++] = py;
            }
            if ((dp >= 0) != (dq >= 0)) {
                double t = dp / (dp - dq);
                out[size++] = px + t * (qx - px);
                out[size++] = py + t * (qy - py);
            }
        }
        return java.util.Arrays.copyOf(out, size);
    }
}
