package ifold.ui.model;

import ifold.foldfile.FoldFile;
import ifold.scene.Animation;
import ifold.scene.Scene;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

/**
 * A job done: what to show, the folds to step through, the figures of its report, and how
 * to write it out. Its scene belongs to the view; {@link #newScene()} makes another for an
 * export, which may run while the view plays its own.
 *
 * @param job what was planned
 * @param title the result in a few words, for the window's title and the status line
 * @param shown the scene and animation for the view
 * @param folds every fold in order, with where the animation has made it
 * @param figures the report, as {@code --report} writes it
 * @param seconds how long the animation plays at speed 1 (the command line's default length)
 * @param scenes makes a new scene of the result, for an export
 * @param obj writes the folded paper as OBJ; null for a job that folds no paper (a model's view)
 * @param sheets the folded sheets, for FOLD; none for a job that folds no paper
 * @param source what the OBJ and FOLD files say they hold
 * @param figureStages where the zig-zag demo's figure (the seed's Figure 11) shows the
 *     animation, or null for a job that has none
 */
public record Plan(Job job, String title, Shown shown, List<Fold> folds, Map<String, Object> figures, double seconds,
        Supplier<Shown> scenes, Writer obj, List<FoldFile.Folded> sheets, String source, double[] figureStages) {

    /** A scene and the animation that plays it. */
    public record Shown(Scene scene, Animation animation) {
    }

    /** Writes the result to a file, whole or not at all. */
    @FunctionalInterface
    public interface Writer {
        void write(Path file) throws IOException;
    }

    /** The animation's length, in its own steps. */
    public int stepCount() {
        return shown.animation().stepCount();
    }

    /** A new scene of the result, for an export: the view's own keeps playing. */
    public Shown newScene() {
        return scenes.get();
    }

    /** Whether the job folded paper, for OBJ and FOLD: a model's view folds none. */
    public boolean hasPaper() {
        return obj != null;
    }

    /** Writes the folded paper as OBJ, as {@code --export-obj} does. */
    public void writeObj(Path file) throws IOException {
        obj.write(file);
    }

    /** Writes the crease pattern and the folded state as a FOLD file, as {@code --export-fold} does. */
    public FoldFile.Counts writeFold(Path file) throws IOException {
        return FoldFile.write(file, source, sheets);
    }
}
