package ifold.scene;

import ifold.geom.PolygonTriangulator;
import ifold.mesh.IndexedPolygons;
import java.util.Arrays;
import java.util.BitSet;

/**
 * Triangles and edges ready to draw: positions (still {@code double}; the renderer converts to
 * {@code float} on upload), three vertex indices per triangle, a colour per triangle, and the
 * edges to outline with a colour each. Polygons are triangulated for drawing, but their outline
 * is drawn, not the diagonals.
 */
public final class SceneMesh {
    /** x, y, z per vertex. */
    private final double[] positions;
    /** Three vertex indices per triangle, in drawing order. */
    private final int[] triangles;
    /** 0xAARRGGBB per triangle. */
    private final int[] triangleColors;
    /** Two vertex indices per edge. */
    private final int[] edges;
    /** 0xAARRGGBB per edge. */
    private final int[] edgeColors;
    private final Bounds bounds = new Bounds();
    /** How the mesh may be drawn with less; null: it may not. */
    private final Layers layers;

    /**
     * What lets a mesh of many layers (paper folded over a model, a million faces) be drawn with
     * less, its triangles shown in the order they come: from when each lies under others, which
     * only close a narrow gap, and, for far away, the patches: pieces of surface their
     * triangles cover, each a few triangles in the colour those average.
     *
     * @param hiddenFrom for each triangle, how many of the mesh's triangles drawn cover it
     *     ({@link Integer#MAX_VALUE}: never)
     * @param seams the triangles that only close a narrow gap between layers (a fold's caps)
     * @param patchOf each triangle's patch
     * @param patchSettled for each patch, how many of the mesh's triangles must be drawn for its
     *     triangles' exposure to hold (one past its last)
     * @param patches the patches' triangles, patch by patch (no edges)
     * @param patchStart patch p is triangles {@code patchStart[p]} to {@code patchStart[p + 1]} of {@code patches}
     */
    public record Layers(int[] hiddenFrom, BitSet seams, int[] patchOf, int[] patchSettled, SceneMesh patches, int[] patchStart) {
    }

    public SceneMesh(double[] positions, int[] triangles, int[] triangleColors, int[] edges, int[] edgeColors) {
        this(positions, triangles, triangleColors, edges, edgeColors, null);
    }

    /** A mesh of many layers, which {@code layers} (null: none) lets the renderer draw with less. */
    public SceneMesh(double[] positions, int[] triangles, int[] triangleColors, int[] edges, int[] edgeColors, Layers layers) {
        if (triangles.length % 3 != 0 || triangleColors.length != triangles.length / 3
                || edges.length % 2 != 0 || edgeColors.length != edges.length / 2 || positions.length % 3 != 0) {
            throw new IllegalArgumentException("inconsistent mesh arrays");
        }
        this.positions = positions;
        this.triangles = triangles;
        this.triangleColors = triangleColors;
        this.edges = edges;
        this.edgeColors = edgeColors;
        if (layers != null) {
            int patchCount = layers.patchSettled().length;
            if (layers.hiddenFrom().length != triangleColors.length || layers.seams().length() > triangleColors.length
                    || layers.patchOf().length != triangleColors.length
                    || layers.patchStart().length != patchCount + 1 || layers.patchStart()[patchCount] != layers.patches().triangleCount()
                    || java.util.Arrays.stream(layers.patchOf()).anyMatch(p -> p < 0 || p >= patchCount)) {
                throw new IllegalArgumentException("inconsistent layers");
            }
        }
        this.layers = layers;
        for (int i = 0; i < positions.length; i += 3) {
            bounds.add(positions[i], positions[i + 1], positions[i + 2]);
        }
    }

    /** The default outline colour: dark grey, drawn over light paper. */
    public static final int EDGE_COLOR = 0xFF3A3A3A;

    /** The faces of {@code mesh} (polygons triangulated), each in its colour, outlined by their edges. */
    public static SceneMesh of(IndexedPolygons mesh) {
        int vertexCount = mesh.vertexCount();
        double[] positions = new double[3 * vertexCount];
        for (int v = 0; v < vertexCount; v++) {
            for (int axis = 0; axis < 3; axis++) {
                positions[3 * v + axis] = mesh.coordinate(v, axis);
            }
        }
        int faceCount = mesh.faceCount();
        int[] triangles = new int[3 * Math.max(1, faceCount)];
        int[] colors = new int[Math.max(1, faceCount)];
        long[] edgeKeys = new long[3 * Math.max(1, faceCount)];
        int triangleCount = 0;
        int edgeCount = 0;
        int[] polygon = new int[16];
        int[] split = new int[3 * 16];
        for (int f = 0; f < faceCount; f++) {
            int size = mesh.faceSize(f);
            if (size > polygon.length) {
                polygon = new int[2 * size];
                split = new int[6 * size];
            }
            for (int k = 0; k < size; k++) {
                polygon[k] = mesh.faceVertex(f, k);
            }
            int count = PolygonTriangulator.triangulate(positions, polygon, size, split);
            if (3 * (triangleCount + count) > triangles.length) {
                triangles = Arrays.copyOf(triangles, Math.max(2 * triangles.length, 3 * (triangleCount + count)));
                colors = Arrays.copyOf(colors, triangles.length / 3);
            }
            System.arraycopy(split, 0, triangles, 3 * triangleCount, 3 * count);
            Arrays.fill(colors, triangleCount, triangleCount + count, mesh.faceColor(f));
            triangleCount += count;
            if (edgeCount + size > edgeKeys.length) {
                edgeKeys = Arrays.copyOf(edgeKeys, Math.max(2 * edgeKeys.length, edgeCount + size));
            }
            for (int k = 0; k < size; k++) {
                int a = polygon[k];
                int b = polygon[(k + 1) % size];
                edgeKeys[edgeCount++] = ((long) Math.min(a, b) << 32) | Math.max(a, b);
            }
        }
        int[] edges = uniqueEdges(edgeKeys, edgeCount);
        int[] edgeColors = new int[edges.length / 2];
        Arrays.fill(edgeColors, EDGE_COLOR);
        return new SceneMesh(positions, Arrays.copyOf(triangles, 3 * triangleCount),
                Arrays.copyOf(colors, triangleCount), edges, edgeColors);
    }

    /** The distinct edges among {@code keys[0..count)} (lower vertex in the high 32 bits). */
    static int[] uniqueEdges(long[] keys, int count) {
        Arrays.sort(keys, 0, count);
        int[] edges = new int[2 * count];
        int unique = 0;
        for (int i = 0; i < count; i++) {
            if (i == 0 || keys[i] != keys[i - 1]) {
                edges[2 * unique] = (int) (keys[i] >>> 32);
                edges[2 * unique + 1] = (int) keys[i];
                unique++;
            }
        }
        return Arrays.copyOf(edges, 2 * unique);
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int triangleCount() {
        return triangles.length / 3;
    }

    public int edgeCount() {
        return edges.length / 2;
    }

    public double[] positions() {
        return positions;
    }

    public int[] triangles() {
        return triangles;
    }

    public int[] triangleColors() {
        return triangleColors;
    }

    public int[] edges() {
        return edges;
    }

    public int[] edgeColors() {
        return edgeColors;
    }

    /** How the mesh may be drawn with less; null where it may not. */
    public Layers layers() {
        return layers;
    }

    /** The bounds in the mesh's own coordinates. */
    public Bounds bounds() {
        return bounds;
    }
}
