package ifold.refine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.InvalidMeshException;
import ifold.mesh.MeshBuilder;
import ifold.mesh.MeshValidator;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.Topology;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.Test;

class HamiltonianRefinementTest {

    static HalfedgeMesh triangles(PolygonSoup soup) {
        try {
            return MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        } catch (InvalidMeshException e) {
            throw new AssertionError(e);
        }
    }

    static HalfedgeMesh polygons(PolygonSoup soup) {
        try {
            return MeshBuilder.build(soup).mesh();
        } catch (InvalidMeshException e) {
            throw new AssertionError(e);
        }
    }

    static Stream<Arguments> solids() {
        return Stream.of(
                Arguments.of("tetrahedron", Solids.tetrahedron(), 18),
                Arguments.of("cube", Solids.cube(), 58),
                Arguments.of("octahedron", Solids.octahedron(), 38),
                Arguments.of("icosahedron", Solids.icosahedron(), 98),
                Arguments.of("torus", Solids.torus(3, 1, 16, 9), 5 * 288 - 2),
                Arguments.of("triangle", Solids.triangle(), 3),
                Arguments.of("figure3", Solids.figure3(), 58));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("solids")
    void claimsHold(String name, PolygonSoup soup, int expectedTriangles) {
        HalfedgeMesh mesh = triangles(soup);
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        assertEquals(expectedTriangles, result.mesh().faceCount());
        assertEquals(List.of(), RefinementClaims.violations(mesh, result));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("solids")
    void refinedSurfaceIsTheSameSurface(String name, PolygonSoup soup, int expectedTriangles) throws InvalidMeshException {
        HalfedgeMesh mesh = triangles(soup);
        RefinedMesh refined = HamiltonianRefinement.refine(mesh).mesh();
        MeshBuilder.Result rebuilt = MeshBuilder.build(refined, new MeshBuilder.Options(true, false));
        assertEquals(List.of(), MeshValidator.validate(rebuilt.mesh()));
        Topology before = Topology.of(mesh);
        Topology after = Topology.of(rebuilt.mesh());
        assertEquals(before.genus(), after.genus());
        assertEquals(before.boundaryLoops(), after.boundaryLoops());
        assertEquals(before.components(), after.components());
        assertEquals(before.eulerCharacteristic(), after.eulerCharacteristic());
    }

    @Test
    void spanningTreeHasOneEdgeFewerThanFaces() {
        HalfedgeMesh mesh = triangles(Solids.icosahedron());
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        int treeEdges = 0;
        for (boolean b : result.treeEdge()) {
            treeEdges += b ? 1 : 0;
        }
        assertEquals(19, treeEdges);
        // The model's 12 corners, an incenter a face, a midpoint a tree edge: counted by kind,
        // not by the numbers the refinement happens to give them.
        int incenters = 0;
        int midpoints = 0;
        for (int v = 0; v < result.mesh().vertexCount(); v++) {
            assertFalse(result.mesh().isIncenter(v) && result.mesh().isMidpoint(v), "vertex " + v + " is of one kind");
            incenters += result.mesh().isIncenter(v) ? 1 : 0;
            midpoints += result.mesh().isMidpoint(v) ? 1 : 0;
        }
        assertEquals(20, incenters);
        assertEquals(19, midpoints);
        assertEquals(12 + 20 + 19, result.mesh().vertexCount());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("solids")
    void everyPathIsACycleAndMayBeginAnywhereOnIt(String name, PolygonSoup soup, int expectedTriangles) {
        HalfedgeMesh mesh = triangles(soup);
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        int n = result.mesh().faceCount();
        assertTrue(result.cyclic(0), name + ": the walk round the tree ends beside where it began");
        for (double along : new double[] {0.25, 0.5, 0.75}) {
            HamiltonianRefinement.Result begun = result.begunAt(along);
            assertEquals(List.of(), RefinementClaims.violations(mesh, begun), name + " begun at " + along);
            int shift = (int) (Math.round(along * n) % n);
            for (int t = 0; t < n; t++) {
                for (int k = 0; k < 3; k++) {
                    assertEquals(result.mesh().faceVertex((t + shift) % n, k), begun.mesh().faceVertex(t, k));
                }
                assertEquals(result.mesh().parentFace((t + shift) % n), begun.mesh().parentFace(t));
            }
        }
    }

    /** Two components: a tetrahedron, and an octahedron 5 along x from it. */
    private static PolygonSoup tetrahedronBesideOctahedron() {
        PolygonSoup two = Solids.tetrahedron();
        PolygonSoup other = Solids.octahedron();
        int offset = two.vertexCount();
        for (int v = 0; v < other.vertexCount(); v++) {
            two.addVertex(other.coordinate(v, 0) + 5, other.coordinate(v, 1), other.coordinate(v, 2));
        }
        for (int f = 0; f < other.faceCount(); f++) {
            two.addTriangle(offset + other.faceVertex(f, 0), offset + other.faceVertex(f, 1), offset + other.faceVertex(f, 2));
        }
        return two;
    }

    @Test
    void eachComponentBeginsAnewOnItsOwnCycle() {
        HalfedgeMesh mesh = triangles(tetrahedronBesideOctahedron());
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        HamiltonianRefinement.Result begun = result.begunAt(0.5);
        assertEquals(List.of(), RefinementClaims.violations(mesh, begun));
        // The tetrahedron's 18 begin at its 9th, the octahedron's 38 at its 19th: neither runs into the other.
        assertEquals(result.mesh().parentFace(9), begun.mesh().parentFace(0));
        assertEquals(result.mesh().parentFace(18 + 19), begun.mesh().parentFace(18));
        assertEquals(result.mesh().parentFace(17), begun.mesh().parentFace(8));
        assertThrows(IllegalArgumentException.class, () -> result.begunAt(1));
        assertThrows(IllegalArgumentException.class, () -> result.begunAt(-0.25));
        assertThrows(IllegalArgumentException.class, () -> result.begunAt(Double.NaN));
    }

    /** Each component run the other way keeps every claim, its triangles the same in the opposite order, and twice is as it was. */
    @Test
    void eachComponentMayBeRunTheOtherWay() {
        HalfedgeMesh mesh = triangles(tetrahedronBesideOctahedron());
        for (HamiltonianRefinement.Result result : List.of(HamiltonianRefinement.refine(mesh), CycleCoverPath.of(mesh))) {
            HamiltonianRefinement.Result back = result.reversed();
            assertEquals(List.of(), result.mesh().ownTriangles() ? CycleCoverPathTest.violations(mesh, back) : RefinementClaims.violations(mesh, back));
            for (int c = 0; c < result.componentCount(); c++) {
                int from = result.componentStart()[c];
                int to = result.componentStart()[c + 1];
                assertTrue(back.cyclic(c), "component " + c);
                for (int t = from; t < to; t++) {
                    for (int k = 0; k < 3; k++) {
                        assertEquals(result.mesh().faceVertex(from + to - 1 - t, k), back.mesh().faceVertex(t, k));
                        assertEquals(result.mesh().faceVertex(t, k), back.reversed().mesh().faceVertex(t, k));
                    }
                }
            }
        }
    }

    @Test
    void eachComponentGetsItsOwnPath() {
        HalfedgeMesh mesh = triangles(tetrahedronBesideOctahedron());
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        assertEquals(2, result.componentCount());
        assertEquals(5 * 12 - 4, result.mesh().faceCount());
        assertEquals(18, result.componentStart()[1]);
        assertEquals(List.of(), RefinementClaims.violations(mesh, result));
    }

    @Test
    void subTrianglesInheritTheirParentsColour() {
        PolygonSoup soup = Solids.tetrahedron();
        soup.setFaceColor(2, 0xFFFF0000);
        HalfedgeMesh mesh = triangles(soup);
        RefinedMesh refined = HamiltonianRefinement.refine(mesh).mesh();
        // Each sub-triangle has its parent's colour, and the red face's sub-triangles cover it:
        // their areas add up to its own.
        double redArea = 0;
        for (int t = 0; t < refined.faceCount(); t++) {
            assertEquals(mesh.faceColor(refined.parentFace(t)), refined.faceColor(t));
            if (refined.faceColor(t) == 0xFFFF0000) {
                assertEquals(2, refined.parentFace(t));
                redArea += area(refined, t);
            }
        }
        assertEquals(area(mesh, 2), redArea, 1e-12 * area(mesh, 2));
    }

    @Test
    void longStripDoesNotOverflowTheStack() {
        // A strip of 400k triangles: a depth-first tree 400k deep.
        PolygonSoup soup = new PolygonSoup();
        int quads = 200_000;
        for (int i = 0; i <= quads; i++) {
            soup.addVertex(i, 0, 0);
            soup.addVertex(i, 1, 0);
        }
        for (int i = 0; i < quads; i++) {
            soup.addTriangle(2 * i, 2 * i + 2, 2 * i + 3);
            soup.addTriangle(2 * i, 2 * i + 3, 2 * i + 1);
        }
        HalfedgeMesh mesh = triangles(soup);
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        assertEquals(5 * 2 * quads - 2, result.mesh().faceCount());
        assertEquals(List.of(), RefinementClaims.violations(mesh, result));
    }

    @Test
    void polygonsAreRefused() {
        HalfedgeMesh cube = polygons(Solids.cube());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> HamiltonianRefinement.refine(cube));
        assertTrue(e.getMessage().contains("triangulate"), e.getMessage());
    }

    @Test
    void claimsCatchABrokenPath() {
        HalfedgeMesh mesh = triangles(Solids.octahedron());
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        assertEquals(List.of(), RefinementClaims.violations(mesh, result), "setup: the path is whole");
        int[] path = result.mesh().pathCodes();
        // Swap two triangles far apart in the path: the path breaks there.
        int swap = path[1];
        path[1] = path[20];
        path[20] = swap;
        assertFalse(RefinementClaims.violations(mesh, result).isEmpty());
    }

    private static double area(ifold.mesh.IndexedPolygons mesh, int t) {
        double[] p = new double[9];
        for (int k = 0; k < 3; k++) {
            for (int axis = 0; axis < 3; axis++) {
                p[3 * k + axis] = mesh.coordinate(mesh.faceVertex(t, k), axis);
            }
        }
        return ifold.geom.Triangles.twiceArea(p, 0, 1, 2) / 2;
    }
}
