package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import ifold.wrap.NestedBends.Bend;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Which flat folds nest about one crease line, and where the rows of those that stand out end. */
class NestedBendsTest {
    private static final double TOLERANCE = 1e-6;

    /** A bend along the x axis from x0 to x1, standing out towards -y, its layers at low and high. */
    private static Bend alongX(double x0, double x1, double y, int low, int high) {
        return new Bend(0, x0, y, x1, y, 0, -1, low, high);
    }

    @Test
    void foldsWrappedOneInsideTheNextAreRankedFromTheInside() {
        // A tuck of three layers folded under along one line: levels 0-5, 1-4, 2-3.
        List<Bend> tuck = List.of(alongX(0, 1, 0, 0, 5), alongX(0.2, 0.9, 0, 1, 4), alongX(0, 1, 0, 2, 3));
        assertArrayEquals(new int[] {2, 1, 0}, NestedBends.ranks(tuck, TOLERANCE));
    }

    @Test
    void onlyFoldsOnTheSameLineOnTheSameSideThatOverlapAlongItNest() {
        List<Bend> bends = List.of(alongX(0, 1, 0, 0, 5),
                alongX(0, 1, 0.001, 1, 4), // a parallel line
                alongX(1.5, 2, 0, 1, 4), // on the line, not overlapping along it
                new Bend(0, 0, 0, 1, 0, 0, 1, 1, 4), // on the line, standing out the other way
                new Bend(1, 0, 0, 1, 0, 0, -1, 1, 4)); // another host
        assertArrayEquals(new int[] {0, 0, 0, 0, 0}, NestedBends.ranks(bends, TOLERANCE));
        // Within the tolerance of the line, running the other way: the same line (the creases of
        // one fold line, computed to rounding).
        List<Bend> near = List.of(alongX(0, 1, 0, 0, 5), new Bend(0, 1, TOLERANCE / 2, 0.5, TOLERANCE / 2, 0, -1, 1, 4));
        assertArrayEquals(new int[] {1, 0}, NestedBends.ranks(near, TOLERANCE));
    }

    @Test
    void foldsWhoseLayersInterleaveOrShareOneAreNotNested() {
        List<Bend> bends = List.of(alongX(0, 1, 0, 0, 3), alongX(0, 1, 0, 1, 4), alongX(0, 1, 0, 0, 2));
        assertArrayEquals(new int[] {0, 0, 0}, NestedBends.ranks(bends, TOLERANCE));
    }

    @Test
    void foldsWrappedByOneThatStandsOutLessStandOutLessStill() {
        List<Bend> tuck = List.of(alongX(0, 1, 0, 0, 5), alongX(0, 1, 0, 1, 4), alongX(0, 1, 0, 2, 3), alongX(3, 4, 0, 1, 4));
        int[] ranks = NestedBends.ranks(tuck, TOLERANCE);
        assertArrayEquals(new int[] {2, 1, 0, 0}, ranks);
        // The outer one was held to half its two thicknesses; the last is on the line but apart.
        double[] out = {1, 1, 0, 0.5};
        NestedBends.keepNested(tuck, ranks, out, TOLERANCE);
        assertArrayEquals(new double[] {1, 0.5, 0, 0.5}, out);
        double[] held = {0, 1, 0, 0.5};
        NestedBends.keepNested(tuck, ranks, held, TOLERANCE);
        assertArrayEquals(new double[] {0, 0, 0, 0.5}, held, "the outer on its crease: the inner too");
    }

    @Test
    void aRowThatWouldRunThroughTheWallOfAFoldAtAnObtuseCornerStopsOnIt() {
        // A pentagon's corner: crease A along the x axis, crease B at 108 degrees to it, both
        // standing out of the pentagon; A stands out 0.1, B not at all.
        double angle = Math.toRadians(108);
        Bend a = alongX(0, 1, 0, 0, 5);
        Bend b = new Bend(0, 0, 0, Math.cos(angle), Math.sin(angle), -Math.sin(angle), Math.cos(angle), 1, 9);
        double[] past = NestedBends.mitres(List.of(a, b), new double[] {0.1, 0}, TOLERANCE);
        // A's row, 0.1 out, ends on B's line at (x, -0.1): x·nB.x - 0.1·nB.y = 0, x = 0.0325.
        double x = 0.1 * b.ny() / b.nx();
        assertEquals(0.0325, x, 1e-4, "setup");
        assertEquals(-x, past[0], 1e-12, "A's row stops short of the corner");
        assertEquals(0, past[1], "A's far end is free");
        assertEquals(0, past[2], "B stands on its crease");
    }

    @Test
    void rowsAtARightAngledCornerOrOfLayersApartRunOnSquare() {
        // A square's corner: the rows stand out of each other's way.
        Bend a = alongX(0, 1, 0, 0, 5);
        Bend b = new Bend(0, 0, 0, 0, 1, -1, 0, 1, 4);
        assertArrayEquals(new double[4], NestedBends.mitres(List.of(a, b), new double[] {0.1, 0.1}, TOLERANCE));
        // At 108 degrees, but B's layers lie above all of A's: the rows pass each other.
        double angle = Math.toRadians(108);
        Bend above = new Bend(0, 0, 0, Math.cos(angle), Math.sin(angle), -Math.sin(angle), Math.cos(angle), 6, 9);
        assertArrayEquals(new double[4], NestedBends.mitres(List.of(a, above), new double[] {0.1, 0}, TOLERANCE));
    }
}
