package ifold.cli;

import ifold.fold.Folder;
import ifold.fold.Paper;
import ifold.fold.PaperAnalysis;
import ifold.scene.Animation;
import ifold.scene.Geometry;
import ifold.scene.PaperView;
import ifold.scene.Scene;
import ifold.script.FoldScript;
import ifold.script.FoldScriptException;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.AccessDeniedException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.joml.Quaterniond;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code ifold fold SCRIPT}: plays a fold script, in the viewer or as frames, and exports the result. */
@Command(name = "fold", mixinStandardHelpOptions = true,
        description = {"Plays a fold script (docs/fold-scripts.md): each fold swings from 0 to its angle.",
            "Without --frames it plays in the viewer (space plays, arrows step through the folds)."})
final class FoldCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCRIPT", description = "a fold script")
    Path script;

    @Mixin
    PaperOutputs outputs = new PaperOutputs();

    @Override
    public Integer call() {
        outputs.check("fold", spec.commandLine().getErr(), false);
        FoldScript parsed;
        List<Folder.Prepared> folds;
        long[] nanosPerFold;
        try {
            parsed = FoldScript.read(script);
            nanosPerFold = new long[parsed.steps().size()];
            folds = parsed.play(nanosPerFold);
        } catch (NoSuchFileException e) {
            throw new UserError(script + ": no such file");
        } catch (AccessDeniedException e) {
            throw new UserError(script + ": permission denied");
        } catch (IOException e) {
            throw new UserError(script + ": cannot read: " + e.getMessage());
        } catch (FoldScriptException e) {
            outputs.frameOptions.removeFolderIfUnused();
            throw new UserError(script + (e.line() > 0 ? ":" + e.getMessage().replaceFirst("^line ", "") : ": " + e.getMessage()));
        }
        Paper start = parsed.paper();
        Paper end = folds.isEmpty() ? start : folds.get(folds.size() - 1).at(1);
        PrintWriter out = spec.commandLine().getOut();
        Map<String, Object> figures = figures(parsed, folds.size(), end);
        figures.put("timing", timing(nanosPerFold, folds));
        outputs.write(end, figures, out);
        out.printf(Locale.ROOT, "%s: %d folds, %d layers at most, %d creases, isometry error %.1e%n", script.getFileName(),
                folds.size(), figures.get("maxLayers"), figures.get("creases"), (Double) figures.get("isometryError"));
        out.flush();

        Scene scene = new Scene();
        Geometry geometry = new Geometry("paper", PaperView.mesh(start), PaperView.MATERIAL);
        scene.root().attach(geometry);
        scene.camera().setOrientation(new Quaterniond().rotateX(-0.75).rotateZ(-0.35));
        scene.frameAll();
        Animation animation = PaperView.folding(geometry, start, folds);
        outputs.show(scene, animation, script.getFileName() + ": " + folds.size() + " folds", outputs.frameOptions.seconds, false,
                spec);
        out.flush();
        return 0;
    }

    private static Map<String, Object> figures(FoldScript script, int folds, Paper paper) {
        int caps = 0;
        for (int f = 0; f < paper.faceCount(); f++) {
            caps += paper.isCap(f) ? 1 : 0;
        }
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("folds", folds);
        figures.put("thickness", paper.thickness());
        figures.put("vertices", paper.vertexCount());
        figures.put("faces", paper.faceCount() - caps);
        figures.put("capFacets", caps);
        figures.put("creases", paper.creaseCount());
        figures.put("maxLayers", PaperAnalysis.maxLayers(paper));
        figures.put("paperArea", PaperAnalysis.paperArea(paper));
        figures.put("isometryError", PaperAnalysis.isometryError(paper));
        return figures;
    }

    /**
     * How long folding took: in total, and per fold in each tenth of the script, with the faces
     * and layers at the end of that tenth, to show how the cost grows.
     */
    private static Map<String, Object> timing(long[] nanos, List<Folder.Prepared> folds) {
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
                Paper after = folds.get(to - 1).paper();
                Map<String, Object> row = new LinkedHashMap<>();
                row.put("millisecondsPerFold", sum * 1e-6 / Math.max(1, to - from));
                row.put("faces", after.faceCount());
                row.put("vertices", after.vertexCount());
                tenths.put("folds " + (from + 1) + "-" + to, row);
            }
            timing.put("byTenth", tenths);
        }
        return timing;
    }
}
