package ifold.cli;

import ifold.job.JobWatcher;
import ifold.job.ModelFiles;
import ifold.mesh.Defect;
import ifold.mesh.MeshBuilder;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Map;

/**
 * A model file read and built ({@link ModelFiles}, as the window reads it), for the commands:
 * every way that can fail is a {@link UserError} naming the file and, where known, the line.
 */
final class LoadedModel {
    private final ModelFiles.Loaded loaded;

    private LoadedModel(ModelFiles.Loaded loaded) {
        this.loaded = loaded;
    }

    /** Refuses a folder, a pipe, a device or a socket before reading it (see {@link ModelFiles#notAFile}). */
    static void requireRegularFile(Path file) {
        String refusal = ModelFiles.notAFile(file);
        if (refusal != null) {
            throw new UserError(refusal);
        }
    }

    static LoadedModel load(Path file, MeshBuilder.Options options) {
        try {
            return new LoadedModel(ModelFiles.load(file, options));
        } catch (ModelFiles.LoadFailure e) {
            throw refusal(e);
        }
    }

    /** A model file that cannot be read or built, as the commands say it: how to let strict mode repair it, where it could. */
    static UserError refusal(ModelFiles.LoadFailure e) {
        return new UserError(e.getMessage() + (e.repairable() ? " (run without --strict to repair)" : ""));
    }

    int inputVertices() {
        return loaded.inputVertices();
    }

    int inputFaces() {
        return loaded.inputFaces();
    }

    /** The format read, in words, and the corners welded (STL; -1 for others). */
    ifold.mesh.io.MeshReaders.Read read() {
        return loaded.read();
    }

    MeshBuilder.Result built() {
        return loaded.built();
    }

    double parseSeconds() {
        return loaded.parseSeconds();
    }

    double buildSeconds() {
        return loaded.buildSeconds();
    }

    Map<Defect, Integer> repairs() {
        return loaded.repairs();
    }

    /** Refuses a model its repairs left without faces, in one line that names the repairs (rather than a line per repair and then the refusal). */
    void requireFaces(Path file, String what) {
        String refusal = loaded.noFacesLeft(file, what);
        if (refusal != null) {
            throw new UserError(refusal);
        }
    }

    /** One line on {@code err} for each kind of repair made, with its count. */
    void reportRepairs(Path file, PrintWriter err) {
        JobWatcher printing = printingNotes(err);
        for (String note : ModelFiles.repairNotes(file, loaded.repairs())) {
            printing.note(note);
        }
    }

    /** A job's watcher for the commands: each note printed on {@code err} as "ifold: NOTE", as {@link #reportRepairs} prints them. */
    static JobWatcher printingNotes(PrintWriter err) {
        return new JobWatcher() {
            @Override
            public void note(String line) {
                err.println("ifold: " + line);
                err.flush();
            }
        };
    }
}
