package ifold.ui.model;

import ifold.check.PaperCollisions;
import ifold.foldfile.FoldFile;
import ifold.geom.Triangle;
import ifold.job.ModelFiles;
import ifold.job.ViewJob;
import ifold.job.Collisions;
import ifold.job.LayerOrders;
import ifold.job.ModelFiles;
import ifold.job.Reports;
import ifold.job.Scenes;
import ifold.job.ScriptJob;
import ifold.job.TriangleText;
import ifold.job.TurnJob;
import ifold.job.WrapJob;
import ifold.job.ZigZagJob;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.refine.HamiltonianRefinement;
import ifold.scene.Animation;
import ifold.scene.Scene;
import ifold.scene.WrapPlayback;
import ifold.script.FoldScript;
import ifold.script.ScriptFolding;
import ifold.sheet.FoldException;
import ifold.geom.ParameterException;
import ifold.wrap.TurnGadget;
import ifold.wrap.Wrap;
import ifold.wrap.WrapExport;
import ifold.wrap.PaperInSpace;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * From a {@link Job} to a {@link Plan}, as the command line does it: the same checks (the
 * core's {@link ParameterException} names the field), the same planner, the same figures and
 * scenes ({@link Reports}, {@link Scenes}).
 */
public final class Planning {
    private Planning() {
    }

    /**
     * What is wrong with the job's parameters, field by field, before any work: a value that is
     * not a number, then whatever the core refuses (it stops at the first such). Empty when
     * the job may run; a wrap's width is checked against the model's triangles only when it runs.
     */
    public static List<Problem> check(Job job) {
        List<Problem> problems = new ArrayList<>();
        try {
            if (job instanceof Job.ZigZag z) {
                zigzagOptions(z, problems);
            } else if (job instanceof Job.Turn t) {
                turnOptions(t, problems);
            } else if (job instanceof Job.WrapModel w) {
                wrapOptions(w, problems);
            } else if (job instanceof Job.Script s) {
                scriptMaxFaces(s, problems);
            } else if (job instanceof Job.View v) {
                requireFile(v.model(), "model", problems);
            }
        } catch (ParameterException e) {
            problems.add(new Problem(e.parameter(), e.getMessage()));
        }
        return problems;
    }

    /**
     * Does the job: checks, plans, analyses, and builds the scene that shows it, calling
     * {@code progress.check()} between stages.
     *
     * @throws JobFailure with the problem to show, at a field or as one message
     * @throws java.util.concurrent.CancellationException if the progress was cancelled
     */
    public static Plan plan(Job job, Progress progress) throws JobFailure {
        List<Problem> problems = check(job);
        if (!problems.isEmpty()) {
            throw new JobFailure(problems.get(0));
        }
        try {
            if (job instanceof Job.ZigZag z) {
                return zigzag(z, progress);
            } else if (job instanceof Job.Turn t) {
                return turn(t, progress);
            } else if (job instanceof Job.WrapModel w) {
                return wrap(w, progress);
            } else if (job instanceof Job.View v) {
                return view(v, progress);
            }
            return script((Job.Script) job, progress);
        } catch (ParameterException e) {
            throw new JobFailure(new Problem(e.parameter(), e.getMessage()));
        }
    }

    /** A text field as a number: blank is {@code blank} (NaN: the core's default); anything else must be a finite number. */
    static double number(String text, String field, double blank, List<Problem> problems) {
        String value = text == null ? "" : text.strip();
        if (value.isEmpty()) {
            return blank;
        }
        try {
            double d = Double.parseDouble(value);
            if (Double.isFinite(d)) {
                return d;
            }
        } catch (NumberFormatException e) {
            // said below
        }
        problems.add(new Problem(field, "'" + value + "' is not a number"));
        return Double.NaN;
    }

    private static Wrap.Options zigzagOptions(Job.ZigZag job, List<Problem> problems) {
        Triangle shape = null;
        try {
            shape = TriangleText.parse(job.triangle());
        } catch (ParameterException e) {
            problems.add(new Problem(e.parameter(), e.getMessage()));
        }
        double width = number(job.width(), "width", Double.NaN, problems);
        double thickness = number(job.thickness(), "thickness", Double.NaN, problems);
        if (!problems.isEmpty()) {
            return null;
        }
        return Wrap.Options.loneTriangle(shape, new Wrap.Ends(job.start(), job.end(), job.enterFrom()), width, thickness);
    }

    private static TurnGadget.Options turnOptions(Job.Turn job, List<Problem> problems) {
        String angleText = job.angle() == null ? "" : job.angle().strip();
        if (angleText.isEmpty()) {
            problems.add(new Problem("angle", "the turn's angle is needed, from " + TurnGadget.Options.MIN_ANGLE + " to "
                    + TurnGadget.Options.MAX_ANGLE + " degrees"));
        }
        double angle = number(angleText, "angle", Double.NaN, problems);
        double overhang = number(job.overhang(), "overhang", 0, problems);
        double width = number(job.width(), "width", 1, problems);
        double thickness = number(job.thickness(), "thickness", Double.NaN, problems);
        if (!problems.isEmpty()) {
            return null;
        }
        return new TurnGadget.Options(angle, overhang, width, thickness);
    }

    private static Wrap.Options wrapOptions(Job.WrapModel job, List<Problem> problems) {
        requireFile(job.model(), "model", problems);
        double width = number(job.width(), "width", Double.NaN, problems);
        double thickness = number(job.thickness(), "thickness", Double.NaN, problems);
        int maxFaces = Wrap.DEFAULT_MAX_FACES;
        String limit = job.maxFaces() == null ? "" : job.maxFaces().strip();
        if (!limit.isEmpty()) {
            try {
                maxFaces = Integer.parseInt(limit);
            } catch (NumberFormatException e) {
                problems.add(new Problem("maxFaces", "'" + limit + "' is not a whole number"));
            }
        }
        if (!problems.isEmpty()) {
            return null;
        }
        return new Wrap.Options(width, thickness, null, maxFaces);
    }

    private static void requireFile(Path file, String field, List<Problem> problems) {
        if (file == null) {
            problems.add(new Problem(field, "no file chosen"));
        } else if (!Files.exists(file)) {
            problems.add(new Problem(field, file + ": no such file"));
        } else if (!Files.isRegularFile(file)) {
            problems.add(new Problem(field, file + ": not a regular file"));
        }
    }

    private static Plan zigzag(Job.ZigZag job, Progress progress) throws JobFailure {
        Wrap.Options options = zigzagOptions(job, new ArrayList<>());
        Triangle shape = TriangleText.parse(job.triangle());
        progress.stage("wrapping the triangle");
        ZigZagJob.Outcome zigzag;
        try {
            zigzag = ZigZagJob.run(new ZigZagJob.Request(job.triangle(), shape, options), watcher(progress));
        } catch (Wrap.WrapException e) {
            throw new JobFailure("cannot wrap this triangle: " + e.getMessage());
        }
        progress.check();
        progress.stage("analysing");
        Wrap.Result result = zigzag.result();
        List<PaperInSpace> geometries = zigzag.geometries();
        Map<String, Object> figures = zigzag.figures();
        LayerOrders.addTo(figures, List.of(new FoldFile.Folded(zigzag.sheet(), result.frames())), "zigzag");
        Collisions.addTo(figures, geometries, result.thickness(), result.mesh());
        progress.check();
        return paperPlan(job, "zig-zag: " + figures.get("folds") + " folds", result, geometries, figures,
                Math.min(120, 2.0 * (result.steps().size() + 2)), zigzag.source(), null,
                scene -> Scenes.zigzag(scene, shape, result, geometries));
    }

    private static Plan turn(Job.Turn job, Progress progress) throws JobFailure {
        TurnGadget.Options options = turnOptions(job, new ArrayList<>());
        progress.stage("folding the turn");
        TurnJob.Outcome turn;
        try {
            turn = TurnJob.run(options);
        } catch (FoldException e) {
            throw new JobFailure("cannot make this turn: " + e.getMessage());
        }
        Wrap.Result result = turn.result();
        List<PaperInSpace> geometries = turn.geometries();
        Map<String, Object> figures = turn.figures();
        LayerOrders.addTo(figures, List.of(new FoldFile.Folded(turn.gadget().sheet(), result.frames())), "turn");
        Collisions.addTo(figures, geometries, result.thickness(), result.mesh());
        progress.check();
        return paperPlan(job, String.format(Locale.ROOT, "turn gadget: %.4g degrees", options.angle()), result, geometries, figures, 6,
                turn.source(), null, scene -> Scenes.turn(scene, result, geometries));
    }

    private static Plan wrap(Job.WrapModel job, Progress progress) throws JobFailure {
        Wrap.Options options = wrapOptions(job, new ArrayList<>());
        Path model = job.model();
        WrapJob.Outcome wrapped;
        try {
            Wrap.Watcher folds = watcher(progress);
            wrapped = WrapJob.run(new WrapJob.Request(model, new MeshBuilder.Options(job.strict(), true), options, job.method()),
                    new WrapJob.Watcher() {
                @Override
                public void wrapped(int done, int total) {
                    folds.wrapped(done, total);
                }

                @Override
                public boolean stopped() {
                    return folds.stopped();
                }

                @Override
                public void stage(String what) {
                    progress.stage(what);
                }
            });
        } catch (ModelFiles.LoadFailure e) {
            throw new JobFailure(new Problem("model", e.getMessage() + (e.repairable() ? " (clear Strict to repair it)" : "")));
        } catch (Wrap.FaceLimitException e) {
            throw new JobFailure(new Problem("maxFaces", model + ": cannot wrap: " + e.getMessage() + " (Max faces raises it)"));
        } catch (Wrap.TooWideException e) {
            throw new JobFailure(new Problem("width", model + ": cannot wrap: " + e.getMessage()));
        } catch (Wrap.WrapException | WrapJob.Refused e) {
            throw new JobFailure(model + ": cannot wrap: " + e.getMessage());
        }
        HalfedgeMesh mesh = wrapped.mesh();
        Wrap.Result result = wrapped.result();
        List<PaperInSpace> geometries = wrapped.geometries();
        HamiltonianRefinement.Result refinement = wrapped.refinement();
        Map<String, Object> figures = wrapped.figures();
        List<FoldFile.Folded> sheets = new ArrayList<>();
        for (Wrap.Strip strip : result.strips()) {
            sheets.add(new FoldFile.Folded(strip.sheet(), result.frames()));
        }
        LayerOrders.addTo(figures, sheets, "wrap");
        progress.check();
        // One check for the report and the view's collisions (View > Collisions), as the command line's C shows them.
        PaperCollisions.Result collisions = Collisions.forScene(geometries, result.thickness(), mesh);
        Collisions.put(figures, collisions, geometries, result.thickness());
        progress.check();
        int folds = result.steps().size() - result.count(Wrap.Kind.END);
        return paperPlan(job, model.getFileName() + ": " + result.strips().size() + (result.strips().size() == 1 ? " strip, " : " strips, ") + folds + " folds",
                result, geometries, figures, 120, "ifold wrap " + model, wrapped.movedBy(), scene -> {
                    WrapPlayback playback = Scenes.wrap(scene, mesh, result, geometries);
                    if (refinement != null) { // the zig-zag's path; the hinge strip's tour is its strip
                        Scenes.refinement(scene, refinement);
                    }
                    Scenes.collisions(scene, geometries, collisions);
                    return playback;
                });
    }

    /**
     * The script's limit on faces (blank: the command line's default), checked as the command
     * line checks {@code --max-faces}; -1 with a problem where it is not a whole number of at least 1.
     */
    private static int scriptMaxFaces(Job.Script job, List<Problem> problems) {
        requireFile(job.file(), "script", problems);
        String limit = job.maxFaces() == null ? "" : job.maxFaces().strip();
        if (limit.isEmpty()) {
            return ScriptFolding.DEFAULT_MAX_FACES;
        }
        try {
            int maxFaces = Integer.parseInt(limit);
            if (maxFaces >= 1) {
                return maxFaces;
            }
            problems.add(new Problem("maxFaces", "must be at least 1, got " + maxFaces));
        } catch (NumberFormatException e) {
            problems.add(new Problem("maxFaces", "'" + limit + "' is not a whole number"));
        }
        return -1;
    }

    /** The command line's way to raise the limit on a script's faces, as its refusals name it. */
    private static final String RAISE_ON_THE_COMMAND_LINE = "--max-faces raises the limit";

    private static Plan script(Job.Script job, Progress progress) throws JobFailure {
        Path file = job.file();
        int maxFaces = scriptMaxFaces(job, new ArrayList<>());
        progress.stage("reading " + file.getFileName());
        ScriptJob.Outcome folding;
        try {
            folding = ScriptJob.run(file, maxFaces, what -> {
                progress.check();
                progress.stage(what);
            });
        } catch (IOException e) {
            throw new JobFailure(new Problem("script", ModelFile.readError(file, e)));
        } catch (ScriptJob.Refused e) {
            // Over the limit on faces: the window's field raises it, and is where the refusal shows.
            if (e.getMessage().contains(RAISE_ON_THE_COMMAND_LINE)) {
                throw new JobFailure(new Problem("maxFaces", e.getMessage().replace(RAISE_ON_THE_COMMAND_LINE, "Max faces raises the limit")));
            }
            throw new JobFailure(e.getMessage());
        }
        progress.check();
        ScriptFolding.Result result = folding.result();
        PaperInSpace folded = folding.folded();
        Map<String, Object> figures = folding.figures();
        // Folded once more on ideal paper where thick (ofScript): once, for the check and the export.
        List<FoldFile.Folded> sheets = folding.sheets(maxFaces);
        LayerOrders.addTo(figures, sheets, "script");
        Collisions.addTo(figures, List.of(folded), result.sheet().thickness(), null);
        Plan.Shown shown = scriptScene(folding);
        List<Fold> folds = new ArrayList<>();
        for (int k = 0; k < result.steps().size(); k++) {
            FoldScript.Step fold = result.steps().get(k).fold();
            String kind = fold.kind().name().toLowerCase(Locale.ROOT);
            folds.add(new Fold(String.format(Locale.ROOT, "fold %d: %s %.4g°%s", k + 1, kind, fold.degrees(),
                    fold.line() > 0 ? ", line " + fold.line() : ""), kind, k));
        }
        if (folding.form() != null) {
            folds.add(new Fold(folding.folds(), "all at once", 0));
        }
        String header = "iFold fold script " + file + ": " + folding.folds() + ", thickness " + result.sheet().thickness();
        return new Plan(job, file.getFileName() + ": " + folding.folds(), shown, List.copyOf(folds), figures, 10,
                () -> scriptScene(folding), out -> WrapExport.writeObj(out, header, List.of(folded)),
                sheets, "ifold fold " + file, null);
    }

    /** The parts of the reveal the list names: about a tenth of the path's triangles each. */
    static final int VIEW_PARTS = 10;

    /** The turntable's parts, each so many degrees. */
    static final int TURN_DEGREES = 45;

    /**
     * A model looked at, as {@code ifold view} does it: read and built as the view builds it
     * (triangulated and refined for the refinement and the path), in the view's scene; the
     * report holds the counts and angles {@code ifold refine} prints for it, and the view's
     * edges by kind.
     */
    private static Plan view(Job.View job, Progress progress) throws JobFailure {
        ViewJob.Outcome shown;
        try {
            shown = ViewJob.run(new ViewJob.Request(job.model(), job.strict(), job.show(), job.colors()), progress.watcher());
        } catch (ModelFiles.LoadFailure e) {
            throw ModelFile.failure(e);
        }
        Map<String, Object> figures = shown.figures();
        progress.check();
        Scenes.View view = shown.view();
        return new Plan(job, view.caption(), new Plan.Shown(shown.scene(), view.animation()), viewParts(view.animation(), job.show()),
                figures, 10, () -> {
                    Scene another = new Scene();
                    return new Plan.Shown(another, shown.viewIn(another).animation());
                }, null, List.of(), "ifold view " + job.model(), null);
    }

    /**
     * The reveal in tenths ("triangles 11-20 of 98"), each beginning where the triangles before
     * it are shown; or the turn around the model in eighths.
     */
    private static List<Fold> viewParts(Animation animation, Scenes.Show show) {
        List<Fold> parts = new ArrayList<>();
        int total = animation.stepCount();
        if (show == Scenes.Show.PATH) {
            int size = Math.max(1, (total + VIEW_PARTS - 1) / VIEW_PARTS);
            for (int first = 0; first < total; first += size) {
                int last = Math.min(total, first + size);
                String name = last == first + 1 ? String.format(Locale.ROOT, "triangle %d of %d", last, total)
                        : String.format(Locale.ROOT, "triangles %d-%d of %d", first + 1, last, total);
                parts.add(new Fold(name, "path", first));
            }
        } else {
            for (int degrees = 0; degrees < 360; degrees += TURN_DEGREES) {
                parts.add(new Fold(String.format(Locale.ROOT, "turn %d°-%d°", degrees, degrees + TURN_DEGREES), "turntable",
                        degrees * total / 360.0));
            }
        }
        return List.copyOf(parts);
    }

    private static Plan.Shown scriptScene(ScriptJob.Outcome folding) {
        Scene scene = new Scene();
        Animation animation = folding.play(scene);
        return new Plan.Shown(scene, animation);
    }

    /** How a scene of a wrap is made: filled into the scene given, its playback returned. */
    @FunctionalInterface
    private interface WrapScene {
        WrapPlayback fill(Scene scene);
    }

    private static Plan paperPlan(Job job, String title, Wrap.Result result, List<PaperInSpace> geometries, Map<String, Object> figures,
            double seconds, String source, double[] movedBy, WrapScene scenes) {
        Scene scene = new Scene();
        WrapPlayback playback = scenes.fill(scene);
        playback.pace(seconds); // the window plays it in as many seconds: its captions as long as a movie's
        List<Fold> folds = new ArrayList<>(result.steps().size());
        boolean several = result.strips().size() > 1;
        for (int j = 0; j < result.steps().size(); j++) {
            Wrap.Step step = result.steps().get(j);
            if (step.kind() == Wrap.Kind.END) {
                continue; // the strip's end is a step of the animation, not a fold
            }
            folds.add(new Fold((several ? "strip " + (step.strip() + 1) + ", " : "") + step.describe(), kindName(step.kind()),
                    playback.positionAfter(j)));
        }
        List<FoldFile.Folded> sheets = new ArrayList<>();
        for (Wrap.Strip strip : result.strips()) {
            sheets.add(new FoldFile.Folded(strip.sheet(), result.frames()));
        }
        return new Plan(job, title, new Plan.Shown(scene, playback), List.copyOf(folds), figures, seconds, () -> {
            Scene another = new Scene();
            WrapPlayback again = scenes.fill(another);
            again.pace(seconds); // laid out as the window's, so that the figure's stages fall where they did
            return new Plan.Shown(another, again);
        }, out -> WrapExport.writeObj(out, WrapExport.aboutCentre(source, movedBy), result, geometries), List.copyOf(sheets), source,
                job instanceof Job.ZigZag ? Scenes.figure11Stages(playback, result) : null);
    }

    /** A fold's kind as the list shows it. */
    static String kindName(Wrap.Kind kind) {
        return switch (kind) {
            case ZIGZAG_TURN -> "zig-zag turn";
            case TURN_GADGET -> "turn gadget";
            case EDGE_CROSSING -> "edge crossing";
            case OVERLAP -> "overlap";
            case TUCK -> "tuck";
            case END -> "the strip ends";
            case DIAGONAL_TURN -> "diagonal turn";
        };
    }

    /**
     * The wrap as the window sees it: each triangle wrapped moves the progress bar, and Cancel
     * (or a newer plan) stops it at its next fold rather than after the whole wrap.
     */
    private static Wrap.Watcher watcher(Progress progress) {
        return new Wrap.Watcher() {
            @Override
            public void wrapped(int done, int total) {
                progress.done(done, total);
            }

            @Override
            public boolean stopped() {
                return progress.cancelled();
            }
        };
    }
}
