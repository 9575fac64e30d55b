package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.refine.HamiltonianRefinement;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/** The tucks at a host's sharp corner, counted before any fold, and a tuck stopped before it cuts past the limit. */
public class CornerTucksTest {
    /** One triangle with a corner of {@code degrees} at the origin, its others at (1, 0, 0) and the unit vector at that angle. */
    static HamiltonianRefinement.Result needle(double degrees) throws Exception {
        double angle = Math.toRadians(degrees);
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(0, 0, 0);
        soup.addVertex(1, 0, 0);
        soup.addVertex(Math.cos(angle), Math.sin(angle), 0);
        soup.addTriangle(0, 1, 2);
        return HamiltonianRefinement.refine(MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh());
    }

    /** Counts the folds of a wrap: it asks at every fold whether to stop. */
    private static final class FoldCounter implements Wrap.Watcher {
        int folds;

        @Override
        public void wrapped(int done, int total) {
        }

        @Override
        public boolean stopped() {
            folds++;
            return false;
        }
    }

    @Test
    void onlyCornersSharperThanADegreeCountAFlapsBouncesEach() throws Exception {
        HamiltonianRefinement.Result half = needle(0.5);
        CornerTucks corners = CornerTucks.of(half.mesh(), HostPieces.of(half.mesh()));
        assertEquals(0, corners.sharpest(), "setup: the triangle is one host, its corner sharp");
        assertEquals(0.5, corners.degrees(0), 1e-9);
        assertEquals(360, corners.tucks(), "180 / 0.5");
        assertEquals(720, corners.fewestFaces(), "2 a tuck");
        HamiltonianRefinement.Result two = needle(2);
        CornerTucks blunt = CornerTucks.of(two.mesh(), HostPieces.of(two.mesh()));
        assertEquals(-1, blunt.sharpest());
        assertEquals(0, blunt.fewestFaces());
        HamiltonianRefinement.Result cube = HamiltonianRefinement.refine(MeshBuilder.build(Solids.cube(), MeshBuilder.Options.REPAIR_TRIANGULATE)
                .mesh());
        assertEquals(0, CornerTucks.of(cube.mesh(), HostPieces.of(cube.mesh())).fewestFaces(), "right angles bounce no flap for long");
    }

    /**
     * One triangle with a corner of 0.001°: its 243,096 passes make at least 486,192 faces,
     * under the limit, and it was folded for 22 s and 1.25 GiB until its second tuck passed
     * the limit (issue 20). With the 180,000 tucks of its corner counted it is refused before
     * any fold, naming the corner and saying no strip fits.
     */
    @Test
    void aCornerOfAThousandthOfADegreeIsRefusedBeforeAnyFold() throws Exception {
        HamiltonianRefinement.Result sharp = needle(0.001);
        FoldCounter counter = new FoldCounter();
        Wrap.FaceLimitException e = assertThrows(Wrap.FaceLimitException.class,
                () -> Wrap.wrap(sharp, new Wrap.Options(Double.NaN, Double.NaN), counter));
        assertEquals(0, counter.folds, "refused before any fold");
        String message = e.getMessage();
        assertTrue(message.startsWith("a strip 2.909e-06 wide would need 243,096 passes, and the corner of 0.0010 degrees at (0.00000 0.00000 0.00000)"
                + " about 180,000 tucks") && message.contains("at least 846,192 faces of paper (486,192 for the passes, 2 a tuck; likely about ")
                && message.contains("more than the limit of " + String.format(java.util.Locale.ROOT, "%,d", Wrap.DEFAULT_MAX_FACES) + " faces; no strip the path takes fits: the widest, 8.727e-06,")
                && message.endsWith("widen the corner"), message);
    }

    /**
     * A corner of 0.9° wraps, and makes at least the floor counted for it (its passes' and 2
     * faces a tuck for its 200 bounces), and not far over the likely figure; its tucks are at
     * least 3/4 of the bounces counted.
     */
    @Test
    void aSharpCornerMakesItsFloorAndAboutItsLikelyFaces() throws Exception {
        HamiltonianRefinement.Result sharp = needle(0.9);
        Wrap.Result result = Wrap.wrap(sharp, new Wrap.Options(Double.NaN, Double.NaN));
        List<PathPlan> plans = PathPlan.plans(sharp.mesh(), sharp.componentStart(), null);
        // As the wrap does.
        PathPlan.chooseLastStart(sharp.mesh(), plans.get(0), result.width(), result.widest(), LayerFloor.angleSums(sharp.mesh()));
        HostPieces pieces = HostPieces.of(sharp.mesh());
        CornerTucks corners = CornerTucks.of(sharp.mesh(), pieces);
        long floor = PathPlan.faces(plans, result.width(), pieces.alone(), false) + corners.fewestFaces();
        long likely = PathPlan.faces(plans, result.width(), pieces.alone(), true) + corners.likelyFaces(plans, result.width());
        int faces = result.strips().get(0).sheet().faceCount();
        // One piece of paper reaches round the corner, the turn into a last pass running away
        // from it (StripFolding.stopShort, evenedUp): its 135° there bounce 3/4 of a half disk's
        // 180/θ times, 151 tucks of the 200 counted (and about 270 of 360 at 0.5°, 450 of
        // 600 at 0.3°); they were 201. The faces they make still pass the floor: 2,111 against 962.
        int tucks = result.count(Wrap.Kind.TUCK);
        assertTrue(tucks >= 3 * corners.tucks() / 4, tucks + " tucks, counted " + corners.tucks());
        assertTrue(faces >= floor && faces < 1.5 * likely, faces + " faces, floor " + floor + ", likely " + likely);
    }

    /**
     * A tuck is stopped before its cut makes the faces that pass the limit: the tuck with the
     * most cuts of the 0.9° corner, under a limit one short of the faces it makes, stops
     * saying what the strip would have once it cut (the limit was checked after each fold: a
     * tuck through all of a needle's 243,096 passes went 295,000 faces past it).
     */
    @Test
    void aTuckThatWouldPassTheLimitStopsBeforeItCuts() throws Exception {
        HamiltonianRefinement.Result sharp = needle(0.9);
        Wrap.Options options = new Wrap.Options(Double.NaN, Double.NaN);
        List<Wrap.Step> steps = Wrap.wrap(sharp, options).steps();
        int biggest = -1;
        for (int s = 1; s < steps.size(); s++) {
            if (steps.get(s).kind() == Wrap.Kind.TUCK && (biggest < 0
                    || steps.get(s).facesAfter() - steps.get(s - 1).facesAfter() > steps.get(biggest).facesAfter() - steps.get(biggest - 1).facesAfter())) {
                biggest = s;
            }
        }
        int before = steps.get(biggest - 1).facesAfter();
        int after = steps.get(biggest).facesAfter();
        assertTrue(after - before > 100, "setup: a tuck that cuts through the passes, " + before + " -> " + after);
        Wrap.FaceLimitException e = assertThrows(Wrap.FaceLimitException.class, () -> Wrap.wrap(sharp, options.withMaxFaces(after - 1)));
        assertTrue(e.getMessage().startsWith(String.format(Locale.ROOT, "the strip would have %,d faces of paper on triangle ", after))
                && e.getMessage().contains(String.format(Locale.ROOT, " once its next tuck cuts through %,d more, more than the limit of %,d faces",
                after - before, after - 1)), e.getMessage());
    }
}
