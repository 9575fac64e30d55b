package ifold.mesh;

import ifold.geom.Polygons;
import ifold.geom.Triangles;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Checks every invariant of a {@link HalfedgeMesh} and returns what is broken as values. The
 * checks are graded as in CGAL's validity test: the structure of the arrays first (if that
 * fails, the later checks could not even walk the mesh, so they are skipped), then the orbits
 * around faces, holes and vertices, then the geometry.
 *
 * <p>Tests call it after every mutation; the error list names the first {@link #LIMIT} problems.
 */
public final class MeshValidator {
    /** At most this many errors are reported, so a wrecked mesh gives a readable answer. */
    public static final int LIMIT = 100;

    private final HalfedgeMesh mesh;
    private final List<MeshError> errors = new ArrayList<>();

    private MeshValidator(HalfedgeMesh mesh) {
        this.mesh = mesh;
    }

    /** All broken invariants of {@code mesh}, or an empty list when it is valid. */
    public static List<MeshError> validate(HalfedgeMesh mesh) {
        MeshValidator validator = new MeshValidator(mesh);
        if (validator.checkStructure()) {
            validator.checkOrbits();
            validator.checkGeometry();
        }
        return List.copyOf(validator.errors);
    }

    public static boolean isValid(HalfedgeMesh mesh) {
        return validate(mesh).isEmpty();
    }

    private void report(MeshError.Kind kind, int element, String message) {
        if (errors.size() < LIMIT) {
            errors.add(new MeshError(kind, element, message));
        }
    }

    private boolean checkStructure() {
        int halfedges = mesh.halfedgeCount();
        int vertices = mesh.vertexCount();
        int faces = mesh.faceCount();
        if ((halfedges & 1) != 0) {
            report(MeshError.Kind.ODD_HALFEDGE_COUNT, halfedges, "halfedge count " + halfedges + " is odd");
        }
        for (int h = 0; h < halfedges; h++) {
            if (!inRange(mesh.next(h), halfedges) || !inRange(mesh.prev(h), halfedges)) {
                report(MeshError.Kind.HANDLE_OUT_OF_RANGE, h, "halfedge " + h + " has next or prev out of range");
            } else if (mesh.prev(mesh.next(h)) != h) {
                report(MeshError.Kind.NEXT_PREV_MISMATCH, h, "prev(next(" + h + ")) is " + mesh.prev(mesh.next(h)));
            }
            if (!inRange(mesh.toVertex(h), vertices)) {
                report(MeshError.Kind.HANDLE_OUT_OF_RANGE, h, "halfedge " + h + " points to vertex " + mesh.toVertex(h));
            }
            if (mesh.face(h) < -1 || mesh.face(h) >= faces) {
                report(MeshError.Kind.HANDLE_OUT_OF_RANGE, h, "halfedge " + h + " has face " + mesh.face(h));
            }
        }
        for (int v = 0; v < vertices; v++) {
            if (mesh.halfedge(v) < -1 || mesh.halfedge(v) >= halfedges) {
                report(MeshError.Kind.HANDLE_OUT_OF_RANGE, v, "vertex " + v + " has halfedge " + mesh.halfedge(v));
            }
        }
        for (int f = 0; f < faces; f++) {
            if (!inRange(mesh.faceHalfedge(f), halfedges)) {
                report(MeshError.Kind.HANDLE_OUT_OF_RANGE, f, "face " + f + " has halfedge " + mesh.faceHalfedge(f));
            }
        }
        return errors.isEmpty();
    }

    private static boolean inRange(int handle, int count) {
        return handle >= 0 && handle < count;
    }

    private void checkOrbits() {
        int halfedges = mesh.halfedgeCount();
        // Faces: each loop stays in its face, closes, and has at least three sides; together the
        // loops cover every interior halfedge exactly once.
        int covered = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int start = mesh.faceHalfedge(f);
            int h = start;
            int size = 0;
            do {
                if (mesh.face(h) != f) {
                    report(MeshError.Kind.FACE_LOOP_BROKEN, f, "face " + f + " loop reaches halfedge " + h
                            + " of face " + mesh.face(h));
                    break;
                }
                size++;
                h = mesh.next(h);
            } while (h != start && size <= halfedges);
            if (size > halfedges) {
                report(MeshError.Kind.FACE_LOOP_BROKEN, f, "face " + f + " loop does not close");
            } else if (size < 3) {
                report(MeshError.Kind.FACE_TOO_SMALL, f, "face " + f + " has " + size + " sides");
            }
            covered += size;
        }
        int interior = 0;
        for (int h = 0; h < halfedges; h++) {
            if (!mesh.isBoundary(h)) {
                interior++;
            } else if (!mesh.isBoundary(mesh.next(h))) {
                report(MeshError.Kind.BOUNDARY_LOOP_BROKEN, h, "boundary halfedge " + h
                        + " is followed by interior halfedge " + mesh.next(h));
            }
            if ((h & 1) == 0 && mesh.isBoundary(h) && mesh.isBoundary(h ^ 1)) {
                report(MeshError.Kind.DANGLING_EDGE, h >>> 1, "edge " + (h >>> 1) + " has no face on either side");
            }
            if (mesh.toVertex(mesh.prev(h)) != mesh.fromVertex(h)) {
                report(MeshError.Kind.VERTEX_MISMATCH, h, "halfedge " + h + " starts at " + mesh.fromVertex(h)
                        + " but its predecessor ends at " + mesh.toVertex(mesh.prev(h)));
            }
        }
        if (covered != interior && errors.isEmpty()) {
            report(MeshError.Kind.FACE_LOOP_BROKEN, -1, "face loops cover " + covered + " of "
                    + interior + " interior halfedges");
        }
        if (!errors.isEmpty()) {
            return; // vertex orbits would walk broken loops
        }
        checkVertexOrbits();
    }

    /**
     * Each vertex's fan holds all its outgoing halfedges, and reaches each neighbour once (two
     * edges between the same two vertices are a split that did not go through; each is
     * reported once, at the lower vertex).
     */
    private void checkVertexOrbits() {
        int vertices = mesh.vertexCount();
        // The last vertex whose fan reached each vertex: a neighbour met twice in one fan is a double edge.
        int[] reachedFrom = new int[vertices];
        Arrays.fill(reachedFrom, -1);
        int[] outgoing = new int[vertices];
        for (int h = 0; h < mesh.halfedgeCount(); h++) {
            outgoing[mesh.fromVertex(h)]++;
        }
        for (int v = 0; v < vertices; v++) {
            int start = mesh.halfedge(v);
            if (start < 0) {
                report(MeshError.Kind.ISOLATED_VERTEX, v, "vertex " + v + " has no halfedge");
                continue;
            }
            if (mesh.fromVertex(start) != v) {
                report(MeshError.Kind.VERTEX_HALFEDGE_WRONG, v, "halfedge(" + v + ") = " + start
                        + " leaves vertex " + mesh.fromVertex(start));
                continue;
            }
            int count = 0;
            boolean boundary = false;
            int h = start;
            do {
                boundary |= mesh.isBoundary(h);
                count++;
                int neighbour = mesh.toVertex(h);
                if (reachedFrom[neighbour] == v && v < neighbour) {
                    report(MeshError.Kind.DUPLICATE_EDGE, v, "vertices " + v + " and " + neighbour + " are joined by two edges");
                }
                reachedFrom[neighbour] = v;
                h = HalfedgeMesh.twin(mesh.prev(h));
            } while (h != start && count <= outgoing[v]);
            if (count != outgoing[v]) {
                report(MeshError.Kind.NON_MANIFOLD_VERTEX, v, "vertex " + v + " has " + outgoing[v]
                        + " outgoing halfedges but " + count + " in its fan");
            } else if (boundary && !mesh.isBoundary(start)) {
                report(MeshError.Kind.VERTEX_HALFEDGE_WRONG, v, "boundary vertex " + v
                        + " does not start at its boundary halfedge");
            }
        }
    }

    private void checkGeometry() {
        double[] xyz = mesh.positionArray();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            if (!Double.isFinite(xyz[3 * v]) || !Double.isFinite(xyz[3 * v + 1]) || !Double.isFinite(xyz[3 * v + 2])) {
                report(MeshError.Kind.NON_FINITE_POSITION, v, "vertex " + v + " has a non-finite coordinate");
            }
        }
        int[] polygon = new int[16];
        for (int f = 0; f < mesh.faceCount(); f++) {
            int size = 0;
            int start = mesh.faceHalfedge(f);
            int h = start;
            do {
                if (size == polygon.length) {
                    polygon = Arrays.copyOf(polygon, 2 * size);
                }
                polygon[size++] = mesh.toVertex(h);
                h = mesh.next(h);
            } while (h != start);
            // Triangles are judged as the builder judges them, by the same test, which does not
            // depend on the corner a loop starts at (and without a polygon's copies).
            boolean area = size == 3 ? !Triangles.isDegenerate(xyz, polygon[0], polygon[1], polygon[2])
                    : Polygons.hasArea(xyz, polygon, size);
            if (!area) {
                report(MeshError.Kind.ZERO_AREA_FACE, f, "face " + f + " has no area");
            }
        }
    }
}
