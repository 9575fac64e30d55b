package ifold.refine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.geom.Triangles;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.io.MeshReaders;
import ifold.testing.SharedMeshes;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.Topology;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
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
     * What the path promises, checked from its triangles alone: consecutive triangles of a
     * component share an edge, and so do its last and first; no triangle twice; each of the
     * mesh's triangles covered by the path's triangles within it, with its area; a triangle cut
     * only by the incentre and the midpoints of split edges.
     */
    static List<String> violations(HalfedgeMesh mesh, HamiltonianRefinement.Result result) {
        List<String> found = new ArrayList<>();
        RefinedMesh path = result.mesh();
        for (int c = 0; c < result.componentCount(); c++) {
            int first = result.componentStart()[c];
            int end = result.componentStart()[c + 1];
            for (int t = first; t < end; t++) {
                int next = t + 1 < end ? t + 1 : first;
                if (end - first > 1 && sharedCorners(path, t, next) != 2) {
                    found.add("triangles " + t + " and " + next + " share no edge");
                }
            }
        }
        Set<String> seen = new HashSet<>();
        double[] area = new double[mesh.faceCount()];
        double[] corners = new double[9];
        for (int t = 0; t < path.faceCount(); t++) {
            int[] v = {path.faceVertex(t, 0), path.faceVertex(t, 1), path.faceVertex(t, 2)};
            int[] sorted = v.clone();
            java.util.Arrays.sort(sorted);
            if (!seen.add(java.util.Arrays.toString(sorted))) {
                found.add("triangle " + t + " twice");
            }
            for (int k = 0; k < 3; k++) {
                for (int axis = 0; axis < 3; axis++) {
                    corners[3 * k + axis] = path.coordinate(v[k], axis);
                }
            }
            area[path.parentFace(t)] += Triangles.twiceArea(corners, 0, 1, 2);
        }
        double[] xyz = mesh.positionArray();
        for (int f = 0; f < mesh.faceCount(); f++) {
            int h = mesh.faceHalfedge(f);
            double own = Triangles.twiceArea(xyz, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h)));
            if (Math.abs(area[f] - own) > 1e-9 * Math.max(1, own)) {
                found.add("triangle " + f + " covered by " + area[f] + " of its " + own);
            }
        }
        return found;
    }

    private static int sharedCorners(RefinedMesh path, int s, int t) {
        int shared = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                shared += path.faceVertex(s, i) == path.faceVertex(t, j) ? 1 : 0;
            }
        }
        return shared;
    }
}
