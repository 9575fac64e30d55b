package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.IndexedPolygons;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.refine.HamiltonianRefinement;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The hosts a wrap's paper rests on, on solids whose flat convex pieces are known. */
class HostPiecesTest {
    private static HostPieces piecesOf(PolygonSoup soup) throws Exception {
        HalfedgeMesh mesh = MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        return HostPieces.of(HamiltonianRefinement.refine(mesh).mesh());
    }

    @Test
    void aCubeHasSixSquares() throws Exception {
        HostPieces pieces = piecesOf(Solids.cube());
        assertEquals(6, pieces.hostCount());
        for (int[] corners : pieces.corners) {
            assertEquals(4, corners.length, "a square's corners, the midpoints of the refinement dropped");
        }
    }

    @Test
    void aTetrahedronAndAnIcosahedronHaveTheirFaces() throws Exception {
        assertEquals(4, piecesOf(Solids.tetrahedron()).hostCount());
        assertEquals(20, piecesOf(Solids.icosahedron()).hostCount());
    }

    @Test
    void aCurvedSurfaceHasATriangleAHost() throws Exception {
        // The icosphere's triangles are all in planes of their own.
        PolygonSoup sphere = Solids.icosphere(1);
        assertEquals(sphere.faceCount(), piecesOf(sphere).hostCount());
    }

    /** An L-shaped prism: each L face (a non-convex hexagon) is cut into two convex pieces, the quads are one each. */
    @Test
    void anLShapedFaceIsCutIntoConvexPieces() throws Exception {
        HalfedgeMesh mesh = MeshBuilder.build(WrapTest.lPrism(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        IndexedPolygons path = HamiltonianRefinement.refine(mesh).mesh();
        HostPieces pieces = HostPieces.of(path);
        assertEquals(6 + 2 * 2, pieces.hostCount(), "six quads, two pieces each L");
        // Every host is convex and every triangle of the path lies in its host.
        for (int t = 0; t < path.faceCount(); t++) {
            int[] corners = pieces.corners[pieces.hostOf[t]];
            Set<Integer> kept = new HashSet<>();
            for (int v : corners) {
                kept.add(v);
            }
            assertTrue(corners.length >= 3 && corners.length <= 4, "a convex piece of an L or a quad: " + corners.length);
            for (int k = 0; k < 3; k++) {
                assertTrue(inside(path, corners, path.faceVertex(t, k)), "triangle " + t + " lies in its host");
            }
        }
    }

    /**
     * Polycubes' faces, squares cut into two triangles each, come back as rectangles: the
     * roundest merge first, not a triangle with 45° corners cut along a diagonal of the L.
     */
    @Test
    void aPolycubesFacesAreCutIntoRectangles() throws Exception {
        for (java.util.List<int[]> cubes : java.util.List.of(ifold.mesh.Polycubes.l(), ifold.mesh.Polycubes.plus(), ifold.mesh.Polycubes.t())) {
            HalfedgeMesh mesh = MeshBuilder.build(ifold.mesh.Polycubes.surface(cubes), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
            IndexedPolygons path = HamiltonianRefinement.refine(mesh).mesh();
            HostPieces pieces = HostPieces.of(path);
            for (int[] corners : pieces.corners) {
                assertEquals(4, corners.length, "a rectangle's corners");
                for (int k = 0; k < 4; k++) {
                    double[] a = point(path, corners[(k + 3) % 4]);
                    double[] b = point(path, corners[k]);
                    double[] c = point(path, corners[(k + 1) % 4]);
                    double dot = (a[0] - b[0]) * (c[0] - b[0]) + (a[1] - b[1]) * (c[1] - b[1]) + (a[2] - b[2]) * (c[2] - b[2]);
                    assertEquals(0, dot, 1e-12, "a right angle at each corner");
                }
            }
        }
    }

    /** Whether vertex v lies in the convex polygon of vertex ids {@code corners} (in its plane, up to rounding). */
    private static boolean inside(IndexedPolygons mesh, int[] corners, int v) {
        double[] n = new double[3];
        int count = corners.length;
        double[] a = point(mesh, corners[0]);
        double[] b = point(mesh, corners[1]);
        double[] c = point(mesh, corners[2]);
        double[] u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double[] w = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        n[0] = u[1] * w[2] - u[2] * w[1];
        n[1] = u[2] * w[0] - u[0] * w[2];
        n[2] = u[0] * w[1] - u[1] * w[0];
        double[] p = point(mesh, v);
        for (int k = 0; k < count; k++) {
            double[] from = point(mesh, corners[k]);
            double[] to = point(mesh, corners[(k + 1) % count]);
            double[] e = {to[0] - from[0], to[1] - from[1], to[2] - from[2]};
            double[] r = {p[0] - from[0], p[1] - from[1], p[2] - from[2]};
            double side = n[0] * (e[1] * r[2] - e[2] * r[1]) + n[1] * (e[2] * r[0] - e[0] * r[2]) + n[2] * (e[0] * r[1] - e[1] * r[0]);
            if (side < -1e-9) {
                return false;
            }
        }
        return true;
    }

    private static double[] point(IndexedPolygons mesh, int v) {
        return new double[] {mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2)};
    }
}
