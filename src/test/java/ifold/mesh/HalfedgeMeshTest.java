package ifold.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The halfedge mesh's own operations, on meshes built by hand through them and by the builder:
 * the handles' arithmetic, the loops around faces and vertices, the boundary, and the convention
 * that a boundary vertex's outgoing halfedge is its boundary one.
 */
class HalfedgeMeshTest {
    /** One triangle 0 → 1 → 2 made edge by edge, as the builder makes faces. */
    private static HalfedgeMesh triangleByHand() {
        HalfedgeMesh mesh = new HalfedgeMesh(3, 1);
        int a = mesh.addVertex(0, 0, 0);
        int b = mesh.addVertex(1, 0, 0);
        int c = mesh.addVertex(0, 1, 0);
        int ab = mesh.addEdge(a, b);
        int bc = mesh.addEdge(b, c);
        int ca = mesh.addEdge(c, a);
        int f = mesh.addFace(ab);
        mesh.link(ab, bc);
        mesh.link(bc, ca);
        mesh.link(ca, ab);
        for (int h : new int[] {ab, bc, ca}) {
            mesh.setFace(h, f);
        }
        // The twins run the other way round, on the boundary.
        mesh.link(HalfedgeMesh.twin(ab), HalfedgeMesh.twin(ca));
        mesh.link(HalfedgeMesh.twin(ca), HalfedgeMesh.twin(bc));
        mesh.link(HalfedgeMesh.twin(bc), HalfedgeMesh.twin(ab));
        mesh.setHalfedge(a, ab);
        mesh.setHalfedge(b, bc);
        mesh.setHalfedge(c, ca);
        for (int v = 0; v < 3; v++) {
            mesh.adjustOutgoingHalfedge(v);
        }
        return mesh;
    }

    @Test
    void handlesPairTwinsAndEdges() {
        for (int h = 0; h < 64; h++) {
            assertEquals(h, HalfedgeMesh.twin(HalfedgeMesh.twin(h)));
            assertEquals(HalfedgeMesh.edge(h), HalfedgeMesh.edge(HalfedgeMesh.twin(h)));
            assertEquals(h, HalfedgeMesh.halfedgeOfEdge(HalfedgeMesh.edge(h), h & 1));
        }
        assertEquals(1, HalfedgeMesh.twin(0));
        assertEquals(3, HalfedgeMesh.edge(7));
    }

    @Test
    void aTriangleMadeByHandIsValidAndItsLoopsClose() {
        HalfedgeMesh mesh = triangleByHand();
        assertEquals(List.of(), MeshValidator.validate(mesh));
        assertEquals(3, mesh.vertexCount());
        assertEquals(6, mesh.halfedgeCount());
        assertEquals(3, mesh.edgeCount());
        assertEquals(1, mesh.faceCount());
        assertEquals(3, mesh.faceSize(0));
        assertEquals(List.of(0, 1, 2), List.of(mesh.faceVertex(0, 0), mesh.faceVertex(0, 1), mesh.faceVertex(0, 2)));
        for (int h = 0; h < mesh.halfedgeCount(); h++) {
            assertEquals(h, mesh.next(mesh.next(mesh.next(h))), "three halfedges round each loop");
            assertEquals(h, mesh.prev(mesh.next(h)));
            assertEquals(mesh.fromVertex(h), mesh.toVertex(HalfedgeMesh.twin(h)));
            assertEquals(mesh.toVertex(h), mesh.fromVertex(mesh.next(h)), "a loop is joined end to start");
            assertTrue(mesh.isBoundary(h) != mesh.isBoundary(HalfedgeMesh.twin(h)), "every edge of a lone triangle is a border");
        }
        for (int v = 0; v < 3; v++) {
            assertTrue(mesh.isBoundaryVertex(v), "the outgoing halfedge kept is the boundary one");
            assertTrue(mesh.isBoundary(mesh.halfedge(v)));
            assertEquals(v, mesh.fromVertex(mesh.halfedge(v)));
            assertEquals(2, mesh.valence(v));
        }
    }

    @Test
    void aClosedSolidHasNoBoundaryAndItsVerticesTheirValence() throws InvalidMeshException {
        HalfedgeMesh cube = MeshBuilder.build(Solids.cube(), MeshBuilder.Options.REPAIR).mesh();
        assertEquals(List.of(), MeshValidator.validate(cube));
        assertEquals(8, cube.vertexCount());
        assertEquals(12, cube.edgeCount());
        assertEquals(6, cube.faceCount());
        for (int e = 0; e < cube.edgeCount(); e++) {
            assertFalse(cube.isBoundaryEdge(e));
        }
        for (int v = 0; v < cube.vertexCount(); v++) {
            assertFalse(cube.isBoundaryVertex(v));
            assertEquals(3, cube.valence(v), "three faces meet at each corner of a cube");
        }
        int corners = 0;
        for (int f = 0; f < cube.faceCount(); f++) {
            assertEquals(4, cube.faceSize(f));
            corners += cube.faceSize(f);
        }
        assertEquals(2 * cube.edgeCount(), corners, "each edge borders two faces");
        // Euler: V - E + F = 2 for a sphere.
        assertEquals(2, cube.vertexCount() - cube.edgeCount() + cube.faceCount());
    }

    @Test
    void aBrokenLinkIsWhatTheValidatorFinds() {
        HalfedgeMesh mesh = triangleByHand();
        // Point the face's loop back on itself at one halfedge: no longer a loop of three.
        int h = mesh.faceHalfedge(0);
        mesh.link(h, h);
        assertFalse(MeshValidator.validate(mesh).isEmpty(), "a loop that does not close is an error");
    }

    @Test
    void positionsAndColoursAreKept() {
        HalfedgeMesh mesh = triangleByHand();
        mesh.setPosition(1, 2, 3, 4);
        assertEquals(2, mesh.x(1));
        assertEquals(3, mesh.y(1));
        assertEquals(4, mesh.z(1));
        assertEquals(3, mesh.coordinate(1, 1));
        assertFalse(mesh.hasFaceColors());
        mesh.setFaceColor(0, 0xFF00FF00);
        assertTrue(mesh.hasFaceColors());
        assertEquals(0xFF00FF00, mesh.faceColor(0));
    }
}
