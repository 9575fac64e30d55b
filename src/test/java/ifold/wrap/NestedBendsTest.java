package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import ifold.sheet.HostFrame;
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
    void aRowThatWouldRunThroughAWallNearlyInLineStopsOnItFarFromTheCorner() {
        // As at a random frustum's side face: wall W runs up the y axis from the corner, standing
        // on its crease, levels 1 to 18; B leaves the corner 7.6 degrees off W, levels 1 to 4,
        // and stands out 0.1 towards W. B's row meets W's line 0.1 / tan(7.6°) = 0.75 from the
        // corner, 7.5 times as far as it stands out (held to 4 times, the row ran on square
        // through W: 5 crossing pairs of caps, 0.99 T deep).
        double angle = Math.toRadians(7.6);
        Bend w = new Bend(0, 0, 0, 0, 2, 1, 0, 1, 18);
        Bend b = new Bend(0, -2 * Math.sin(angle), 2 * Math.cos(angle), 0, 0, Math.cos(angle), Math.sin(angle), 1, 4);
        double[] past = NestedBends.of(List.of(w, b), TOLERANCE).mitres(new double[] {0, 0.1});
        assertEquals(-0.1 / Math.tan(angle), past[3], 1e-12);
        assertEquals(0, past[2], "B's other end is free");
        // Nearly in line (within asin 0.1, 5.7 degrees), the corner is left square.
        double inLine = Math.toRadians(5);
        Bend near = new Bend(0, -2 * Math.sin(inLine), 2 * Math.cos(inLine), 0, 0, Math.cos(inLine), Math.sin(inLine), 1, 4);
        assertArrayEquals(new double[4], NestedBends.of(List.of(w, near), TOLERANCE).mitres(new double[] {0, 0.1}));
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
    void rowsOfCoplanarHostsMeetingAtAReflexCornerOfTheirFaceStopOnEachOther() {
        // An L-shaped face cut into two convex hosts whose frames are turned a quarter apart, its
        // reflex corner at (1, 1). Host 0 (the plane's frame) has A along y = 1, from x = 2 to the
        // corner, standing out towards +y; host 1 (origin (5, 5), x axis along +y) has B along
        // x = 1, from y = 2 to the corner, standing out towards +x: into the same notch.
        HostFrame plane = frame(new double[] {0, 0, 0}, new double[] {1, 0, 0}, new double[] {0, 1, 0});
        HostFrame turned = frame(new double[] {5, 5, 0}, new double[] {0, 1, 0}, new double[] {-1, 0, 0});
        Bend a = new Bend(0, 2, 1, 1, 1, 0, 1, 6, 12);
        Bend b = new Bend(1, -3, 4, -4, 4, 0, -1, 6, 12);
        NestedBends nested = NestedBends.of(List.of(a, b), TOLERANCE);
        double[] out = {0.1, 0.1};
        assertArrayEquals(new double[4], nested.mitres(out), "check the setup: host by host, nothing meets");
        // In the plane's frame the rows stop on each other, a picture frame's corner.
        assertArrayEquals(new double[] {0, -0.1, 0, -0.1}, nested.mitres(out, CoplanarHosts.of(new HostFrame[] {plane, turned}, 1e-9)),
                1e-12);
        // The same host 1 a little above the plane: another plane, nothing to meet.
        HostFrame above = frame(new double[] {5, 5, 0.01}, new double[] {0, 1, 0}, new double[] {-1, 0, 0});
        assertArrayEquals(new double[4], nested.mitres(out, CoplanarHosts.of(new HostFrame[] {plane, above}, 1e-9)));
    }

    /** A frame in space with a unit square for its polygon, its normal ex × ey. */
    private static HostFrame frame(double[] origin, double[] ex, double[] ey) {
        double[] normal = {ex[1] * ey[2] - ex[2] * ey[1], ex[2] * ey[0] - ex[0] * ey[2], ex[0] * ey[1] - ex[1] * ey[0]};
        return new HostFrame(origin, ex, ey, normal, new double[] {0, 0, 1, 0, 1, 1, 0, 1});
    }

    @Test
    void aCreaseSquareToTheRowsToRoundingEntersItsBand() {
        // As at the L's reflex corner: B leaves A's end square to A but for 1e-13 radians of
        // rounding, turned away from A's band, and stands out towards A's row.
        Bend a = new Bend(0, 1, 0, 0, 0, 0, 1, 6, 12);
        double off = 1e-13;
        Bend b = new Bend(0, -Math.sin(off), Math.cos(off), 0, 0, Math.cos(off), Math.sin(off), 6, 12);
        double[] past = NestedBends.of(List.of(a, b), TOLERANCE).mitres(new double[] {0.1, 0.1});
        assertEquals(-0.1, past[1], 1e-12);
        assertEquals(-0.1, past[3], 1e-12);
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
