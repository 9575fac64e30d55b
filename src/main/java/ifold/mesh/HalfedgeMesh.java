package ifold.mesh;

import java.util.Arrays;

/**
 * An index-based halfedge mesh of polygons (see the package documentation for the vocabulary).
 * Connectivity lives in {@code int} arrays and positions in one interleaved {@code double[]};
 * there is no object per element.
 *
 * <p>The mutators here are low level: they keep the arrays in step but not the invariants
 * between them. Whoever mutates (the {@link MeshBuilder}) restores the invariants, and tests
 * call {@link MeshValidator#validate(HalfedgeMesh)} after every mutation. (Paper is not a
 * halfedge mesh: the fold engine keeps it in {@code ifold.sheet}.)
 */
public final class HalfedgeMesh implements IndexedPolygons {
    /** x, y, z of each vertex, interleaved. */
    private double[] positions;
    /** An outgoing halfedge of each vertex (the boundary one on the boundary), or -1. */
    private int[] vertexHalfedge;
    private int vertexCount;

    /** The next halfedge around the face (or hole) of each halfedge. */
    private int[] next;
    /** The previous halfedge around the face (or hole) of each halfedge. */
    private int[] prev;
    /** The vertex each halfedge points to. */
    private int[] toVertex;
    /** The face of each halfedge, or -1 on the boundary. */
    private int[] face;
    private int halfedgeCount;

    /** One halfedge of each face. */
    private int[] faceHalfedge;
    /** Packed 0xAARRGGBB colour of each face; null when the mesh has no colours. */
    private int[] faceColor;
    private int faceCount;

    public HalfedgeMesh() {
        this(16, 32);
    }

    /** An empty mesh with room for the given numbers of vertices and faces. */
    public HalfedgeMesh(int expectedVertices, int expectedFaces) {
        int v = Math.max(4, expectedVertices);
        int f = Math.max(4, expectedFaces);
        positions = new double[3 * v];
        vertexHalfedge = new int[v];
        int h = Math.max(8, 2 * (v + f));
        next = new int[h];
        prev = new int[h];
        toVertex = new int[h];
        face = new int[h];
        faceHalfedge = new int[f];
    }

    /**
     * Takes over fully built arrays (for {@link MeshBuilder}, which fills them in bulk rather than
     * one mutation at a time). The arrays may be longer than the counts.
     */
    static HalfedgeMesh adopt(double[] positions, int[] vertexHalfedge, int vertexCount,
            int[] next, int[] prev, int[] toVertex, int[] face, int halfedgeCount,
            int[] faceHalfedge, int[] faceColor, int faceCount) {
        HalfedgeMesh mesh = new HalfedgeMesh(0, 0);
        mesh.positions = positions;
        mesh.vertexHalfedge = vertexHalfedge;
        mesh.vertexCount = vertexCount;
        mesh.next = next;
        mesh.prev = prev;
        mesh.toVertex = toVertex;
        mesh.face = face;
        mesh.halfedgeCount = halfedgeCount;
        mesh.faceHalfedge = faceHalfedge;
        mesh.faceColor = faceColor;
        mesh.faceCount = faceCount;
        return mesh;
    }

    // ---- handles ----------------------------------------------------------------------------

    public static int twin(int h) {
        return h ^ 1;
    }

    public static int edge(int h) {
        return h >>> 1;
    }

    /** The halfedge of edge {@code e} on side 0 or 1. */
    public static int halfedgeOfEdge(int e, int side) {
        return (e << 1) | side;
    }

    // ---- counts -----------------------------------------------------------------------------

    @Override
    public int vertexCount() {
        return vertexCount;
    }

    public int halfedgeCount() {
        return halfedgeCount;
    }

    public int edgeCount() {
        return halfedgeCount >>> 1;
    }

    @Override
    public int faceCount() {
        return faceCount;
    }

    // ---- connectivity -----------------------------------------------------------------------

    public int next(int h) {
        return next[h];
    }

    public int prev(int h) {
        return prev[h];
    }

    public int toVertex(int h) {
        return toVertex[h];
    }

    public int fromVertex(int h) {
        return toVertex[h ^ 1];
    }

    public int face(int h) {
        return face[h];
    }

    public boolean isBoundary(int h) {
        return face[h] < 0;
    }

    public boolean isBoundaryEdge(int e) {
        return face[e << 1] < 0 || face[(e << 1) | 1] < 0;
    }

    /** An outgoing halfedge of {@code v}, the boundary one when {@code v} is on the boundary; -1 if isolated. */
    public int halfedge(int v) {
        return vertexHalfedge[v];
    }

    public boolean isBoundaryVertex(int v) {
        int h = vertexHalfedge[v];
        return h >= 0 && face[h] < 0;
    }

    public int faceHalfedge(int f) {
        return faceHalfedge[f];
    }

    @Override
    public int faceSize(int f) {
        int size = 0;
        int h = faceHalfedge[f];
        do {
            size++;
            h = next[h];
        } while (h != faceHalfedge[f]);
        return size;
    }

    /** The {@code k}-th vertex of face {@code f}, counting from the tip of {@code faceHalfedge(f)}'s predecessor. */
    @Override
    public int faceVertex(int f, int k) {
        int h = prev[faceHalfedge[f]];
        for (int i = 0; i < k; i++) {
            h = next[h];
        }
        return toVertex[h];
    }

    /** Number of outgoing halfedges of {@code v}, found by turning around it. */
    public int valence(int v) {
        int start = vertexHalfedge[v];
        if (start < 0) {
            return 0;
        }
        int count = 0;
        int h = start;
        do {
            count++;
            h = twin(prev[h]);
        } while (h != start);
        return count;
    }

    // ---- geometry ---------------------------------------------------------------------------

    @Override
    public double coordinate(int v, int axis) {
        return positions[3 * v + axis];
    }

    public double x(int v) {
        return positions[3 * v];
    }

    public double y(int v) {
        return positions[3 * v + 1];
    }

    public double z(int v) {
        return positions[3 * v + 2];
    }

    public void setPosition(int v, double x, double y, double z) {
        positions[3 * v] = x;
        positions[3 * v + 1] = y;
        positions[3 * v + 2] = z;
    }

    /** The positions array itself (x, y, z interleaved; only the first 3·vertexCount entries count). */
    public double[] positionArray() {
        return positions;
    }

    @Override
    public boolean hasFaceColors() {
        return faceColor != null;
    }

    @Override
    public int faceColor(int f) {
        return faceColor == null ? PolygonSoup.DEFAULT_COLOR : faceColor[f];
    }

    public void setFaceColor(int f, int argb) {
        if (faceColor == null) {
            faceColor = new int[faceHalfedge.length];
            Arrays.fill(faceColor, PolygonSoup.DEFAULT_COLOR);
        }
        faceColor[f] = argb;
    }

    // ---- low-level mutation -----------------------------------------------------------------

    /** Adds an isolated vertex and returns its handle. */
    public int addVertex(double x, double y, double z) {
        if (vertexCount == vertexHalfedge.length) {
            int capacity = grow(vertexCount);
            positions = Arrays.copyOf(positions, 3 * capacity);
            vertexHalfedge = Arrays.copyOf(vertexHalfedge, capacity);
        }
        int v = vertexCount++;
        setPosition(v, x, y, z);
        vertexHalfedge[v] = -1;
        return v;
    }

    /**
     * Adds an edge from {@code from} to {@code to} and returns its halfedge pointing to {@code to};
     * the twin points to {@code from}. Both halfedges start with no face and link to themselves,
     * which is not valid until the caller links them.
     */
    public int addEdge(int from, int to) {
        if (halfedgeCount + 2 > next.length) {
            int capacity = grow(halfedgeCount);
            next = Arrays.copyOf(next, capacity);
            prev = Arrays.copyOf(prev, capacity);
            toVertex = Arrays.copyOf(toVertex, capacity);
            face = Arrays.copyOf(face, capacity);
        }
        int h = halfedgeCount;
        halfedgeCount += 2;
        toVertex[h] = to;
        toVertex[h + 1] = from;
        face[h] = -1;
        face[h + 1] = -1;
        next[h] = h;
        prev[h] = h;
        next[h + 1] = h + 1;
        prev[h + 1] = h + 1;
        return h;
    }

    /** Adds a face whose loop starts at {@code h}; the caller sets {@code face} on the loop. */
    public int addFace(int h) {
        if (faceCount == faceHalfedge.length) {
            int capacity = grow(faceCount);
            faceHalfedge = Arrays.copyOf(faceHalfedge, capacity);
            if (faceColor != null) {
                int old = faceColor.length;
                faceColor = Arrays.copyOf(faceColor, capacity);
                Arrays.fill(faceColor, old, capacity, PolygonSoup.DEFAULT_COLOR);
            }
        }
        faceHalfedge[faceCount] = h;
        return faceCount++;
    }

    /** Links {@code h} to {@code hNext}: sets both {@code next(h)} and {@code prev(hNext)}. */
    public void link(int h, int hNext) {
        next[h] = hNext;
        prev[hNext] = h;
    }

    public void setToVertex(int h, int v) {
        toVertex[h] = v;
    }

    public void setFace(int h, int f) {
        face[h] = f;
    }

    public void setHalfedge(int v, int h) {
        vertexHalfedge[v] = h;
    }

    public void setFaceHalfedge(int f, int h) {
        faceHalfedge[f] = h;
    }

    /**
     * Makes {@code halfedge(v)} the boundary halfedge leaving {@code v} if there is one, as the
     * package convention asks. Call after changing the faces around {@code v}.
     */
    public void adjustOutgoingHalfedge(int v) {
        int start = vertexHalfedge[v];
        if (start < 0) {
            return;
        }
        int h = start;
        do {
            if (face[h] < 0) {
                vertexHalfedge[v] = h;
                return;
            }
            h = twin(prev[h]);
        } while (h != start);
    }

    private static int grow(int size) {
        return Math.max(16, size + (size >> 1));
    }
}
