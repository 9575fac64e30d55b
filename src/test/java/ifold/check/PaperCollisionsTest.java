package ifold.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.check.PaperCollisions.Crossing;
import ifold.check.PaperCollisions.Kind;
import ifold.check.PaperCollisions.Point;
import ifold.check.PaperCollisions.Result;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The collision checker on small folded sheets written inline, each with an answer known by hand. */
class PaperCollisionsTest {
    /** The thickness of every sheet here: the touching distance is then 1e-5. */
    private static final double T = 0.01;

    /** The unit cube [0, 1]^3 as 12 triangles, outward; its top z = 1 cut along the diagonal y = x. */
    private static final double[] CUBE = {
        0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 1, 1, 0,
        0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 1, 1,
        0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1,
        0, 1, 0, 1, 1, 1, 1, 1, 0, 0, 1, 0, 0, 1, 1, 1, 1, 1,
        0, 0, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 1, 0,
        1, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 1};

    private static Result check(String obj) {
        return PaperCollisions.check(obj, T);
    }

    private static void assertClean(Result result) {
        assertTrue(result.isClean(), result::summary);
        assertEquals(0, result.crossingPairs());
        assertEquals(0, result.coplanarPairs());
        assertNull(result.deepest());
    }

    private static void assertPoint(double x, double y, double z, Point p, double tolerance) {
        assertEquals(x, p.x(), tolerance, () -> "x of " + p);
        assertEquals(y, p.y(), tolerance, () -> "y of " + p);
        assertEquals(z, p.z(), tolerance, () -> "z of " + p);
    }

    /** The segment's ends are a and b, in either order. */
    private static void assertSegment(double[] a, double[] b, Crossing c, double tolerance) {
        boolean forward = Math.abs(c.from().x() - a[0]) + Math.abs(c.from().y() - a[1]) + Math.abs(c.from().z() - a[2])
                <= Math.abs(c.from().x() - b[0]) + Math.abs(c.from().y() - b[1]) + Math.abs(c.from().z() - b[2]);
        double[] from = forward ? a : b;
        double[] to = forward ? b : a;
        assertPoint(from[0], from[1], from[2], c.from(), tolerance);
        assertPoint(to[0], to[1], to[2], c.to(), tolerance);
    }

    @Test
    void twoParallelSheetsOneThicknessApartDoNotCross() {
        Result result = check("""
                o strip-1
                v 0 0 0
                v 1 0 0
                v 1 1 0
                v 0 1 0
                v 0 0 0.01
                v 1 0 0.01
                v 1 1 0.01
                v 0 1 0.01
                g paper
                f 1 2 3 4
                f 5 6 7 8
                """);
        assertEquals(2, result.faces(), "setup: two quads");
        assertEquals(4, result.triangles(), "setup: fanned into two triangles each");
        assertClean(result);
        assertEquals("collisions: 0 crossing pairs (0 with caps), 0 pairs overlapping in one plane, 0 paper-model crossings, 0 paper points inside the solid", result.summary());
    }

    /**
     * An X: a small sheet tilted 30 degrees through a big flat one. Its two lower corners lie
     * 0.05 = 5 T below the flat sheet, its upper one 0.1 above, and the flat sheet's corners are
     * far from the small one's plane: 5 T deep, along the segment where z = 0 cuts it, a third
     * of the way up: x in [-1/15, 1/15].
     */
    @Test
    void sheetsCrossedInAnXCrossOnceAsDeepAsTheNearerCorners() {
        String x = """
                o strip-1
                v -3 -3 0
                v 3 -3 0
                v 0 3 0
                v -0.1 -0.08660254037844387 -0.05
                v 0.1 -0.08660254037844387 -0.05
                v 0 0.17320508075688773 0.1
                g paper
                f 1 2 3
                f 4 5 6
                """;
        Result result = check(x);
        assertEquals(1, result.crossingPairs(), result::summary);
        assertEquals(1, result.facePairs());
        assertEquals(0, result.capPairs());
        Crossing c = result.deepest();
        assertEquals(Kind.PAPER, c.kind());
        assertEquals(1, c.faceA());
        assertEquals(2, c.faceB());
        assertEquals(5, c.depth(), 1e-9);
        assertSegment(new double[] {-1.0 / 15, 0, 0}, new double[] {1.0 / 15, 0, 0}, c, 1e-12);
        assertEquals(String.format(Locale.ROOT, "collisions: 1 crossing pair (0 with caps), deepest %.4g T (faces 1 and 2), 0 pairs overlapping in one plane, "
                + "0 paper-model crossings, 0 paper points inside the solid", 5.0), result.summary());
        assertEquals(result.crossings(), java.util.List.of(c), "the list holds the one crossing");
        // Far from the origin the same, to rounding of the coordinates' size.
        Result far = check(x.replace("v -3 -3 0", "v 997 997 1000").replace("v 3 -3 0", "v 1003 997 1000").replace("v 0 3 0", "v 1000 1003 1000")
                .replace("v -0.1 -0.08660254037844387 -0.05", "v 999.9 999.9133974596216 999.95")
                .replace("v 0.1 -0.08660254037844387 -0.05", "v 1000.1 999.9133974596216 999.95")
                .replace("v 0 0.17320508075688773 0.1", "v 1000 1000.1732050807569 1000.1"));
        assertEquals(1, far.crossingPairs());
        assertEquals(5, far.deepest().depth(), 1e-6);
    }

    /** The same X, but the small sheet's lower corners only reach 1e-3 T below (0.9e-3 T: touching) or 2e-3 T below (crossing). */
    @ParameterizedTest
    @ValueSource(doubles = {0.9e-3, 2e-3})
    void aCrossingCountsOnlyDeeperThanTheTouchingDistance(double reach) {
        double z = -reach * T;
        Result result = check("o strip-1\nv -3 -3 0\nv 3 -3 0\nv 0 3 0\n"
                + "v -0.1 0 " + z + "\nv 0.1 0 " + z + "\nv 0 0.1 0.1\ng paper\nf 1 2 3\nf 4 5 6\n");
        if (reach < PaperCollisions.TOUCH) {
            assertClean(result);
        } else {
            assertEquals(1, result.crossingPairs(), result::summary);
            assertEquals(reach, result.deepest().depth(), 1e-9);
        }
    }

    /**
     * A strip z-folded flat: three layers 0, T and 2T up, each fold bent round by a cap of two
     * 45-degree facets (as PaperInSpace makes them) half a thickness beyond the crease. Every
     * face meets its neighbours only at shared edges: nothing crosses.
     */
    private static final String Z_FOLD = """
            # three layers of a strip, x in [0.2, 1], two caps
            o strip-1
            v 0 0 0
            v 1 0 0
            v 1 1 0
            v 0 1 0
            v 1.005 0 0.005
            v 1.005 1 0.005
            v 1 0 0.01
            v 1 1 0.01
            v 0.2 1 0.01
            v 0.2 0 0.01
            v 0.195 0 0.015
            v 0.195 1 0.015
            v 0.2 0 0.02
            v 0.2 1 0.02
            v 1 1 0.02
            v 1 0 0.02
            g paper
            f 1/1 2/2 3/3 4/4
            f 7/7 8/8 9/9 10/10
            f 13/13 16/16 15/15 14/14
            g cap
            f 2/2 5/5 6/6 3/3
            f 5/5 7/7 8/8 6/6
            f 10/10 11/11 12/12 9/9
            f 11/11 13/13 14/14 12/12
            """;

    @Test
    void aZFoldWithItsCapsStackedDoesNotCross() {
        Result result = check(Z_FOLD);
        assertEquals(7, result.faces(), "setup");
        assertEquals(4, result.capFaces(), "setup");
        assertClean(result);
    }

    /**
     * Three layers 0, T and 2T up; the middle one runs on to x = 1.5, and the cap that should
     * bend round its end joins the bottom and top layers straight up at x = 1, through it: one
     * pair of faces crossing along x = 1, z = T, across the strip. The cap reaches T below the
     * middle layer and T above; of its fan's triangles, the one cut along the diagonal from (1,
     * 0, 0) to (1, 1, 2T) comes free of the layer a hair sooner, moving across that diagonal
     * and the layer's edge: 1 / sqrt(1 + (2T)^2) T.
     */
    @Test
    void aCapThroughTheMiddleLayerCrossesItOneThicknessDeep() {
        Result result = check("""
                o strip-1
                v 0 0 0
                v 1 0 0
                v 1 1 0
                v 0 1 0
                v 0 0 0.01
                v 1.5 0 0.01
                v 1.5 1 0.01
                v 0 1 0.01
                v 0 0 0.02
                v 1 0 0.02
                v 1 1 0.02
                v 0 1 0.02
                g paper
                f 1 2 3 4
                f 5 6 7 8
                f 9 10 11 12
                g cap
                f 2 10 11 3
                """);
        assertEquals(1, result.facePairs(), result::summary);
        assertTrue(result.crossingPairs() >= 1);
        assertEquals(result.crossingPairs(), result.capPairs(), "every crossing has the cap in it");
        Crossing c = result.deepest();
        assertEquals(Kind.CAP, c.kind());
        assertEquals(2, c.faceA());
        assertEquals(4, c.faceB());
        assertEquals(1 / Math.sqrt(1 + 4 * T * T), c.depth(), 1e-9);
        for (Crossing each : result.crossings()) {
            assertEquals(1, each.from().x(), 1e-12);
            assertEquals(0.01, each.from().z(), 1e-12);
            assertEquals(1, each.to().x(), 1e-12);
            assertEquals(0.01, each.to().z(), 1e-12);
        }
        double across = 0;
        for (Crossing each : result.crossings()) {
            across += each.length();
        }
        assertTrue(across >= 1 - 1e-12, "the pieces of the segment span the strip: " + across);
    }

    /**
     * A sheet lying half a thickness over the cube's top does not touch it; pushed in, with one
     * corner 0.2 below the top, it crosses the top 0.05 = T/2 deep (its other corners are only
     * that far above), and that corner lies inside the cube.
     */
    @Test
    void aSheetPushedIntoTheCubeCrossesItsSurfaceAndEntersIt() {
        Result onTop = PaperCollisions.check("""
                o strip-1
                v 0.2 0.2 1.005
                v 0.8 0.2 1.005
                v 0.8 0.8 1.005
                v 0.2 0.8 1.005
                g paper
                f 1 2 3 4
                """, T, CUBE);
        assertClean(onTop);
        assertEquals(0, onTop.modelCrossings());
        Result pushed = PaperCollisions.check("""
                o strip-1
                v 0.2 0.2 1.005
                v 0.8 0.2 1.005
                v 0.5 0.8 0.8
                g paper
                f 1 2 3
                """, T, CUBE);
        assertEquals(0, pushed.crossingPairs());
        assertEquals(2, pushed.modelCrossings(), "the sheet crosses both triangles of the top: " + pushed.summary());
        Crossing c = pushed.deepestIntoModel();
        assertEquals(Kind.MODEL, c.kind());
        assertEquals(1, c.faceA());
        assertTrue(c.faceB() == 3 || c.faceB() == 4, "a top triangle (3 or 4): " + c);
        assertEquals(0.5, c.depth(), 1e-9);
        assertEquals(1, c.from().z(), 1e-12);
        assertEquals(1, pushed.pointsInside());
        assertEquals(3, pushed.inside().get(0).vertex());
        assertPoint(0.5, 0.8, 0.8, pushed.inside().get(0).point(), 0);
        assertFalse(pushed.isClean());
        assertTrue(pushed.summary().endsWith("2 paper-model crossings (deepest 0.5000 T, face 1 into model triangle " + c.faceB()
                + "), 1 paper point inside the solid"), pushed.summary());
    }

    /** Paper lying in the cube's top itself, with no gap: it overlaps the surface in one plane, a collision with the model. */
    @Test
    void aSheetLyingInTheSurfaceOverlapsIt() {
        Result result = PaperCollisions.check("o strip-1\nv 0.2 0.2 1\nv 0.8 0.2 1\nv 0.8 0.8 1\nv 0.2 0.8 1\ng paper\nf 1 2 3 4\n", T, CUBE);
        assertEquals(0, result.crossingPairs());
        assertTrue(result.modelCrossings() >= 2, result::summary);
        for (Crossing c : result.intoModel()) {
            assertTrue(c.coplanar(), c::toString);
            assertEquals(0, c.depth());
        }
        assertNull(result.deepestIntoModel(), "lying in the surface is no depth");
        assertEquals(0, result.pointsInside(), "on the surface is not inside");
    }

    /** Faces that share an edge, flat or folded to any angle short of flat onto each other, touch only there. */
    @ParameterizedTest
    @ValueSource(strings = {"0.5 -1 0", "0.5 -0.5 0.7", "0.5 0 1", "0.5 0.9 0.2", "0.5 1 0.01"})
    void sheetsSharingAnEdgeDoNotCross(String apex) {
        Result result = check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0.5 1 0\nv " + apex + "\ng paper\nf 1 2 3\nf 2 1 4\n");
        assertClean(result);
    }

    /** Folded flat onto each other with no gap, two faces sharing an edge lie at one height: that is a coplanar overlap. */
    @Test
    void sheetsFoldedFlatWithoutAGapOverlapInOnePlane() {
        Result result = check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 1 0.000001\ng paper\nf 1 2 3\nf 2 1 4\n");
        assertEquals(0, result.crossingPairs());
        assertEquals(1, result.coplanarPairs(), result::summary);
    }

    /** The same edge written twice (the vertices repeated, as two strips would have them): still only touching. */
    @Test
    void sheetsMeetingAlongAnEdgeOfRepeatedVerticesDoNotCross() {
        Result result = check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0.5 1 0\ng paper\nf 1 2 3\n"
                + "o strip-2\nv 1 0 0\nv 0 0 0\nv 0.5 -0.4 0.6\ng paper\nf 4 5 6\n");
        assertEquals(2, result.faces(), "setup");
        assertClean(result);
    }

    @Test
    void sheetsTouchingAtAVertexDoNotCross() {
        // Sharing vertex 1, the other sheet rising away from the first.
        assertClean(check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0.5\nv 0 -1 0.5\ng paper\nf 1 2 3\nf 1 4 5\n"));
        // A corner resting on the other's middle (a vertex of its own at the same place).
        assertClean(check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.25 0.25 0\nv 0.25 0.5 0.5\nv 0.5 0.25 0.5\ng paper\nf 1 2 3\nf 4 5 6\n"));
        // A corner resting on the other's edge, and corner to corner.
        assertClean(check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.5 0 0\nv 0.5 -0.5 0.5\nv 0.6 -0.5 -0.5\ng paper\nf 1 2 3\nf 4 5 6\n"));
        assertClean(check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 2 0 0.5\nv 2 0.5 -0.5\ng paper\nf 1 2 3\nf 4 5 6\n"));
    }

    /** Sharing a vertex does not excuse a crossing elsewhere: a fin from a shared corner standing through the sheet. */
    @Test
    void sheetsSharingAVertexStillCrossWhereTheyPassThrough() {
        Result result = check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.4 0.4 0.3\nv 0.4 0.4 -0.3\ng paper\nf 1 2 3\nf 1 4 5\n");
        assertEquals(1, result.crossingPairs(), result::summary);
        assertTrue(result.deepest().depth() > 1, "deep: " + result.deepest());
        assertSegment(new double[] {0, 0, 0}, new double[] {0.4, 0.4, 0}, result.deepest(), 1e-12);
    }

    /**
     * Two layers at the same height that overlap: no depth across the plane, but a collision,
     * counted apart as coplanar. The overlap is the triangle x, y >= 0.2, x + y <= 1 (area 0.18);
     * its longest chord is its hypotenuse.
     */
    @Test
    void coplanarOverlapIsCountedApartWithDepthZero() {
        Result result = check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.2 0.2 0\nv 1.2 0.2 0\nv 0.2 1.2 0\ng paper\nf 1 2 3\nf 4 5 6\n");
        assertEquals(0, result.crossingPairs());
        assertEquals(1, result.coplanarPairs(), result::summary);
        assertEquals(1, result.facePairs());
        assertFalse(result.isClean());
        assertNull(result.deepest(), "a coplanar overlap has no depth to be deepest by");
        Crossing c = result.crossings().get(0);
        assertTrue(c.coplanar());
        assertEquals(0, c.depth());
        assertSegment(new double[] {0.8, 0.2, 0}, new double[] {0.2, 0.8, 0}, c, 1e-12);
        assertTrue(result.summary().startsWith("collisions: 0 crossing pairs (0 with caps), 1 pair overlapping in one plane"), result.summary());
        // Side by side in the plane, sharing an edge (repeated vertices) or just apart: no overlap.
        assertClean(check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\ng paper\nf 1 2 3\nf 4 5 6\n"));
        assertClean(check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0.000001 0\nv 0 1.000001 0\nv 1 1 0\ng paper\nf 1 2 3\nf 4 5 6\n"));
    }

    /** Numerically nasty: layers within rounding of one height, at hair-thin angles, slivers, rounding of non-representable heights. */
    @Test
    void nearlyCoplanarCasesAreDecidedByTheTouchingDistance() {
        String square = "o strip-1\nv 0 0 Z0\nv 1 0 Z0\nv 1 1 Z1\nv 0 1 Z1\nv 0.1 0.1 W0\nv 0.9 0.1 W0\nv 0.9 0.9 W1\nv 0.1 0.9 W1\ng paper\nf 1 2 3 4\nf 5 6 7 8\n";
        // Layers 1e-4 T apart: at one height, overlapping.
        Result close = check(square.replace("Z0", "0.1").replace("Z1", "0.1").replace("W0", "0.100001").replace("W1", "0.100001"));
        assertEquals(0, close.crossingPairs());
        assertTrue(close.coplanarPairs() >= 1, close::summary);
        // Layers exactly T apart at heights no double holds exactly: apart.
        assertClean(check(square.replace("Z0", "0.1").replace("Z1", "0.1").replace("W0", "0.11").replace("W1", "0.11")));
        // A layer tilted 1e-7 through another: it reaches 4e-8 to either side, far within touching: coplanar.
        Result thin = check(square.replace("Z0", "0").replace("Z1", "0").replace("W0", "-4e-8").replace("W1", "4e-8"));
        assertEquals(0, thin.crossingPairs());
        assertTrue(thin.coplanarPairs() >= 1, thin::summary);
        // Tilted 1e-3 through: 4e-4 = 0.04 T to either side, a crossing that deep (a millionth
        // less, freed along an axis of the fans' diagonals tilted by 1e-3 both ways).
        Result tilted = check(square.replace("Z0", "0").replace("Z1", "0").replace("W0", "-0.0004").replace("W1", "0.0004"));
        assertEquals(0, tilted.coplanarPairs(), tilted::summary);
        assertTrue(tilted.crossingPairs() >= 1);
        assertEquals(0.04 / Math.sqrt(1 + 2e-6), tilted.deepest().depth(), 1e-12);
        // A face with collinear corners (no area, no normal) is left out, not divided by zero.
        assertClean(check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.1 0.1 -1\nv 0.2 0.2 0\nv 0.3 0.3 1\ng paper\nf 1 2 3\nf 4 5 6\n"));
    }

    @Test
    void badInputIsRefusedWithTheLine() {
        IllegalArgumentException group = assertThrows(IllegalArgumentException.class,
                () -> check("o strip-1\nv 0 0 0\nv 1 0 0\nv 0 1 0\ng sheet\nf 1 2 3\n"));
        assertTrue(group.getMessage().startsWith("line 5: "), group.getMessage());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> check("v 0 0 0\nv 1 0 0\nv 0 1 0\ng paper\nf 1 2 3\n"))
                .getMessage().contains("line 5: a face before any 'o' strip"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> check("o s\nv 0 0 0\nv 1 0 0\nv 0 1 0\ng paper\nf 1 2 4\n"))
                .getMessage().contains("line 6: vertex 4 is not among the 3 read so far"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> check("o s\nv 0 0 0\nv 1 0 0\ng paper\nf 1 2\n"))
                .getMessage().contains("line 5: a face needs 3 or more corners"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> check("o s\nv 0 zero 0\n")).getMessage().startsWith("line 2: not a number"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> check("o s\nv 0 0\n")).getMessage().contains("line 2: a vertex needs x y z"));
        assertThrows(IllegalArgumentException.class, () -> PaperCollisions.check(Z_FOLD, 0));
        assertThrows(IllegalArgumentException.class, () -> PaperCollisions.check(Z_FOLD, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> PaperCollisions.check(Z_FOLD, T, new double[8]));
        // Negative (relative) indices, CRLF lines, normals and comments are OBJ too.
        assertClean(check("# a comment\r\no strip-1\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nvn 0 0 1\r\ng paper\r\nf -3//1 -2//1 -1//1\r\n"));
    }

    /** More crossings than the list holds: the count is whole, the list the first in order of faces. */
    @Test
    void theListHoldsTheFirstCrossingsInOrderOfFaces() {
        StringBuilder obj = new StringBuilder("o strip-1\nv -3 -3 0\nv 3 -3 0\nv 0 3 0\n");
        for (int k = 0; k < 5; k++) {
            double x = -1 + 0.5 * k;
            obj.append(String.format(Locale.ROOT, "v %s -0.1 -0.05\nv %s -0.1 -0.05\nv %s 0.1 0.1%n", x - 0.1, x + 0.1, x));
        }
        obj.append("g paper\nf 1 2 3\n");
        for (int k = 0; k < 5; k++) {
            obj.append("f ").append(4 + 3 * k).append(' ').append(5 + 3 * k).append(' ').append(6 + 3 * k).append('\n');
        }
        Result result = PaperCollisions.check(obj.toString(), T, new double[0], new PaperCollisions.Options(3, 2));
        assertEquals(5, result.crossingPairs(), result::summary);
        assertEquals(3, result.crossings().size());
        for (int k = 0; k < 3; k++) {
            assertEquals(1, result.crossings().get(k).faceA());
            assertEquals(2 + k, result.crossings().get(k).faceB());
        }
        assertEquals(result.summary(), PaperCollisions.check(obj.toString(), T, new double[0], new PaperCollisions.Options(3, 1)).summary(),
                "one thread or two: the same answer");
    }
}
