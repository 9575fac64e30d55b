package ifold.scene;

import java.util.ArrayDeque;
import java.util.List;

/** Faces of paper that collide, as the viewer shows them: in red, each a fan of triangles. */
public final class CollisionView {
    /** The geometry's name: the viewer's C shows and hides what has it. */
    public static final String NAME = "collisions";

    /** Red both sides, unlit by face colours, with its edges: a warning, not paper. */
    public static final Material MATERIAL = new Material(0xFFE0262B, 0xFFB01E22, false, true);

    private CollisionView() {
    }

    /** Shows what is named {@link #NAME} below {@code root} where it is hidden, and hides it where shown; whether there was any. */
    public static boolean toggle(Spatial root) {
        boolean found = false;
        ArrayDeque<Spatial> open = new ArrayDeque<>(List.of(root));
        while (!open.isEmpty()) {
            Spatial spatial = open.pop();
            if (NAME.equals(spatial.name())) {
                spatial.setVisible(!spatial.isVisible());
                found = true;
            }
            if (spatial instanceof Node node) {
                open.addAll(node.children());
            }
        }
        return found;
    }

    /** A mesh of {@code polygons}, each its corners x, y, z interleaved (convex, as the faces of a sheet are). */
    public static SceneMesh mesh(List<double[]> polygons) {
        int vertices = 0;
        int triangles = 0;
        for (double[] polygon : polygons) {
            vertices += polygon.length / 3;
            triangles += polygon.length / 3 - 2;
        }
        double[] positions = new double[3 * vertices];
        int[] corners = new int[3 * triangles];
        int[] colors = new int[triangles];
        int[] edges = new int[2 * vertices];
        int[] edgeColors = new int[vertices];
        int v = 0;
        int t = 0;
        int e = 0;
        for (double[] polygon : polygons) {
            int n = polygon.length / 3;
            System.arraycopy(polygon, 0, positions, 3 * v, polygon.length);
            for (int k = 1; k + 1 < n; k++) {
                corners[3 * t] = v;
                corners[3 * t + 1] = v + k;
                corners[3 * t + 2] = v + k + 1;
                colors[t++] = MATERIAL.front();
            }
            for (int k = 0; k < n; k++) {
                edges[2 * e] = v + k;
                edges[2 * e + 1] = v + (k + 1) % n;
                edgeColors[e++] = 0xFF600000;
            }
            v += n;
        }
        return new SceneMesh(positions, corners, colors, edges, edgeColors);
    }
}
