package ifold.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class MeshBuilderTest {

    private static MeshBuilder.Result build(PolygonSoup soup) throws InvalidMeshException {
        MeshBuilder.Result result = MeshBuilder.build(soup);
        assertEquals(List.of(), MeshValidator.validate(result.mesh()));
        return result;
    }

    @Test
    void closedSolidsBuildWithoutRepairs() throws InvalidMeshException {
        for (PolygonSoup soup : List.of(Solids.tetrahedron(), Solids.cube(), Solids.octahedron(), Solids.icosahedron())) {
            MeshBuilder.Result result = build(soup);
            Topology topology = Topology.of(result.mesh());
            assertEquals(Map.of(), result.repairs());
            assertEquals(soup.faceCount(), topology.faces());
            assertEquals(0, topology.boundaryLoops());
            assertEquals(2, topology.eulerCharacteristic());
            assertEquals(0, topology.genus());
        }
    }

    @Test
    void squareIsOpenWithOneBoundaryLoop() throws InvalidMeshException {
        HalfedgeMesh mesh = build(Fixtures.square()).mesh();
        assertEquals(4, mesh.vertexCount());
        assertEquals(5, mesh.edgeCount());
        assertEquals(1, Topology.of(mesh).boundaryLoops());
        for (int v = 0; v < 4; v++) {
            assertTrue(mesh.isBoundaryVertex(v));
            assertTrue(mesh.isBoundary(mesh.halfedge(v)), "boundary vertex starts at its boundary halfedge");
        }
    }

    @Test
    void oneRingCentreHasValenceSix() throws InvalidMeshException {
        HalfedgeMesh mesh = build(Fixtures.oneRing()).mesh();
        assertFalse(mesh.isBoundaryVertex(0));
        assertEquals(6, mesh.valence(0));
        assertEquals(3, mesh.valence(1)); // two edges and the boundary halfedge
    }

    @Test
    void halfedgesAreCounterClockwiseSeenFromOutside() throws InvalidMeshException {
        HalfedgeMesh mesh = build(Solids.tetrahedron()).mesh();
        double[] xyz = mesh.positionArray();
        for (int f = 0; f < mesh.faceCount(); f++) {
            int h = mesh.faceHalfedge(f);
            int a = mesh.fromVertex(h);
            int b = mesh.toVertex(h);
            int c = mesh.toVertex(mesh.next(h));
            double[] n = cross(xyz, a, b, c);
            // The centroid of the tetrahedron is the origin: outward normals point away from it.
            double dot = n[0] * (xyz[3 * a] + xyz[3 * b] + xyz[3 * c])
                    + n[1] * (xyz[3 * a + 1] + xyz[3 * b + 1] + xyz[3 * c + 1])
                    + n[2] * (xyz[3 * a + 2] + xyz[3 * b + 2] + xyz[3 * c + 2]);
            assertTrue(dot > 0, "face " + f + " faces outward");
        }
    }

    private static double[] cross(double[] xyz, int a, int b, int c) {
        double ux = xyz[3 * b] - xyz[3 * a];
        double uy = xyz[3 * b + 1] - xyz[3 * a + 1];
        double uz = xyz[3 * b + 2] - xyz[3 * a + 2];
        double vx = xyz[3 * c] - xyz[3 * a];
        double vy = xyz[3 * c + 1] - xyz[3 * a + 1];
        double vz = xyz[3 * c + 2] - xyz[3 * a + 2];
        return new double[] {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
    }

    @Test
    void insideOutClosedMeshIsTurnedOutward() throws InvalidMeshException {
        PolygonSoup soup = Solids.tetrahedron();
        PolygonSoup inverted = new PolygonSoup();
        for (int v = 0; v < soup.vertexCount(); v++) {
            inverted.addVertex(soup.coordinate(v, 0), soup.coordinate(v, 1), soup.coordinate(v, 2));
        }
        for (int f = 0; f < soup.faceCount(); f++) {
            inverted.addTriangle(soup.faceVertex(f, 2), soup.faceVertex(f, 1), soup.faceVertex(f, 0));
        }
        MeshBuilder.Result result = build(inverted);
        assertEquals(Map.of(Defect.INWARD_COMPONENT, 1), result.repairs());
        HalfedgeMesh mesh = result.mesh();
        int h = mesh.faceHalfedge(0);
        assertEquals(soup.faceVertex(0, 0), mesh.fromVertex(h), "face restored to the outward order");
    }

    @Test
    void eachClosedComponentIsTurnedOutwardOnItsOwn() throws InvalidMeshException {
        // Four tetrahedra side by side, the second and fourth inside out, and an open triangle
        // between them: the volumes are summed per component in one pass over all faces.
        PolygonSoup tetrahedron = Solids.tetrahedron();
        PolygonSoup soup = new PolygonSoup();
        for (int k = 0; k < 4; k++) {
            int base = soup.vertexCount();
            for (int v = 0; v < tetrahedron.vertexCount(); v++) {
                soup.addVertex(tetrahedron.coordinate(v, 0) + 5 * k, tetrahedron.coordinate(v, 1), tetrahedron.coordinate(v, 2));
            }
            for (int f = 0; f < tetrahedron.faceCount(); f++) {
                int a = base + tetrahedron.faceVertex(f, 0);
                int b = base + tetrahedron.faceVertex(f, 1);
                int c = base + tetrahedron.faceVertex(f, 2);
                if (k % 2 == 1) {
                    soup.addTriangle(c, b, a);
                } else {
                    soup.addTriangle(a, b, c);
                }
            }
            if (k == 1) {
                int t = soup.addVertex(0, 10, 0);
                soup.addVertex(1, 10, 0);
                soup.addVertex(0, 11, 0);
                soup.addTriangle(t, t + 2, t + 1); // facing down, and open: left as it is
            }
        }
        MeshBuilder.Result result = build(soup);
        assertEquals(Map.of(Defect.INWARD_COMPONENT, 2), result.repairs());
        HalfedgeMesh mesh = result.mesh();
        assertEquals(5, Topology.of(mesh).components());
        double[] volume = new double[4];
        for (int f = 0; f < mesh.faceCount(); f++) {
            int h = mesh.faceHalfedge(f);
            int a = mesh.fromVertex(h);
            int b = mesh.toVertex(h);
            int c = mesh.toVertex(mesh.next(h));
            if (mesh.y(a) > 5) {
                assertTrue((mesh.x(b) - mesh.x(a)) * (mesh.y(c) - mesh.y(a)) - (mesh.y(b) - mesh.y(a)) * (mesh.x(c) - mesh.x(a)) < 0,
                        "the open triangle keeps its side");
                continue;
            }
            int k = (int) Math.round(mesh.x(a) / 5);
            volume[k] += mesh.x(a) * (mesh.y(b) * mesh.z(c) - mesh.z(b) * mesh.y(c))
                    + mesh.y(a) * (mesh.z(b) * mesh.x(c) - mesh.x(b) * mesh.z(c))
                    + mesh.z(a) * (mesh.x(b) * mesh.y(c) - mesh.y(b) * mesh.x(c));
        }
        for (int k = 0; k < 4; k++) {
            assertTrue(volume[k] > 0, "tetrahedron " + k + " faces outward: " + volume[k]);
        }
    }

    @Test
    void aFlatClosedSheetHasNoInsideToTurnOut() throws InvalidMeshException {
        // Four coplanar points, closed up as a tetrahedron: its volume is zero up to rounding,
        // and whichever order the faces come in, nothing is turned over.
        double[] xyz = {1.290374832472678, 1.940921685319108, 0.3411372815378284, 1.408423222078428, 1.1958132451665138,
            1.070387244795604, -0.8177662809970427, -0.7005408575908934, -0.1721546565569769, -0.9929686923922412,
            0.12163697899470616, -1.0319505961493693};
        int[][] faces = {{0, 1, 2}, {0, 2, 3}, {1, 3, 2}, {1, 0, 3}};
        for (int shift = 0; shift < 4; shift++) {
            int[][] order = new int[4][];
            for (int f = 0; f < 4; f++) {
                order[f] = faces[(f + shift) % 4];
            }
            assertEquals(Map.of(), build(Fixtures.soup(xyz, order)).repairs(), "faces from " + shift);
        }
    }

    @Test
    void anInsideOutSolidFarFromTheOriginIsStillTurnedOut() throws InvalidMeshException {
        // Volumes are measured from a vertex of the solid: a million units away, rounding of
        // the products about the origin would swamp the tetrahedron's.
        PolygonSoup tetrahedron = Solids.tetrahedron();
        PolygonSoup far = new PolygonSoup();
        for (int v = 0; v < 4; v++) {
            far.addVertex(tetrahedron.coordinate(v, 0) + 1e6, tetrahedron.coordinate(v, 1) - 3e6, tetrahedron.coordinate(v, 2) + 2e6);
        }
        for (int f = 0; f < 4; f++) {
            far.addTriangle(tetrahedron.faceVertex(f, 2), tetrahedron.faceVertex(f, 1), tetrahedron.faceVertex(f, 0));
        }
        assertEquals(Map.of(Defect.INWARD_COMPONENT, 1), build(far).repairs());
    }

    @Test
    void twoClosedSolidsTouchingAtAVertexGetAVertexEach() throws InvalidMeshException {
        // Two tetrahedra sharing vertex 0: both fans around it are closed, and the second gets
        // a copy of the vertex.
        PolygonSoup tetrahedron = Solids.tetrahedron();
        PolygonSoup soup = new PolygonSoup();
        for (int v = 0; v < 4; v++) {
            soup.addVertex(tetrahedron.coordinate(v, 0), tetrahedron.coordinate(v, 1), tetrahedron.coordinate(v, 2));
        }
        for (int v = 1; v < 4; v++) { // the point reflection of the first through vertex 0
            soup.addVertex(2 - tetrahedron.coordinate(v, 0), 2 - tetrahedron.coordinate(v, 1), 2 - tetrahedron.coordinate(v, 2));
        }
        int[] second = {0, 4, 5, 6};
        for (int f = 0; f < 4; f++) {
            soup.addTriangle(tetrahedron.faceVertex(f, 0), tetrahedron.faceVertex(f, 1), tetrahedron.faceVertex(f, 2));
        }
        for (int f = 0; f < 4; f++) {
            soup.addTriangle(second[tetrahedron.faceVertex(f, 0)], second[tetrahedron.faceVertex(f, 1)],
                    second[tetrahedron.faceVertex(f, 2)]);
        }
        MeshBuilder.Result result = build(soup);
        assertEquals(1, result.repairs().get(Defect.NON_MANIFOLD_VERTEX));
        HalfedgeMesh mesh = result.mesh();
        assertEquals(8, mesh.vertexCount());
        assertEquals(0, result.sourceVertex()[7], "the copy comes from the shared vertex");
        assertEquals(2, Topology.of(mesh).components());
        assertEquals(0, Topology.of(mesh).boundaryLoops());
        for (int v : new int[] {0, 7}) {
            int degree = 0;
            int h = mesh.halfedge(v);
            do {
                assertEquals(v, mesh.fromVertex(h));
                degree++;
                h = HalfedgeMesh.twin(mesh.prev(h));
            } while (h != mesh.halfedge(v));
            assertEquals(3, degree, "vertex " + v + " has a closed fan of three faces");
        }
    }

    @Test
    void polygonsStayPolygonsUnlessTriangulated() throws InvalidMeshException {
        HalfedgeMesh cube = build(Solids.cube()).mesh();
        assertEquals(6, cube.faceCount());
        assertEquals(4, cube.faceSize(0));
        HalfedgeMesh triangulated = MeshBuilder.build(Solids.cube(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        assertEquals(List.of(), MeshValidator.validate(triangulated));
        assertEquals(12, triangulated.faceCount());
        assertEquals(18, triangulated.edgeCount());
    }

    @Test
    void trianglesThenPolygonsKeepTheirSizes() throws InvalidMeshException {
        // A triangle, a quad and a triangle side by side: the builder switches from its
        // all-triangles layout to the general one in the middle of the faces.
        PolygonSoup soup = Fixtures.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 3, 0, 0},
                new int[] {0, 1, 5}, new int[] {1, 3, 4, 5}, new int[] {3, 6, 4});
        HalfedgeMesh mesh = build(soup).mesh();
        assertEquals(3, mesh.faceSize(0));
        assertEquals(4, mesh.faceSize(1));
        assertEquals(3, mesh.faceSize(2));
        assertEquals(1, Topology.of(mesh).components());
    }

    @Test
    void nonConvexPolygonTriangulatesInsideItsOutline() throws InvalidMeshException {
        HalfedgeMesh mesh = MeshBuilder.build(Fixtures.lShape(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        assertEquals(List.of(), MeshValidator.validate(mesh));
        assertEquals(4, mesh.faceCount());
        double area = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int h = mesh.faceHalfedge(f);
            double signed = signedArea2d(mesh, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h)));
            assertTrue(signed > 0, "triangle " + f + " keeps the polygon's orientation");
            area += signed;
        }
        assertEquals(3.0, area, 1e-12, "the L covers three unit squares");
    }

    private static double signedArea2d(HalfedgeMesh mesh, int a, int b, int c) {
        return 0.5 * ((mesh.x(b) - mesh.x(a)) * (mesh.y(c) - mesh.y(a)) - (mesh.y(b) - mesh.y(a)) * (mesh.x(c) - mesh.x(a)));
    }

    @Test
    void pinchVertexIsSplit() throws InvalidMeshException {
        MeshBuilder.Result result = build(Fixtures.bowtie());
        assertEquals(Map.of(Defect.NON_MANIFOLD_VERTEX, 1), result.repairs());
        assertEquals(6, result.mesh().vertexCount());
        assertEquals(0, result.sourceVertex()[5], "the copy comes from the pinched vertex");
        assertEquals(2, Topology.of(result.mesh()).components());
    }

    @Test
    void nonManifoldEdgeIsSplit() throws InvalidMeshException {
        MeshBuilder.Result result = build(Fixtures.book());
        assertEquals(1, result.repairs().get(Defect.NON_MANIFOLD_EDGE));
        assertEquals(3, result.mesh().faceCount());
        assertEquals(2, Topology.of(result.mesh()).components(), "the third page comes loose");
    }

    @Test
    void inconsistentFaceIsTurnedOver() throws InvalidMeshException {
        // Three triangles of a fan; the middle one lists its corners the other way round.
        PolygonSoup soup = Fixtures.soup(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0, 0},
                new int[] {0, 1, 2}, new int[] {0, 3, 2}, new int[] {0, 3, 4});
        MeshBuilder.Result result = build(soup);
        assertEquals(Map.of(Defect.INCONSISTENT_ORIENTATION, 1), result.repairs());
        HalfedgeMesh mesh = result.mesh();
        assertEquals(1, Topology.of(mesh).components(), "turned over, the fan is one sheet again");
        assertEquals(2, mesh.fromVertex(mesh.faceHalfedge(1)), "the middle face now runs 2, 3, 0");
    }

    @Test
    void moebiusBandIsCutOpen() throws InvalidMeshException {
        MeshBuilder.Result result = build(Fixtures.moebius());
        assertEquals(1, result.repairs().get(Defect.NON_ORIENTABLE));
        assertEquals(5, result.mesh().faceCount());
    }

    @Test
    void degenerateDuplicateAndUnreferencedAreDropped() throws InvalidMeshException {
        PolygonSoup soup = Fixtures.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0, 9, 9, 9},
                new int[] {0, 1, 2},
                new int[] {2, 1, 0},       // duplicate, reversed
                new int[] {0, 1, 3},       // collinear: zero area
                new int[] {0, 0, 1, 2},    // repeated corner, then a duplicate of the first
                new int[] {1, 2, 1});      // fewer than three distinct vertices
        MeshBuilder.Result result = build(soup);
        assertEquals(1, result.mesh().faceCount());
        assertEquals(3, result.mesh().vertexCount());
        assertEquals(Map.of(Defect.DUPLICATE_FACE, 2, Defect.ZERO_AREA_FACE, 1, Defect.REPEATED_VERTEX, 2,
                Defect.DEGENERATE_FACE, 1, Defect.UNREFERENCED_VERTEX, 2), result.repairs());
    }

    @Test
    void duplicatesInABigMeshAreFoundOnTheSecondThreadToo() throws InvalidMeshException {
        PolygonSoup soup = Solids.torus(3, 1, 160, 160); // 51,200 faces: past the threshold for a second thread
        soup.addTriangle(soup.faceVertex(100, 2), soup.faceVertex(100, 1), soup.faceVertex(100, 0));
        MeshBuilder.Result result = build(soup);
        assertEquals(Map.of(Defect.DUPLICATE_FACE, 1), result.repairs());
        assertEquals(51_200, result.mesh().faceCount());
        assertEquals(1, Topology.of(result.mesh()).genus());
        PolygonSoup strictSoup = Solids.torus(3, 1, 160, 160);
        strictSoup.addTriangle(strictSoup.faceVertex(7, 0), strictSoup.faceVertex(7, 1), strictSoup.faceVertex(7, 2));
        assertEquals(Defect.DUPLICATE_FACE, assertThrows(InvalidMeshException.class,
                () -> MeshBuilder.build(strictSoup, new MeshBuilder.Options(true, false))).defect());
    }

    @Test
    void strictModeRefusesNamingTheDefectAndLine() {
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(0, 0, 0);
        soup.addVertex(1, 0, 0);
        soup.addVertex(0, 1, 0);
        soup.addVertex(-1, 0, 0);
        soup.addVertex(0, -1, 0);
        soup.addFace(new int[] {0, 1, 2}, 3, 7);
        soup.addFace(new int[] {0, 3, 4}, 3, 8);
        soup.addFace(new int[] {2, 1, 0}, 3, 9);
        InvalidMeshException e = assertThrows(InvalidMeshException.class,
                () -> MeshBuilder.build(soup, new MeshBuilder.Options(true, false)));
        assertEquals(Defect.DUPLICATE_FACE, e.defect());
        assertEquals(9, e.sourceLine());
        assertTrue(e.getMessage().contains("face 2"), e.getMessage());
    }

    @Test
    void strictModeRefusesPinchAndNonManifoldEdge() {
        MeshBuilder.Options strict = new MeshBuilder.Options(true, false);
        assertEquals(Defect.NON_MANIFOLD_VERTEX,
                assertThrows(InvalidMeshException.class, () -> MeshBuilder.build(Fixtures.bowtie(), strict)).defect());
        assertEquals(Defect.NON_MANIFOLD_EDGE,
                assertThrows(InvalidMeshException.class, () -> MeshBuilder.build(Fixtures.book(), strict)).defect());
        assertEquals(Defect.NON_ORIENTABLE,
                assertThrows(InvalidMeshException.class, () -> MeshBuilder.build(Fixtures.moebius(), strict)).defect());
    }

    @Test
    void indexOutOfRangeIsNeverRepaired() {
        PolygonSoup soup = Fixtures.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, new int[] {0, 1, 3});
        InvalidMeshException e = assertThrows(InvalidMeshException.class, () -> MeshBuilder.build(soup));
        assertEquals(Defect.INDEX_OUT_OF_RANGE, e.defect());
        assertTrue(e.getMessage().contains("vertex 3"), e.getMessage());
    }

    @Test
    void nonFiniteCoordinateIsRefused() {
        PolygonSoup soup = Fixtures.soup(new double[] {0, 0, 0, 1, Double.NaN, 0, 0, 1, 0}, new int[] {0, 1, 2});
        assertEquals(Defect.NON_FINITE_COORDINATE,
                assertThrows(InvalidMeshException.class, () -> MeshBuilder.build(soup)).defect());
    }

    @Test
    void coloursFollowTheirFaces() throws InvalidMeshException {
        PolygonSoup soup = Fixtures.square();
        soup.setFaceColor(1, 0xFF112233);
        HalfedgeMesh mesh = build(soup).mesh();
        assertTrue(mesh.hasFaceColors());
        assertEquals(PolygonSoup.DEFAULT_COLOR, mesh.faceColor(0));
        assertEquals(0xFF112233, mesh.faceColor(1));
    }

    @Test
    void facesAddedAfterTheFirstColourStayGreyWhenTheSoupGrows() {
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(0, 0, 0);
        soup.addVertex(1, 0, 0);
        soup.addVertex(0, 1, 0);
        soup.addTriangle(0, 1, 2);
        soup.setFaceColor(0, 0xFF00FF00);
        for (int i = 0; i < 1000; i++) {
            soup.addTriangle(0, 1, 2);
        }
        assertEquals(0xFF00FF00, soup.faceColor(0));
        assertEquals(PolygonSoup.DEFAULT_COLOR, soup.faceColor(999));
    }

    @Test
    void torusHasGenusOne() throws InvalidMeshException {
        Topology topology = Topology.of(build(Solids.torus(3, 1, 12, 8)).mesh());
        assertEquals(1, topology.genus());
        assertEquals(192, topology.faces());
        assertEquals(0, topology.eulerCharacteristic());
    }
}
