package ifold.sheet;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Thick paper at a concave edge of its host keeps to its mitre, and stays on the host. */
class HostFrameTest {
    private static HostFrame host(double[] corners, double[][] mitre) {
        return new HostFrame(new double[] {0, 0, 0}, new double[] {1, 0, 0}, new double[] {0, 1, 0}, new double[] {0, 0, 1}, corners)
                .withEdges(null, mitre);
    }

    /** The unit square whose edge x = 0 (edge 3, from (0, 1) to (0, 0)) is concave by 90 degrees: its mitre is as far in as up. */
    private static final HostFrame SQUARE = host(new double[] {0, 0, 1, 0, 1, 1, 0, 1}, new double[][] {null, null, null, {0, 1, 1}});

    @Test
    void paperAtAConcaveEdgeStandsBackToItsMitre() {
        double[] at = new double[2];
        assertTrue(SQUARE.mitred(0, 0.5, 0.1, at), "a layer 0.1 up ran to the edge");
        assertArrayEquals(new double[] {0.1, 0.5}, at, 1e-15);
        assertFalse(SQUARE.mitred(0.3, 0.5, 0.1, at), "paper beyond its mitre stays where it is");
        assertArrayEquals(new double[] {0.3, 0.5}, at);
        assertFalse(SQUARE.mitred(0, 0.5, 0, at), "at no height there is no mitre");
        HostFrame convex = host(new double[] {0, 0, 1, 0, 1, 1, 0, 1}, null);
        assertFalse(convex.mitred(0, 0.5, 0.1, at), "no concave edge, no mitre");
    }

    /**
     * Near a corner sharper than 90 degrees a straight move in from the concave edge would take
     * paper out across the other edge: it slides along that edge instead, staying on the host.
     */
    @Test
    void paperAtASharpCornerSlidesAlongTheOtherEdge() {
        // A triangle with a corner of 26.6 degrees at the origin: its base (edge 0, y = 0) is
        // concave by 90 degrees; edge 2 runs from (1, 0.5) back to the origin, along y = x / 2.
        HostFrame sharp = host(new double[] {0, 0, 1, 0, 1, 0.5}, new double[][] {{0, 1, 1}, null, null});
        double[] at = new double[2];
        assertTrue(sharp.mitred(0.1, 0.05, 0.1, at));
        assertArrayEquals(new double[] {0.2, 0.1}, at, 1e-12, "on edge 2's line, 0.1 up from the base");
        assertTrue(sharp.mitred(0.5, 0, 0.1, at));
        assertArrayEquals(new double[] {0.5, 0.1}, at, 1e-12, "away from the corner: straight in");
    }

    /** An edge concave along part of it only (a low block beside a tall one): paper beside the rest keeps to the edge. */
    @Test
    void onlyTheConcaveStretchOfAnEdgeMitres() {
        // Edge 0 of the square, y = 0 from x = 0 to 1, concave from x = 0 to 0.5 only.
        HostFrame partly = host(new double[] {0, 0, 1, 0, 1, 1, 0, 1}, new double[][] {{0, 0.5, 1}, null, null, null});
        double[] at = new double[2];
        assertTrue(partly.mitred(0.25, 0, 0.1, at));
        assertArrayEquals(new double[] {0.25, 0.1}, at, 1e-15);
        assertFalse(partly.mitred(0.75, 0, 0.1, at), "beside the convex stretch the paper stays");
        assertArrayEquals(new double[] {0.75, 0}, at);
    }

    /**
     * A host narrower than its stacks need (a groove whose two walls are concave): paper goes no
     * farther than the far side, nearer than its mitre, where it meets the paper across; two
     * concave edges at a sharp corner: paper goes where their mitres meet.
     */
    @Test
    void paperNeverLeavesItsHostAndMeetsBothMitresAtASharpCorner() {
        HostFrame groove = host(new double[] {0, 0, 1, 0, 1, 0.1, 0, 0.1}, new double[][] {{0, 1, 1}, null, {0, 1, 1}, null});
        double[] at = new double[2];
        groove.mitred(0.5, 0, 0.15, at);
        assertTrue(at[1] >= -1e-12 && at[1] <= 0.1 + 1e-12, "within the groove: " + at[1]);

        // A corner of 30 degrees at the origin between two concave edges: edge 0 along y = 0,
        // edge 2 from the far corner back to the origin along y = x tan 30.
        double t = Math.tan(Math.toRadians(30));
        HostFrame sharp = host(new double[] {0, 0, 2, 0, 2, 2 * t}, new double[][] {{0, 2, 1}, null, {0, 2 / Math.cos(Math.toRadians(30)), 1}});
        assertTrue(sharp.mitred(0.05, 0.01, 0.05, at));
        double fromBase = at[1];
        double fromSide = (at[0] * t - at[1]) * Math.cos(Math.toRadians(30));
        assertTrue(fromBase >= 0.05 - 1e-12 && fromSide >= 0.05 - 1e-12, "0.05 from both edges: " + fromBase + ", " + fromSide);
    }

    /**
     * {@link HostFrame#keepsFrom} says whether {@link HostFrame#keepFrom} would move a point, so
     * that the walls a point lies far from can be passed over: the same answer for points inside,
     * on and beyond the edge's line, at the keep's distance, a rounding step either side of it,
     * and near a corner where the move slides along the other edge.
     */
    @Test
    void keepsFromAnswersAsKeepFromMoves() {
        HostFrame triangle = host(new double[] {0, 0, 1, 0, 0.3, 0.7}, null);
        double keep = 0.1;
        double[] ys = {-0.05, 0, 0.02, Math.nextDown(keep), keep, Math.nextUp(keep), keep * (1 - 1e-13), keep * (1 - 1e-11), 0.3, 0.6};
        int moved = 0;
        for (int k = 0; k < 3; k++) {
            for (double x : new double[] {0.01, 0.2, 0.5, 0.9}) {
                for (double y : ys) {
                    // The point that distance in from edge k, at a place x along it (each edge in its own terms).
                    double[] edge = triangle.edge(k);
                    double tx = edge[2] / edge[4];
                    double ty = edge[3] / edge[4];
                    double[] p = {edge[0] + x * edge[2] - y * ty, edge[1] + x * edge[3] + y * tx};
                    boolean says = triangle.keepsFrom(k, keep, p);
                    double[] q = p.clone();
                    boolean moves = triangle.keepFrom(k, keep, q);
                    assertEquals(moves, says, "edge " + k + " at " + x + ", " + y + " in");
                    assertArrayEquals(p, says ? p : q, "a point keepsFrom lets be does not move");
                    moved += moves ? 1 : 0;
                }
            }
        }
        assertTrue(moved > 40 && moved < 100, "points both near and far: " + moved + " of 120 moved");
    }

    /**
     * A stop at the corner (1, 0) of the unit square, on its edge y = 0 (edge 0) running back
     * towards (0, 0), for a face across the corner (host 7) whose stack stands 0.02 high, leaving
     * the edge at 60 degrees to its normal (slope 2): paper going over the edge keeps 0.04 from
     * the corner along it; paper on the edge that does not go over it, paper beyond the stop, and
     * paper off the edge stay.
     */
    @Test
    void paperOverAConvexEdgeKeepsFromAStopAsFarAsTheWallStandsHigh() {
        HostFrame stopped = SQUARE.withStops(new HostFrame.Stop[] {new HostFrame.Stop(0, 1, -1, 7, 2)});
        double[] tops = new double[8];
        tops[7] = 0.02;
        double[] over = {0.5, 0};
        double[] at = {1, 0};
        assertTrue(stopped.stopped(tops, 1e-12, over, at), "the crease's end at the corner");
        assertArrayEquals(new double[] {0.96, 0}, at, 1e-15);
        at = new double[] {0.99, 0};
        assertTrue(stopped.stopped(tops, 1e-12, over, at), "a crease point nearer the corner than the stop keeps it");
        assertArrayEquals(new double[] {0.96, 0}, at, 1e-15);
        at = new double[] {0.9, 0};
        assertFalse(stopped.stopped(tops, 1e-12, over, at), "beyond the stop's reach");
        at = new double[] {1, 0};
        assertFalse(stopped.stopped(tops, 1e-12, new double[] {1, 0.5}, at), "paper going over the other edge at the corner");
        assertFalse(stopped.stopped(tops, 1e-12, null, at), "paper going over no edge");
        at = new double[] {1, 0.01};
        assertFalse(stopped.stopped(tops, 1e-12, over, at), "off the edge");
        tops[7] = 0;
        at = new double[] {1, 0};
        assertFalse(stopped.stopped(tops, 1e-12, over, at), "a face across with no paper on it stops nothing");
        assertThrows(IllegalArgumentException.class, () -> SQUARE.withStops(new HostFrame.Stop[] {new HostFrame.Stop(4, 0, 1, 0, 1)}));
    }
    /**
     * A pit: a triangle whose three edges are concave. Paper by one corner, held there between
     * two mitres, goes where those two meet, not where another corner's do (each pair met in
     * turn, the last won: across the triangle); and paper on an edge whose mitre is a hair's
     * breadth stays by where it lay, not sent to the far end of that edge, where the next edge's
     * mitre meets it (moved in by the hair, rounding left it short again round after round).
     */
    @Test
    void inAPitPaperMeetsTheMitresOfItsOwnCorner() {
        // Corners (0, 0), (1, 0), (0.4, 1): edges 0 (base), 1 and 2 (back to the origin), all concave by 90 degrees.
        HostFrame pit = host(new double[] {0, 0, 1, 0, 0.4, 1}, new double[][] {{0, 1, 1}, {0, Math.hypot(0.6, 1), 1}, {0, Math.hypot(0.4, 1), 1}});
        double[] at = new double[2];
        assertTrue(pit.mitred(0.01, 0.005, 0.05, at));
        double toBase = at[1];
        double toEdge2 = pit.inside(2, at);
        assertTrue(Math.hypot(at[0], at[1]) < 0.2, "by the origin, where edges 0 and 2 meet: " + at[0] + ", " + at[1]);
        assertTrue(toBase >= 0.05 - 1e-12 && toEdge2 >= 0.05 - 1e-12, "0.05 from both: " + toBase + ", " + toEdge2);

        // Edge 2's mitre a turn of 0.0024 degrees, edge 1's of 0.7: a host of the elephant with
        // holes, and a corner of a piece of paper on edge 2 two and a half thicknesses up (its numbers).
        HostFrame gentle = host(new double[] {0, 0, 0.025673047228562493, 0, 0.009111924533825535, 0.022383074194128647},
                new double[][] {null, {0, 0.027843720931118372, 0.006083959160276323}, {0, 0.024166695659315927, 2.0822114818028354E-5}});
        double[] onEdge2 = {0.0017022697770602536, 0.004181556879325518};
        assertTrue(Math.abs(gentle.inside(2, onEdge2)) < 1e-12, "check the setup: on edge 2");
        gentle.mitred(onEdge2[0], onEdge2[1], 0.0019281604574434928, 0.004701787437474755, 2.5 * 1.3067365247860811E-5, at);
        assertTrue(Math.hypot(at[0] - onEdge2[0], at[1] - onEdge2[1]) < 1e-8, "stays by where it lay: " + at[0] + ", " + at[1]);
    }
}
