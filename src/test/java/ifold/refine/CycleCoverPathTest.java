package ifold.refine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.io.MeshReaders;
import ifold.testing.OpenSurfaces;
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
    void aLoneTriangleIsGoneRoundFromItsIncentreAsTheRefinementGoesRoundIt() {
        HalfedgeMesh mesh = HamiltonianRefinementTest.triangles(Solids.triangle());
        HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
        assertEquals(3, result.mesh().faceCount());
        assertEquals(List.of(), violations(mesh, result));
        assertEquals(HamiltonianRefinement.refine(mesh).mesh().faceCount(), result.mesh().faceCount());
    }

    /** A triangle on a cycle is one piece, or four where a splice cuts it; a cut one three and one more for each split side. */
    static int pieces(HalfedgeMesh mesh, HamiltonianRefinement.Result result, boolean[] cut) {
        int pieces = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int splits = 0;
            int h = mesh.faceHalfedge(f);
            for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                splits += result.treeEdge()[HalfedgeMesh.edge(h)] ? 1 : 0;
            }
            pieces += cut[f] ? 3 + splits : splits == 0 ? 1 : 4;
        }
        return pieces;
    }

    @Test
    void anOpenTubeIsCoveredByCyclesAsAClosedSurfaceIs() {
        // Its end rings' triangles have a side on the boundary and keep both others for their cycle.
        HalfedgeMesh mesh = HamiltonianRefinementTest.triangles(OpenSurfaces.tube(12, 5));
        HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
        assertNotNull(result);
        assertEquals(List.of(), violations(mesh, result));
        CycleCoverPath.Cover cover = CycleCoverPath.cover(mesh);
        for (boolean cut : cover.cut()) {
            assertFalse(cut, "a triangle cut");
        }
        int splices = 0;
        for (boolean split : result.treeEdge()) {
            splices += split ? 1 : 0;
        }
        assertEquals(mesh.faceCount() + 6 * splices, result.mesh().faceCount());
    }

    @Test
    void earsAreCutAndGoneRoundFromTheirIncentres() {
        // A flat grid: an ear at two of its corners, which no cycle passes.
        HalfedgeMesh mesh = HamiltonianRefinementTest.triangles(OpenSurfaces.grid(6));
        CycleCoverPath.Cover cover = CycleCoverPath.cover(mesh);
        int cut = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            if (CycleCoverPath.neighbours(mesh, f) == 1) {
                assertTrue(cover.cut()[f], "an ear not cut");
            }
            cut += cover.cut()[f] ? 1 : 0;
        }
        // Its boundary's triangles keep both other sides for their cycles, which an ear ends:
        // 48 of its 72 are cut, and the path is 280 pieces, against the refinement's 358.
        assertTrue(cut >= 2 && cut < mesh.faceCount(), cut + " of " + mesh.faceCount() + " cut");
        HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
        assertEquals(List.of(), violations(mesh, result));
        assertEquals(pieces(mesh, result, cover.cut()), result.mesh().faceCount());
        assertTrue(result.mesh().faceCount() < 5 * mesh.faceCount() - 2, "as long as the refinement");
    }

    @Test
    void aTriangleLeftUnmatchedFacesANeighbourCutForIt() {
        // figure3: 12 triangles of one plane, a boundary all round, no perfect matching of those with three neighbours.
        HalfedgeMesh mesh = HamiltonianRefinementTest.triangles(Solids.figure3());
        CycleCoverPath.Cover cover = CycleCoverPath.cover(mesh);
        HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
        assertEquals(List.of(), violations(mesh, result));
        assertEquals(pieces(mesh, result, cover.cut()), result.mesh().faceCount());
        for (int f = 0; f < mesh.faceCount(); f++) {
            if (!cover.cut()[f]) {
                // On a cycle: two sides to triangles on cycles, the third (if any) matched or facing a cut one.
                int h = mesh.faceHalfedge(f);
                int onCycles = 0;
                for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                    int g = mesh.face(HalfedgeMesh.twin(h));
                    onCycles += g >= 0 && !cover.cut()[g] && h != cover.offCycle()[f] ? 1 : 0;
                }
                assertEquals(2, onCycles, "triangle " + f + "'s sides on its cycle");
            }
        }
    }

    /**
     * Random pieces of an icosphere (grown from a triangle, some holes punched in half of them):
     * surfaces with boundaries of every shape, ears, lone triangles and several components. Each
     * gets a path that keeps every claim, a cycle per component.
     */
    @Test
    void everyRandomPieceOfASphereGetsOne() throws Exception {
        HalfedgeMesh sphere = HamiltonianRefinementTest.triangles(Solids.icosphere(2));
        int n = sphere.faceCount();
        double[] xyz = sphere.positionArray();
        java.util.Random random = new java.util.Random(11);
        for (int trial = 0; trial < 150; trial++) {
            boolean[] in = new boolean[n];
            List<Integer> frontier = new ArrayList<>(List.of(random.nextInt(n)));
            int size = 1 + random.nextInt(n - 1);
            for (int count = 0; count < size && !frontier.isEmpty(); ) {
                int f = frontier.remove(random.nextInt(frontier.size()));
                if (!in[f]) {
                    in[f] = true;
                    count++;
                    int h = sphere.faceHalfedge(f);
                    for (int k = 0; k < 3; k++, h = sphere.next(h)) {
                        frontier.add(sphere.face(HalfedgeMesh.twin(h)));
                    }
                }
            }
            PolygonSoup soup = new PolygonSoup();
            int[] id = new int[sphere.vertexCount()];
            java.util.Arrays.fill(id, -1);
            boolean holes = random.nextBoolean();
            for (int f = 0; f < n; f++) {
                if (!in[f] || holes && random.nextInt(12) == 0) {
                    continue;
                }
                int[] corner = new int[3];
                int h = sphere.faceHalfedge(f);
                for (int k = 0; k < 3; k++, h = sphere.next(h)) {
                    int v = sphere.fromVertex(h);
                    if (id[v] < 0) {
                        id[v] = soup.addVertex(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
                    }
                    corner[k] = id[v];
                }
                soup.addTriangle(corner[0], corner[1], corner[2]);
            }
            if (soup.faceCount() == 0) {
                continue;
            }
            // Repairs may split a vertex the piece touches itself at: the mesh built is what is covered.
            HalfedgeMesh mesh = MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
            HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
            assertNotNull(result, "trial " + trial);
            assertEquals(List.of(), violations(mesh, result), "trial " + trial);
            assertEquals(Topology.of(mesh).components(), result.componentCount(), "trial " + trial);
            assertEquals(pieces(mesh, result, CycleCoverPath.cover(mesh).cut()), result.mesh().faceCount(), "trial " + trial);
        }
    }

    static Stream<String> valid() {
        return SharedMeshes.names("valid");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("valid")
    void everySharedModelGetsOne(String name) throws Exception {
        assumeTrue(SharedMeshes.present(), "../shared/meshes is absent");
        PolygonSoup soup = MeshReaders.read(SharedMeshes.ROOT.resolve("valid").resolve(name));
        HalfedgeMesh mesh = MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
        assertNotNull(result, "a path");
        assertEquals(List.of(), violations(mesh, result));
        assertEquals(Topology.of(mesh).components(), result.componentCount());
        assertEquals(pieces(mesh, result, CycleCoverPath.cover(mesh).cut()), result.mesh().faceCount());
        if (Topology.of(mesh).boundaryLoops() == 0) {
            assertTrue(result.mesh().faceCount() < 1.2 * mesh.faceCount(), "a closed surface's cycles: few splices");
        }
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
