package ifold.cli;

import ifold.job.JobWatcher;
import ifold.job.PrintJob;
import ifold.scene.Animation;
import ifold.scene.Scene;
import java.io.IOException;
import java.nio.file.Path;
import java.util.function.Function;
import picocli.CommandLine.Option;

/** {@code --export-diagrams FILE.pdf}: step diagrams, a panel a fold (a wrap's: a panel a triangle of its path). */
final class DiagramOutput {
    @Option(names = "--export-diagrams", paramLabel = "FILE.pdf", description = "draw step diagrams as PDF: a title page with"
            + " the folded paper and the steps listed, then a panel a fold (a wrap's: a triangle of its path), six to a"
            + " page (--page letter, a4-landscape, ...), each showing the paper as the fold begins, its crease and an arrow"
            + " for its motion in origami's notation, numbered and captioned as the movie captions it")
    Path file;

    /** Checks the file, and that no other output of {@code outputs} names it (the second would overwrite the first). */
    void check(PaperOutputs outputs) {
        if (file != null) {
            OutputFiles.checkWritableFile(file, "--export-diagrams", ".pdf");
        }
        outputs.checkDistinct(file);
        outputs.checkPrintOptionsUsed(file);
    }

    /**
     * Draws the diagrams if asked: {@code animationIn} puts the movie's animation in the scene it
     * is given (a fresh one, not the viewer's).
     */
    void write(PaperOutputs outputs, String title, String method, Function<Scene, Animation> animationIn) {
        if (file == null) {
            return;
        }
        try {
            Scene scene = new Scene();
            Animation animation = animationIn.apply(scene);
            PrintJob.Printed printed = PrintJob.diagrams(title, method, scene, animation, file, outputs.printPage(), JobWatcher.NONE);
            outputs.wrote(file, printed.stepsSummary());
        } catch (IOException e) {
            outputs.discardWritten();
            throw new UserError("cannot draw the step diagrams: " + e.getMessage());
        }
    }
}
