package ifold.mesh;

/**
 * One broken invariant found by {@link MeshValidator}: what kind, which element (a vertex,
 * halfedge or face handle, as the kind says), and a sentence for people.
 */
public record MeshError(Kind kind, int element, String message) {

    /** The invariants, in the order they are checked: structure, then orbits, then geometry. */
    public enum Kind {
        // Structure: the arrays themselves.
        ODD_HALFEDGE_COUNT,
        HANDLE_OUT_OF_RANGE,
        NEXT_PREV_MISMATCH,
        // Orbits: loops around faces, holes and vertices.
        FACE_LOOP_BROKEN,
        FACE_TOO_SMALL,
        BOUNDARY_LOOP_BROKEN,
        DANGLING_EDGE,
        VERTEX_MISMATCH,
        VERTEX_HALFEDGE_WRONG,
        NON_MANIFOLD_VERTEX,
        ISOLATED_VERTEX,
        DUPLICATE_EDGE,
        // Geometry.
        NON_FINITE_POSITION,
        ZERO_AREA_FACE
    }

    @Override
    public String toString() {
        return kind + " at " + element + ": " + message;
    }
}
