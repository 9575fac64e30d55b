package ifold.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Each corruption is caught as its own kind of error. */
class MeshValidatorTest {

    private static HalfedgeMesh tetrahedron() {
        HalfedgeMesh mesh = Fixtures.build(Solids.tetrahedron());
        assertEquals(List.of(), MeshValidator.validate(mesh), "setup: the fixture is valid");
        return mesh;
    }

    private static MeshError.Kind firstKind(HalfedgeMesh mesh) {
        List<MeshError> errors = MeshValidator.validate(mesh);
        assertTrue(!errors.isEmpty(), "corruption not detected");
        return errors.get(0).kind();
    }

    @Test
    void brokenNextPrevIsStructural() {
        HalfedgeMesh mesh = tetrahedron();
        int h = mesh.faceHalfedge(0);
        mesh.link(h, mesh.prev(h)); // next(h) now skips a halfedge
        assertEquals(MeshError.Kind.NEXT_PREV_MISMATCH, firstKind(mesh));
    }

    @Test
    void handleOutOfRange() {
        HalfedgeMesh mesh = tetrahedron();
        mesh.setToVertex(3, 99);
        assertEquals(MeshError.Kind.HANDLE_OUT_OF_RANGE, firstKind(mesh));
    }

    @Test
    void faceLoopThroughAnotherFace() {
        HalfedgeMesh mesh = tetrahedron();
        int h = mesh.faceHalfedge(0);
        mesh.setFace(mesh.next(h), 1);
        assertEquals(MeshError.Kind.FACE_LOOP_BROKEN, firstKind(mesh));
    }

    @Test
    void wrongTargetVertexBreaksTheChain() {
        HalfedgeMesh mesh = tetrahedron();
        int h = mesh.faceHalfedge(0);
        int other = (mesh.toVertex(h) + 1) % 4 == mesh.fromVertex(h) ? (mesh.toVertex(h) + 2) % 4 : (mesh.toVertex(h) + 1) % 4;
        mesh.setToVertex(h, other);
        assertEquals(MeshError.Kind.VERTEX_MISMATCH, firstKind(mesh));
    }

    @Test
    void vertexHalfedgeMustLeaveTheVertex() {
        HalfedgeMesh mesh = tetrahedron();
        int h = mesh.halfedge(0);
        mesh.setHalfedge(0, HalfedgeMesh.twin(h));
        assertEquals(MeshError.Kind.VERTEX_HALFEDGE_WRONG, firstKind(mesh));
    }

    @Test
    void boundaryVertexMustStartAtItsBoundaryHalfedge() {
        HalfedgeMesh mesh = Fixtures.build(Fixtures.square());
        int h = mesh.halfedge(0);
        mesh.setHalfedge(0, HalfedgeMesh.twin(mesh.prev(h)));
        assertEquals(MeshError.Kind.VERTEX_HALFEDGE_WRONG, firstKind(mesh));
    }

    @Test
    void isolatedVertex() {
        HalfedgeMesh mesh = tetrahedron();
        mesh.addVertex(5, 5, 5);
        assertEquals(MeshError.Kind.ISOLATED_VERTEX, firstKind(mesh));
    }

    @Test
    void danglingEdge() {
        HalfedgeMesh mesh = tetrahedron();
        mesh.addEdge(0, 1);
        List<MeshError> errors = MeshValidator.validate(mesh);
        assertTrue(errors.stream().anyMatch(e -> e.kind() == MeshError.Kind.DANGLING_EDGE), errors.toString());
    }

    @Test
    void zeroAreaFace() {
        HalfedgeMesh mesh = tetrahedron();
        mesh.setPosition(0, 0, 0, 0);
        mesh.setPosition(1, 0, 0, 0);
        assertEquals(MeshError.Kind.ZERO_AREA_FACE, firstKind(mesh));
    }

    @Test
    void nonFinitePosition() {
        HalfedgeMesh mesh = tetrahedron();
        mesh.setPosition(2, Double.POSITIVE_INFINITY, 0, 0);
        assertEquals(MeshError.Kind.NON_FINITE_POSITION, firstKind(mesh));
    }

    @Test
    void pinchedFanIsNonManifold() {
        // Glue the two fans of a bowtie back onto one vertex by hand.
        HalfedgeMesh mesh = Fixtures.build(Fixtures.bowtie());
        int copy = mesh.vertexCount() - 1;
        for (int h = 0; h < mesh.halfedgeCount(); h++) {
            if (mesh.toVertex(h) == copy) {
                mesh.setToVertex(h, 0);
            }
        }
        List<MeshError> errors = MeshValidator.validate(mesh);
        assertTrue(errors.stream().anyMatch(e -> e.kind() == MeshError.Kind.NON_MANIFOLD_VERTEX), errors.toString());
    }

    /**
     * A closed surface of four triangles in which two edges join the same two vertices u and
     * v (two digons, each filled by two triangles): every orbit is sound, and only the double
     * edge is wrong, reported once.
     */
    @Test
    void twoEdgesBetweenTheSameVerticesAreReportedOnce() {
        HalfedgeMesh mesh = new HalfedgeMesh();
        int u = mesh.addVertex(0, 0, 0);
        int v = mesh.addVertex(1, 0, 0);
        int a = mesh.addVertex(0.5, 1, 0);
        int b = mesh.addVertex(0.5, -1, 0.5);
        int e1 = mesh.addEdge(u, v);
        int e2 = mesh.addEdge(u, v);
        int ua = mesh.addEdge(u, a);
        int va = mesh.addEdge(v, a);
        int ub = mesh.addEdge(u, b);
        int vb = mesh.addEdge(v, b);
        int[][] loops = {
            {e1, va, HalfedgeMesh.twin(ua)}, // u v a
            {HalfedgeMesh.twin(e2), ua, HalfedgeMesh.twin(va)}, // v u a
            {HalfedgeMesh.twin(e1), ub, HalfedgeMesh.twin(vb)}, // v u b
            {e2, vb, HalfedgeMesh.twin(ub)}, // u v b
        };
        for (int[] loop : loops) {
            int f = mesh.addFace(loop[0]);
            for (int k = 0; k < 3; k++) {
                mesh.link(loop[k], loop[(k + 1) % 3]);
                mesh.setFace(loop[k], f);
            }
        }
        mesh.setHalfedge(u, e1);
        mesh.setHalfedge(v, HalfedgeMesh.twin(e1));
        mesh.setHalfedge(a, HalfedgeMesh.twin(ua));
        mesh.setHalfedge(b, HalfedgeMesh.twin(ub));
        assertEquals(2, Topology.of(mesh).eulerCharacteristic(), "setup: a sphere");
        List<MeshError> errors = MeshValidator.validate(mesh);
        assertEquals(1, errors.size(), errors.toString());
        assertEquals(MeshError.Kind.DUPLICATE_EDGE, errors.get(0).kind());
        assertEquals("vertices 0 and 1 are joined by two edges", errors.get(0).message());
    }
}
