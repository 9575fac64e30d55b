package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.PolygonSoup;
import ifold.sheet.HostFrame;
import org.junit.jupiter.api.Test;

/** The room beyond a host's edges: tan(φ/2) over a convex turn φ, none beside a coplanar host, 45 degrees elsewhere. */
class BendRoomTest {
    /**
     * Two triangles sharing the edge (0,0,0)-(1,0,0): one in the plane z = 0 (y < 0), the other
     * turned about the edge by {@code turn} radians: down (convex) for a positive turn.
     */
    private static HostFrame[] hinge(double turn) {
        PolygonSoup mesh = new PolygonSoup();
        mesh.addVertex(0, 0, 0);
        mesh.addVertex(1, 0, 0);
        mesh.addVertex(0.5, -1, 0);
        mesh.addVertex(0.5, Math.cos(turn), -Math.sin(turn));
        mesh.addFace(new int[] {0, 2, 1}, 3, 0);
        mesh.addFace(new int[] {0, 1, 3}, 3, 0);
        HostFrame[] frames = new HostFrame[2];
        for (int t = 0; t < 2; t++) {
            double[][] p = new double[3][];
            for (int k = 0; k < 3; k++) {
                int v = mesh.faceVertex(t, k);
                p[k] = new double[] {mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2)};
            }
            frames[t] = HostFrame.onEdge(p[0], p[1], p[2]);
        }
        return BendRoom.of(mesh, new int[] {0, 1}, frames, 1e-9);
    }

    /** The room host {@code h} has along the shared edge, and along its other edges. */
    private static double[] room(HostFrame[] frames, int h) {
        HostFrame f = frames[h];
        double[] zero = {0, 0, 0};
        double[] one = {1, 0, 0};
        double shared = f.roomBeyond(f.localX(zero), f.localY(zero), f.localX(one), f.localY(one), 1e-9);
        double least = HostFrame.OPEN;
        double[] c = f.corners();
        for (int k = 0; k < 3; k++) {
            double ax = c[2 * k];
            double ay = c[2 * k + 1];
            double bx = c[2 * ((k + 1) % 3)];
            double by = c[2 * ((k + 1) % 3) + 1];
            double r = f.roomBeyond(ax, ay, bx, by, 1e-9);
            if (Math.abs(ay - f.localY(zero)) + Math.abs(by - f.localY(one)) > 1e-9 && r != shared) {
                least = Math.min(least, r);
            }
        }
        return new double[] {shared, least};
    }

    @Test
    void aConvexTurnLeavesTheHalfAngle() {
        for (double degrees : new double[] {20, 41.81, 90}) {
            HostFrame[] frames = hinge(Math.toRadians(degrees));
            for (int h = 0; h < 2; h++) {
                double[] room = room(frames, h);
                assertEquals(Math.min(1, Math.tan(Math.toRadians(degrees) / 2)), room[0], 1e-12, degrees + " degrees, host " + h);
                assertEquals(HostFrame.OPEN, room[1], "the other edges border nothing");
            }
        }
        // Sharper than a right angle, the bend keeps its 45 degrees.
        assertEquals(HostFrame.OPEN, room(hinge(Math.toRadians(120)), 0)[0]);
    }

    @Test
    void aHostInTheSamePlaneLeavesNone() {
        assertEquals(0, room(hinge(0), 0)[0]);
    }

    @Test
    void aConcaveEdgeIsNotLimitedHere() {
        assertEquals(HostFrame.OPEN, room(hinge(Math.toRadians(-60)), 0)[0]);
    }

    @Test
    void aCreaseAlongPartOfAnEdgeGetsItsRoomAndOneInsideTheHostNone() {
        HostFrame f = hinge(Math.toRadians(60))[0];
        double[] a = {0.25, 0, 0};
        double[] b = {0.5, 0, 0};
        assertEquals(Math.tan(Math.toRadians(30)), f.roomBeyond(f.localX(a), f.localY(a), f.localX(b), f.localY(b), 1e-9), 1e-12);
        double[] c = {0.25, -0.1, 0};
        assertEquals(HostFrame.OPEN, f.roomBeyond(f.localX(a), f.localY(a), f.localX(c), f.localY(c), 1e-9));
    }

    /**
     * One edge of a host, (0,0,0)-(2,0,0), with a convex turn of {@code turn} across its first
     * half and a coplanar host across its second (a T-shaped face cut into convex pieces).
     */
    private static HostFrame halfConvex(double turn) {
        PolygonSoup mesh = new PolygonSoup();
        mesh.addVertex(0, 0, 0);
        mesh.addVertex(1, 0, 0);
        mesh.addVertex(2, 0, 0);
        mesh.addVertex(1, -1, 0);
        mesh.addVertex(0.5, Math.cos(turn), -Math.sin(turn));
        mesh.addVertex(1.5, 1, 0);
        mesh.addFace(new int[] {0, 3, 1}, 3, 0);
        mesh.addFace(new int[] {1, 3, 2}, 3, 0);
        mesh.addFace(new int[] {0, 1, 4}, 3, 0);
        mesh.addFace(new int[] {1, 2, 5}, 3, 0);
        double[][] p = new double[6][];
        for (int v = 0; v < 6; v++) {
            p[v] = new double[] {mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2)};
        }
        HostFrame[] frames = {HostFrame.onEdge(p[0], p[3], p[2]), HostFrame.onEdge(p[0], p[1], p[4]), HostFrame.onEdge(p[1], p[2], p[5])};
        return BendRoom.of(mesh, new int[] {0, 0, 1, 2}, frames, 1e-9)[0];
    }

    /** The room beyond the crease from a to b, points in space on host frame f. */
    private static double roomBeyond(HostFrame f, double[] a, double[] b) {
        return f.roomBeyond(f.localX(a), f.localY(a), f.localX(b), f.localY(b), 1e-9);
    }

    @Test
    void anEdgeConvexAlongPartOfItHasItsRoomThereAndNoneBesideTheCoplanarHost() {
        double turn = Math.toRadians(60);
        HostFrame f = halfConvex(turn);
        double[] a = {0.2, 0, 0};
        double[] b = {0.8, 0, 0};
        double[] c = {1.2, 0, 0};
        double[] d = {1.8, 0, 0};
        assertEquals(Math.tan(turn / 2), roomBeyond(f, a, b), 1e-12, "beside the convex turn");
        assertEquals(0, roomBeyond(f, c, d), "beside the coplanar host");
        assertEquals(0, roomBeyond(f, a, d), "a crease along both gets the least");
        // A bend standing out from the crease at height 0.01: beside the convex turn as far as
        // it asks, beside the coplanar host not at all. (The host lies at y < 0 in space, so out
        // of it is +y, in the frame (ex·y, ey·y).)
        double height = 0.01;
        double slope = Math.tan(turn / 2);
        double nx = f.ex()[1];
        double ny = f.ey()[1];
        assertEquals(0.005, f.lean(f.localX(a), f.localY(a), nx, ny, height, slope, 0.005, 0), 1e-12);
        assertEquals(0, f.lean(f.localX(d), f.localY(d), nx, ny, height, slope, 0.005, 0), 1e-12);
    }

    /**
     * A bend standing out along the line of an edge of no room, from a point on it, comes no
     * nearer beyond it, whichever way rounding tips its direction and its point: on the L prism's
     * top, three folds from the reflex corner square to the diagonal (rank 2, 1 and 0) stood on one
     * line, 12 pairs in one plane, as the first leaned out 1e-13 towards the cut from 1e-13 beyond
     * it and was held to 0, while the fold wrapping them, tipped the other way, stood out 3 T.
     */
    @Test
    void aBendStandingOutAlongAnEdgeOfNoRoomIsNotHeldByRounding() {
        double turn = Math.toRadians(60);
        HostFrame f = halfConvex(turn);
        double height = 0.01;
        double slope = Math.tan(turn / 2);
        // Along the edge (+x in space), tipped 2e-13 out of the host (+y), from 1e-13 beyond the edge.
        double nx = f.ex()[0] + 2e-13 * f.ex()[1];
        double ny = f.ey()[0] + 2e-13 * f.ey()[1];
        double[] d = {1.8, 1e-13, 0};
        double[] inside = {1.8, -0.001, 0};
        assertEquals(0, roomBeyond(f, new double[] {1.2, 0, 0}, d), "setup: beside the coplanar host, no room");
        assertEquals(0.005, f.lean(f.localX(d), f.localY(d), nx, ny, height, slope, 0.005, 0), 1e-12);
        // Standing out across the edge from inside, it is held as before.
        assertEquals(0.001, f.lean(f.localX(inside), f.localY(inside), f.ex()[1], f.ey()[1], height, slope, 0.005, 0), 1e-9);
    }

    /**
     * A crease along a convex edge that ends at a reflex corner of a face cut into coplanar
     * hosts leans over its own stretch, even where its end is off the corner by as much as the
     * sheet's tolerance. The host is one of the 2,200-triangle torus's flat bottom ring
     * ({@code generate torus --around 50 --across 22}; its figures as that wrap placed them): a
     * trapezoid whose inner edge 0 (from the origin) turns by 16.4 degrees, its sides 1 and 3 cut
     * from the coplanar hosts beside it (no room), its corners at the inner edge 93.6 degrees, so
     * that a bend standing out beyond the inner edge at its end leans 3.6 degrees over the line of
     * the cut, into the air beyond the ring's inner rim. Along that wrap's strip, a crease of the
     * inner edge (a tuck's fold of rank 2, levels 1 to 8) ended 1.13e-9 from the corner along the
     * cut, beyond the 5.7e-10 the cut's stretch was given, and was held to 1.4e-12 (its nest with
     * it): three bends' walls on one line, 306 pairs in one plane, 17 such corners.
     */
    @Test
    void aCreaseEndingAtAReflexCornerToTheSheetsToleranceStandsOut() {
        double[] corners = {0, 0, 0.2865443944172902, -0.21605729861159578, 0.4718368564541063, 0, 0.15675221575932002,
            0.23757692570102157};
        double slope = 0.14405102110761064; // tan(8.2 degrees): half the turn of the inner and outer edges
        HostFrame frame = new HostFrame(new double[] {0, 0, 0}, new double[] {1, 0, 0}, new double[] {0, 1, 0}, new double[] {0, 0, 1},
                corners, null, null, null);
        double[][] room = new double[4][];
        for (int k = 0; k < 4; k++) {
            room[k] = new double[] {0, frame.edge(k)[4], k % 2 == 0 ? slope : 0};
        }
        frame = frame.withEdges(room, null);
        double thickness = 2.1402138410246894E-4;
        double tolerance = 8e-9; // a billionth of the model's size
        // The crease's end: on side 3, 1.13e-9 from the corner; the bend stands out along edge 0's outward normal.
        double[] toCorner3 = {corners[6] / frame.edge(3)[4], corners[7] / frame.edge(3)[4]};
        double x = 1.13e-9 * toCorner3[0];
        double y = 1.13e-9 * toCorner3[1];
        double nx = frame.edge(0)[3] / frame.edge(0)[4];
        double ny = -frame.edge(0)[2] / frame.edge(0)[4];
        double out = 2 * thickness * 2 * slope / (1 + slope); // rank 2
        double height = 1.5 * thickness;
        double[] end = {-0.0171 * ny, 0.0171 * nx}; // the crease's other end, a strip's width along the inner edge
        assertTrue(frame.along(0, x, y, end[0], end[1], tolerance) && frame.roomBeyond(x, y, end[0], end[1], tolerance) == slope,
                "setup: the crease lies along the inner edge");
        assertEquals(out, frame.lean(x, y, nx, ny, height, slope, out, tolerance), 1e-15);
        // Held by the cut, as before, where its end lies farther along the cut than the tolerance.
        assertEquals(0, frame.lean(20 * x, 20 * y, nx, ny, height, slope, out, tolerance), 1e-10);
    }
    /**
     * A face cut into two convex hosts through the end of a concave edge: host A (a triangle)
     * has the concave edge (0,0,0)-(1,0,0) under a wall rising from it, host B (a quad) only a
     * corner at its end, its edge along the edge's line running on the other way and its side
     * along the cut leaning over the concave edge's stretch. B's paper there, under the wall, is
     * mitred from the edge's line as A's is; it was not (a random polycube's host corners 0 in
     * from such an edge, up to 17 thicknesses high). Beside B's own edge, where nothing rises,
     * nothing is mitred.
     */
    @Test
    void aHostWithACornerAtTheEndOfAConcaveEdgeIsMitredBesideIt() {
        PolygonSoup mesh = new PolygonSoup();
        mesh.addVertex(0, 0, 0);
        mesh.addVertex(1, 0, 0);
        mesh.addVertex(1, -1, 0);
        mesh.addVertex(-1, 0, 0);
        mesh.addVertex(-1, -1, 0);
        mesh.addVertex(1, 0, 1);
        mesh.addVertex(0, 0, 1);
        mesh.addFace(new int[] {0, 2, 1}, 3, 0); // A
        mesh.addFace(new int[] {0, 3, 4}, 3, 0); // B
        mesh.addFace(new int[] {0, 4, 2}, 3, 0); // B
        mesh.addFace(new int[] {0, 1, 5}, 3, 0); // the wall, facing -y
        mesh.addFace(new int[] {0, 5, 6}, 3, 0);
        double[][] p = new double[7][];
        for (int v = 0; v < 7; v++) {
            p[v] = new double[] {mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2)};
        }
        HostFrame b = HostFrame.onEdge(p[0], p[3], p[4]);
        double[] quad = new double[8];
        int[] corners = {0, 3, 4, 2};
        for (int k = 0; k < 4; k++) {
            quad[2 * k] = b.localX(p[corners[k]]);
            quad[2 * k + 1] = b.localY(p[corners[k]]);
        }
        HostFrame[] frames = {HostFrame.onEdge(p[0], p[2], p[1]), new HostFrame(b.origin(), b.ex(), b.ey(), b.normal(), quad),
            HostFrame.onEdge(p[0], p[1], p[5])};
        HostFrame[] limited = BendRoom.of(mesh, new int[] {0, 1, 1, 2, 2}, frames, 1e-9);
        HostFrame host = limited[1];
        double height = 0.2;
        double[] under = {0.1, -0.11, 0};
        double[] out = new double[2];
        assertTrue(host.mitred(host.localX(under), host.localY(under), height, out), "under the wall");
        double[] moved = {0, 0, 0};
        host.toSpace(out[0], out[1], 0, moved, 0);
        assertEquals(-height, moved[1], 1e-12, "in from the edge's line by height * tan(45 degrees)");
        double[] beside = {-0.5, -0.1, 0};
        assertFalse(host.mitred(host.localX(beside), host.localY(beside), height, out), "beside B's own edge");
    }
}
