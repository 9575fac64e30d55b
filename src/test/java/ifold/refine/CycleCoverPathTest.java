package ifold.refine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.io.MeshReaders;
import ifold.testing.SharedMeshes;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.Topology;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

class CycleCoverPathTest {

    static Stream<Arguments> closedSolids() {
        return Stream.of(
                Arguments.of("tetrahedron", Solids.tetrahedron()),
                Arguments.of("cube", Solids.cube()),
                Arguments.of("octahedron", Solids.octahedron()),
                Arguments.of("icosahedron", Solids.icosahedron()),
                Arguments.of("icosphere", Solids.icosphere(3)),
                Arguments.of("torus", Solids.torus(3, 1, 16, 9)),
                Arguments.of("long torus", Solids.torus(3, 1, 60, 7)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("closedSolids")
    void aClosedSolidGetsOneCycleThroughItsOwnTriangles(String name, PolygonSoup soup) {
        HalfedgeMesh mesh = HamiltonianRefinementTest.triangles(soup);
        HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
        assertNotNull(result);
        assertEquals(List.of(), violations(mesh, result));
        assertEquals(Topology.of(mesh).components(), result.componentCount());
    }

    @Test
    void cyclesAreSplicedWhereTheMatchingLeavesSeveral() {
        // A long thin torus: its matching leaves rings round the tube, which are spliced.
        HalfedgeMesh mesh = HamiltonianRefinementTest.triangles(Solids.torus(3, 1, 60, 7));
        HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
        int splices = 0;
        for (boolean split : result.treeEdge()) {
            splices += split ? 1 : 0;
        }
        assertTrue(splices > 0, "no splice made");
        assertEquals(mesh.faceCount() + 6 * splices, result.mesh().faceCount());
        assertEquals(List.of(), violations(mesh, result));
    }

    @Test
    void aSurfaceWithABoundaryHasNoSuchPath() {
        assertNull(CycleCoverPath.of(HamiltonianRefinementTest.triangles(Solids.triangle())));
        assertNull(CycleCoverPath.of(HamiltonianRefinementTest.triangles(Solids.figure3())));
    }

    static Stream<String> valid() {
        return SharedMeshes.names("valid");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("valid")
    void everyClosedSharedModelGetsOne(String name) throws Exception {
        assumeTrue(SharedMeshes.present(), "../shared/meshes is absent");
        PolygonSoup soup = MeshReaders.read(SharedMeshes.ROOT.resolve("valid").resolve(name));
        HalfedgeMesh mesh = MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
        if (Topology.of(mesh).boundaryLoops() > 0) {
            assertNull(result, "a surface with a boundary");
            return;
        }
        assertNotNull(result, "a closed surface");
        assertEquals(List.of(), violations(mesh, result));
    }

    /**
     * What the path promises, checked from its triangles alone: what any path of triangles
     * promises ({@link RefinementClaims#pathViolations}), and that each component's last triangle
     * shares an edge with its first, so that the strip may begin anywhere on it.
     */
    static List<String> violations(HalfedgeMesh mesh, HamiltonianRefinement.Result result) {
        List<String> found = new ArrayList<>(RefinementClaims.pathViolations(mesh, result));
        for (int c = 0; c < result.componentCount(); c++) {
            if (result.componentStart()[c + 1] - result.componentStart()[c] > 2 && !result.cyclic(c)) {
                found.add("component " + c + " is not a cycle");
            }
        }
        return found;
    }
}
