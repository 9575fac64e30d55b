package ifold.scene;

import ifold.refine.HamiltonianRefinement;
import ifold.refine.RefinedMesh;
import java.util.Arrays;

/**
 * The Hamiltonian path on screen (the seed's Figure 10): the refined triangles in path order,
 * coloured by their position along the path, with the spanning-tree edges (incentre to
 * midpoint) in green, the other new edges (incentre to corner) light, and the edges of the
 * original mesh dark.
 */
public final class PathView {
    public static final int TREE_EDGE = 0xFF00A030;
    public static final int NEW_EDGE = 0xFFC8C8C8;
    public static final int ORIGINAL_EDGE = 0xFF303030;

    private PathView() {
    }

    public static SceneMesh mesh(HamiltonianRefinement.Result refinement) {
        RefinedMesh refined = refinement.mesh();
        int vertexCount = refined.vertexCount();
        double[] positions = new double[3 * vertexCount];
        for (int v = 0; v < vertexCount; v++) {
            for (int axis = 0; axis < 3; axis++) {
                positions[3 * v + axis] = refined.coordinate(v, axis);
            }
        }
        int count = refined.faceCount();
        int[] triangles = new int[3 * count];
        int[] colors = new int[count];
        long[] edgeKeys = new long[3 * count];
        int[] componentStart = refinement.componentStart();
        for (int c = 0; c + 1 < componentStart.length; c++) {
            int from = componentStart[c];
            int length = Math.max(1, componentStart[c + 1] - from - 1);
            for (int t = from; t < componentStart[c + 1]; t++) {
                // The ends of Turbo are near black and near maroon: keep to the readable middle.
                colors[t] = Colormap.turbo(0.08 + 0.84 * (t - from) / length);
            }
        }
        for (int t = 0; t < count; t++) {
            for (int k = 0; k < 3; k++) {
                triangles[3 * t + k] = refined.faceVertex(t, k);
            }
            for (int k = 0; k < 3; k++) {
                int a = triangles[3 * t + k];
                int b = triangles[3 * t + (k + 1) % 3];
                edgeKeys[3 * t + k] = ((long) Math.min(a, b) << 32) | Math.max(a, b);
            }
        }
        int[] edges = SceneMesh.uniqueEdges(edgeKeys, edgeKeys.length);
        int[] edgeColors = new int[edges.length / 2];
        for (int e = 0; e < edgeColors.length; e++) {
            int a = edges[2 * e];
            int b = edges[2 * e + 1];
            edgeColors[e] = edgeColor(refined, a, b);
        }
        return new SceneMesh(positions, triangles, colors, edges, edgeColors);
    }

    /** Which kind of edge joins a and b: tree (incentre–midpoint), new (incentre–corner) or original. */
    static int edgeColor(RefinedMesh refined, int a, int b) {
        boolean incentre = refined.isIncenter(a) || refined.isIncenter(b);
        boolean midpoint = refined.isMidpoint(a) || refined.isMidpoint(b);
        if (incentre && midpoint) {
            return TREE_EDGE;
        }
        return incentre ? NEW_EDGE : ORIGINAL_EDGE;
    }

    /** Reveals the path's triangles one after another. */
    public static RevealAnimation reveal(Geometry geometry) {
        return new RevealAnimation(geometry);
    }

    /** How many edges of each kind the mesh has, as {tree, new, original}: for tests and the status line. */
    public static int[] edgeKindCounts(SceneMesh mesh) {
        int[] counts = new int[3];
        for (int color : mesh.edgeColors()) {
            counts[color == TREE_EDGE ? 0 : color == NEW_EDGE ? 1 : 2]++;
        }
        return Arrays.copyOf(counts, 3);
    }
}
