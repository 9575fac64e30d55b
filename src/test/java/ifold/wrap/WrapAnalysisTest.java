package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The layers counted on a triangle's arrangement of faces, against answers known by hand. */
class WrapAnalysisTest {
    private static final double[] TRIANGLE = {0, 0, 4, 0, 0, 4};
    private static final double TOLERANCE = 1e-9;

    private static double[] square(double x, double y, double side) {
        return new double[] {x, y, x + side, y, x + side, y + side, x, y + side};
    }

    @Test
    void countsTheMostFacesOverAPoint() {
        // Squares of side 1 at (0.5, 0.5) and (1, 1) overlap in [1, 1.5]², a square of side 0.8
        // at (2.2, 0.1) lies apart: 2 at most, over 1 + 1 - 0.25 + 0.64 of the triangle's 8.
        List<double[]> faces = List.of(square(0.5, 0.5, 1), square(1, 1, 1), square(2.2, 0.1, 0.8));
        double[] cells = FaceArrangement.depths(TRIANGLE, faces, TOLERANCE);
        assertEquals(8, cells[0], 1e-12);
        assertEquals(2.39, cells[1], 1e-12);
        assertEquals(2, (int) cells[2]);
        // The deepest point: the centre of the overlap, the largest cell of two layers.
        assertEquals(1.25, cells[3], 1e-12);
        assertEquals(1.25, cells[4], 1e-12);
    }

    @Test
    void aPileOfManyFacesIsCountedWholeWhateverTheGrid() {
        // 40 strips laid side by side across the triangle, then 7 of the same squares on top:
        // 8 over the squares, whatever buckets the faces fall into.
        List<double[]> faces = new ArrayList<>();
        for (int i = 0; i < 40; i++) {
            faces.add(new double[] {0, 0.05 * i, 3, 0.05 * i, 3, 0.05 * (i + 1), 0, 0.05 * (i + 1)});
        }
        for (int k = 0; k < 7; k++) {
            faces.add(square(0.3, 0.3, 0.5));
        }
        assertEquals(8, (int) FaceArrangement.depths(TRIANGLE, faces, TOLERANCE)[2]);
    }

    /**
     * A face no wider than the tolerance covers nothing: before, its edges, all too short to
     * cut a cell, cut none, and every cell its box met was counted under it (the cube at width
     * 1e-3 showed 21 layers where 20 lie over the deepest point).
     */
    @Test
    void aFaceThinnerThanTheToleranceAddsNoLayer() {
        List<double[]> faces = List.of(square(0.5, 0.5, 1), square(1, 1, 1), square(1.2, 1.2, 1e-13),
                new double[] {1.1, 1.1, 1.9, 1.9, 1.9, 1.9 + 1e-13});
        assertEquals(2, (int) FaceArrangement.depths(TRIANGLE, faces, TOLERANCE)[2]);
    }
}
