package ifold.cli;

import ifold.job.Json;
import ifold.job.ModelInfo;
import ifold.mesh.MeshBuilder;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code ifold info MODEL}: what a model is, as a surface, after loading and repair. */
@Command(name = "info", mixinStandardHelpOptions = true,
        description = "Loads a model, builds and validates its halfedge mesh, and prints its counts and topology.")
final class InfoCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MODEL", description = "an .off, .obj, .ply or .stl model")
    java.nio.file.Path model;

    @Option(names = "--json", description = "print as JSON")
    boolean json;

    @Option(names = "--strict", description = "refuse defective input instead of repairing it")
    boolean strict;

    @Override
    public Integer call() {
        LoadedModel loaded = LoadedModel.load(model, new MeshBuilder.Options(strict, false));
        loaded.requireFaces(model, "nothing to describe");
        loaded.reportRepairs(model, spec.commandLine().getErr());
        Map<String, Object> report = ModelInfo.of(model.toString(), loaded.read(), loaded.inputVertices(), loaded.inputFaces(), loaded.built());
        var out = spec.commandLine().getOut();
        if (json) {
            out.print(Json.write(report));
        } else {
            for (Map.Entry<String, Object> entry : report.entrySet()) {
                Object value = entry.getValue();
                if (value instanceof Map<?, ?> map) {
                    value = map.isEmpty() ? "none" : map.toString().replaceAll("[{}]", "");
                }
                out.println(entry.getKey() + ": " + value);
            }
        }
        out.flush();
        return 0;
    }
}
