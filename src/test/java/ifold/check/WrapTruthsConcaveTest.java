package ifold.check;

import static ifold.check.WrapTruthsTest.T;
import static ifold.check.WrapTruthsTest.assertBroken;
import static ifold.check.WrapTruthsTest.check;
import static ifold.check.WrapTruthsTest.truths;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.check.WrapTruths.Violation;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * The checker where thick paper meets a concave edge of the model: paper stands back from the
 * edge by its mitre (its height times tan(φ/2)) and no more, and only there may it creep.
 */
class WrapTruthsConcaveTest {
    /**
     * An inside corner: the floor z = 0 (normal +z) and a wall x = 0 (normal +x) rising from its
     * edge along y, a concave edge turning by 90 degrees (its mitre: in as far as up).
     */
    private static final List<double[]> INSIDE_CORNER = List.of(
            new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0},
            new double[] {0, 0, 0, 1, 1, 0, 0, 1, 0},
            new double[] {0, 0, 0, 0, 1, 0, 0, 1, 1},
            new double[] {0, 0, 0, 0, 1, 1, 0, 0, 1});

    /**
     * A unit sheet on the floor and one on the wall, half a thickness up, each standing back
     * {@code floorIn} and {@code wallIn} from the corner's edge, as thick layers must there.
     */
    private static String insideCorner(double floorIn, double wallIn) {
        return insideCorner(floorIn, wallIn, 0.005);
    }

    /** As {@link #insideCorner(double, double)}, the sheets {@code up} from the surface. */
    private static String insideCorner(double floorIn, double wallIn, double up) {
        return quad(1, new double[][] {{floorIn, 0, up}, {1, 0, up}, {1, 1, up}, {floorIn, 1, up}}, 1, 1)
                + quad(2, new double[][] {{up, 0, wallIn}, {up, 1, wallIn}, {up, 1, 1}, {up, 0, 1}}, 1, 1);
    }

    /**
     * Strip {@code strip} of the file: one face, its sheet the rectangle [0, u] x [0, v] laid on
     * the four {@code corners} in space (counter-clockwise on the sheet from its origin); its
     * vertices numbered on from the strips before, four each.
     */
    private static String quad(int strip, double[][] corners, double u, double v) {
        double[][] sheet = {{0, 0}, {u, 0}, {u, v}, {0, v}};
        StringBuilder obj = new StringBuilder("o strip-" + strip + "\n");
        for (int k = 0; k < 4; k++) {
            obj.append(String.format(java.util.Locale.ROOT, "v %s %s %s%nvt %s %s%n", corners[k][0], corners[k][1], corners[k][2], sheet[k][0],
                    sheet[k][1]));
        }
        int first = 4 * (strip - 1) + 1;
        return obj.append(String.format("g paper%nf %d/%d %d/%d %d/%d %d/%d%n", first, first, first + 1, first + 1, first + 2, first + 2, first + 3,
                first + 3)).toString();
    }

    /**
     * Thick paper at a concave edge stands back from it (its creases creep): a face whose corners
     * stand in from the edge by its mitre (its height, at 90 degrees) is no stretch, and the
     * floor by the edge under no paper of its own plane is no hole; a corner nearer the edge than
     * its mitre runs into the layers across, and one farther in than the creep zone is a stretch
     * and leaves a hole; without thickness nothing creeps.
     */
    @Test
    void paperStandsBackFromAConcaveEdgeByItsMitreAndNoMore() {
        assertEquals(List.of(), check(insideCorner(0.005, 0.005), INSIDE_CORNER, T), "mitred at the corner");
        assertEquals(List.of(), check(insideCorner(0.02, 0.005), INSIDE_CORNER, T), "in farther, within the zone (a fold's wall)");

        List<Violation> nearer = check(insideCorner(0.002, 0.005), INSIDE_CORNER, T);
        assertBroken(nearer, WrapTruths.ISOMETRIC, "vertex 1 is 0.002", "nearer than its mitre");
        // Laid as it would be without thickness, congruent but running into the wall's layers.
        List<Violation> unmitred = check(insideCorner(0, 0), INSIDE_CORNER, T);
        assertBroken(unmitred, WrapTruths.ISOMETRIC, "face 1", "vertex 1 is 0.0 in", "nearer than its mitre");
        assertBroken(unmitred, WrapTruths.ISOMETRIC, "face 2", "vertex 5 is 0.0 in", "nearer than its mitre");

        List<Violation> far = check(insideCorner(0.2, 0.005), INSIDE_CORNER, T);
        assertBroken(far, WrapTruths.ISOMETRIC, "face 1", "is stretched");
        assertBroken(far, WrapTruths.COVERED, "lies under no paper face");

        List<Violation> thin = check(insideCorner(0.005, 0.005, 0), INSIDE_CORNER, 0);
        assertBroken(thin, WrapTruths.ISOMETRIC, "is stretched");
    }

    /** A room's corner: the floor z = 0 between two walls, x = 0 (normal +x) and y = 0 (normal +y). */
    private static final List<double[]> ROOM_CORNER = List.of(
            new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0},
            new double[] {0, 0, 0, 1, 1, 0, 0, 1, 0},
            new double[] {0, 0, 0, 0, 1, 0, 0, 1, 1},
            new double[] {0, 0, 0, 0, 1, 1, 0, 0, 1},
            new double[] {0, 0, 0, 0, 0, 1, 1, 0, 1},
            new double[] {0, 0, 0, 1, 0, 1, 1, 0, 0});

    /**
     * The checker's allowances at concave edges hold only where paper creeps: floor paper that
     * keeps its mitre from one wall but runs into the other is caught (it passed, kept clear of
     * the first), and a gap in the floor's paper away from the edge is a hole, though narrower
     * than a creep zone (it passed too).
     */
    @Test
    void creepIsAllowedOnlyWherePaperStandsBackFromEveryConcaveEdge() {
        String floor = """
                o strip-1
                v 0 0.005 0.005
                vt 0 0
                v 1 0.005 0.005
                vt 1 0
                v 1 1 0.005
                vt 1 1
                v 0 1 0.005
                vt 0 1
                g paper
                f 1/1 2/2 3/3 4/4
                """;
        assertBroken(check(floor, ROOM_CORNER, T), WrapTruths.ISOMETRIC, "vertex 1 is 0.0 in", "nearer than its mitre");

        String gap = """
                o strip-1
                v 0.005 0 0.005
                vt 0 0
                v 0.47 0 0.005
                vt 0.465 0
                v 0.47 1 0.005
                vt 0.465 1
                v 0.005 1 0.005
                vt 0 1
                g paper
                f 1/1 2/2 3/3 4/4
                o strip-2
                v 0.53 0 0.005
                vt 0 0
                v 1 0 0.005
                vt 0.47 0
                v 1 1 0.005
                vt 0.47 1
                v 0.53 1 0.005
                vt 0 1
                g paper
                f 5/5 6/6 7/7 8/8
                o strip-3
                v 0.005 0 0.005
                vt 0 0
                v 0.005 1 0.005
                vt 1 0
                v 0.005 1 1
                vt 1 0.995
                v 0.005 0 1
                vt 0 0.995
                g paper
                f 9/9 10/10 11/11 12/12
                """;
        assertBroken(check(gap, INSIDE_CORNER.subList(0, 2), T), WrapTruths.COVERED, "lies under no paper face");
        List<Violation> holed = check(gap, INSIDE_CORNER, T);
        assertEquals(Set.of(WrapTruths.COVERED), truths(holed), "the wall's paper and the floor's keep every other truth");
        assertTrue(holed.stream().allMatch(v -> !v.message().contains("model point (") || v.message().contains("of triangle 1 ")
                || v.message().contains("of triangle 2 ")), "only the floor's gap is bare: " + holed);
    }

    /** A floor z = 0 two long (y from 0 to 2) with a wall x = 0 rising beside its first half only: a concave edge from (0, 0) to (0, 1). */
    private static final List<double[]> HALF_WALL = List.of(
            new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0},
            new double[] {0, 0, 0, 1, 1, 0, 0, 1, 0},
            new double[] {0, 1, 0, 1, 1, 0, 1, 2, 0},
            new double[] {0, 1, 0, 1, 2, 0, 0, 2, 0},
            new double[] {0, 0, 0, 0, 1, 0, 0, 1, 1},
            new double[] {0, 0, 0, 0, 1, 1, 0, 0, 1});

    /**
     * The floor's paper beside the wall, the wall's, and the floor's beyond the wall's end from
     * {@code beyondFrom} in y to 2, running up to x = 0.
     */
    private static String halfWall(double beyondFrom) {
        return String.format(java.util.Locale.ROOT, """
                o strip-1
                v 0.005 0 0.005
                vt 0 0
                v 1 0 0.005
                vt 0.995 0
                v 1 1 0.005
                vt 0.995 1
                v 0.005 1 0.005
                vt 0 1
                g paper
                f 1/1 2/2 3/3 4/4
                o strip-2
                v 0.005 0 0.005
                vt 0 0
                v 0.005 1 0.005
                vt 1 0
                v 0.005 1 1
                vt 1 0.995
                v 0.005 0 1
                vt 0 0.995
                g paper
                f 5/5 6/6 7/7 8/8
                o strip-3
                v 0 %1$s 0.005
                vt 0 0
                v 1 %1$s 0.005
                vt 1 0
                v 1 2 0.005
                vt 1 %2$s
                v 0 2 0.005
                vt 0 %2$s
                g paper
                f 9/9 10/10 11/11 12/12
                """, beyondFrom, 2 - beyondFrom);
    }

    /**
     * The mitre stands beside the edge: paper beyond the wall's end, which only touches the
     * concave edge's end with a corner, keeps no mitre (nothing across rises there); the same
     * paper reaching back beside the wall, a corner on the edge, runs into the wall's layers.
     */
    @Test
    void paperBeyondAConcaveEdgesEndKeepsNoMitre() {
        List<Violation> beyond = check(halfWall(1), HALF_WALL, T);
        assertTrue(beyond.stream().noneMatch(v -> v.truth().equals(WrapTruths.ISOMETRIC)), beyond.toString());
        assertBroken(check(halfWall(0.5), HALF_WALL, T), WrapTruths.ISOMETRIC, "face 3", "vertex 9 is 0.0 in", "nearer than its mitre");
    }

    /** The floor's slope beyond x = 0: a concave edge along y turning by this, so slight that the two sides' normals agree to 1 - 1e-9. */
    private static final double SLIGHT = 1e-7;

    /**
     * A floor z = 0 for x from 0 to 1, and beyond x = 0 one rising by {@link #SLIGHT} as x falls:
     * a concave edge along y whose sides are two planes, though their normals agree to within the
     * checker's parallel tolerance (a bumpy sphere's edge).
     */
    private static final List<double[]> SLIGHT_FOLD = List.of(
            new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0},
            new double[] {0, 0, 0, 1, 1, 0, 0, 1, 0},
            new double[] {-1, 0, SLIGHT, 0, 0, 0, 0, 1, 0},
            new double[] {-1, 0, SLIGHT, 0, 1, 0, -1, 1, SLIGHT});

    /**
     * Paper on each side of a concave edge turning by 1e-7 rad, 0.4 thicknesses up and 0.0012 in
     * from the edge (its mitre there, 2e-10 in, is far less), the far side's a narrow band: it is
     * held to its own side's mitre, not reported as lying 0.0012 beyond the near side's edge (it
     * was: the two sides were taken for one plane, their normals agreeing, though the far side's
     * corner lies 1e-7 off the near side's plane; a bumpy sphere's edge turning by 1.7e-6 rad).
     */
    @Test
    void theSidesOfASlightConcaveEdgeAreTwoPlanes() {
        double up = 0.004;
        double in = 0.0012;
        double far = 0.003; // the far side's paper so narrow that it lies within rounding of the near side's plane too
        String obj = String.format(java.util.Locale.ROOT, """
                o strip-1
                v %1$s 0 %2$s
                vt 0 0
                v 1 0 %2$s
                vt %3$s 0
                v 1 1 %2$s
                vt %3$s 1
                v %1$s 1 %2$s
                vt 0 1
                g paper
                f 1/1 2/2 3/3 4/4
                o strip-2
                v -%6$s 0 %4$s
                vt 0 0
                v -%1$s 0 %5$s
                vt %7$s 0
                v -%1$s 1 %5$s
                vt %7$s 1
                v -%6$s 1 %4$s
                vt 0 1
                g paper
                f 5/5 6/6 7/7 8/8
                """, in, up, 1 - in, SLIGHT * far + up, SLIGHT * in + up, far, far - in);
        List<Violation> violations = check(obj, SLIGHT_FOLD, T);
        assertTrue(violations.stream().noneMatch(v -> v.truth().equals(WrapTruths.ISOMETRIC)), violations.toString());
    }

    /**
     * An L of three unit squares in z = 0 (normal +z): A at the origin, B beside it along x, C
     * beside it along y; the side x = 1 between A and B is a cut of a non-convex face.
     */
    private static final List<double[]> FLAT_L = List.of(
            new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0},
            new double[] {0, 0, 0, 1, 1, 0, 0, 1, 0},
            new double[] {1, 0, 0, 2, 0, 0, 2, 1, 0},
            new double[] {1, 0, 0, 2, 1, 0, 1, 1, 0},
            new double[] {0, 1, 0, 1, 1, 0, 1, 2, 0},
            new double[] {0, 1, 0, 1, 2, 0, 0, 2, 0});

    /**
     * The L's paper: B and C each under a square of their own, and A under a face that stands
     * back {@code gap} from the cut x = 1, its sheet {@code squashed} longer than its place.
     */
    private static String flatL(double gap, double squashed) {
        double x = 1 - gap;
        return quad(1, new double[][] {{1, 0, 0.005}, {2, 0, 0.005}, {2, 1, 0.005}, {1, 1, 0.005}}, 1, 1)
                + quad(2, new double[][] {{0, 1, 0.005}, {1, 1, 0.005}, {1, 2, 0.005}, {0, 2, 0.005}}, 1, 1)
                + quad(3, new double[][] {{0, 0, 0.005}, {x, 0, 0.005}, {x, 1, 0.005}, {0, 1, 0.005}}, x + squashed, 1);
    }

    /**
     * Paper crept back from a cut between coplanar hosts (a fold nested along it stands back a
     * thickness for each fold wrapping it, along the whole of its crease) leaves the surface
     * beside the cut bare no wider than the stack is high, as truth 2 lets it creep: no hole
     * (figure3's wrap had such a band, 2.5 thicknesses wide, by a fold wrapped along part of its
     * length). Wider than that, or beside paper that did not creep, it is a hole.
     */
    @Test
    void paperCreptBackFromACutLeavesNoHoleWithinItsCreep() {
        // The check's stack of 1 level: paper stands at most 2 T = 0.02 high.
        assertEquals(List.of(), check(flatL(0.015, 0.001), FLAT_L, T), "crept 0.015 back: within the creep");
        List<Violation> isometric = check(flatL(0.015, 0), FLAT_L, T);
        assertEquals(Set.of(WrapTruths.COVERED), truths(isometric), "placed 0.015 back without creeping: a hole");
        List<Violation> far = check(flatL(0.03, 0.001), FLAT_L, T);
        assertBroken(far, WrapTruths.COVERED, "of triangle 1 ", "lies under no paper face");
    }
    /**
     * A step's corner: the top A (z = 0, normal +z) and front B (y = 0, normal -y) of a low block
     * meet at the convex edge along x from (0, 0, 0) to (1, 0, 0); at its end (1, 0, 0) a wall W
     * (x = 1, normal -x, fanned from that corner) rises across the wedge of air above the edge.
     */
    private static final List<double[]> STEP_CORNER = List.of(
            new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0},
            new double[] {0, 0, 0, 1, 1, 0, 0, 1, 0},
            new double[] {0, 0, 0, 0, 0, -1, 1, 0, -1},
            new double[] {0, 0, 0, 1, 0, -1, 1, 0, 0},
            new double[] {1, 0, 0, 1, 1, -1, 1, -1, -1},
            new double[] {1, 0, 0, 1, -1, -1, 1, -1, 1},
            new double[] {1, 0, 0, 1, -1, 1, 1, 1, 1},
            new double[] {1, 0, 0, 1, 1, 1, 1, 1, -1});

    /** The step's top and front without the wall: nothing rises at the edge's end. */
    private static final List<double[]> STEP_WITHOUT_WALL = STEP_CORNER.subList(0, 4);

    /**
     * A unit sheet on the step's top, half a thickness up, its corner on the convex edge at
     * {@code x} moved {@code kept} along the edge away from that end (a crease's end kept from it).
     */
    private static String keptAlongTheEdge(double x, double kept) {
        double[][] corners = {{0, 0, 0.005}, {1, 0, 0.005}, {1, 1, 0.005}, {0, 1, 0.005}};
        corners[x == 0 ? 0 : 1][0] = x == 0 ? kept : 1 - kept;
        return quad(1, corners, 1, 1);
    }

    private static List<Violation> isometric(List<Violation> violations) {
        return violations.stream().filter(v -> v.truth().equals(WrapTruths.ISOMETRIC)).toList();
    }

    /**
     * Paper over a convex edge keeps from its end where a face at that corner rises across it,
     * as far as that face's stack stands out along the edge: a face whose corner there is kept
     * 1.5 thicknesses along the edge (within the stack of 2 T over the cosine, 1) is no stretch;
     * kept farther than the zone allows, or at the other end of the edge where nothing rises,
     * or with the wall gone, it is one.
     */
    @Test
    void paperKeepsFromAConvexEdgesEndWhereAFaceRisesAcrossIt() {
        assertEquals(List.of(), isometric(check(keptAlongTheEdge(1, 0.015), STEP_CORNER, T)), "kept 1.5 T from the wall's corner");
        assertBroken(check(keptAlongTheEdge(1, 0.2), STEP_CORNER, T), WrapTruths.ISOMETRIC, "is stretched");
        assertBroken(check(keptAlongTheEdge(0, 0.015), STEP_CORNER, T), WrapTruths.ISOMETRIC, "is stretched");
        assertBroken(check(keptAlongTheEdge(1, 0.015), STEP_WITHOUT_WALL, T), WrapTruths.ISOMETRIC, "is stretched");
    }
}
