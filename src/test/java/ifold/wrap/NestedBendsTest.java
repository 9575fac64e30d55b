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
        assertArrayEquals(new int[] {2, 1, 0}, NestedBends.of(tuck, TOLERANCE).ranks());
    }

    @Test
    void onlyFoldsOnTheSameLineOnTheSameSideThatOverlapAlongItNest() {
        List<Bend> bends = List.of(alongX(0, 1, 0, 0, 5),
                alongX(0, 1, 0.001, 1, 4), // a parallel line
                alongX(1.5, 2, 0, 1, 4), // on the line, not overlapping along it
                new Bend(0, 0, 0, 1, 0, 0, 1, 1, 4), // on the line, standing out the other way
                new Bend(1, 0, 0, 1, 0, 0, -1, 1, 4)); // another host
        assertArrayEquals(new int[] {0, 0, 0, 0, 0}, NestedBends.of(bends, TOLERANCE).ranks());
        // Within the tolerance of the line, running the other way: the same line (the creases of
        // one fold line, computed to rounding).
        List<Bend> near = List.of(alongX(0, 1, 0, 0, 5), new Bend(0, 1, TOLERANCE / 2, 0.5, TOLERANCE / 2, 0, -1, 1, 4));
        assertArrayEquals(new int[] {1, 0}, NestedBends.of(near, TOLERANCE).ranks());
    }

    @Test
    void foldsWhoseLayersInterleaveOrShareOneAreNotNested() {
        List<Bend> bends = List.of(alongX(0, 1, 0, 0, 3), alongX(0, 1, 0, 1, 4), alongX(0, 1, 0, 0, 2));
        assertArrayEquals(new int[] {0, 0, 0}, NestedBends.of(bends, TOLERANCE).ranks());
    }

    @Test
    void foldsWrappedByOneThatStandsOutLessStandOutLessStill() {
        List<Bend> tuck = List.of(alongX(0, 1, 0, 0, 5), alongX(0, 1, 0, 1, 4), alongX(0, 1, 0, 2, 3), alongX(3, 4, 0, 1, 4));
        NestedBends nested = NestedBends.of(tuck, TOLERANCE);
        int[] ranks = nested.ranks();
        assertArrayEquals(new int[] {2, 1, 0, 0}, ranks);
        // The outer one was held to half its two thicknesses; the last is on the line but apart.
        double[] out = {1, 1, 0, 0.5};
        nested.keepNested(out);
        assertArrayEquals(new double[] {1, 0.5, 0, 0.5}, out);
        double[] held = {0, 1, 0, 0.5};
        nested.keepNested(held);
        assertArrayEquals(new double[] {0, 0, 0, 0.5}, held, "the outer on its crease: the inner too");
    }

    @Test
    void aRowThatWouldRunThroughTheWallOfAFoldAtACornerStopsOnIt() {
        // A pentagon's corner, as on the dodecahedron: crease A runs down the y axis to the corner
        // and stands out 0.1 towards +x; the wall W leaves the corner at 54 degrees, into the band
        // A's row stands out over, its layers meeting A's.
        double angle = Math.toRadians(54);
        Bend a = new Bend(0, 0, 1, 0, 0, 1, 0, 0, 5);
        Bend w = new Bend(0, 0, 0, Math.cos(angle), Math.sin(angle), Math.sin(angle), -Math.cos(angle), 1, 9);
        double[] past = NestedBends.of(List.of(a, w), TOLERANCE).mitres(new double[] {0.1, 0});
        // A's row, at x = 0.1, meets W's line at y = 0.1·tan(54°): it stops that far short of the corner.
        assertEquals(-0.1 * Math.tan(angle), past[1], 1e-12);
        assertEquals(0, past[0], "A's other end is free");
        assertEquals(0, past[2] + past[3], "W stands on its crease");
        // W's layers above all of A's: the rows pass each other.
        Bend above = new Bend(0, 0, 0, Math.cos(angle), Math.sin(angle), Math.sin(angle), -Math.cos(angle), 6, 9);
        assertArrayEquals(new double[4], NestedBends.of(List.of(a, above), TOLERANCE).mitres(new double[] {0.1, 0}));
        // The same corner on another host: nothing to meet.
        Bend elsewhere = new Bend(1, 0, 0, Math.cos(angle), Math.sin(angle), Math.sin(angle), -Math.cos(angle), 1, 9);
        assertArrayEquals(new double[4], NestedBends.of(List.of(a, elsewhere), TOLERANCE).mitres(new double[] {0.1, 0}));
    }

    @Test
    void aRowThatComesToAFoldFromItsLayersSideStopsOnItsCrease() {
        // As at a corner of the torus's outer half: B runs along the x axis to the corner and
        // stands out 0.1 towards +y; A leaves the corner at 60 degrees, into B's band, and stands
        // out 0.05 away from B, over the edge beyond it. B's row at y = 0.1 reaches A's crease
        // first, at x = 0.1/tan(60°); run on to A's row it would cross the whole of A's bend.
        double angle = Math.toRadians(60);
        Bend b = new Bend(0, 1, 0, 0, 0, 0, 1, 0, 3);
        Bend a = new Bend(0, 0, 0, Math.cos(angle), Math.sin(angle), -Math.sin(angle), Math.cos(angle), 0, 9);
        NestedBends nested = NestedBends.of(List.of(b, a), TOLERANCE);
        assertArrayEquals(new int[] {0, 0}, nested.ranks(), "check the setup: two lines, nothing nested");
        double[] past = nested.mitres(new double[] {0.1, 0.05});
        assertEquals(-0.1 / Math.tan(angle), past[1], 1e-12);
        assertEquals(0, past[0], "B's other end is free");
        assertArrayEquals(new double[2], new double[] {past[2], past[3]}, "A's band holds no crease: its row runs on square");
    }

    @Test
    void rowsWhoseBandNoCreaseEntersRunOnSquare() {
        // A square's corner: the rows stand out of each other's way.
        Bend a = alongX(0, 1, 0, 0, 5);
        Bend b = new Bend(0, 0, 0, 0, 1, -1, 0, 1, 4);
        assertArrayEquals(new double[4], NestedBends.of(List.of(a, b), TOLERANCE).mitres(new double[] {0.1, 0.1}));
        // A crease leaving A's end at 108 degrees, away from the band below A: A's row runs past
        // that crease's line, but not through its wall.
        double angle = Math.toRadians(108);
        Bend away = new Bend(0, 0, 0, Math.cos(angle), Math.sin(angle), -Math.sin(angle), Math.cos(angle), 1, 9);
        assertArrayEquals(new double[4], NestedBends.of(List.of(a, away), TOLERANCE).mitres(new double[] {0.1, 0}));
    }
}
