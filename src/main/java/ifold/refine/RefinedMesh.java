package ifold.refine;

import ifold.mesh.IndexedPolygons;
import ifold.mesh.PolygonSoup;

/**
 * The triangles of a Hamiltonian refinement, listed in path order: triangle {@code t} and
 * {@code t + 1} share an edge, except where one component's path ends and the next begins.
 *
 * <p>Vertices come in three blocks: the original vertices keep their indices
 * {@code [0, originalVertices)}; then one incentre per original face, in face order; then one
 * midpoint per spanning-tree edge. Held as flat arrays (no halfedges) because a refinement has
 * five times the triangles of its input, and its connectivity is implied by the path.
 */
public final class RefinedMesh implements IndexedPolygons {
    /** x, y, z of each vertex, interleaved. */
    private final double[] positions;
    private final int vertexCount;
    private final int originalVertices;
    private final int originalFaces;
    /** Three vertex indices per triangle, in path order. */
    private final int[] triangles;
    /** The original face each triangle lies in. */
    private final int[] parentFace;
    /** Packed colours of the original faces, or null: sub-triangles inherit them. */
    private final int[] parentColor;

    RefinedMesh(double[] positions, int vertexCount, int originalVertices, int originalFaces,
            int[] triangles, int[] parentFace, int[] parentColor) {
        this.positions = positions;
        this.vertexCount = vertexCount;
        this.originalVertices = originalVertices;
        this.originalFaces = originalFaces;
        this.triangles = triangles;
        this.parentFace = parentFace;
        this.parentColor = parentColor;
    }

    @Override
    public int vertexCount() {
        return vertexCount;
    }

    @Override
    public double coordinate(int v, int axis) {
        return positions[3 * v + axis];
    }

    /** The positions array itself (x, y, z interleaved). */
    public double[] positionArray() {
        return positions;
    }

    /** The triangles array itself: three vertex indices per triangle, in path order. */
    public int[] triangleArray() {
        return triangles;
    }

    @Override
    public int faceCount() {
        return parentFace.length;
    }

    @Override
    public int faceSize(int f) {
        return 3;
    }

    @Override
    public int faceVertex(int f, int k) {
        return triangles[3 * f + k];
    }

    /** The original face that triangle {@code t} lies in. */
    public int parentFace(int t) {
        return parentFace[t];
    }

    @Override
    public boolean hasFaceColors() {
        return parentColor != null;
    }

    @Override
    public int faceColor(int f) {
        return parentColor == null ? PolygonSoup.DEFAULT_COLOR : parentColor[parentFace[f]];
    }

    public boolean isOriginalVertex(int v) {
        return v < originalVertices;
    }

    /** Whether {@code v} is the incentre of an original face. */
    public boolean isIncenter(int v) {
        return v >= originalVertices && v < originalVertices + originalFaces;
    }

    /** Whether {@code v} is the midpoint of a spanning-tree edge. */
    public boolean isMidpoint(int v) {
        return v >= originalVertices + originalFaces;
    }
}
