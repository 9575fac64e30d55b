package ifold.ui.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.cli.Main;
import ifold.job.Json;
import ifold.job.Scenes;
import ifold.scene.Animation;
import ifold.scene.Geometry;
import ifold.scene.PathView;
import ifold.scene.RevealAnimation;
import ifold.scene.Turntable;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CancellationException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Parameters to plan, as the command line does it: the same checks, messages, figures and folds. */
class PlanningTest {
    @TempDir
    Path dir;

    /** What the command line printed on stderr and the exit code. */
    private record Run(int code, String err) {
    }

    private static Run cli(String... args) {
        StringWriter err = new StringWriter();
        int code = Main.commandLine(new PrintWriter(new StringWriter()), new PrintWriter(err)).execute(args);
        return new Run(code, err.toString());
    }

    @Test
    void theDemoPlansTheCommandLinesReport() throws Exception {
        Path report = dir.resolve("zigzag.json");
        Run run = cli("demo", "zigzag", "--no-view", "--report", report.toString());
        assertEquals(0, run.code(), run.err());
        Plan plan = Planning.plan(Job.ZigZag.DEMO, Progress.NONE);
        assertEquals(Files.readString(report), Json.write(plan.figures()), "the window's report is the command line's, byte for byte");
        assertEquals(5, plan.figures().get("passes"));
        int folds = (Integer) plan.figures().get("folds");
        assertEquals(folds, plan.folds().size(), "one entry a fold");
        assertEquals("zig-zag turn", plan.folds().get(0).kind());
        assertEquals(0.0, plan.folds().get(0).position(), "the first fold begins at the start");
        assertEquals("tuck", plan.folds().get(folds - 1).kind(), "the tucks come last");
        for (int i = 1; i < folds; i++) {
            assertTrue(plan.folds().get(i).position() > plan.folds().get(i - 1).position(), "folds in order along the animation");
        }
        assertTrue(plan.folds().get(folds - 1).position() < plan.stepCount(), "the turn round comes after the last fold");
    }

    @Test
    void aBadValueIsMarkedAtItsFieldWithTheCommandLinesMessage() {
        String[][] cases = {
            {"width", "9", "--width"},
            {"width", "-1", "--width"},
            {"thickness", "0.5", "--thickness"},
            {"triangle", "0,0,1,1,2,2", "--triangle"},
            {"triangle", "1,2,3", "--triangle"},
        };
        for (String[] c : cases) {
            Job.ZigZag demo = Job.ZigZag.DEMO;
            Job.ZigZag job = switch (c[0]) {
                case "width" -> new Job.ZigZag(demo.triangle(), demo.start(), demo.end(), -1, c[1], "");
                case "thickness" -> new Job.ZigZag(demo.triangle(), demo.start(), demo.end(), -1, "1", c[1]);
                default -> new Job.ZigZag(c[1], demo.start(), demo.end(), -1, "", "");
            };
            List<Problem> problems = Planning.check(job);
            assertEquals(1, problems.size(), c[0] + " " + c[1] + ": " + problems);
            assertEquals(c[0], problems.get(0).field());
            String[] args = c[0].equals("triangle") ? new String[] {"demo", "zigzag", "--no-view", "--triangle", c[1]}
                    : c[0].equals("width") ? new String[] {"demo", "zigzag", "--no-view", "--width", c[1]}
                    : new String[] {"demo", "zigzag", "--no-view", "--width", "1", "--thickness", c[1]};
            Run run = cli(args);
            assertEquals(2, run.code(), run.err());
            assertEquals("ifold: option " + c[2] + ": " + problems.get(0).message(), run.err().lines().findFirst().orElseThrow(),
                    "the same message as the command line");
            JobFailure failure = assertThrows(JobFailure.class, () -> Planning.plan(job, Progress.NONE), "nothing runs");
            assertEquals(c[0], failure.problem().field());
        }
    }

    @Test
    void textThatIsNoNumberIsItsFieldsProblemAndEveryFieldIsMarked() {
        List<Problem> problems = Planning.check(new Job.ZigZag("0,0,10,0,3.5,8", 2, 0, -1, "wide", "thin"));
        assertEquals(List.of(new Problem("width", "'wide' is not a number"), new Problem("thickness", "'thin' is not a number")), problems);
        assertEquals("end", Planning.check(new Job.ZigZag("0,0,10,0,3.5,8", 1, 1, -1, "", "")).get(0).field());
        assertEquals(List.of(), Planning.check(Job.ZigZag.DEMO));
    }

    @Test
    void theTurnChecksItsAngleAndOverhangAsTheCommandLine() {
        Problem tooFar = Planning.check(new Job.Turn("200", "0", "1", "")).get(0);
        assertEquals("angle", tooFar.field());
        Run run = cli("demo", "turn", "--no-view", "--angle", "200");
        assertEquals("ifold: option --angle: " + tooFar.message(), run.err().lines().findFirst().orElseThrow());
        assertEquals("angle", Planning.check(new Job.Turn(" ", "0", "1", "")).get(0).field(), "the angle has no default");
        assertEquals("overhang", Planning.check(new Job.Turn("60", "-3", "1", "")).get(0).field());
        assertEquals(List.of(), Planning.check(Job.Turn.DEMO));
    }

    @Test
    void aTurnAndAScriptPlanWithTheirFolds() throws Exception {
        Plan turn = Planning.plan(Job.Turn.DEMO, Progress.NONE);
        assertEquals(turn.figures().get("folds"), turn.folds().size(), "folds, not the strip's end");
        assertTrue(turn.folds().stream().allMatch(f -> f.kind().equals("turn gadget")), turn.folds().toString());
        Animation turning = turn.shown().animation();
        assertEquals("turned: the strip runs on at the angle asked, top side up", turning.describe(turning.stepCount()),
                "the turn ends on what it did, not on a wrap's words");
        Animation zigzag = Planning.plan(Job.ZigZag.DEMO, Progress.NONE).shown().animation();
        assertEquals("wrapped: the strip covers the triangle, its excess tucked under", zigzag.describe(zigzag.stepCount()));
        Plan script = Planning.plan(new Job.Script(Path.of("models", "scripts", "pleat20.fold")), Progress.NONE);
        assertEquals(script.figures().get("folds"), script.folds().size());
        assertEquals(script.folds().size(), script.stepCount(), "a script's animation is a step a fold");
        assertEquals(0.0, script.folds().get(0).position(), "the first fold begins at the start");
        assertEquals(1.0, script.folds().get(1).position(), "and the second once it is made");
    }

    /**
     * A FOLD file folded every crease at once plays in the window as on the command line: one
     * motion, listed as one entry, its end the folded form, its FOLD export the same state.
     */
    @Test
    void aFoldFileFoldedAtOncePlaysAsOneMotion() throws Exception {
        Plan plan = Planning.plan(new Job.Script(Path.of("src", "test", "resources", "fold-examples", "simple.fold")), Progress.NONE);
        assertEquals(1, plan.stepCount(), "every crease together: one step");
        assertEquals(1, plan.folds().size(), plan.folds().toString());
        assertEquals("3 creases folded at once (a folded form, unfolded onto one sheet)", plan.folds().get(0).name());
        Animation motion = plan.shown().animation();
        assertEquals("folded: 4 faces, a folded form, unfolded onto one sheet", motion.describe(1));
        assertTrue(motion.describe(0.5).startsWith("all 3 creases folding at once (50 %)"), motion.describe(0.5));
        assertEquals("all at once: a folded form, unfolded onto one sheet", plan.figures().get("folding"));
    }

    /** A FOLD file that begins with a UTF-8 byte order mark is still a FOLD file, as on the command line. */
    @Test
    void aFoldFileWithAByteOrderMarkIsFoldedAsOne() throws Exception {
        String pattern = "{\"file_spec\": 1.2, \"vertices_coords\": [[0, 0], [2, 0], [2, 1], [0, 1], [1, 0], [1, 1]],"
                + " \"edges_vertices\": [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]],"
                + " \"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"V\"],"
                + " \"faces_vertices\": [[0, 4, 5, 3], [4, 1, 2, 5]]}";
        Path plain = dir.resolve("plain.fold");
        java.nio.file.Files.writeString(plain, pattern);
        Plan expected = Planning.plan(new Job.Script(plain), Progress.NONE);
        assertEquals(1, expected.folds().size(), "setup: the pattern folds once");
        Path marked = dir.resolve("marked.fold");
        java.nio.file.Files.writeString(marked, "\uFEFF" + pattern);
        Plan plan = Planning.plan(new Job.Script(marked), Progress.NONE);
        assertEquals(1, plan.folds().size());
    }

    @Test
    void aModelIsWrappedAndItsFileIsItsField() throws Exception {
        Plan cube = Planning.plan(new Job.WrapModel(Path.of("models", "cube.off"), "", ""), Progress.NONE);
        assertEquals(1.0, (Double) cube.figures().get("coverage"), 1e-9);
        assertEquals(12, cube.figures().get("inputTriangles"));
        assertFalse(cube.folds().isEmpty());
        Problem missing = Planning.check(new Job.WrapModel(dir.resolve("none.off"), "", "")).get(0);
        assertEquals("model", missing.field());
        assertTrue(missing.message().endsWith("none.off: no such file"), missing.message());
        Path broken = dir.resolve("broken.off");
        Files.writeString(broken, "OFF\n3 1 0\n0 0 0\n1 0 0\n");
        JobFailure failure = assertThrows(JobFailure.class, () -> Planning.plan(new Job.WrapModel(broken, "", ""), Progress.NONE));
        assertEquals("model", failure.problem().field());
        assertFalse(failure.getMessage().contains("\n"), "one line: " + failure.getMessage());
        JobFailure tooWide = assertThrows(JobFailure.class,
                () -> Planning.plan(new Job.WrapModel(Path.of("models", "cube.off"), "5", ""), Progress.NONE));
        Run run = cli("wrap", "models/cube.off", "--no-view", "--width", "5");
        assertEquals("ifold: " + tooWide.getMessage(), run.err().strip(), "a width too wide for the triangles: the command line's message");
    }

    @Test
    void theWrapsMethodIsAChoiceOfItsCard() throws Exception {
        Path cube = Path.of("models", "cube.off");
        Plan hinge = Planning.plan(new Job.WrapModel(cube, "", "", "", false, ifold.wrap.Wrap.Method.HINGE), Progress.NONE);
        assertEquals("hinge", hinge.figures().get("method"));
        assertEquals(2, hinge.figures().get("maxLayers"));
        assertEquals(0.5, (Double) hinge.figures().get("paperEfficiency"), 1e-9);
        // Its folds listed as the command line says them, pass by pass.
        assertTrue(hinge.folds().get(0).name().startsWith("pass 1 of 12: "), hinge.folds().get(0).name());
        // A width that does not divide the lattice's square marks the width, in the command line's words.
        JobFailure thirds = assertThrows(JobFailure.class,
                () -> Planning.plan(new Job.WrapModel(cube, "0.3", "", "", false, ifold.wrap.Wrap.Method.HINGE), Progress.NONE));
        assertEquals("width", thirds.problem().field());
        Run run = cli("wrap", cube.toString(), "--no-view", "--method", "hinge", "--width", "0.3");
        assertEquals(2, run.code());
        assertEquals("ifold: option --width: " + thirds.problem().message(), run.err().strip());
        // A model that is no grid polyhedron is refused in one line naming its face.
        JobFailure slanted = assertThrows(JobFailure.class, () -> Planning.plan(new Job.WrapModel(Path.of("models", "tetrahedron.off"),
                "", "", "", false, ifold.wrap.Wrap.Method.HINGE), Progress.NONE));
        assertTrue(slanted.getMessage().contains("is not square to the axes"), slanted.getMessage());
        Run typo = cli("wrap", cube.toString(), "--no-view", "--method", "hing");
        assertEquals(2, typo.code());
        assertTrue(typo.err().startsWith("ifold: invalid value for option '--method': 'hing' (zigzag or hinge)"), typo.err());
        Run refused = cli("wrap", "models/tetrahedron.off", "--no-view", "--method", "hinge");
        assertEquals(1, refused.code());
        assertEquals("ifold: " + slanted.getMessage(), refused.err().strip());
    }

    @Test
    void theWindowsWrapIsPacedForItsSecondsAsTheCommandLinesMovie() throws Exception {
        Plan cube = Planning.plan(new Job.WrapModel(Path.of("models", "cube.off"), "", ""), Progress.NONE);
        for (Animation animation : new Animation[] {cube.shown().animation(), cube.newScene().animation()}) {
            // Sampled as a movie at 30 frames a second over the plan's seconds: no caption gone in under 1.5 s.
            int frames = (int) Math.round(30 * cube.seconds());
            String caption = animation.describe(0);
            int run = 0;
            for (int k = 1; k <= frames; k++) {
                String now = animation.describe(animation.stepCount() * (double) k / frames);
                if (!now.equals(caption)) {
                    assertTrue(run + 1 >= 30 * ifold.scene.WrapView.CAPTION_SECONDS - 1, "'" + caption + "' for " + (run + 1) / 30.0 + " s");
                    caption = now;
                    run = 0;
                } else {
                    run++;
                }
            }
        }
    }

    @Test
    void aScriptsLimitOnFacesIsItsFieldsProblemAndRaisesIt() throws Exception {
        // Four folds halving a square: 32 faces at the fourth (the command line's FoldCommandTest, one fold fewer).
        String script = "paper square 1024\nthickness 0.0001\n"
                + "fold valley 180 points 512 0 0 512 1 0 right\n"
                + "fold valley 180 points 0 512 0 1 512 0 left\n"
                + "fold valley 180 points 256 0 0 256 1 0 right\n"
                + "fold valley 180 points 0 256 0 1 256 0 left\n"
                + "fold valley 180 points 128 0 0 128 1 0 right\n";
        Path file = Files.writeString(dir.resolve("halve5.fold"), script);
        Problem zero = Planning.check(new Job.Script(file, "0")).get(0);
        assertEquals("maxFaces", zero.field());
        Run run = cli("fold", file.toString(), "--no-view", "--max-faces", "0");
        assertEquals("ifold: option --max-faces: " + zero.message(), run.err().strip(), "the command line's message");
        assertEquals("maxFaces", Planning.check(new Job.Script(file, "many")).get(0).field());
        JobFailure few = assertThrows(JobFailure.class, () -> Planning.plan(new Job.Script(file, "16"), Progress.NONE));
        assertEquals("maxFaces", few.problem().field(), "a script refused at the limit marks the limit");
        assertTrue(few.problem().message().contains("more than the 16 allowed") && few.problem().message().contains("Max faces raises the limit")
                && !few.problem().message().contains("--max-faces"), few.problem().message());
        assertFalse(Planning.plan(new Job.Script(file, "64"), Progress.NONE).folds().isEmpty(), "raised, it folds");
        assertFalse(Planning.plan(new Job.Script(file), Progress.NONE).folds().isEmpty(), "blank: the command line's default");
    }

    @Test
    void theWrapsLimitOnFacesIsItsFieldsProblem() throws Exception {
        Path cube = Path.of("models", "cube.off");
        Problem zero = Planning.check(new Job.WrapModel(cube, "", "", "0")).get(0);
        assertEquals("maxFaces", zero.field());
        Run run = cli("wrap", cube.toString(), "--no-view", "--max-faces", "0");
        assertEquals("ifold: option --max-faces: " + zero.message(), run.err().strip());
        assertEquals("maxFaces", Planning.check(new Job.WrapModel(cube, "", "", "many")).get(0).field());
        JobFailure few = assertThrows(JobFailure.class, () -> Planning.plan(new Job.WrapModel(cube, "", "", "50"), Progress.NONE));
        assertEquals("maxFaces", few.problem().field(), "a wrap stopped by the limit marks the limit");
        JobFailure wide = assertThrows(JobFailure.class, () -> Planning.plan(new Job.WrapModel(cube, "0.3", "", ""), Progress.NONE));
        assertEquals("width", wide.problem().field(), "a strip too wide for this model marks the width");
        Run tooWide = cli("wrap", cube.toString(), "--no-view", "--width", "0.3");
        assertEquals("ifold: " + wide.problem().message(), tooWide.err().strip(), "with the command line's message");
    }

    @Test
    void aCancelledPlanStopsAtItsNextStage() {
        Progress cancelled = new Progress() {
            @Override
            public void stage(String what) {
            }

            @Override
            public void done(int done, int total) {
            }

            @Override
            public boolean cancelled() {
                return true;
            }
        };
        assertThrows(CancellationException.class, () -> Planning.plan(Job.ZigZag.DEMO, cancelled));
        assertThrows(CancellationException.class, () -> Planning.plan(new Job.WrapModel(Path.of("models", "cube.off"), "", ""), cancelled));
    }

    /** Cancel stops a wrap in the middle, not after it: the progress bar had moved, and not to the end. */
    @Test
    void aCancelledWrapStopsMidWrapAndItsProgressWasReported() {
        int[] done = {0, 0};
        Progress cancelledMidWrap = new Progress() {
            @Override
            public void stage(String what) {
            }

            @Override
            public void done(int count, int total) {
                done[0] = count;
                done[1] = total;
            }

            @Override
            public boolean cancelled() {
                return done[0] >= 10;
            }
        };
        assertThrows(CancellationException.class,
                () -> Planning.plan(new Job.WrapModel(Path.of("models", "icosahedron.off"), "", ""), cancelledMidWrap));
        assertEquals(10, done[0], "stopped after the tenth triangle");
        assertEquals(98, done[1], "out of the refinement's 98");
    }

    /** The command line's standard output for {@code args}, which must succeed. */
    private static String cliOut(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(args);
        assertEquals(0, code, err.toString());
        return out.toString();
    }

    @Test
    void viewingTheTorussPathRevealsTheRefinementTheCommandLineMakes() throws Exception {
        Path torus = Path.of("models", "torus.off");
        Plan plan = Planning.plan(new Job.View(torus, Scenes.Show.PATH, PathView.Colors.DARKNESS, false), Progress.NONE);
        String json = cliOut("refine", torus.toString(), "-o", dir.resolve("torus-refined.off").toString(), "--json");
        for (String key : List.of("inputTriangles", "components", "outputTriangles", "minAngleInDegrees", "minAngleOutDegrees")) {
            assertTrue(json.contains("\"" + key + "\": " + plan.figures().get(key) + ","), key + " as ifold refine reports it: "
                    + plan.figures().get(key) + " in " + json);
        }
        assertEquals(576, plan.figures().get("inputTriangles"), "the torus's triangles");
        int refined = (Integer) plan.figures().get("outputTriangles");
        assertEquals(5 * 576 - 2, refined, "5n - 2c for one component");
        Geometry shown = ((RevealAnimation) plan.shown().animation()).geometry();
        assertEquals(Scenes.VIEWED, shown.name());
        assertEquals(refined, shown.mesh().triangleCount(), "the view's mesh is the refinement");
        assertEquals(refined, plan.stepCount(), "a step a triangle, as ifold view --path reveals them");
        assertEquals("torus.off: 576 -> " + refined + " triangles", plan.title(), "ifold view's caption");
        assertEquals(PathView.edgeKindCounts(shown.mesh())[0], plan.figures().get("treeEdges"));
        assertTrue((Integer) plan.figures().get("treeEdges") > 0 && (Integer) plan.figures().get("steinerEdges") > 0,
                "tree and Steiner edges drawn: " + plan.figures());

        List<Fold> parts = plan.folds();
        assertEquals(Planning.VIEW_PARTS, parts.size(), "the reveal in tenths: " + parts);
        assertEquals(new Fold("triangles 1-288 of " + refined, "path", 0), parts.get(0));
        assertEquals("triangles 2593-" + refined + " of " + refined, parts.get(parts.size() - 1).name());
        for (int i = 1; i < parts.size(); i++) {
            assertTrue(parts.get(i).position() > parts.get(i - 1).position() && parts.get(i).position() < plan.stepCount(), parts.toString());
        }
        plan.shown().animation().apply(parts.get(3).position());
        assertEquals(3 * 288, shown.revealed(), "at a part's start, the parts before it shown");
        assertEquals("path: triangle " + refined + " of " + refined, plan.shown().animation().describe(plan.stepCount()));

        Plan.Shown export = plan.newScene();
        assertTrue(export.scene() != plan.shown().scene(), "an export plays a scene of its own");
        assertEquals(refined, export.animation().stepCount());
        assertThrows(JobFailure.class, () -> Exports.obj(plan, dir.resolve("none.obj"), Progress.NONE), "a view folds no paper");
        assertFalse(Files.exists(dir.resolve("none.obj")));
    }

    @Test
    void aModelOrItsRefinementIsViewedTurningRound() throws Exception {
        Path cube = Path.of("models", "cube.off");
        Plan model = Planning.plan(new Job.View(cube, Scenes.Show.MODEL, PathView.Colors.DARKNESS, false), Progress.NONE);
        assertEquals(6, model.figures().get("faces"), "the cube's quads, not triangulated, as ifold view reads them");
        assertEquals(12, model.figures().get("triangles"));
        assertEquals("cube.off: 6 faces, 12 triangles", model.title());
        assertTrue(model.shown().animation() instanceof Turntable);
        assertEquals(360 / Planning.TURN_DEGREES, model.folds().size());
        assertEquals("turntable", model.folds().get(1).kind());
        assertEquals(model.stepCount() * Planning.TURN_DEGREES / 360.0, model.folds().get(1).position(), 1e-9);
        Plan refinement = Planning.plan(new Job.View(cube, Scenes.Show.REFINEMENT, PathView.Colors.RAINBOW, false), Progress.NONE);
        assertEquals(58, refinement.figures().get("outputTriangles"), "5 * 12 - 2");
        assertEquals("model", Planning.check(new Job.View(dir.resolve("none.off"), Scenes.Show.PATH, PathView.Colors.DARKNESS, false))
                .get(0).field());
        Path defective = dir.resolve("twice.off");
        Files.writeString(defective, "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 2\n");
        JobFailure strict = assertThrows(JobFailure.class,
                () -> Planning.plan(new Job.View(defective, Scenes.Show.PATH, PathView.Colors.DARKNESS, true), Progress.NONE));
        assertEquals("model", strict.problem().field(), strict.getMessage());
    }

    @Test
    void eachExportSceneIsNewSoThatTheViewKeepsItsOwn() throws Exception {
        Plan plan = Planning.plan(Job.ZigZag.DEMO, Progress.NONE);
        Plan.Shown one = plan.newScene();
        assertTrue(one.scene() != plan.shown().scene() && one.scene() != plan.newScene().scene());
        assertEquals(plan.stepCount(), one.animation().stepCount());
        Map<String, Object> figures = plan.figures();
        assertEquals("C", figures.get("start"));
    }

    /** The window prints the plan's crease pattern as the command line does: the zig-zag's strip on one A4 page, in four pieces. */
    @Test
    void theCreasePatternIsPrintedAsTheCommandLinePrintsIt() throws Exception {
        Plan plan = Planning.plan(Job.ZigZag.DEMO, Progress.NONE);
        ifold.print.CreasePatternPages.Options options = new ifold.print.CreasePatternPages.Options(20, ifold.print.Page.A4);
        ifold.job.PrintJob.Printed pdf = Exports.creasePattern(plan, dir.resolve("zigzag.pdf"), options, Progress.NONE);
        assertEquals(1, pdf.pages());
        assertEquals(4, pdf.pieces());
        assertTrue(Files.size(dir.resolve("zigzag.pdf")) > 1000);
        ifold.job.PrintJob.Printed svg = Exports.creasePattern(plan, dir.resolve("zigzag.svg"), options, Progress.NONE);
        assertEquals(java.util.List.of(dir.resolve("zigzag.svg")), svg.files());
        // Too wide for the page: a problem at the width's field, nothing written.
        JobFailure wide = assertThrows(JobFailure.class, () -> Exports.creasePattern(plan, dir.resolve("wide.pdf"),
                new ifold.print.CreasePatternPages.Options(300, ifold.print.Page.A4), Progress.NONE));
        assertEquals("paperWidth", wide.problem().field());
        assertFalse(Files.exists(dir.resolve("wide.pdf")));
    }

    /** The window draws step diagrams as the command line does: the zig-zag's 12 folds and its end on 4 pages. */
    @Test
    void stepDiagramsAreDrawnAsTheCommandLineDrawsThem() throws Exception {
        Plan plan = Planning.plan(Job.ZigZag.DEMO, Progress.NONE);
        ifold.job.PrintJob.Printed printed = Exports.diagrams(plan, dir.resolve("steps.pdf"), ifold.print.Page.A4, Progress.NONE);
        assertEquals(4, printed.pages());
        assertEquals(12, printed.pieces(), "a step a fold: the strip's end has a panel, but is no step");
        assertEquals("wrote " + dir.resolve("steps.pdf") + ": 4 pages, 12 steps", printed.stepsSummary());
        assertTrue(Files.size(dir.resolve("steps.pdf")) > 10_000);
    }
}
