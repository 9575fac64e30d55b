package ifold.cli;

import ifold.foldfile.FoldFile;
import ifold.foldfile.FoldSteps;
import ifold.job.PrintJob;
import ifold.job.ScriptJob;
import ifold.scene.Animation;
import ifold.scene.Scene;
import ifold.script.FoldScriptException;
import ifold.script.ScriptFolding;
import ifold.wrap.PaperInSpace;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code ifold fold SCRIPT}: plays a fold script or a FOLD crease pattern, in the viewer or as frames, and exports the result. */
@Command(name = "fold", mixinStandardHelpOptions = true,
        // One paragraph: the list of commands shows a description's first element alone.
        description = {"Plays a fold script (docs/fold-scripts.md) or a FOLD file (JSON, as written by "
            + "--export-fold or another tool). A crease pattern on a rectangle whose creases run from border to border folds "
            + "one crease line at a time, in its order; any other FOLD file folds every crease at once: any outline, fold "
            + "angles in 3D (a box's net; every cycle of creases must close), a pattern folded flat without a layer order "
            + "(each vertex checked by Maekawa's and Kawasaki's theorems, its layer order found), a folded form alone "
            + "(unfolded onto one sheet, as the FOLD repository's box), and iFold's own files with their folded state. "
            + "Each fold swings from 0 to its angle. "
            + "Without --frames it plays in the viewer (space plays, arrows step through the folds). "
            + "The animation takes ten seconds unless --seconds says otherwise."})
final class FoldCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCRIPT", description = "a fold script, or a FOLD file: a crease pattern, a folded form, or both")
    Path script;

    @Option(names = "--max-faces", paramLabel = "N", defaultValue = "" + ScriptFolding.DEFAULT_MAX_FACES,
            description = "the most faces the folds may cut the paper into (default ${DEFAULT-VALUE}): a fold that would make more is"
            + " refused. Set for time, not memory as the wrap's is: a fold through a pile costs about the square of its layers"
            + " (14 folds halving a square, 16,384 faces, take 3.5 s; 17 take 4.5 minutes). A FOLD file folded all at once"
            + " keeps the faces its pattern has, whatever the limit")
    int maxFaces;

    @Option(names = "--fold-frames", description = "with --export-fold: a frame after each fold in its file_frames (its faces,"
            + " vertices in space, fold angles and face orders, on paper of no thickness), the folding sequence other tools play")
    boolean foldFrames;

    @Mixin
    PaperOutputs outputs = new PaperOutputs();

    @Mixin
    DiagramOutput diagrams = new DiagramOutput();

    @Override
    public Integer call() {
        if (maxFaces < 1) {
            throw UserError.usage("option --max-faces: must be at least 1, got " + maxFaces);
        }
        // Without a display it does the exports asked for and renders frames where the viewer was
        // wanted, as the demos and the wrap do.
        // The script first: a movie said to be rendered for a script that is not there, or is a
        // folder, was one line too many.
        if (Files.isDirectory(script)) {
            throw new UserError(script + ": is a folder, expected a fold script");
        }
        LoadedModel.requireRegularFile(script);
        if (Files.notExists(script)) {
            throw new UserError(script + ": no such file");
        }
        outputs.check("fold", spec.commandLine().getErr(), true);
        diagrams.check(outputs);
        if (foldFrames && outputs.exportFold == null) {
            throw UserError.usage("option --fold-frames: only with --export-fold, whose file holds the frames");
        }
        ScriptJob.Outcome folding;
        try {
            folding = ScriptJob.run(script, maxFaces, stage -> { });
        } catch (NoSuchFileException e) {
            throw new UserError(script + ": no such file");
        } catch (AccessDeniedException e) {
            throw new UserError(script + ": permission denied");
        } catch (IOException e) {
            throw new UserError(script + ": cannot read: " + e.getMessage());
        } catch (ScriptJob.Refused e) {
            throw new UserError(e.getMessage());
        }
        ScriptFolding.Result result = folding.result();
        long[] nanosPerFold = folding.nanosPerFold();
        PaperInSpace folded = folding.folded();
        PrintWriter out = spec.commandLine().getOut();
        Map<String, Object> figures = folding.figures();
        figures.put("timing", timing(nanosPerFold, result.steps()));
        // The FOLD file's folded state folds the script again on paper of no thickness: only where a
        // FOLD file is written or the layer order checked (from the same FOLD text, made in memory).
        List<FoldFile.Folded> sheets = outputs.checksLayerOrder() || outputs.prints() ? folding.sheets(maxFaces) : List.of();
        outputs.exportFold(sheets, "ifold fold " + script, figures, foldFrames ? steps(folding) : null);
        String method = folding.fromFoldFile() ? PrintJob.FOLD : PrintJob.SCRIPT;
        outputs.exportPrint(sheets, script.getFileName().toString(), method);
        diagrams.write(outputs, script.getFileName().toString(), method, folding::play);
        outputs.write(List.of(folded), result.sheet().thickness(), "iFold fold script " + script + ": " + folding.folds() + ", thickness "
                + result.sheet().thickness(), figures);
        int creases = ((Number) figures.get("creases")).intValue();
        int layers = ((Number) figures.get("maxLayers")).intValue();
        out.printf(Locale.ROOT, "%s: %s, %d %s at most, %d %s, isometry error %.1e%n", script.getFileName(), folding.folds(), layers,
                layers == 1 ? "layer" : "layers", creases, creases == 1 ? "crease" : "creases", (Double) figures.get("isometryError"));
        outputs.printChecksAndFiles(out);
        out.flush();

        Scene scene = new Scene();
        // The camera frames the paper as it stands, folding up.
        Animation animation = folding.play(scene);
        outputs.show(scene, animation, script.getFileName() + ": " + folding.folds(), outputs.frameOptions.seconds, false, spec);
        out.flush();
        return 0;
    }

    /** The frame after each fold, for --fold-frames: the script folded again on paper of no thickness. */
    private FoldSteps steps(ScriptJob.Outcome folding) {
        if (folding.form() != null) {
            throw UserError.usage("option --fold-frames: " + script.getFileName() + " folds every crease at once, in one step: --export-fold"
                    + " writes its crease pattern and its folded state");
        }
        try {
            return FoldSteps.of(folding.script(), maxFaces);
        } catch (FoldScriptException e) {
            throw new UserError(script + ": cannot be folded again without thickness for --fold-frames: " + e.getMessage());
        }
    }

    /**
     * How long folding took: in total, and per fold in each tenth of the script, with the paper
     * faces at the end of that tenth (as {@code faces} counts them: caps apart), to show how the
     * cost grows.
     */
    private static Map<String, Object> timing(long[] nanos, List<ScriptFolding.Step> folds) {
        Map<String, Object> timing = new LinkedHashMap<>();
        long total = 0;
        for (long n : nanos) {
            total += n;
        }
        timing.put("seconds", total * 1e-9);
        timing.put("millisecondsPerFold", nanos.length == 0 ? 0.0 : total * 1e-6 / nanos.length);
        if (nanos.length >= 10) {
            Map<String, Object> tenths = new LinkedHashMap<>();
            for (int tenth = 0; tenth < 10; tenth++) {
                int from = tenth * nanos.length / 10;
                int to = (tenth + 1) * nanos.length / 10;
                long sum = 0;
                for (int i = from; i < to; i++) {
                    sum += nanos[i];
                }
                Map<String, Object> row = new LinkedHashMap<>();
                row.put("millisecondsPerFold", sum * 1e-6 / Math.max(1, to - from));
                row.put("faces", folds.get(to - 1).facesAfter());
                tenths.put("folds " + (from + 1) + "-" + to, row);
            }
            timing.put("byTenth", tenths);
        }
        return timing;
    }
}
