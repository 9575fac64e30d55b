package ifold.print;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Crease numbers beside their creases, none over another. */
class NumberPlacesTest {
    private static final double SIZE = 2.4;

    /** The box "30" or "59" takes with its baseline starting at p: x0, y0 (top), x1, y1. */
    private static double[] box(double[] p, String text) {
        return new double[] {p[0], p[1] - 0.72 * SIZE, p[0] + 0.56 * SIZE * text.length(), p[1]};
    }

    private static boolean overlap(double[] a, double[] b) {
        return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
    }

    /** A lone number goes beside its crease's middle, clear of it: to the right of a crease drawn down, above one drawn across. */
    @Test
    void aLoneNumberGoesBesideTheMiddleOfItsCreaseClearOfIt() {
        NumberPlaces places = new NumberPlaces(0, 0, 100, 20, SIZE);
        // "19" is 2.688 wide and 1.728 high: centred 0.4 beyond its half width right of x = 50.
        assertArrayEquals(new double[] {50.4, 10.864}, places.place("19", 50, 0, 50, 20), 1e-12);
        assertArrayEquals(new double[] {19.328, 14.6}, places.place("7", 10, 15, 30, 15), 1e-12);
        // Across a slanted crease, its nearest corner clears the line.
        double[] at = places.place("42", 60, 20, 80, 0);
        double[] box = box(at, "42");
        for (double[] corner : new double[][] {{box[0], box[1]}, {box[2], box[1]}, {box[0], box[3]}, {box[2], box[3]}}) {
            double across = ((corner[0] - 60) * -20 - (corner[1] - 20) * 20) / Math.hypot(20, 20);
            assertTrue(Math.abs(across) >= 0.4 - 1e-9, "a corner " + Math.abs(across) + " from the crease");
        }
    }

    /** Two creases side by side, or crossing at their middles: two numbers apart, both by their creases and in the piece. */
    @Test
    void numbersOfCreasesThatMeetDoNotOverlap() {
        NumberPlaces places = new NumberPlaces(0, 0, 100, 20, SIZE);
        double[] a = places.place("30", 10, 0, 20, 20);
        double[] b = places.place("59", 10.5, 0, 20.5, 20);
        double[] c = places.place("60", 20, 0, 10, 20);
        double[][] boxes = {box(a, "30"), box(b, "59"), box(c, "60")};
        for (int i = 0; i < 3; i++) {
            for (int j = i + 1; j < 3; j++) {
                assertTrue(!overlap(boxes[i], boxes[j]), i + " and " + j);
            }
            assertTrue(boxes[i][0] >= 0 && boxes[i][2] <= 100 && boxes[i][1] >= 0 && boxes[i][3] <= 20, "in the piece: " + i);
        }
        // Each still beside its own crease: within a number's width of it.
        assertTrue(Math.abs(a[0] - (10 + (20 - a[1]) / 20 * 10)) < 5);
    }

    /** Where there is no room, the number still goes by its crease's middle, inside the piece: crowded, not lost, nor on a glue tab. */
    @Test
    void aNumberWithNoRoomStillGoesByItsCreaseInsideThePiece() {
        NumberPlaces places = new NumberPlaces(0, 0, 2.4, 4, SIZE);
        double[] first = places.place("1", 1.2, 0, 1.2, 4);
        double[] second = places.place("2", 1.2, 0, 1.2, 4);
        for (double[] at : new double[][] {first, second}) {
            double[] box = box(at, "1");
            assertTrue(box[0] >= -1e-12 && box[2] <= 2.4 + 1e-12 && box[1] >= -1e-12 && box[3] <= 4 + 1e-12, java.util.Arrays.toString(box));
        }
    }
}
