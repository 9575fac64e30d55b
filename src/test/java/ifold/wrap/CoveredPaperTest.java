package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.sheet.HostFrame;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Which paper lies under other paper of its host, on layouts whose answer is known. */
class CoveredPaperTest {
    private static final double T = 0.01;
    private static final HostFrame[] PLANE = {HostFrame.onEdge(new double[] {0, 0, 0}, new double[] {1, 0, 0}, new double[] {0, 1, 0})};

    /** Faces on the plane z = 0 (one host), each a rectangle at a level, and caps. */
    private static final class Layout {
        final List<double[]> points = new ArrayList<>();
        final List<int[]> faces = new ArrayList<>();
        final List<int[]> caps = new ArrayList<>();
        final List<Integer> capAfter = new ArrayList<>();

        int vertex(double x, double y, double z) {
            points.add(new double[] {x, y, z});
            return points.size() - 1;
        }

        /** A rectangle at {@code level}, counter-clockwise seen from above (its top side out) unless {@code flipped}. */
        int rectangle(double x0, double y0, double x1, double y1, int level, boolean flipped) {
            double z = (level + 0.5) * T;
            int a = vertex(x0, y0, z);
            int b = vertex(x1, y0, z);
            int c = vertex(x1, y1, z);
            int d = vertex(x0, y1, z);
            faces.add(flipped ? new int[] {a, d, c, b} : new int[] {a, b, c, d});
            return faces.size() - 1;
        }

        /** A fold's cap along x = x0 from y0 to y1 joining levels {@code low} and {@code high}, bulging to x0 + half the gap. */
        void cap(double x0, double y0, double y1, int low, int high, int after) {
            double zl = (low + 0.5) * T;
            double zh = (high + 0.5) * T;
            double bulge = x0 + (zh - zl) / 2;
            int la = vertex(x0, y0, zl);
            int lb = vertex(x0, y1, zl);
            int ma = vertex(bulge, y0, (zl + zh) / 2);
            int mb = vertex(bulge, y1, (zl + zh) / 2);
            int ha = vertex(x0, y0, zh);
            int hb = vertex(x0, y1, zh);
            caps.add(new int[] {la, lb, mb, ma});
            caps.add(new int[] {ma, mb, hb, ha});
            capAfter.add(after);
            capAfter.add(after);
        }

        CoveredPaper.Covered covered(double thickness) {
            return covered(thickness, false);
        }

        CoveredPaper.Covered covered(double thickness, boolean bothSides) {
            double[] xyz = new double[3 * points.size()];
            for (int i = 0; i < points.size(); i++) {
                System.arraycopy(points.get(i), 0, xyz, 3 * i, 3);
            }
            PaperInSpace geometry = new PaperInSpace(xyz, new double[2 * points.size()], faces, new int[faces.size()], caps,
                    capAfter.stream().mapToInt(Integer::intValue).toArray());
            return CoveredPaper.of(geometry, PLANE, thickness, bothSides);
        }
    }

    @Test
    void aFaceUnderABiggerOneIsCoveredAndTheTopOneIsNot() {
        Layout layout = new Layout();
        int under = layout.rectangle(0.2, 0.2, 0.8, 0.8, 0, false);
        int over = layout.rectangle(0, 0, 1, 1, 3, false);
        CoveredPaper.Covered covered = layout.covered(T);
        assertTrue(covered.face(under));
        assertFalse(covered.face(over));
        assertEquals(over, covered.faceCover()[under], "covered once the face over it is laid");
    }

    @Test
    void aFaceIsCoveredWhenTheLastOfThoseThatCoverItIsLaid() {
        Layout layout = new Layout();
        layout.rectangle(0, 0, 0.5, 1, 2, false); // face 0: half of what covers it, laid before it
        int under = layout.rectangle(0.1, 0.1, 0.9, 0.9, 0, false);
        int unrelated = layout.rectangle(3, 3, 4, 4, 5, false);
        int second = layout.rectangle(0.5, 0, 1, 1, 4, false);
        layout.rectangle(0, 0, 1, 1, 6, false); // laid last, it would cover alone, but the two did first
        CoveredPaper.Covered covered = layout.covered(T);
        assertEquals(second, covered.faceCover()[under]);
        assertEquals(-1, covered.faceCover()[unrelated]);
    }

    @Test
    void aFaceHalfCoveredIsSeenAndSoIsOneOnTheSameLayer() {
        Layout layout = new Layout();
        int half = layout.rectangle(0, 0, 1, 1, 0, false);
        layout.rectangle(0, 0, 0.5, 1, 1, false);
        int beside = layout.rectangle(0.2, 0.2, 0.4, 0.4, 1, false);
        layout.rectangle(0, 0, 1, 1, 1, false); // the same layer as `beside`: not above it
        CoveredPaper.Covered covered = layout.covered(T);
        assertFalse(covered.face(beside), "paper on the same layer does not cover");
        assertTrue(covered.face(half), "the whole of it lies under the two at level 1 together");
        Layout open = new Layout();
        int seen = open.rectangle(0, 0, 1, 1, 0, false);
        open.rectangle(0, 0, 0.5, 1, 1, false);
        assertFalse(open.covered(T).face(seen), "half of it is in the open");
    }

    @Test
    void twoFacesMeetingAlongALineCoverWhatLiesUnderBoth() {
        Layout layout = new Layout();
        int under = layout.rectangle(0.1, 0.1, 0.9, 0.9, 0, false);
        layout.rectangle(0, 0, 0.5, 1, 2, false);
        layout.rectangle(0.5, 0, 1, 1, 4, true);
        CoveredPaper.Covered covered = layout.covered(T);
        assertTrue(covered.face(under));
        // A gap between them, narrow but real, leaves it seen.
        Layout gap = new Layout();
        int seen = gap.rectangle(0.1, 0.1, 0.9, 0.9, 0, false);
        gap.rectangle(0, 0, 0.49, 1, 2, false);
        gap.rectangle(0.5, 0, 1, 1, 2, false);
        assertFalse(gap.covered(T).face(seen));
    }

    @Test
    void theSideOutAndTheAreaOfEachFace() {
        Layout layout = new Layout();
        int up = layout.rectangle(0, 0, 1, 0.5, 0, false);
        int down = layout.rectangle(0, 0, 0.25, 1, 1, true);
        CoveredPaper.Covered covered = layout.covered(T);
        assertFalse(covered.undersideOut().get(up));
        assertTrue(covered.undersideOut().get(down), "its loop runs clockwise seen from outside: its underside is out");
        assertEquals(0.5, covered.areas()[up], 1e-12);
        assertEquals(0.25, covered.areas()[down], 1e-12);
    }

    @Test
    void aCapIsCoveredWherePaperAboveItsTopHidesItsFootprint() {
        Layout layout = new Layout();
        int low = layout.rectangle(0.2, 0.2, 0.5, 0.8, 0, false);
        int high = layout.rectangle(0.2, 0.2, 0.5, 0.8, 2, false);
        layout.cap(0.5, 0.2, 0.8, 0, 2, high);
        layout.rectangle(0, 0, 1, 1, 5, false);
        CoveredPaper.Covered covered = layout.covered(T);
        assertTrue(covered.face(low) && covered.face(high));
        assertTrue(covered.cap(0) && covered.cap(1), "both facets lie under level 5");
        Layout bare = new Layout();
        bare.rectangle(0.2, 0.2, 0.5, 0.8, 0, false);
        int top = bare.rectangle(0.2, 0.2, 0.5, 0.8, 2, false);
        bare.cap(0.5, 0.2, 0.8, 0, 2, top);
        bare.rectangle(0, 0, 0.5, 1, 5, false); // ends at the crease: the bulge beyond it is seen
        CoveredPaper.Covered seen = bare.covered(T);
        assertFalse(seen.cap(0) || seen.cap(1));
    }

    /**
     * An open surface is seen from below too (the zig-zag demo's lone triangle): a flap tucked
     * under the strip, lower than the paper over it, is seen from below, not covered (the demo's
     * underside showed all of one colour, its tucks hidden); paper under both higher and lower
     * paper is covered from the moment the later of them is laid, and a cap likewise.
     */
    @Test
    void seenFromBothSidesPaperIsCoveredOnlyFromBoth() {
        Layout layout = new Layout();
        int flap = layout.rectangle(0.2, 0.2, 0.8, 0.8, 0, true);
        int strip = layout.rectangle(0, 0, 1, 1, 2, false);
        assertTrue(layout.covered(T).face(flap), "setup: on a solid the strip hides the flap");
        CoveredPaper.Covered both = layout.covered(T, true);
        assertFalse(both.face(flap), "the flap under the strip is seen from below");
        assertFalse(both.face(strip));
        Layout between = new Layout();
        int below = between.rectangle(0, 0, 1, 1, 0, false);
        int middle = between.rectangle(0.2, 0.2, 0.5, 0.8, 2, false);
        int top = between.rectangle(0.2, 0.2, 0.5, 0.8, 4, false);
        between.cap(0.5, 0.2, 0.8, 2, 4, top);
        int over = between.rectangle(0, 0, 1, 1, 7, false);
        CoveredPaper.Covered hidden = between.covered(T, true);
        assertEquals(top, hidden.faceCover()[middle], "hidden from above by the face laid over it, from below by the first");
        assertEquals(over, hidden.faceCover()[top]);
        assertTrue(hidden.cap(0) && hidden.cap(1), "the cap between them is hidden from both sides");
        assertFalse(hidden.face(below) || hidden.face(over), "the outermost paper on each side is seen");
        Layout tuckedLast = new Layout();
        tuckedLast.rectangle(0, 0, 1, 1, 4, false);
        int lying = tuckedLast.rectangle(0.2, 0.2, 0.8, 0.8, 2, false);
        int lastFlap = tuckedLast.rectangle(0, 0, 1, 1, 0, true); // tucked under both, laid last
        assertEquals(lastFlap, tuckedLast.covered(T, true).faceCover()[lying], "hidden once the flap under it is laid, not before");
    }

    @Test
    void withoutThicknessNothingLiesAboveAnything() {
        Layout layout = new Layout();
        layout.rectangle(0.2, 0.2, 0.8, 0.8, 0, false);
        layout.rectangle(0, 0, 1, 1, 3, false);
        CoveredPaper.Covered covered = layout.covered(0);
        assertFalse(covered.face(0) || covered.face(1));
    }
}
