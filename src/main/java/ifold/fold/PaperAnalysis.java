package ifold.fold;

import ifold.geom.Tolerance;
import org.joml.Vector3d;

/**
 * Measures of a folded paper: how many layers lie over a point, the most anywhere, the paper's
 * area, and how far its faces are from being isometric to the unfolded sheet.
 */
public final class PaperAnalysis {
    private PaperAnalysis() {
    }

    /**
     * The largest difference between an edge's 3D length and its paper length, relative to the
     * size of its face (the face's longest paper edge), over all paper faces: how far from rigid
     * the faces are placed. Relative to the face, not the edge, because a fold that cuts a face
     * near a corner leaves an edge far shorter than the rounding of the face's placement allows
     * it to be measured against.
     */
    public static double isometryError(Paper paper) {
        double worst = 0;
        for (int f = 0; f < paper.faceCount(); f++) {
            if (paper.isCap(f)) {
                continue;
            }
            int[] face = paper.faces.get(f);
            double size = 0;
            for (int i = 0; i < face.length; i++) {
                int a = face[i];
                int b = face[(i + 1) % face.length];
                size = Math.max(size, Math.hypot(paper.u(b) - paper.u(a), paper.v(b) - paper.v(a)));
            }
            for (int i = 0; i < face.length; i++) {
                int a = face[i];
                int b = face[(i + 1) % face.length];
                double paperLength = Math.hypot(paper.u(b) - paper.u(a), paper.v(b) - paper.v(a));
                double spaceLength = Math.sqrt(square(paper.x(b) - paper.x(a)) + square(paper.y(b) - paper.y(a))
                        + square(paper.z(b) - paper.z(a)));
                double error = Math.abs(spaceLength - paperLength) / Math.max(size, 1e-300);
                if (!(error <= worst)) {
                    worst = Double.isNaN(error) ? Double.POSITIVE_INFINITY : error;
                }
            }
        }
        return worst;
    }

    private static double square(double x) {
        return x * x;
    }

    /** The area of the paper faces, measured on the unfolded sheet. */
    public static double paperArea(Paper paper) {
        double area = 0;
        for (int f = 0; f < paper.faceCount(); f++) {
            if (!paper.isCap(f)) {
                int[] face = paper.faces.get(f);
                double twice = 0;
                for (int i = 0; i < face.length; i++) {
                    int a = face[i];
                    int b = face[(i + 1) % face.length];
                    twice += paper.u(a) * paper.v(b) - paper.u(b) * paper.v(a);
                }
                area += twice / 2;
            }
        }
        return area;
    }

    /**
     * How many paper faces lie over the point, seen along the paper's normal: the faces whose
     * shadow on the plane of the unfolded sheet contains its shadow. Points on a face's boundary
     * count as inside it.
     */
    public static int layersAt(Paper paper, double x, double y, double z) {
        Basis basis = new Basis(paper.normal);
        double pu = basis.u(x, y, z);
        double pv = basis.v(x, y, z);
        double tolerance = Tolerance.ON_PLANE * paper.size(); // relative to the sheet, whatever its scale
        int layers = 0;
        for (int f = 0; f < paper.faceCount(); f++) {
            if (!paper.isCap(f) && contains(paper, basis, paper.faces.get(f), pu, pv, tolerance, false)) {
                layers++;
            }
        }
        return layers;
    }

    /**
     * The most layers over any point of the sheet, found by sampling the centroid of every face
     * and a grid of 64 by 64 points over the sheet's shadow, each counting the faces that hold it
     * strictly inside (a sample on the border between two faces lying side by side is not an
     * overlap): exact for sheets folded through all layers, whose overlaps always contain a
     * face's centroid; otherwise a lower bound.
     */
    public static int maxLayers(Paper paper) {
        Basis basis = new Basis(paper.normal);
        int best = 0;
        double minU = Double.POSITIVE_INFINITY;
        double maxU = Double.NEGATIVE_INFINITY;
        double minV = Double.POSITIVE_INFINITY;
        double maxV = Double.NEGATIVE_INFINITY;
        for (int v = 0; v < paper.vertexCount(); v++) {
            double u = basis.u(paper.x(v), paper.y(v), paper.z(v));
            double w = basis.v(paper.x(v), paper.y(v), paper.z(v));
            minU = Math.min(minU, u);
            maxU = Math.max(maxU, u);
            minV = Math.min(minV, w);
            maxV = Math.max(maxV, w);
        }
        double tolerance = Tolerance.ON_PLANE * paper.size(); // relative to the sheet, whatever its scale
        for (int f = 0; f < paper.faceCount(); f++) {
            if (paper.isCap(f)) {
                continue;
            }
            int[] face = paper.faces.get(f);
            double cu = 0;
            double cv = 0;
            for (int v : face) {
                cu += basis.u(paper.x(v), paper.y(v), paper.z(v));
                cv += basis.v(paper.x(v), paper.y(v), paper.z(v));
            }
            best = Math.max(best, countAt(paper, basis, cu / face.length, cv / face.length, tolerance));
        }
        int grid = 64;
        for (int i = 0; i < grid; i++) {
            for (int j = 0; j < grid; j++) {
                double u = minU + (maxU - minU) * (i + 0.5) / grid;
                double w = minV + (maxV - minV) * (j + 0.5) / grid;
                best = Math.max(best, countAt(paper, basis, u, w, tolerance));
            }
        }
        return best;
    }

    /** Layers strictly over (u, v): a sample on the border of two faces side by side is no overlap. */
    private static int countAt(Paper paper, Basis basis, double u, double v, double tolerance) {
        int layers = 0;
        for (int f = 0; f < paper.faceCount(); f++) {
            if (!paper.isCap(f) && contains(paper, basis, paper.faces.get(f), u, v, tolerance, true)) {
                layers++;
            }
        }
        return layers;
    }

    /**
     * Whether the convex face's shadow contains (u, v), either way round: with its border (within
     * {@code tolerance}), or {@code strictly} inside it by more than that.
     */
    private static boolean contains(Paper paper, Basis basis, int[] face, double u, double v, double tolerance, boolean strictly) {
        boolean left = true;
        boolean right = true;
        for (int i = 0; i < face.length; i++) {
            int a = face[i];
            int b = face[(i + 1) % face.length];
            double au = basis.u(paper.x(a), paper.y(a), paper.z(a));
            double av = basis.v(paper.x(a), paper.y(a), paper.z(a));
            double bu = basis.u(paper.x(b), paper.y(b), paper.z(b));
            double bv = basis.v(paper.x(b), paper.y(b), paper.z(b));
            double length = Math.hypot(bu - au, bv - av);
            double cross = (bu - au) * (v - av) - (bv - av) * (u - au);
            double margin = (strictly ? -1 : 1) * tolerance * length;
            left &= cross >= -margin;
            right &= cross <= margin;
        }
        return left || right;
    }

    /** Two directions across the paper's normal: coordinates of shadows. */
    private static final class Basis {
        private final Vector3d e1;
        private final Vector3d e2;

        Basis(org.joml.Vector3dc normal) {
            Vector3d helper = Math.abs(normal.x()) < 0.9 ? new Vector3d(1, 0, 0) : new Vector3d(0, 1, 0);
            e1 = new Vector3d(normal).cross(helper).normalize();
            e2 = new Vector3d(normal).cross(e1).normalize();
        }

        double u(double x, double y, double z) {
            return e1.x * x + e1.y * y + e1.z * z;
        }

        double v(double x, double y, double z) {
            return e2.x * x + e2.y * y + e2.z * z;
        }
    }
}
