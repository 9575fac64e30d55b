package ifold.refine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.IndexedPolygons;
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

    /** {@link #pieces(HalfedgeMesh, HamiltonianRefinement.Result, boolean[], CycleCoverPath.Leaf)} round the incentres. */
    static int pieces(HalfedgeMesh mesh, HamiltonianRefinement.Result result, boolean[] cut) {
        return pieces(mesh, result, cut, CycleCoverPath.Leaf.ROUND_INCENTRE);
    }

    /**
     * A triangle on a cycle is one piece, or four where a splice cuts it; a cut one two where it is
     * joined by one split side and {@code leaf} halves it about it, but for the first of its
     * component's path, else three and one more for each split side.
     */
    static int pieces(HalfedgeMesh mesh, HamiltonianRefinement.Result result, boolean[] cut, CycleCoverPath.Leaf leaf) {
        // The path begins at each component's lowest triangle.
        boolean[] seen = new boolean[mesh.faceCount()];
        boolean[] first = new boolean[mesh.faceCount()];
        for (int s = 0; s < mesh.faceCount(); s++) {
            if (seen[s]) {
                continue;
            }
            first[s] = true;
            java.util.ArrayDeque<Integer> queue = new java.util.ArrayDeque<>(List.of(s));
            seen[s] = true;
            while (!queue.isEmpty()) {
                int h = mesh.faceHalfedge(queue.poll());
                for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                    int g = mesh.face(HalfedgeMesh.twin(h));
                    if (g >= 0 && !seen[g]) {
                        seen[g] = true;
                        queue.add(g);
                    }
                }
            }
        }
        int pieces = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int splits = 0;
            int h = mesh.faceHalfedge(f);
            for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                splits += result.treeEdge()[HalfedgeMesh.edge(h)] ? 1 : 0;
            }
            pieces += cut[f] ? (leaf == CycleCoverPath.Leaf.HALVED && splits == 1 && !first[f] ? 2 : 3 + splits) : splits == 0 ? 1 : 4;
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
    void earsAreCutAndHalvedAboutTheSideTheyAreJoinedBy() {
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
        // 48 of its 72 are cut, and the path is 280 pieces round their incentres, 256 with the
        // leaves halved, against the refinement's 358.
        assertTrue(cut >= 2 && cut < mesh.faceCount(), cut + " of " + mesh.faceCount() + " cut");
        HamiltonianRefinement.Result result = CycleCoverPath.of(mesh);
        assertEquals(List.of(), violations(mesh, result));
        assertEquals(pieces(mesh, result, cover.cut()), result.mesh().faceCount());
        assertTrue(result.mesh().faceCount() < 5 * mesh.faceCount() - 2, "as long as the refinement");
        HamiltonianRefinement.Result halved = CycleCoverPath.of(mesh, new CycleCoverPath.Way(false, CycleCoverPath.Leaf.HALVED));
        assertEquals(List.of(), violations(mesh, halved));
        assertEquals(pieces(mesh, halved, cover.cut(), CycleCoverPath.Leaf.HALVED), halved.mesh().faceCount());
        assertTrue(halved.mesh().faceCount() < result.mesh().faceCount(), "fewer pieces halved");
        // A leaf's halves are each at least half as wide as the triangle; its pieces round the
        // incentre here (right isosceles triangles of legs 1, inradius 0.2929) are narrower.
        int[] codes = halved.mesh().pathCodes();
        int halves = 0;
        for (int t = 0; t < codes.length; t++) {
            if ((codes[t] & 7) == RefinedMesh.FACE_FIRST_HALF || (codes[t] & 7) == RefinedMesh.FACE_SECOND_HALF) {
                halves++;
                double triangle = narrowest(mesh, halved.mesh().parentFace(t));
                assertTrue(narrowest(halved.mesh(), t) >= triangle / 2 - 1e-12, "piece " + t + ": " + narrowest(halved.mesh(), t) + " of " + triangle);
                assertTrue(narrowest(halved.mesh(), t) > 0.2929, "piece " + t + ": " + narrowest(halved.mesh(), t));
            }
        }
        assertEquals(result.mesh().faceCount() - halved.mesh().faceCount(), halves, "two halves for each leaf's four pieces round its incentre");
        assertTrue(narrowest(halved) >= narrowest(result), narrowest(halved) + " halved, " + narrowest(result) + " round the incentres");
    }

    /** The smallest altitude of any triangle on {@code result}'s path. */
    static double narrowest(HamiltonianRefinement.Result result) {
        double least = Double.POSITIVE_INFINITY;
        for (int t = 0; t < result.mesh().faceCount(); t++) {
            least = Math.min(least, narrowest(result.mesh(), t));
        }
        return least;
    }

    /** The smallest altitude of triangle {@code t} of {@code polygons}. */
    static double narrowest(IndexedPolygons polygons, int t) {
        double[][] p = new double[3][];
        for (int k = 0; k < 3; k++) {
            int v = polygons.faceVertex(t, k);
            p[k] = new double[] {polygons.coordinate(v, 0), polygons.coordinate(v, 1), polygons.coordinate(v, 2)};
        }
        double twiceArea = norm(cross(sub(p[1], p[0]), sub(p[2], p[0])));
        double least = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            least = Math.min(least, twiceArea / norm(sub(p[(k + 1) % 3], p[k])));
        }
        return least;
    }

    private static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double norm(double[] a) {
        return Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    }

    /**
     * A triangular bipyramid whose north pole lies just off the middle of the equator's side AB:
     * the face A, B, N a sliver, its first side B, N. The plain greedy matching takes its first
     * side; begun with the slivers, it is matched across AB, its longest, and so passed by its two
     * short sides, never left across the one it is narrowest over.
     */
    @Test
    void aSliverIsMatchedAcrossItsLongestSideWhereTheSliversComeFirst() {
        PolygonSoup soup = new PolygonSoup();
        int a = soup.addVertex(1, 0, 0);
        int b = soup.addVertex(-0.5, Math.sqrt(0.75), 0);
        int c = soup.addVertex(-0.5, -Math.sqrt(0.75), 0);
        // Just outside AB's midpoint, just above the equator.
        int n = soup.addVertex(0.25 + 0.02 * Math.sqrt(0.75), Math.sqrt(0.75) / 2 + 0.02 * 0.5, 0.01);
        int s = soup.addVertex(0, 0, -1);
        soup.addTriangle(b, n, a);
        soup.addTriangle(c, n, b);
        soup.addTriangle(a, n, c);
        soup.addTriangle(a, s, b);
        soup.addTriangle(b, s, c);
        soup.addTriangle(c, s, a);
        HalfedgeMesh mesh = HamiltonianRefinementTest.triangles(soup);
        int sliver = 0;
        assertTrue(java.util.Arrays.equals(new int[] {sliver}, CycleCoverPath.slivers(mesh)), java.util.Arrays.toString(CycleCoverPath.slivers(mesh)));
        int longest = CycleCoverPath.longestSide(mesh, sliver);
        assertTrue(CycleCoverPath.cover(mesh, false).offCycle()[sliver] != longest, "the plain matching takes its first side");
        assertEquals(longest, CycleCoverPath.cover(mesh, true).offCycle()[sliver]);
        for (HamiltonianRefinement.Result path : CycleCoverPath.ways(mesh)) {
            assertEquals(List.of(), violations(mesh, path));
        }
        assertEquals(2, CycleCoverPath.ways(mesh).size(), "closed: no leaves to halve; a sliver: matched first or not");
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
            everyWayKeepsEveryClaim(mesh, "trial " + trial);
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
        everyWayKeepsEveryClaim(mesh, name);
        if (Topology.of(mesh).boundaryLoops() == 0) {
            assertTrue(result.mesh().faceCount() < 1.2 * mesh.faceCount(), "a closed surface's cycles: few splices");
        }
    }

    /** Every {@link CycleCoverPath.Way} makes a path that keeps every claim, its pieces as many as its cover and leaves ask. */
    static void everyWayKeepsEveryClaim(HalfedgeMesh mesh, String what) {
        for (boolean sliversFirst : new boolean[] {false, true}) {
            boolean[] cut = CycleCoverPath.cover(mesh, sliversFirst).cut();
            for (CycleCoverPath.Leaf leaf : CycleCoverPath.Leaf.values()) {
                HamiltonianRefinement.Result path = CycleCoverPath.of(mesh, new CycleCoverPath.Way(sliversFirst, leaf));
                String way = what + ", slivers first " + sliversFirst + ", " + leaf;
                assertEquals(List.of(), violations(mesh, path), way);
                assertEquals(Topology.of(mesh).components(), path.componentCount(), way);
                assertEquals(pieces(mesh, path, cut, leaf), path.mesh().faceCount(), way);
            }
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
