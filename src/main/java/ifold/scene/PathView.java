package ifold.scene;

import ifold.refine.HamiltonianRefinement;
import ifold.refine.RefinedMesh;
import java.util.ArrayList;
import java.util.List;

/**
 * The Hamiltonian path on screen, as the seed draws it (Figures 3 and 10): the refined
 * triangles in path order, darker the farther along the path (or in rainbow colours); the
 * path itself as a dotted curve through the triangles, from incentre to the middle of the edge
 * it crosses to the next incentre, its corners rounded; the spanning-tree edges (incentre to
 * midpoint) dashed green, the Steiner edges (incentre to corner) light and dashed, and the
 * edges of the original mesh dark and solid.
 */
public final class PathView {
    public static final int TREE_EDGE = 0xFF00A030;
    public static final int NEW_EDGE = 0xFFC8C8C8;
    public static final int ORIGINAL_EDGE = 0xFF303030;
    public static final int PATH_CURVE = 0xFFB0281E;
    /** Dashes per tree edge and per Steiner edge; original edges are solid. */
    static final int TREE_DASHES = 3;
    static final int NEW_DASHES = 4;

    /** How the triangles are coloured along the path. */
    public enum Colors { DARKNESS, RAINBOW }

    private PathView() {
    }

    public static SceneMesh mesh(HamiltonianRefinement.Result refinement) {
        return mesh(refinement, Colors.DARKNESS, false);
    }

    /**
     * @param dense whether the mesh is too fine for every edge to be told apart: the Steiner
     *     edges and the path's curve are left out (the colours show the path), the tree edges
     *     (solid) and the original edges kept
     */
    public static SceneMesh mesh(HamiltonianRefinement.Result refinement, Colors coloring, boolean dense) {
        RefinedMesh refined = refinement.mesh();
        int vertexCount = refined.vertexCount();
        List<double[]> points = new ArrayList<>();
        for (int v = 0; v < vertexCount; v++) {
            points.add(new double[] {refined.coordinate(v, 0), refined.coordinate(v, 1), refined.coordinate(v, 2)});
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
                double along = (double) (t - from) / length;
                // The ends of Turbo are near black and near maroon: keep to the readable middle.
                colors[t] = coloring == Colors.RAINBOW ? Colormap.turbo(0.08 + 0.84 * along) : darkness(along);
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
        int[] unique = SceneMesh.uniqueEdges(edgeKeys, edgeKeys.length);
        List<Integer> edges = new ArrayList<>();
        List<Integer> edgeColors = new ArrayList<>();
        for (int e = 0; e < unique.length / 2; e++) {
            int a = unique[2 * e];
            int b = unique[2 * e + 1];
            int color = edgeColor(refined, a, b);
            if (color == ORIGINAL_EDGE) {
                edges.add(a);
                edges.add(b);
                edgeColors.add(color);
            } else if (color == TREE_EDGE) {
                dashed(points, a, b, dense ? 1 : TREE_DASHES, dense ? 1 : 0.7, color, edges, edgeColors);
            } else if (!dense) {
                dashed(points, a, b, NEW_DASHES, 0.5, color, edges, edgeColors);
            }
        }
        for (int c = 0; c + 1 < componentStart.length && !dense; c++) {
            pathCurve(refined, componentStart[c], componentStart[c + 1], points, edges, edgeColors);
        }
        double[] positions = new double[3 * points.size()];
        for (int p = 0; p < points.size(); p++) {
            System.arraycopy(points.get(p), 0, positions, 3 * p, 3);
        }
        return new SceneMesh(positions, triangles, colors, edges.stream().mapToInt(Integer::intValue).toArray(),
                edgeColors.stream().mapToInt(Integer::intValue).toArray());
    }

    /** Light to dark along the path, as the seed's Figure 10(c): a warm near-white to a deep blue-grey. */
    static int darkness(double along) {
        double[] light = {0.96, 0.94, 0.86};
        double[] dark = {0.16, 0.22, 0.38};
        int argb = 0xFF000000;
        for (int k = 0; k < 3; k++) {
            double value = light[k] + (dark[k] - light[k]) * along;
            argb |= (int) Math.round(255 * value) << (16 - 8 * k);
        }
        return argb;
    }

    /** Edge a-b as {@code dashes} dashes, each {@code ink} of its share of the edge, with gaps between. */
    private static void dashed(List<double[]> points, int a, int b, int dashes, double ink, int color, List<Integer> edges,
            List<Integer> edgeColors) {
        double[] pa = points.get(a);
        double[] pb = points.get(b);
        double share = 1.0 / dashes;
        for (int d = 0; d < dashes; d++) {
            double start = (d + (1 - ink) / 2) * share;
            double end = start + ink * share;
            edges.add(point(points, pa, pb, start));
            edges.add(point(points, pa, pb, end));
            edgeColors.add(color);
        }
    }

    private static int point(List<double[]> points, double[] a, double[] b, double t) {
        points.add(new double[] {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])});
        return points.size() - 1;
    }

    /**
     * The path of triangles {@code first} to {@code end} as a dotted curve: incentre, middle of
     * the edge crossed, next incentre, ..., its corners cut twice (Chaikin), drawn every other
     * piece.
     */
    private static void pathCurve(RefinedMesh refined, int first, int end, List<double[]> points, List<Integer> edges,
            List<Integer> edgeColors) {
        List<double[]> curve = new ArrayList<>();
        for (int t = first; t < end; t++) {
            curve.add(incentre(refined, t));
            if (t + 1 < end) {
                double[] mid = sharedMidpoint(refined, t, t + 1);
                if (mid != null) {
                    curve.add(mid);
                }
            }
        }
        for (int round = 0; round < 2 && curve.size() > 2; round++) {
            List<double[]> cut = new ArrayList<>();
            cut.add(curve.get(0));
            for (int i = 0; i + 1 < curve.size(); i++) {
                double[] p = curve.get(i);
                double[] q = curve.get(i + 1);
                cut.add(lerp(p, q, 0.25));
                cut.add(lerp(p, q, 0.75));
            }
            cut.add(curve.get(curve.size() - 1));
            curve = cut;
        }
        for (int i = 0; i + 1 < curve.size(); i += 2) {
            points.add(curve.get(i));
            points.add(curve.get(i + 1));
            edges.add(points.size() - 2);
            edges.add(points.size() - 1);
            edgeColors.add(PATH_CURVE);
        }
    }

    private static double[] lerp(double[] p, double[] q, double t) {
        return new double[] {p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])};
    }

    /** The incentre of refined triangle t: its corners weighted by the opposite sides. */
    private static double[] incentre(RefinedMesh refined, int t) {
        double[][] c = new double[3][3];
        for (int k = 0; k < 3; k++) {
            for (int axis = 0; axis < 3; axis++) {
                c[k][axis] = refined.coordinate(refined.faceVertex(t, k), axis);
            }
        }
        double[] weight = new double[3];
        double total = 0;
        for (int k = 0; k < 3; k++) {
            double[] p = c[(k + 1) % 3];
            double[] q = c[(k + 2) % 3];
            weight[k] = Math.sqrt(Math.pow(p[0] - q[0], 2) + Math.pow(p[1] - q[1], 2) + Math.pow(p[2] - q[2], 2));
            total += weight[k];
        }
        double[] centre = new double[3];
        for (int k = 0; k < 3; k++) {
            for (int axis = 0; axis < 3; axis++) {
                centre[axis] += weight[k] / total * c[k][axis];
            }
        }
        return centre;
    }

    private static double[] sharedMidpoint(RefinedMesh refined, int s, int t) {
        double[] sum = new double[3];
        int shared = 0;
        for (int i = 0; i < 3; i++) {
            int v = refined.faceVertex(s, i);
            for (int j = 0; j < 3; j++) {
                if (refined.faceVertex(t, j) == v) {
                    for (int axis = 0; axis < 3; axis++) {
                        sum[axis] += refined.coordinate(v, axis);
                    }
                    shared++;
                }
            }
        }
        return shared == 2 ? new double[] {sum[0] / 2, sum[1] / 2, sum[2] / 2} : null;
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

    /** How many edges of each kind the mesh has, as {tree, new, original}, a dashed edge once: for tests and the status line. */
    public static int[] edgeKindCounts(SceneMesh mesh) {
        int[] segments = new int[3];
        for (int color : mesh.edgeColors()) {
            if (color != PATH_CURVE) {
                segments[color == TREE_EDGE ? 0 : color == NEW_EDGE ? 1 : 2]++;
            }
        }
        boolean dashedTree = segments[1] > 0; // a dense mesh draws its tree solid and no Steiner edges
        return new int[] {dashedTree ? segments[0] / TREE_DASHES : segments[0], segments[1] / NEW_DASHES, segments[2]};
    }
}
