package ifold.script;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.sheet.Sheet;
import ifold.sheet.SheetChecks;
import ifold.wrap.WrapAnalysis;
import ifold.wrap.WrapExport;
import ifold.wrap.PaperInSpace;
import ifold.check.WrapTruths;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Fold scripts on the sheet engine: flat folds through the layers and of flaps, folds part of the way, and their invariants. */
class ScriptFoldingTest {
    private static final double T = 0.01;

    @TempDir
    Path dir;

    private static ScriptFolding.Result play(String script) throws FoldScriptException {
        return FoldScript.parse(script).play();
    }

    /** Where paper point (u, v) lies in space, on the faces holding it (several where it lies on a crease): {x, y, z} of the first. */
    private static double[] where(ScriptFolding.Result result, double u, double v) {
        PaperInSpace geometry = PaperInSpace.of(result.sheet(), result.frames());
        for (int p = 0; p < geometry.vertexCount(); p++) {
            if (Math.abs(geometry.uv()[2 * p] - u) < 1e-12 && Math.abs(geometry.uv()[2 * p + 1] - v) < 1e-12) {
                return new double[] {geometry.xyz()[3 * p], geometry.xyz()[3 * p + 1], geometry.xyz()[3 * p + 2]};
            }
        }
        throw new AssertionError("no paper vertex at (" + u + ", " + v + ")");
    }

    /** The distinct heights of the paper faces' corners, rounded to 1e-12. */
    private static TreeSet<Double> heights(ScriptFolding.Result result) {
        PaperInSpace geometry = PaperInSpace.of(result.sheet(), result.frames());
        TreeSet<Double> heights = new TreeSet<>();
        for (int[] face : geometry.paperFaces()) {
            for (int p : face) {
                heights.add(Math.rint(geometry.xyz()[3 * p + 2] * 1e12) / 1e12);
            }
        }
        return heights;
    }

    /** The truths any folded paper keeps, checked on its OBJ: it tiles its sheet once, no face stretched, none torn. */
    private void assertSound(ScriptFolding.Result result) throws Exception {
        PaperInSpace geometry = PaperInSpace.of(result.sheet(), result.frames());
        Path obj = dir.resolve("folded.obj");
        WrapExport.writeObj(obj, "test", List.of(geometry));
        WrapTruths truths = WrapTruths.read(Files.readString(obj));
        // No surface to rest on but the table (a triangle under the sheet sets the scale): paper
        // turned up stands in the air, so truth 5 does not apply.
        List<double[]> table = List.<double[]>of(new double[] {-50, -50, 0, 150, -50, 0, -50, 150, 0});
        List<WrapTruths.Violation> violations = truths.check(table, result.sheet().thickness(), result.sheet().stackLevels(), 0, 1)
                .stream().filter(v -> !v.truth().equals(WrapTruths.ON_SURFACE)).toList();
        assertTrue(violations.isEmpty(), () -> violations.subList(0, Math.min(3, violations.size())).toString());
        assertTrue(WrapAnalysis.isometryError(geometry, result.sheet().width()) <= 1e-9);
        SheetChecks.assertLayersApart(result.sheet(), result.frames().length);
        for (double c : geometry.xyz()) {
            assertTrue(Double.isFinite(c));
        }
    }

    private static int maxLayers(ScriptFolding.Result result) {
        return WrapAnalysis.maxLayers(result.sheet(), result.frames().length);
    }

    @Test
    void aValleyFoldLaysTheMovingHalfOneThicknessAbove() throws Exception {
        ScriptFolding.Result result = play("paper strip 10 1\nthickness 0.01\nfold valley 180 paper 5 0 5 1 right\n");
        assertSound(result);
        assertEquals(new TreeSet<>(List.of(0.0, T)), heights(result), "the table's layer at z = 0, the folded one a thickness up");
        double[] corner = where(result, 10, 0);
        assertEquals(0, corner[0], 1e-12);
        assertEquals(0, corner[1], 1e-12);
        assertEquals(T, corner[2], 1e-12, "the far corner lands over (0, 0), one thickness up");
        assertEquals(2, maxLayers(result));
        assertEquals(1, result.frames().length, "a flat fold keeps the paper on its plane");
    }

    @Test
    void aMountainFoldGoesUnder() throws Exception {
        ScriptFolding.Result result = play("paper strip 10 1\nthickness 0.01\nfold mountain 180 paper 5 0 5 1 right\n");
        assertSound(result);
        assertTrue(where(result, 10, 0)[2] < where(result, 0, 0)[2] - T / 2, "the moved half lies under the half that stayed");
    }

    @Test
    void aSquareFoldedInHalfTwiceHasFourLayersOneThicknessApart() throws Exception {
        ScriptFolding.Result result = play("paper square 2\nthickness 0.01\nfold valley 180 paper 1 0 1 2 right\n"
                + "fold valley 180 points 0 1 0 1 1 0 left\n");
        assertSound(result);
        assertEquals(new TreeSet<>(List.of(0.0, T, 2 * T, 3 * T)), heights(result));
        assertEquals(4, maxLayers(result));
    }

    @Test
    void aFoldThroughCornersMakesNoNewVertices() throws Exception {
        ScriptFolding.Result result = play("paper square 2\nthickness 0\nfold valley 180 paper 0 0 2 2 right\n");
        assertSound(result);
        assertEquals(4, result.sheet().vertexCount(), "the diagonal runs through two corners: nothing to split");
        assertEquals(2, result.sheet().faceCount());
        assertEquals(2, maxLayers(result));
        double[] corner = where(result, 2, 0);
        assertEquals(0, corner[0], 1e-12, "the lower right half now lies over the upper left");
        assertEquals(2, corner[1], 1e-12);
    }

    @Test
    void aFoldPartOfTheWayTurnsByItsAngle() throws Exception {
        ScriptFolding.Result result = play("paper strip 10 1\nthickness 0\nfold valley 90 paper 5 0 5 1 right\n");
        assertSound(result);
        double[] corner = where(result, 10, 1);
        assertEquals(5, corner[0], 1e-12);
        assertEquals(1, corner[1], 1e-12);
        assertEquals(5, corner[2], 1e-12, "turned up by 90 degrees");
        assertEquals(2, result.frames().length, "the standing half rests on a plane of its own");
        // With thickness, the standing half turns about the top of the layer: clear of the half that stays.
        ScriptFolding.Result thick = play("paper strip 10 1\nthickness 0.01\nfold valley 90 paper 5 0 5 1 right\n");
        assertSound(thick);
        assertTrue(where(thick, 10, 1)[0] > 5, "the standing half stands beside the line, not through the paper");
    }

    @Test
    void aFlapFoldedUpAndDownAgainLiesFlatOnItsPlane() throws Exception {
        ScriptFolding.Result result = play("paper strip 10 1\nthickness 0\nfold valley 90 paper 5 0 5 1 right\n"
                + "fold mountain 90 points 5 0 0 5 1 0 right\n");
        assertSound(result);
        double[] corner = where(result, 10, 1);
        assertEquals(10, corner[0], 1e-12);
        assertEquals(0, corner[2], 1e-12, "back on the table");
        assertEquals(1, maxLayers(result));
        // The flap form names the paper beyond the crease on the sheet, wherever it stands.
        ScriptFolding.Result flap = play("paper strip 10 1\nthickness 0\nfold valley 90 paper 5 0 5 1 right\n"
                + "fold mountain 90 flap 5 0 5 1 right\n");
        assertEquals(10, where(flap, 10, 1)[0], 1e-12);
        assertEquals(0, where(flap, 10, 1)[2], 1e-12);
    }

    @Test
    void aFlapFoldTurnsOnlyThePaperBeyondItsCreaseOnTheSheet() throws Exception {
        ScriptFolding.Result result = FoldScript.read(Path.of("models", "scripts", "zigzag-turn.fold")).play();
        assertSound(result);
        assertEquals(2, maxLayers(result), "only the turn holds two layers");
        double[] end = where(result, 12, 1);
        // The strip's end runs back along the band below the first pass, on the table.
        assertEquals(0, end[0], 1e-9);
        assertEquals(-1, end[1], 1e-9);
        assertEquals(0, end[2], 1e-9);
        // The builder makes the same folds.
        ScriptFolding.Result built = FoldScript.builder().strip(12, 1).thickness(0.02)
                .flap(FoldScript.Kind.VALLEY, 180, 5, 1, 6, 0, FoldScript.Side.LEFT)
                .flap(FoldScript.Kind.VALLEY, 180, 6, 0, 7, 1, FoldScript.Side.RIGHT).build().play();
        assertEquals(result.sheet().vertexCount(), built.sheet().vertexCount());
        assertEquals(end[1], where(built, 12, 1)[1], 0);
    }

    @Test
    void aHundredRollingFoldsStaySound() throws Exception {
        // Roll a strip up from its end: each fold lays the growing stack over the next unit.
        StringBuilder script = new StringBuilder("paper strip 110 1\nthickness 0.001\n");
        for (int k = 1; k <= 100; k++) {
            script.append("fold valley 180 paper ").append(110 - k).append(" 0 ").append(110 - k).append(" 1 right\n");
        }
        ScriptFolding.Result result = play(script.toString());
        assertSound(result);
        assertEquals(101, maxLayers(result));
        TreeSet<Double> expected = new TreeSet<>();
        for (int k = 0; k <= 100; k++) {
            expected.add(Math.rint(k * 0.001 * 1e12) / 1e12);
        }
        assertEquals(expected, heights(result), "101 layers, exactly one thickness apart");
    }

    @Test
    void randomFlatFoldsOnASquareStaySound() throws Exception {
        Random random = new Random(11);
        int made = 0;
        for (int trial = 0; trial < 20; trial++) {
            StringBuilder script = new StringBuilder("paper square 4\nthickness 0.01\n");
            ScriptFolding.Result result = null;
            for (int k = 0; k < 4; k++) {
                // A line through a random point near the middle, in a random direction.
                double angle = random.nextDouble() * Math.PI;
                double x = 1 + 2 * random.nextDouble();
                double y = 1 + 2 * random.nextDouble();
                String line = String.format(java.util.Locale.ROOT, "fold %s 180 point %.6f %.6f 0 direction %.6f %.6f 0 %s\n",
                        random.nextBoolean() ? "valley" : "mountain", x, y, Math.cos(angle), Math.sin(angle),
                        random.nextBoolean() ? "left" : "right");
                try {
                    result = play(script + line);
                } catch (FoldScriptException e) {
                    assertTrue(e.getMessage().contains("moves"), e.getMessage()); // the line missed what is left: a clear refusal
                    continue;
                }
                script.append(line);
                made++;
                assertSound(result);
            }
        }
        assertTrue(made > 40, "most random folds were made: " + made);
    }

    @Test
    void valleyAndMountainAreThePapersOwn() throws Exception {
        // The far half laid back over (back up), then its end folded: a paper valley on paper
        // lying back up turns down, under; a paper mountain turns up, over.
        ScriptFolding.Result valley = play("paper strip 12 1\nthickness 0.01\nfold valley 180 paper 6 0 6 1 right\n"
                + "fold valley 180 flap 9 0 9 1 right\n");
        ScriptFolding.Result mountain = play("paper strip 12 1\nthickness 0.01\nfold valley 180 paper 6 0 6 1 right\n"
                + "fold mountain 180 flap 9 0 9 1 right\n");
        assertSound(valley);
        assertSound(mountain);
        double[] under = where(valley, 12, 0);
        double[] over = where(mountain, 12, 0);
        assertEquals(6, under[0], 1e-12, "the end comes back to x = 6");
        assertEquals(6, over[0], 1e-12);
        assertEquals(heights(valley).first(), under[2], 1e-12, "a valley of the back-up flap goes down, under the layers");
        assertEquals(heights(mountain).last(), over[2], 1e-12, "a mountain of the back-up flap comes up, over them");
        assertEquals(3, heights(valley).size());
        assertEquals(3, heights(mountain).size());
    }

    @Test
    void randomFlapAndLayerFoldsOnAStripStaySound() throws Exception {
        // Flap folds cut along a line of the sheet, wherever its paper lies, and take away paper
        // that may lie between layers that stay: their order must survive it.
        Random random = new Random(5);
        int made = 0;
        for (int trial = 0; trial < 25; trial++) {
            StringBuilder script = new StringBuilder("paper strip 12 2\nthickness 0.01\n");
            for (int k = 0; k < 6; k++) {
                double u = 1 + 10 * random.nextDouble();
                double slant = (random.nextDouble() - 0.5) * 2;
                String kind = random.nextBoolean() ? "valley" : "mountain";
                String side = random.nextBoolean() ? "left" : "right";
                String line = random.nextBoolean()
                        ? String.format(java.util.Locale.ROOT, "fold %s 180 flap %.5f 0 %.5f 2 %s\n", kind, u, u + slant, side)
                        : String.format(java.util.Locale.ROOT, "fold %s 180 paper %.5f 0 %.5f 2 %s\n", kind, u, u + slant, side);
                ScriptFolding.Result result;
                try {
                    result = play(script + line);
                } catch (FoldScriptException e) {
                    continue; // not on the paper, nothing or everything moves, or a tear: refused clearly
                }
                script.append(line);
                made++;
                assertSound(result);
            }
        }
        assertTrue(made > 60, "most random folds were made: " + made);
    }

    @Test
    void everyFoldIsJournaledForTheAnimation() throws Exception {
        ScriptFolding.Result result = FoldScript.read(Path.of("models", "scripts", "square-quarters.fold")).play();
        Sheet sheet = result.sheet();
        ScriptFolding.Step second = result.steps().get(1);
        assertEquals(sheet.faceCount(), second.facesAfter());
        assertEquals(2, result.steps().get(0).facesAfter(), "the first fold cuts the square in two");
        assertEquals(2, second.moved().length, "the second turns both layers of the top half");
        for (int i = 0; i < second.faces().length; i++) {
            if (second.faces()[i] >= second.facesBefore()) {
                assertEquals(null, second.loopsBefore()[i], "a face the fold cut off was not there before it");
            }
        }
    }

    @Test
    void aLineReadsTheSameFromEitherEndOfACrease() throws FoldScriptException {
        // After the first fold the right half lies back up on the left. The second line runs
        // along y = 5 on the left half, written from its outer end or from the crease: the
        // paper it runs on names the fold either way, so both fold the same.
        String first = "paper square 10\nfold valley 180 paper 5 0 5 10 right\n";
        ScriptFolding.Result outward = play(first + "fold valley 180 paper 0 5 5 5 left\n");
        ScriptFolding.Result inward = play(first + "fold valley 180 paper 5 5 0 5 right\n");
        assertEquals(java.util.Arrays.toString(outward.sheet().levels()), java.util.Arrays.toString(inward.sheet().levels()));
        assertTrue(where(outward, 0, 10)[2] > where(outward, 0, 0)[2], "a valley on paper top side up: the top half comes up");
        for (double[] corner : new double[][] {{0, 0}, {0, 10}, {10, 0}, {10, 10}}) {
            assertEquals(java.util.Arrays.toString(where(outward, corner[0], corner[1])),
                    java.util.Arrays.toString(where(inward, corner[0], corner[1])), "corner " + java.util.Arrays.toString(corner));
        }
    }
}
