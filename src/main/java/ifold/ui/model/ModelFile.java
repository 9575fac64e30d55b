package ifold.ui.model;

import ifold.job.InfoJob;
import ifold.job.ModelFiles;
import ifold.mesh.MeshBuilder;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;

/**
 * A model file read and built into a halfedge mesh, for the window's jobs on it (the wrap, its
 * information, its refinement), by {@link ModelFiles} as the command line reads it. Every way
 * that fails is a {@link JobFailure} at the model's field, in the command line's one line.
 *
 * @param inputVertices vertices in the file
 * @param inputFaces faces in the file
 * @param built the halfedge mesh and its repairs
 */
public record ModelFile(int inputVertices, int inputFaces, ifold.mesh.io.MeshReaders.Read read, MeshBuilder.Result built) {

    /**
     * Reads and builds {@code file}; in strict mode a defect the builder could repair is refused.
     *
     * @throws java.util.concurrent.CancellationException if the progress was cancelled after reading
     */
    public static ModelFile load(Path file, MeshBuilder.Options options, Progress progress) throws JobFailure {
        try {
            ModelFiles.Loaded loaded = ModelFiles.load(file, options, progress.watcher());
            return new ModelFile(loaded.inputVertices(), loaded.inputFaces(), loaded.read(), loaded.built());
        } catch (ModelFiles.LoadFailure e) {
            throw failure(e);
        }
    }

    /** Refuses a model its repairs left without faces, naming the repairs: there is nothing to {@code what} ("wrap", "refine"). */
    public void requireFaces(Path file, String what) throws JobFailure {
        String refusal = ModelFiles.noFacesLeft(file, built, "nothing to " + what);
        if (refusal != null) {
            throw new JobFailure(new Problem("model", refusal));
        }
    }

    /**
     * What the model is, as a surface: the figures of {@code ifold info --json}, read and built
     * as {@code ifold info} does (faces kept as they are, not triangulated).
     */
    public static Map<String, Object> information(Path file, boolean strict, Progress progress) throws JobFailure {
        try {
            return InfoJob.run(new InfoJob.Request(file, strict), progress.watcher());
        } catch (ModelFiles.LoadFailure e) {
            throw failure(e);
        }
    }

    /** Whether {@code file} is named as a model iFold reads: .off, .obj, .ply or .stl, in any case. */
    public static boolean isModelName(Path file) {
        return ifold.mesh.io.MeshReaders.isModel(file);
    }

    /** Whether {@code file} is named as a model iFold writes: .off, .obj, .ply or .stl, in any case. */
    public static boolean isWritableModelName(Path file) {
        return ifold.mesh.io.MeshWriters.writes(file);
    }

    static String readError(Path file, IOException e) {
        return ModelFiles.readError(file, e);
    }

    /** A model file that cannot be read or built, as the window says it: at the model's field, and how to let strict mode repair it. */
    static JobFailure failure(ModelFiles.LoadFailure e) {
        return new JobFailure(new Problem("model", e.getMessage() + (e.repairable() ? " (clear Strict to repair it)" : "")));
    }
}
