package ifold.job;

import ifold.mesh.MeshBuilder;
import java.nio.file.Path;
import java.util.Map;

/**
 * What a model is, as a surface, as {@code ifold info} and the window's Model information both
 * tell it: read and built as it is (its faces kept, not triangulated), repaired unless strict,
 * and its counts and topology measured ({@link ModelInfo}).
 */
public final class InfoJob {
    private InfoJob() {
    }

    /** The model file, and whether a defect the builder could repair is refused instead. */
    public record Request(Path model, boolean strict) {
    }

    /**
     * Reads, builds and measures the model: the figures of {@code ifold info --json}.
     *
     * @throws ModelFiles.LoadFailure where the file cannot be read or built, or its repairs leave no faces
     * @throws java.util.concurrent.CancellationException once the watcher says stop
     */
    public static Map<String, Object> run(Request request, JobWatcher watcher) throws ModelFiles.LoadFailure {
        Path model = request.model();
        ModelFiles.Loaded loaded = ModelFiles.loadSurface(model, new MeshBuilder.Options(request.strict(), false), "describe", watcher);
        watcher.stopIfAsked();
        watcher.stage("measuring " + model.getFileName());
        return ModelInfo.of(model.toString(), loaded.read(), loaded.inputVertices(), loaded.inputFaces(), loaded.built());
    }
}
