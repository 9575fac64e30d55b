package ifold.job;

import ifold.foldfile.CreasePattern;
import ifold.foldfile.FoldJson;
import ifold.script.FoldScript;
import ifold.script.FoldScriptException;
import ifold.script.ScriptFolding;
import ifold.wrap.PaperInSpace;
import java.io.IOException;
import java.nio.file.Path;
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
            long[] nanosPerFold, boolean fromFoldFile) {
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
        try {
            if (FoldJson.isFoldFile(file)) {
                pattern = CreasePattern.read(file);
                parsed = pattern.script();
            } else {
                parsed = FoldScript.read(file);
            }
            nanosPerFold = new long[parsed.steps().size()];
            stage.accept("folding " + parsed.steps().size() + " folds");
            if (pattern != null) {
                CreasePattern.Folding folding = pattern.fold(nanosPerFold, maxFaces);
                parsed = folding.script(); // some lines may have been folded the other way
                result = folding.result();
            } else {
                result = parsed.play(nanosPerFold, maxFaces);
            }
        } catch (CreasePattern.Refused e) {
            throw new Refused(file + ": " + e.getMessage());
        } catch (FoldScriptException e) {
            if (pattern != null) {
                throw new Refused(file + ": cannot be folded one crease line at a time in this order: " + e.getMessage());
            }
            throw new Refused(file + (e.line() > 0 ? ":" + e.getMessage().replaceFirst("^line ", "") : ": " + e.getMessage()));
        }
        PaperInSpace folded = PaperInSpace.of(result.sheet(), result.frames());
        return new Outcome(parsed, result, folded, Reports.script(result, folded), nanosPerFold, pattern != null);
    }
}
