package ifold.job;

import ifold.foldfile.CreasePattern;
import ifold.foldfile.FoldFile;
import ifold.foldfile.FoldedForm;
import ifold.foldfile.FoldJson;
import ifold.scene.Animation;
import ifold.scene.Scene;
import ifold.script.FoldScript;
import ifold.script.FoldScriptException;
import ifold.script.ScriptFolding;
import ifold.wrap.PaperInSpace;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * A fold script or a FOLD crease pattern folded, as {@code ifold fold} and the window's Fold,
 * Play a script both do it: the file read (a FOLD file is told by its content, and folded one
 * crease line at a time), each fold played on the sheet, the paper placed in space, and the
 * figures of its report. The front ends read what the user asked, run it, and present what it
 * returns; each says a file that cannot be read in its own words.
 */
public final class ScriptJob {
    private ScriptJob() {
    }

    /**
     * The file folded.
     *
     * @param script the folds played: a FOLD file's crease lines as folded (some may have been
     *     folded the other way than the file first said)
     * @param folded the paper in space
     * @param figures the report's figures ({@link Reports#script})
     * @param nanosPerFold how long each fold took
     * @param fromFoldFile whether the file was a FOLD crease pattern
     */
    public record Outcome(FoldScript script, ScriptFolding.Result result, PaperInSpace folded, Map<String, Object> figures,
            long[] nanosPerFold, boolean fromFoldFile, FoldedForm.Result form) {
        /**
         * The folded sheet as a FOLD file, a print or the layer-order check read it: a script's
         * folded again on paper of no thickness where it has some (FOLD's folded state is of
         * ideal paper); a FOLD file folded all at once, as it is (its hosts are the planes).
         */
        public List<FoldFile.Folded> sheets(int maxFaces) {
            return List.of(form != null ? new FoldFile.Folded(form.sheet(), form.frames()) : FoldFile.Folded.ofScript(script, result, maxFaces));
        }

        /** The folding, played in {@code scene}: fold by fold, or every crease at once. */
        public Animation play(Scene scene) {
            return form != null ? Scenes.form(scene, form, folded) : Scenes.script(scene, result, folded);
        }

        /** What was folded, in a few words: "20 folds", or "12 creases folded at once (its fold angles)". */
        public String folds() {
            if (form != null) {
                return form.creases() + (form.creases() == 1 ? " crease" : " creases") + " folded at once (" + form.kind().words() + ")";
            }
            int folds = result.steps().size();
            return folds + (folds == 1 ? " fold" : " folds");
        }
    }

    /** The file holds no folds iFold can play: the line or the key, and why, after the file's name. */
    public static final class Refused extends Exception {
        private static final long serialVersionUID = 1L;

        Refused(String message) {
            super(message);
        }
    }

    /**
     * Folds {@code file}, making at most {@code maxFaces} faces of paper.
     *
     * @param stage told the stage that begins: "folding 12 folds"
     * @throws IOException where the file cannot be read
     * @throws Refused where it is not a script or crease pattern iFold can fold
     */
    public static Outcome run(Path file, int maxFaces, java.util.function.Consumer<String> stage) throws IOException, Refused {
        CreasePattern pattern = null;
        FoldScript parsed;
        ScriptFolding.Result result;
        long[] nanosPerFold;
        Map<String, Object> fold = null;
        try {
            if (FoldJson.isFoldFile(file)) {
                fold = FoldJson.read(file);
                // Checked whole whichever way it folds: its keys, indices and edges.
                FoldedForm.check(fold);
                try {
                    pattern = CreasePattern.of(fold);
                } catch (CreasePattern.Refused e) {
                    // Not a rectangle creased from border to border: folded all at once instead.
                    return allAtOnce(file, fold, stage);
                }
                parsed = pattern.script();
            } else {
                parsed = FoldScript.read(file);
            }
            nanosPerFold = new long[parsed.steps().size()];
            stage.accept("folding " + parsed.steps().size() + " folds");
            if (pattern != null) {
                CreasePattern.Folding folding;
                try {
                    folding = pattern.fold(nanosPerFold, maxFaces);
                } catch (CreasePattern.NotInOrder e) {
                    return allAtOnce(file, fold, stage);
                }
                parsed = folding.script(); // some lines may have been folded the other way
                result = folding.result();
                int stated = FoldedForm.statedStack(fold);
                if (stated > 0 && result.sheet().stackLevels() > stated) {
                    // The file's own folded state stacks its paper lower than its lines folded one
                    // at a time do (a hinge strip's on some polycubes): fold it as the file has it.
                    try {
                        return allAtOnce(file, fold, stage);
                    } catch (Refused notAtOnce) {
                        // keep the line-by-line folding
                    }
                }
                if (!layersHold(parsed, result, maxFaces)) {
                    // Folded line by line its layers cross (a flap through the paper): all at once,
                    // its order found from the pattern, where that finds one.
                    try {
                        return allAtOnce(file, fold, stage);
                    } catch (Refused notAtOnce) {
                        // keep the line-by-line folding: its report says what is wrong
                    }
                }
            } else {
                result = parsed.play(nanosPerFold, maxFaces);
            }
        } catch (CreasePattern.Refused e) {
            throw new Refused(file + ": " + e.getMessage());
        } catch (FoldScriptException e) {
            if (pattern != null) {
                // Its lines cannot be folded one at a time in its order: all at once, then.
                return allAtOnce(file, fold, stage);
            }
            throw new Refused(file + (e.line() > 0 ? ":" + e.getMessage().replaceFirst("^line ", "") : ": " + e.getMessage()));
        }
        PaperInSpace folded = PaperInSpace.of(result.sheet(), result.frames());
        return new Outcome(parsed, result, folded, Reports.script(result, folded), nanosPerFold, pattern != null, null);
    }

    /**
     * The most faces times layers whose layer order is checked after a line-by-line folding, to
     * fall back on folding at once: the check reads every pair of layers, and a pleat of 1,000
     * layers (a million pairs) would take twice as long again as its folding.
     */
    static final long MOST_CHECKED_LAYERS = 100_000;

    /** Whether a FOLD crease pattern folded line by line has a valid layer order, as the independent check reads its FOLD text. */
    private static boolean layersHold(FoldScript script, ScriptFolding.Result result, int maxFaces) {
        if ((long) result.sheet().faceCount() * result.sheet().stackLevels() > MOST_CHECKED_LAYERS) {
            return true;
        }
        try {
            String text = FoldFile.text("check", List.of(FoldFile.Folded.ofScript(script, result, maxFaces)));
            return ifold.check.LayerOrder.check(text).valid();
        } catch (java.io.IOException e) {
            return true; // made in memory: cannot fail to be read
        }
    }

    /** A FOLD file folded with every crease at once ({@link FoldedForm}). */
    private static Outcome allAtOnce(Path file, Map<String, Object> fold, java.util.function.Consumer<String> stage) throws Refused {
        stage.accept("folding every crease at once");
        long start = System.nanoTime();
        FoldedForm.Result form;
        try {
            form = FoldedForm.fold(fold);
        } catch (CreasePattern.Refused e) {
            throw new Refused(file + ": " + e.getMessage());
        }
        ScriptFolding.Result result = new ScriptFolding.Result(form.sheet(), form.frames(), List.of());
        PaperInSpace folded = PaperInSpace.of(form.sheet(), form.frames());
        Map<String, Object> figures = Reports.script(result, folded);
        figures.put("folding", "all at once: " + form.kind().words());
        figures.put("foldedCreases", form.creases());
        return new Outcome(null, result, folded, figures, new long[] {System.nanoTime() - start}, true, form);
    }
}
