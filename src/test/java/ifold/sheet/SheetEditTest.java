package ifold.sheet;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Set;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * Edits of laid paper ({@link SheetEdit}), as fold scripts make them: cuts along a line of a
 * host or of the sheet, journaled; moves that fold paper over or under; and the stack's order
 * when a move takes away the face that lay between two others.
 */
class SheetEditTest {
    private static final double T = 0.01;

    /** A sheet 3 × 1 flat on host 0, its paper coordinates its host's. */
    private static Sheet strip() {
        return Sheet.rectangle(3, 1, T, 1e-9, 0, Isometry2.IDENTITY);
    }

    private static Set<Integer> set(int... faces) {
        return Arrays.stream(faces).boxed().collect(Collectors.toSet());
    }

    /** The smallest and largest x of face f as placed. */
    private static double[] xRange(Sheet sheet, int f) {
        double[] xy = sheet.placed(f);
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < xy.length; k += 2) {
            min = Math.min(min, xy[k]);
            max = Math.max(max, xy[k]);
        }
        return new double[] {min, max};
    }

    @Test
    void aCutOnAHostSplitsTheFacesItCrossesAndJournalsThem() {
        Sheet sheet = strip();
        SheetEdit edit = sheet.edit();
        // The line x = 2, upwards: the paper on its right (x > 2) is beyond it.
        int[] beyond = edit.cutOnHost(0, 2, 0, 0, 1);
        assertArrayEquals(new int[] {1}, beyond, "the one face cut, its far part a new face");
        assertEquals(2, sheet.faceCount());
        assertArrayEquals(new double[] {0, 2}, xRange(sheet, 0), 1e-12);
        assertArrayEquals(new double[] {2, 3}, xRange(sheet, 1), 1e-12);
        SheetEdit.Journal journal = edit.journal();
        assertEquals(1, journal.facesBefore());
        assertArrayEquals(new int[] {0}, journal.changed(), "the face there before that the cut changed");
        assertEquals(4, journal.loopsBefore()[0].length, "its loop before: the whole sheet");
        assertEquals(0, journal.parentOf(1), "the new face was cut from face 0");
        assertEquals(0, journal.parentOf(0));
        // The two faces share the cut as an edge of both, its new vertices theirs alike.
        int[] left = sheet.loop(0);
        boolean shared = false;
        for (int i = 0; i < left.length; i++) {
            shared |= sheet.faceAcross(left[i], left[(i + 1) % left.length]) == 1;
        }
        assertTrue(shared, "face 1 lies across an edge of face 0");
    }

    @Test
    void aCutThatCrossesNothingChangesNothing() {
        Sheet sheet = strip();
        SheetEdit edit = sheet.edit();
        assertArrayEquals(new int[] {}, edit.cutOnHost(0, 5, 0, 0, 1), "nothing lies beyond x = 5");
        assertArrayEquals(new int[] {0}, edit.cutOnHost(0, -1, 0, 0, 1), "all of it lies beyond x = -1, uncut");
        assertEquals(1, sheet.faceCount());
        assertArrayEquals(new int[] {0}, edit.journal().changed(), "looked at, not cut");
    }

    @Test
    void aMoveFoldsThePaperOverAndTheCreaseIsMarked() {
        Sheet sheet = strip();
        SheetEdit edit = sheet.edit();
        int[] beyond = edit.cutOnHost(0, 2, 0, 0, 1);
        edit.crease(set(beyond), Sheet.Crease.FOLD);
        edit.move(set(beyond), 0, Isometry2.reflection(2, 0, 0, 1), Sheet.Placement.OVER);
        assertArrayEquals(new double[] {1, 2}, xRange(sheet, 1), 1e-12, "reflected over x = 2 onto [1, 2]");
        assertEquals(0, sheet.level(0));
        assertEquals(1, sheet.level(1), "over the paper it lands on");
        int[] loop = sheet.loop(1);
        int creased = 0;
        for (int i = 0; i < loop.length; i++) {
            creased += sheet.crease(loop[i], loop[(i + 1) % loop.length]) == Sheet.Crease.FOLD ? 1 : 0;
        }
        assertEquals(1, creased, "one edge of the flap is the fold's crease");
    }

    @Test
    void aMoveUnderLandsBelow() {
        Sheet sheet = strip();
        SheetEdit edit = sheet.edit();
        int[] beyond = edit.cutOnHost(0, 2, 0, 0, 1);
        edit.move(set(beyond), 0, Isometry2.reflection(2, 0, 0, 1), Sheet.Placement.UNDER);
        assertEquals(1, sheet.level(0));
        assertEquals(0, sheet.level(1));
    }

    /**
     * A Z of three layers: A at the bottom, B, then C. C over A is implied by B, which lies
     * between and holds all of where they overlap, so it is not recorded; when a cut along the
     * sheet takes B away, the order of A and C must be recorded, or C would fall to A's level.
     */
    @Test
    void takingAwayTheFaceBetweenTwoKeepsTheirOrder() {
        Sheet sheet = strip();
        SheetEdit first = sheet.edit();
        int[] end = first.cutOnHost(0, 2, 0, 0, 1); // [2, 3] onto [1, 2], over
        first.move(set(end), 0, Isometry2.reflection(2, 0, 0, 1), Sheet.Placement.OVER);
        SheetEdit second = sheet.edit();
        int[] folded = second.cutOnHost(0, 1, 0, 0, 1); // both layers on [1, 2] onto [0, 1], over
        second.move(set(folded), 0, Isometry2.reflection(1, 0, 0, 1), Sheet.Placement.OVER);
        // Faces by their paper: A = u in [0, 1], B = [2, 3], C = [1, 2].
        int a = faceAt(sheet, 0.5);
        int b = faceAt(sheet, 2.5);
        int c = faceAt(sheet, 1.5);
        assertEquals(0, sheet.level(a));
        assertEquals(1, sheet.level(b));
        assertEquals(2, sheet.level(c));
        int relations = sheet.orderRelations();
        assertEquals(2, relations, "A < B and B < C; A < C is implied, not recorded");
        // Cut along the sheet at u = 2, the crease between B and C, and take B to another host.
        SheetEdit away = sheet.edit();
        int[] taken = away.cutOnSheet(2, 0, 2, 1);
        assertArrayEquals(new int[] {b}, taken);
        away.move(set(taken), 1, Isometry2.IDENTITY, Sheet.Placement.OVER);
        assertEquals(0, sheet.level(a));
        assertEquals(1, sheet.level(c), "C still lies over A");
        assertEquals(0, sheet.level(b), "alone on its new host");
        assertTrue(sheet.facesOn(0).length == 2 && sheet.facesOn(1).length == 1);
    }

    private static int faceAt(Sheet sheet, double u) {
        for (int f = 0; f < sheet.faceCount(); f++) {
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int p : sheet.loop(f)) {
                min = Math.min(min, sheet.u(p));
                max = Math.max(max, sheet.u(p));
            }
            if (u > min && u < max) {
                return f;
            }
        }
        throw new AssertionError("no face at u = " + u);
    }
}
