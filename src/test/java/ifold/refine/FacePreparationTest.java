package ifold.refine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.geom.Triangles;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.io.MeshReaders;
import ifold.testing.SameSurface;
import ifold.testing.SharedMeshes;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The faces of a model triangulated again for wrapping: checked against the model itself, not
 * the preparation's own bookkeeping: the same surface (every new vertex on a face of the model,
 * the same area, the same topology, the model's creases kept), and well-shaped triangles.
 */
class FacePreparationTest {
    static HalfedgeMesh box(double a, double b, double c) throws Exception {
        return build(Solids.box(a, b, c));
    }

    private static HalfedgeMesh build(PolygonSoup soup) throws Exception {
        return MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
    }

    @Test
    void wellShapedFacesAreLeftAsTheyAre() throws Exception {
        HalfedgeMesh cube = build(Solids.cube());
        FacePreparation.Result result = FacePreparation.prepare(cube);
        assertEquals(6, result.regions());
        assertEquals(0, result.prepared());
        assertSame(cube, result.mesh());
        assertEquals(45, result.minAngleBefore(), 1e-9);
        assertNull(result.kept());
    }

    /** A prism over a regular polygon of n corners, its two n-gon faces cut into triangles from one corner. */
    static HalfedgeMesh prism(int n) throws Exception {
        PolygonSoup soup = new PolygonSoup();
        for (int z = 0; z < 2; z++) {
            for (int k = 0; k < n; k++) {
                soup.addVertex(Math.cos(2 * Math.PI * k / n), Math.sin(2 * Math.PI * k / n), 1.5 * z);
            }
        }
        int[] bottom = new int[n];
        int[] top = new int[n];
        for (int k = 0; k < n; k++) {
            bottom[k] = n - 1 - k;
            top[k] = n + k;
            soup.addFace(new int[] {k, (k + 1) % n, n + (k + 1) % n, n + k}, 4, 0);
        }
        soup.addFace(bottom, n, 0);
        soup.addFace(top, n, 0);
        return build(soup);
    }

    @Test
    void aPentagonFannedFromOneCornerIsFannedFromItsCentre() throws Exception {
        HalfedgeMesh prism = prism(5);
        FacePreparation.Result result = FacePreparation.prepare(prism);
        assertEquals(2, result.centredRegions());
        assertEquals(0, result.prepared());
        assertNull(result.kept());
        assertSame(result.centred(), result.mesh(), "nothing else prepared: the path follows the fans");
        assertEquals(prism.faceCount() + 2 * 2, result.trianglesAfter(), "each pentagon 5 triangles rather than 3");
        assertEquals(prism.faceCount(), result.trianglesBefore());
        SameSurface.assertSameSurface(prism, result.mesh());
        // Each corner of a pentagon in two of its triangles, none in three.
        HalfedgeMesh fanned = result.mesh();
        int[] around = new int[fanned.vertexCount()];
        for (int f = 0; f < fanned.faceCount(); f++) {
            int h = fanned.faceHalfedge(f);
            double z = 0;
            for (int c = 0; c < 3; c++, h = fanned.next(h)) {
                z += fanned.positionArray()[3 * fanned.fromVertex(h) + 2];
            }
            if (z == 0 || z == 4.5) {
                for (int c = 0; c < 3; c++, h = fanned.next(h)) {
                    around[fanned.fromVertex(h)]++;
                }
            }
        }
        for (int v = 0; v < fanned.vertexCount(); v++) {
            assertTrue(around[v] == 2 || around[v] == 5, "vertex " + v + " in " + around[v] + " triangles of its pentagon");
        }
    }

    @Test
    void squaresAreNotFanned() throws Exception {
        HalfedgeMesh cube = build(Solids.cube());
        FacePreparation.Result result = FacePreparation.prepare(cube);
        assertEquals(0, result.centredRegions());
        assertSame(cube, result.centred());
    }

    @Test
    void hexagonsAreFannedFromTheirCentre() throws Exception {
        HalfedgeMesh hexagonal = prism(6);
        FacePreparation.Result result = FacePreparation.prepare(hexagonal);
        assertEquals(2, result.centredRegions());
        assertEquals(hexagonal.faceCount() + 2 * 2, result.trianglesAfter(), "each hexagon 6 triangles rather than 4");
        SameSurface.assertSameSurface(hexagonal, result.mesh());
    }

    @Test
    void aLongBoxBecomesARowOfWellShapedTriangles() throws Exception {
        HalfedgeMesh box = box(100, 1, 1);
        assertTrue(RefinementClaims.minAngleDegrees(box) < 1, "setup: the long faces are cut into 0.57° triangles");
        FacePreparation.Result result = FacePreparation.prepare(box);
        assertNull(result.kept());
        assertEquals(6, result.regions());
        assertEquals(4, result.prepared(), "the four long faces; the square ends are well shaped already");
        assertTrue(result.minAngleAfter() >= FacePreparation.TARGET_ANGLE, "smallest angle " + result.minAngleAfter());
        SameSurface.assertSameSurface(box, result.mesh());
        // Well shaped and about as wide as the faces are high: a few hundred triangles, not thousands.
        assertTrue(result.trianglesAfter() > 4 * 100 && result.trianglesAfter() < 4 * 400, "triangles " + result.trianglesAfter());
    }

    @Test
    void anOpenThinRectangleKeepsItsOneBoundary() throws Exception {
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(0, 0, 0);
        soup.addVertex(50, 0, 0);
        soup.addVertex(50, 1, 0);
        soup.addVertex(0, 1, 0);
        soup.addFace(new int[] {0, 1, 2, 3}, 4, 0);
        HalfedgeMesh sheet = build(soup);
        FacePreparation.Result result = FacePreparation.prepare(sheet);
        assertEquals(1, result.prepared());
        assertTrue(result.minAngleAfter() >= FacePreparation.TARGET_ANGLE, "smallest angle " + result.minAngleAfter());
        SameSurface.assertSameSurface(sheet, result.mesh());
        assertEquals(102, boundaryLength(result.mesh()), 1e-9);
    }

    @Test
    void aFaceWithAHoleKeepsItsHole() throws Exception {
        // A 10 × 10 square with a 6 × 6 hole: the builder's triangles of the frame are long and thin.
        PolygonSoup soup = new PolygonSoup();
        double[][] corners = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {8, 2}, {8, 8}, {2, 8}};
        for (double[] c : corners) {
            soup.addVertex(c[0], c[1], 0);
        }
        int[][] quads = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
        for (int[] quad : quads) {
            soup.addFace(quad, 4, 0);
        }
        HalfedgeMesh frame = build(soup);
        assertTrue(RefinementClaims.minAngleDegrees(frame) < FacePreparation.TARGET_ANGLE, "setup: a thin triangle");
        FacePreparation.Result result = FacePreparation.prepare(frame);
        assertEquals(1, result.regions(), "one plane");
        assertEquals(1, result.prepared());
        SameSurface.assertSameSurface(frame, result.mesh());
        assertEquals(40 + 24, boundaryLength(result.mesh()), 1e-9, "both boundaries, their lengths kept");
        assertTrue(result.minAngleAfter() >= FacePreparation.TARGET_ANGLE, "smallest angle " + result.minAngleAfter());
    }

    @Test
    void aSharpCornerIsLeftForTheWrapToHandle() throws Exception {
        // A tetrahedron with a 2° spike: no triangulation widens its apex, and refining towards it
        // would make triangles too small for any strip.
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(0, 0, 0);
        soup.addVertex(1, 0, 0);
        soup.addVertex(0.5, 0.8, 0);
        soup.addVertex(0.5, 0.3, 30);
        soup.addTriangle(0, 2, 1);
        soup.addTriangle(0, 1, 3);
        soup.addTriangle(1, 2, 3);
        soup.addTriangle(2, 0, 3);
        HalfedgeMesh spike = build(soup);
        FacePreparation.Result result = FacePreparation.prepare(spike);
        assertEquals(0, result.prepared());
        assertSame(spike, result.mesh());
    }

    @Test
    void aFaceTooThinToPrepareKeepsTheModelsTriangles() throws Exception {
        HalfedgeMesh box = box(1e7, 1, 1);
        FacePreparation.Result result = FacePreparation.prepare(box);
        assertSame(box, result.mesh());
        assertNotNull(result.kept());
        assertTrue(result.kept().contains("too thin"), result.kept());
    }

    /** A prism of height {@code height} over the triangle (0, 0), (1, 0) turned {@code degrees} about the origin and scaled by {@code ratio}. */
    static HalfedgeMesh wedge(double degrees, double ratio, double height) throws Exception {
        double a = Math.toRadians(degrees);
        double[][] corners = {{0, 0}, {1, 0}, {ratio * Math.cos(a), ratio * Math.sin(a)}};
        PolygonSoup soup = new PolygonSoup();
        for (int z = 0; z < 2; z++) {
            for (double[] c : corners) {
                soup.addVertex(c[0], c[1], z * height);
            }
        }
        soup.addTriangle(0, 2, 1);
        soup.addTriangle(3, 4, 5);
        for (int k = 0; k < 3; k++) {
            soup.addFace(new int[] {k, (k + 1) % 3, 3 + (k + 1) % 3, 3 + k}, 4, 0);
        }
        return build(soup);
    }

    @Test
    void aCornerJustWiderThanTheTargetIsNotHalvedAgainAndAgain() throws Exception {
        // The ends' 20.4° corners need nothing, but the thin sides cut the ends' edges, 0.7 and 1
        // long, into pieces of other lengths; each end's refinement then split both edges at
        // that corner, and, triangulated again for those points, split them again, halving the
        // pieces there every time until Tinfour merged two ("region 0 (face 0) could not be
        // triangulated, even from its boundary alone"), as the shared capsule's 20.4° corners did.
        HalfedgeMesh wedge = wedge(20.4, 0.7, 0.2);
        assertEquals(20.4, Math.toDegrees(Triangles.minAngle(wedge.positionArray(), 0, 1, 2)), 1e-9, "setup: the ends' smallest corner");
        FacePreparation.Result result = FacePreparation.prepare(wedge);
        assertNull(result.kept());
        assertEquals(5, result.prepared(), "the sides, and the ends for the points on their edges");
        SameSurface.assertSameSurface(wedge, result.mesh());
        assertTrue(result.minAngleAfter() >= FacePreparation.TARGET_ANGLE, "smallest angle " + result.minAngleAfter());
    }

    @Test
    void twoRegionsDoNotCutEachOtherForeverAtASharedCorner() throws Exception {
        // A slanted frustum over a scalene triangle (found among random ones): refined from its
        // boundary each time a neighbour gave it a point, each side gave the next one a point
        // back at their shared corners, round after round, until Tinfour merged two ("region 4
        // (face 6) could not be triangulated"). Each region is refined three times at most.
        HalfedgeMesh frustum = frustum(new double[][] {{0.7277428584784392, 0.34413468011841397, 0},
            {0.9251277183430583, 0.5575746990939552, 0}, {0.16812460851228095, 0.7125184032915431, 0},
            {0.18149909513999582, 0.4986947051575154, 0.20285017868816976}, {0.282511124645883, 0.6079229889746325, 0.20285017868816976},
            {-0.10488647271148825, 0.6872156866561716, 0.20285017868816976}});
        FacePreparation.Result result = FacePreparation.prepare(frustum);
        assertEquals(5, result.regions(), "setup: two ends and three trapezoids");
        assertNull(result.kept());
        SameSurface.assertSameSurface(frustum, result.mesh());
        assertTrue(result.minAngleAfter() > result.minAngleBefore(), result.minAngleBefore() + " -> " + result.minAngleAfter());
    }

    /** A frustum of {@code corners}, three at its foot and three at its head, its sides cut in two from the foot's corners. */
    private static HalfedgeMesh frustum(double[][] corners) throws Exception {
        PolygonSoup soup = new PolygonSoup();
        for (double[] c : corners) {
            soup.addVertex(c[0], c[1], c[2]);
        }
        soup.addTriangle(0, 2, 1);
        soup.addTriangle(3, 4, 5);
        for (int k = 0; k < 3; k++) {
            soup.addTriangle(k, (k + 1) % 3, 3 + (k + 1) % 3);
            soup.addTriangle(k, 3 + (k + 1) % 3, 3 + k);
        }
        return build(soup);
    }

    @Test
    void aRegionThatWouldComeOutSharperIsKeptAndTheOthersArePrepared() throws Exception {
        // A slanted frustum (found among random ones) whose head, a sliver, triangulated again
        // with the points its thin sides cut its edges at, had a corner of 3.73° against the
        // model's 6.17°: the whole model kept its triangles. The head alone keeps them now.
        HalfedgeMesh frustum = frustum(new double[][] {{0.7324906626029803, 0.35828168671931826, 0},
            {0.942361279530953, 0.2516763643231372, 0}, {0.30396468915119246, 0.8939390473582698, 0},
            {0.2314775970764285, 0.1913669771622466, 0.3947179900968223}, {0.40995651580041453, 0.10070729859455892, 0.3947179900968223},
            {-0.1329509899566358, 0.6469026206591886, 0.3947179900968223}});
        FacePreparation.Result result = FacePreparation.prepare(frustum);
        assertNull(result.kept());
        assertEquals(1, result.keptRegions().size(), result.keptRegions().toString());
        assertTrue(result.keptRegions().get(0).startsWith("face 1: "), "the head: " + result.keptRegions());
        assertTrue(result.keptRegions().get(0).contains("sharper than the model's sharpest"), result.keptRegions().get(0));
        assertEquals(4, result.prepared(), "the foot and the three sides");
        SameSurface.assertSameSurface(frustum, result.mesh());
        assertTrue(result.minAngleAfter() >= result.minAngleBefore(), result.minAngleBefore() + " -> " + result.minAngleAfter());
        // The head's own triangle, its edges uncut.
        double[] head = {0.2314775970764285, 0.1913669771622466, 0.3947179900968223};
        assertTrue(hasTriangleAt(result.mesh(), head), "the head's triangle kept");
    }

    /** Whether a triangle of {@code mesh} has a corner at {@code point} and its other two at the head of the frustum (z the same), no point between. */
    private static boolean hasTriangleAt(HalfedgeMesh mesh, double[] point) {
        int inHead = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int h = mesh.faceHalfedge(f);
            boolean allHead = true;
            for (int c = 0; c < 3; c++, h = mesh.next(h)) {
                allHead &= mesh.z(mesh.fromVertex(h)) == point[2];
            }
            inHead += allHead ? 1 : 0;
        }
        return inHead == 1;
    }

    @Test
    void theSharedPolyhedraWithThinFacesArePreparedIntoTheSameSurfaces() throws Exception {
        assumeTrue(SharedMeshes.present(), "../shared/meshes is not here");
        for (String name : List.of("long_box.off", "square_frame.off", "t_prism.off", "house.off", "hex_prism.off")) {
            Path file = SharedMeshes.ROOT.resolve("polyhedra").resolve(name);
            assumeTrue(Files.exists(file), file + " is not here");
            HalfedgeMesh mesh = build(MeshReaders.read(file));
            FacePreparation.Result result = FacePreparation.prepare(mesh);
            assertNull(result.kept(), name);
            SameSurface.assertSameSurface(mesh, result.mesh());
            assertTrue(result.minAngleAfter() >= Math.min(FacePreparation.TARGET_ANGLE, result.minAngleBefore()),
                    name + ": smallest angle " + result.minAngleBefore() + " -> " + result.minAngleAfter());
        }
    }

    @Test
    void theSharedModelsWhoseRegionsCouldNotBeTriangulatedArePrepared() throws Exception {
        // Each kept its triangles whole: "region 68 (face 72) could not be triangulated, even
        // from its boundary alone" (mpi), region 8652 (face 8924) (the capsule), region 1055
        // (face 1169) (the rabbit). Now a few slivers keep theirs, the rest prepared.
        assumeTrue(SharedMeshes.present(), "../shared/meshes is not here");
        for (String name : List.of("cgal_mpi.off", "trimesh_capsule.obj", "trimesh_rabbit.obj")) {
            Path file = SharedMeshes.ROOT.resolve("valid").resolve(name);
            assumeTrue(Files.exists(file), file + " is not here");
            HalfedgeMesh mesh = build(MeshReaders.read(file));
            FacePreparation.Result result = FacePreparation.prepare(mesh);
            assertNull(result.kept(), name);
            assertTrue(result.prepared() > 0, name);
            assertTrue(result.keptRegions().size() < result.prepared(), name + ": " + result.keptRegions());
            for (String kept : result.keptRegions()) {
                assertTrue(kept.startsWith("face ") && kept.contains("sharper than the model's sharpest"), name + ": " + kept);
            }
            SameSurface.assertSameSurface(mesh, result.mesh());
            assertTrue(result.minAngleAfter() >= result.minAngleBefore(), name + ": " + result.minAngleBefore() + " -> " + result.minAngleAfter());
            if (name.startsWith("trimesh_rabbit")) {
                // Its faces 1136 and 1168 had flat triangles along an edge (3.80° and 0°): kept before.
                assertEquals(List.of(), result.keptRegions(), name);
            }
        }
    }

    private static double boundaryLength(HalfedgeMesh mesh) {
        List<Integer> boundary = new ArrayList<>();
        for (int h = 0; h < mesh.halfedgeCount(); h++) {
            if (mesh.isBoundary(h)) {
                boundary.add(h);
            }
        }
        double length = 0;
        for (int h : boundary) {
            length += length(mesh, h);
        }
        return length;
    }

    private static double length(HalfedgeMesh mesh, int h) {
        int a = mesh.fromVertex(h);
        int b = mesh.toVertex(h);
        return Math.sqrt(sq(mesh.x(a) - mesh.x(b)) + sq(mesh.y(a) - mesh.y(b)) + sq(mesh.z(a) - mesh.z(b)));
    }

    private static double sq(double x) {
        return x * x;
    }
}
