package ifold.sheet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The sheet: folds of the tail, folds over an edge, tucks, stacks; every face congruent to its paper. */
class SheetTest {
    private static final double TOLERANCE = 1e-9;

    /** A strip of width 1 along +x on host 0, its start at the origin. */
    private static Sheet strip() {
        return new Sheet(1, 0.01, TOLERANCE, 0, Isometry2.IDENTITY);
    }

    /** Every face's corners, placed, are as far apart as on the sheet. */
    private static void assertCongruent(Sheet sheet) {
        for (int f = 0; f < sheet.faceCount(); f++) {
            int[] loop = sheet.loop(f);
            double[] xy = sheet.placed(f);
            for (int i = 0; i < loop.length; i++) {
                for (int j = i + 1; j < loop.length; j++) {
                    double paper = Math.hypot(sheet.u(loop[i]) - sheet.u(loop[j]), sheet.v(loop[i]) - sheet.v(loop[j]));
                    double placed = Math.hypot(xy[2 * i] - xy[2 * j], xy[2 * i + 1] - xy[2 * j + 1]);
                    assertEquals(paper, placed, 1e-12 * Math.max(1, paper), "face " + f);
                }
            }
        }
    }

    /** No face's edge has another face's vertex inside it: the sheet is conforming. */
    private static void assertConforming(Sheet sheet) {
        for (int f = 0; f < sheet.faceCount(); f++) {
            int[] loop = sheet.loop(f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                int across = sheet.faceAcross(a, b);
                if (across >= 0) {
                    int[] other = sheet.loop(across);
                    boolean twin = false;
                    for (int k = 0; k < other.length; k++) {
                        twin |= other[k] == b && other[(k + 1) % other.length] == a;
                    }
                    assertTrue(twin, "faces " + f + " and " + across + " share edge " + a + "-" + b + " both ways");
                }
            }
        }
    }

    @Test
    void aTurnOfTwo45DegreeFoldsKeepsTheTopSideUpAndLaysThePassesSideBySide() throws FoldException {
        Sheet sheet = strip();
        // Valley along the 45° line from (5, 1) to (6, 0): the tail runs down, back side up.
        int pass = sheet.foldTail(5, 1, 1, -1, Sheet.Placement.OVER, Sheet.Crease.TURN);
        assertTrue(sheet.tailPose().mirrors(), "after one fold the tail shows its back");
        assertEquals(0, sheet.tailPose().dx(1, 0), 1e-15);
        assertEquals(-1, sheet.tailPose().dy(1, 0), 1e-15, "running down");
        // Mountain one width on: back along -x, top side up, in the band [-1, 0].
        int turn = sheet.foldTail(6, 0, -1, -1, Sheet.Placement.UNDER, Sheet.Crease.TURN);
        assertFalse(sheet.tailPose().mirrors(), "after two the top is up again");
        int back = sheet.endTail(0, 0, 0, 1);
        assertEquals(3, sheet.faceCount());
        assertEquals(-1, sheet.pose(back).dx(1, 0), 1e-15, "the second pass runs back");
        double[] xy = sheet.placed(back);
        for (int k = 1; k < xy.length; k += 2) {
            assertTrue(xy[k] <= 1e-12 && xy[k] >= -1 - 1e-12, "the second pass lies in the band [-1, 0]: " + xy[k]);
        }
        assertEquals(0, sheet.level(pass));
        assertEquals(1, sheet.level(turn), "the turn lies over the pass it came from");
        assertEquals(0, sheet.level(back), "the next pass slides under the turn: flat beside the first");
        assertEquals(2, sheet.stackLevels());
        assertEquals(5 + 1 + 6, sheet.length(), 1e-12, "5 along, the turn's two triangles, 6 back");
        assertCongruent(sheet);
        assertConforming(sheet);
    }

    @Test
    void foldsMustFollowOneAnotherAcrossTheStrip() throws FoldException {
        Sheet sheet = strip();
        sheet.foldTail(5, 0, 0, 1, Sheet.Placement.OVER, Sheet.Crease.GADGET);
        // The tail now runs back from x = 5: a crease at x = 6 lies behind it on the strip.
        FoldException behind = assertThrows(FoldException.class,
                () -> sheet.foldTail(6, 0, 0, 1, Sheet.Placement.OVER, Sheet.Crease.GADGET));
        assertTrue(behind.getMessage().contains("crosses the one before"), behind.getMessage());
        FoldException along = assertThrows(FoldException.class,
                () -> sheet.foldTail(0, 0.5, 1, 0, Sheet.Placement.OVER, Sheet.Crease.GADGET));
        assertTrue(along.getMessage().contains("runs along the strip"), along.getMessage());
    }

    @Test
    void aTuckFoldsOnlyThePaperBeyondItsLineUnderTheRest() throws FoldException {
        Sheet sheet = strip();
        int pass = sheet.foldTail(5, 0, 0, 1, Sheet.Placement.OVER, Sheet.Crease.GADGET);
        int back = sheet.endTail(2, 0, 0, 1);
        // Both layers poke beyond x = 4; tuck them under along that line (direction +y: +x is on its right).
        Tuck tuck = sheet.tuck(0, 4, 0, 0, 1);
        assertEquals(2, tuck.changed().length, "both layers were cut");
        assertEquals(2, tuck.moved().length, "and their parts beyond the line moved");
        for (int f = 0; f < sheet.faceCount(); f++) {
            double[] xy = sheet.placed(f);
            for (int k = 0; k < xy.length; k += 2) {
                assertTrue(xy[k] <= 4 + 1e-12, "nothing beyond the tuck line: face " + f + " at x = " + xy[k]);
            }
        }
        // The flap, two layers, turns over as a whole (its order reverses) and goes under, onto the surface.
        int flapTop = -1;
        int flapBottom = Integer.MAX_VALUE;
        for (int f : tuck.moved()) {
            flapTop = Math.max(flapTop, sheet.level(f));
            flapBottom = Math.min(flapBottom, sheet.level(f));
        }
        assertEquals(0, flapBottom);
        assertEquals(1, flapTop);
        assertEquals(2, sheet.level(pass), "the rest rests on the flap");
        assertEquals(3, sheet.level(back), "in the order it had");
        assertCongruent(sheet);
        assertConforming(sheet);
        FoldException nothing = assertThrows(FoldException.class, () -> sheet.tuck(0, 4, 0, 0, 1));
        assertTrue(nothing.getMessage().contains("nothing to tuck"), nothing.getMessage());
    }

    @Test
    void aTuckThatWouldTearTheStripFromTheNextTriangleIsRefused() throws FoldException {
        Sheet sheet = strip();
        // Over an edge at x = 5 onto host 1, whose frame is this one turned a quarter about the edge's foot.
        sheet.crossTail(5, 0, 0, 1, 1, Isometry2.placement(0, 0, Math.PI / 2, false));
        sheet.endTail(0, 8, 1, 0); // in host 1's frame the strip runs along +y from y = 5
        // On host 0, the paper beyond x = 3 is joined to host 1's paper along x = 5, off the line.
        FoldException tear = assertThrows(FoldException.class, () -> sheet.tuck(0, 3, 0, 0, 1));
        assertTrue(tear.getMessage().contains("tear"), tear.getMessage());
    }

    @Test
    void tenThousandFoldsOfTheTailDoNotDrift() throws FoldException {
        Sheet sheet = new Sheet(1, 0.01, 1e-9 * 5e4, 0, Isometry2.IDENTITY);
        double y = 0;
        int d = 1;
        for (int k = 0; k < 5000; k++) {
            double x1 = d > 0 ? 5 : 0;
            sheet.foldTail(x1, y + 1, d, -1, Sheet.Placement.OVER, Sheet.Crease.TURN);
            sheet.foldTail(x1 + d, y, -d, -1, Sheet.Placement.UNDER, Sheet.Crease.TURN);
            y -= 1;
            d = -d;
        }
        Isometry2 pose = sheet.tailPose();
        assertEquals(d, pose.dx(1, 0), 0, "the tail runs exactly along the pass");
        assertEquals(0, pose.dy(1, 0), 0);
        double edge = pose.y(sheet.tailStart(false), 0);
        assertEquals(d > 0 ? y : y + 1, edge, 1e-9, "its edge lies on the band, 5,000 passes on");
        assertEquals(10_000, sheet.faceCount());
        assertEquals(2, sheet.stackLevels(), "every pass on the surface, every turn one layer up");
    }

    @Test
    void isometriesComposeAndInvertExactly() {
        Isometry2 a = Isometry2.placement(3, -2, 0.7, false);
        Isometry2 r = Isometry2.reflection(1, 1, 2, 1);
        Isometry2 composed = r.after(a);
        assertTrue(composed.mirrors());
        Isometry2 back = composed.inverse();
        double u = 1e4 + 0.25;
        double v = 0.5;
        double x = composed.x(u, v);
        double y = composed.y(u, v);
        assertEquals(u, back.x(x, y), 1e-9);
        assertEquals(v, back.y(x, y), 1e-9);
        assertEquals(r.x(a.x(u, v), a.y(u, v)), x, 1e-9);
        Isometry2 anchored = composed.anchoredAt(u, v);
        assertEquals(x, anchored.x(u, v), 0, "the same motion about another anchor");
    }
}
