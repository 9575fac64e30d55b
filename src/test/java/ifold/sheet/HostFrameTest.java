package ifold.sheet;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Thick paper at a concave edge of its host keeps to its mitre, and stays on the host. */
class HostFrameTest {
    private static HostFrame host(double[] corners, double[] mitre) {
        return new HostFrame(new double[] {0, 0, 0}, new double[] {1, 0, 0}, new double[] {0, 1, 0}, new double[] {0, 0, 1}, corners)
                .withEdges(null, mitre);
    }

    /** The unit square whose edge x = 0 (edge 3, from (0, 1) to (0, 0)) is concave by 90 degrees: its mitre is as far in as up. */
    private static final HostFrame SQUARE = host(new double[] {0, 0, 1, 0, 1, 1, 0, 1}, new double[] {0, 0, 0, 1});

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
        HostFrame sharp = host(new double[] {0, 0, 1, 0, 1, 0.5}, new double[] {1, 0, 0});
        double[] at = new double[2];
        assertTrue(sharp.mitred(0.1, 0.05, 0.1, at));
        assertArrayEquals(new double[] {0.2, 0.1}, at, 1e-12, "on edge 2's line, 0.1 up from the base");
        assertTrue(sharp.mitred(0.5, 0, 0.1, at));
        assertArrayEquals(new double[] {0.5, 0.1}, at, 1e-12, "away from the corner: straight in");
    }
}
