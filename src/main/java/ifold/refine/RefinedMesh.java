package ifold.refine;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.IndexedPolygons;
import ifold.mesh.PolygonSoup;

/**
 * The triangles of a Hamiltonian refinement, listed in path order: triangle {@code t} and
 * {@code t + 1} share an edge, except where one component's path ends and the next begins.
 *
 * <p>Vertices come in three blocks: the original vertices keep their indices
 * {@code [0, V)}; then one incentre per original face, in face order; then one midpoint per
 * spanning-tree edge.
 *
 * <p>The triangles are not stored as vertex triples. Each is the part of an original face cut
 * off by one of its halfedges {@code h}: the whole sub-triangle (incentre, from(h), to(h)), or
 * its first or second half when the edge of {@code h} is split at its midpoint; on the path
 * through a mesh's own triangles ({@link CycleCoverPath}), the face itself (its corner opposite
 * h, from(h), to(h)), the split edges those of its splices, or its half on the side of h's
 * start or end where that side is split (the face cut from that corner to the side's
 * midpoint). So the path is one {@code int} per triangle, {@code h << SHIFT | part}, and the refinement of 1.4 million
 * triangles takes about a third of the memory that explicit triples would.
 */
public final class RefinedMesh implements IndexedPolygons {
    static final int WHOLE = 0;
    static final int FIRST_HALF = 1;
    static final int SECOND_HALF = 2;
    /** The whole face, its corner opposite {@code h} in the incentre's place ({@link CycleCoverPath}). */
    static final int FACE = 3;
    /** The face's half at from(h) where h's edge is split: its corner opposite h, from(h), the midpoint ({@link CycleCoverPath}). */
    static final int FACE_FIRST_HALF = 4;
    /** The face's half at to(h) where h's edge is split: its corner opposite h, the midpoint, to(h). */
    static final int FACE_SECOND_HALF = 5;
    /** A path code is the halfedge shifted left by this, or'ed with its part. */
    static final int SHIFT = 3;
    private static final int PART = (1 << SHIFT) - 1;

    private final HalfedgeMesh original;
    /** Per triangle in path order: the halfedge it stands on, shifted left by 2, or'ed with its part. */
    private final int[] path;
    /** x, y, z of the incentre of each original face, interleaved. */
    private final double[] incentres;
    /** The tree edges, one bit per original edge, with the number of set bits before each word. */
    private final EdgeSet treeEdges;

    /** Whether the path passes the original triangles whole but where it splices ({@link CycleCoverPath}). */
    private final boolean ownTriangles;

    RefinedMesh(HalfedgeMesh original, int[] path, double[] incentres, EdgeSet treeEdges, boolean ownTriangles) {
        this.original = original;
        this.path = path;
        this.incentres = incentres;
        this.treeEdges = treeEdges;
        this.ownTriangles = ownTriangles;
    }

    /**
     * Whether this is the path through the original triangles themselves ({@link CycleCoverPath}),
     * rather than the Hamiltonian refinement.
     */
    public boolean ownTriangles() {
        return ownTriangles;
    }

    /**
     * The same triangles with each component's path begun {@code shift[c]} triangles later and
     * going on round to where it began: a path whose first and last triangles share an edge
     * is a cycle, and may begin anywhere on it.
     */
    RefinedMesh rotated(int[] componentStart, int[] shift) {
        int[] turned = new int[path.length];
        for (int c = 0; c + 1 < componentStart.length; c++) {
            int from = componentStart[c];
            int length = componentStart[c + 1] - from;
            for (int i = 0; i < length; i++) {
                turned[from + i] = path[from + Math.floorMod(i + shift[c], length)];
            }
        }
        return new RefinedMesh(original, turned, incentres, treeEdges, ownTriangles);
    }

    /** The same pieces with each component's path run the other way. */
    RefinedMesh reversed(int[] componentStart) {
        int[] back = new int[path.length];
        for (int c = 0; c + 1 < componentStart.length; c++) {
            int from = componentStart[c];
            int to = componentStart[c + 1];
            for (int i = from; i < to; i++) {
                back[i] = path[from + to - 1 - i];
            }
        }
        return new RefinedMesh(original, back, incentres, treeEdges, ownTriangles);
    }

    /** The mesh that was refined; its vertices are the first vertices of this one. */
    public HalfedgeMesh original() {
        return original;
    }

    @Override
    public int vertexCount() {
        return original.vertexCount() + original.faceCount() + treeEdges.size();
    }

    /**
     * Midpoints are not stored: a midpoint's coordinate is computed from its edge's ends when
     * asked, which saves a third of the refinement's memory at the cost of an addition.
     */
    @Override
    public double coordinate(int v, int axis) {
        int originals = original.vertexCount();
        if (v < originals) {
            return original.coordinate(v, axis);
        }
        int steiner = v - originals;
        if (steiner < original.faceCount()) {
            return incentres[3 * steiner + axis];
        }
        int e = treeEdges.select(steiner - original.faceCount());
        return 0.5 * (original.coordinate(original.toVertex(2 * e), axis) + original.coordinate(original.toVertex(2 * e + 1), axis));
    }

    @Override
    public int faceCount() {
        return path.length;
    }

    @Override
    public int faceSize(int f) {
        return 3;
    }

    @Override
    public int faceVertex(int t, int k) {
        int code = path[t];
        int h = code >>> SHIFT;
        int part = code & PART;
        if (k == 0) {
            return part >= FACE ? original.toVertex(original.next(h)) : original.vertexCount() + original.face(h);
        }
        if (k == 1) {
            return part == SECOND_HALF || part == FACE_SECOND_HALF ? midpoint(h) : original.fromVertex(h);
        }
        return part == FIRST_HALF || part == FACE_FIRST_HALF ? midpoint(h) : original.toVertex(h);
    }

    private int midpoint(int h) {
        return original.vertexCount() + original.faceCount() + treeEdges.rank(HalfedgeMesh.edge(h));
    }

    /** The original face that triangle {@code t} lies in. */
    public int parentFace(int t) {
        return original.face(path[t] >>> SHIFT);
    }

    /** The original halfedge that triangle {@code t} stands on: its side opposite the incentre (or the face's corner) lies along it. */
    public int parentHalfedge(int t) {
        return path[t] >>> SHIFT;
    }

    @Override
    public boolean hasFaceColors() {
        return original.hasFaceColors();
    }

    @Override
    public int faceColor(int t) {
        return original.hasFaceColors() ? original.faceColor(parentFace(t)) : PolygonSoup.DEFAULT_COLOR;
    }

    public boolean isOriginalVertex(int v) {
        return v < original.vertexCount();
    }

    /** Whether {@code v} is the incentre of an original face. */
    public boolean isIncenter(int v) {
        return v >= original.vertexCount() && v < original.vertexCount() + original.faceCount();
    }

    /** Whether {@code v} is the midpoint of a spanning-tree edge. */
    public boolean isMidpoint(int v) {
        return v >= original.vertexCount() + original.faceCount() && v < vertexCount();
    }

    /** The path codes themselves, for tests that break the path on purpose. */
    int[] pathCodes() {
        return path;
    }
}
