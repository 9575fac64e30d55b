package ifold.check;

import java.util.Arrays;

/**
 * The triangles a check pairs up, paper and model in one numbering: paper triangles (the fans of
 * the file's faces) first, model triangles after them with three vertices each of their own; each
 * with its unit normal and its box, grown by half the touching distance so that boxes meet
 * wherever their triangles come that close.
 */
final class TriangleSet {
    final PaperObj paper;
    /** The touching distance, in the file's units. */
    final double touch;
    /** Paper triangles are 0 .. paperTriangles - 1, model triangles after them. */
    final int paperTriangles;
    final int modelTriangles;
    /** The paper's vertices, then three for each model triangle, x y z interleaved. */
    final double[] xyz;
    /** Each triangle's corners (vertex indices into xyz). */
    final int[] tri;
    /** Each triangle's unit normal (as TriangleContact.frame makes it), x y z. */
    final double[] normals;
    /**
     * Each triangle's box, grown by half the touching distance: min x y z, max x y z; NaN for a
     * degenerate triangle, which the grid leaves out.
     */
    final double[] boxes;

    /**
     * @param model the model's triangles, 9 numbers each
     */
    TriangleSet(PaperObj paper, double[] model, double touch) {
        this.paper = paper;
        this.touch = touch;
        paperTriangles = paper.triangleCount();
        modelTriangles = model.length / 9;
        int n = paperTriangles + modelTriangles;
        int paperVertices = paper.vertexCount();
        xyz = Arrays.copyOf(paper.xyz, paper.xyz.length + model.length);
        System.arraycopy(model, 0, xyz, paper.xyz.length, model.length);
        tri = Arrays.copyOf(paper.tri, 3 * n);
        for (int m = 0; m < modelTriangles; m++) {
            for (int k = 0; k < 3; k++) {
                tri[3 * (paperTriangles + m) + k] = paperVertices + 3 * m + k;
            }
        }
        normals = new double[3 * n];
        boxes = new double[6 * n];
        double grow = touch / 2;
        double[] corners = new double[9];
        double[] edges = new double[9];
        double[] normal = new double[3];
        for (int t = 0; t < n; t++) {
            for (int k = 0; k < 3; k++) {
                System.arraycopy(xyz, 3 * tri[3 * t + k], corners, 3 * k, 3);
            }
            if (!TriangleContact.frame(corners, edges, normal)) {
                Arrays.fill(boxes, 6 * t, 6 * t + 6, Double.NaN);
                continue;
            }
            System.arraycopy(normal, 0, normals, 3 * t, 3);
            for (int axis = 0; axis < 3; axis++) {
                double lo = Math.min(corners[axis], Math.min(corners[3 + axis], corners[6 + axis]));
                double hi = Math.max(corners[axis], Math.max(corners[3 + axis], corners[6 + axis]));
                boxes[6 * t + axis] = lo - grow;
                boxes[6 * t + 3 + axis] = hi + grow;
            }
        }
    }

    int count() {
        return paperTriangles + modelTriangles;
    }

    boolean isModel(int t) {
        return t >= paperTriangles;
    }
}
