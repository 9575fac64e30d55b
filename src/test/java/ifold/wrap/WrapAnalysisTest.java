package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

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

    /**
     * Where only the most layers of a whole wrap are wanted, a triangle's buckets that cannot
     * hold as many as found elsewhere are covered, not counted: the area and the area covered
     * stay, the most and its cell stay where the triangle can reach the most found, and where it
     * cannot, it says fewer. Random rectangles and triangles, strewn and piled.
     */
    @Test
    void bucketsThatCannotBeDeepestAreCoveredNotCounted() {
        java.util.Random random = new java.util.Random(7);
        for (int trial = 0; trial < 40; trial++) {
            List<double[]> faces = new ArrayList<>();
            int count = 20 + random.nextInt(200);
            for (int i = 0; i < count; i++) {
                double x = 4 * random.nextDouble();
                double y = 4 * random.nextDouble();
                double w = 0.05 + (random.nextBoolean() ? 3 : 0.5) * random.nextDouble();
                double h = 0.05 + 0.5 * random.nextDouble();
                faces.add(random.nextBoolean() ? new double[] {x, y, x + w, y, x + w, y + h, x, y + h}
                        : new double[] {x, y, x + w, y + h / 3, x + w / 3, y + h});
            }
            double[] exact = FaceArrangement.depths(TRIANGLE, faces, TOLERANCE);
            int most = (int) exact[2];
            for (int elsewhere : new int[] {0, most / 2, most, most + 1, most + 5}) {
                // Each face a level of its own, or faces that do not overlap sharing levels, as a stack's do.
                for (int[] levels : new int[][] {null, levelsApart(faces)}) {
                    java.util.concurrent.atomic.AtomicInteger found = new java.util.concurrent.atomic.AtomicInteger(elsewhere);
                    double[] cells = FaceArrangement.depths(TRIANGLE, faces, levels, TOLERANCE, found);
                    String what = "trial " + trial + ", " + elsewhere + " found elsewhere, levels " + java.util.Arrays.toString(levels);
                    assertEquals(exact[0], cells[0], 1e-9, what);
                    assertEquals(exact[1], cells[1], 1e-9, what);
                    if (elsewhere <= most) {
                        assertEquals(most, (int) cells[2], what);
                        org.junit.jupiter.api.Assertions.assertArrayEquals(java.util.Arrays.copyOfRange(exact, 3, exact.length),
                                java.util.Arrays.copyOfRange(cells, 3, cells.length), what);
                        assertEquals(Math.max(elsewhere, most), found.get(), what);
                    } else {
                        org.junit.jupiter.api.Assertions.assertTrue((int) cells[2] < elsewhere, what);
                        assertEquals(elsewhere, found.get(), what);
                    }
                }
            }
        }
    }

    /** Levels for faces as a stack gives them: each the lowest that no face it overlaps below it has. */
    private static int[] levelsApart(List<double[]> faces) {
        int[] levels = new int[faces.size()];
        for (int i = 0; i < faces.size(); i++) {
            for (int j = 0; j < i; j++) {
                double[] a = faces.get(i);
                double[] b = faces.get(j);
                if (ifold.sheet.Polygons2.overlap(a, a.length / 2, b, b.length / 2, TOLERANCE)) {
                    levels[i] = Math.max(levels[i], levels[j] + 1);
                }
            }
        }
        return levels;
    }

    /**
     * One triangle of paper a width w = 0.001 across and 2e-6 long (a sliver), laid at u along the
     * strip with one corner {@code off} out of place in space.
     */
    private static double[] isometryErrors(double u, double off) {
        double w = 1e-3;
        double[] uv = {u, 0, u + 2e-6, 0, u, w};
        double[] xyz = {0, 0, 0, 2e-6 + off, 0, 0, 0, w, 0};
        PaperInSpace geometry = new PaperInSpace(xyz, uv, List.of(new int[] {0, 1, 2}), new int[1], List.of(), new int[0]);
        return WrapAnalysis.isometryErrors(geometry, w, 0, 1);
    }

    @Test
    void farAlongAStripThePosesDriftIsNoStretch() {
        // 1.3e-11 off at u = 787 (as on CGAL's elephant, a strip 0.00106 wide): 1.3e-8 of the
        // width, but under the drift the sheet itself allows there (1e-12 u = 7.9e-10).
        double[] far = isometryErrors(787, 1.3e-11);
        assertEquals(1.3e-8, far[0], 1e-10);
        assertTrue(far[1] < 1, "within the poses' drift: " + far[1]);
        // The same at the strip's start is stretched: 1.3e-11 against 1e-9 of the width, 1e-12.
        assertTrue(isometryErrors(0, 1.3e-11)[1] > 1);
        // And far along, a corner 1e-8 out is more than any drift: stretched.
        assertTrue(isometryErrors(787, 1e-8)[1] > 1);
    }
}
