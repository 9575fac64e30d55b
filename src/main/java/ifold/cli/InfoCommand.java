package ifold.cli;

import ifold.job.Json;
import ifold.mesh.Defect;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.MeshValidator;
import ifold.mesh.Topology;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
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

    @Parameters(index = "0", paramLabel = "MODEL", description = "an .off or .obj model")
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
        HalfedgeMesh mesh = loaded.built().mesh();
        Topology topology = Topology.of(mesh);
        boolean valid = MeshValidator.validate(mesh).isEmpty();
        Map<Defect, Integer> repairs = loaded.repairs();
        // The input was manifold if nothing had to be split or cut to make it so.
        boolean manifold = !repairs.containsKey(Defect.NON_MANIFOLD_EDGE) && !repairs.containsKey(Defect.NON_MANIFOLD_VERTEX);
        Map<String, Object> report = new LinkedHashMap<>();
        report.put("file", model.toString());
        report.put("inputVertices", loaded.inputVertices());
        report.put("inputFaces", loaded.inputFaces());
        report.put("vertices", topology.vertices());
        report.put("faces", topology.faces());
        report.put("edges", topology.edges());
        report.put("faceSizes", faceSizes(mesh));
        report.put("boundaryLoops", topology.boundaryLoops());
        report.put("closed", topology.boundaryLoops() == 0);
        report.put("components", topology.components());
        report.put("eulerCharacteristic", topology.eulerCharacteristic());
        report.put("genus", topology.genus());
        report.put("manifold", manifold);
        report.put("valid", valid);
        Map<String, Object> repaired = new LinkedHashMap<>();
        new TreeMap<>(repairs).forEach((defect, count) -> repaired.put(defect.name().toLowerCase(Locale.ROOT), count));
        report.put("repairs", repaired);
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

    /** How many faces have each number of sides, e.g. {3: 176, 4: 496}. */
    private static Map<String, Object> faceSizes(HalfedgeMesh mesh) {
        TreeMap<Integer, Integer> sizes = new TreeMap<>();
        for (int f = 0; f < mesh.faceCount(); f++) {
            sizes.merge(mesh.faceSize(f), 1, Integer::sum);
        }
        Map<String, Object> result = new LinkedHashMap<>();
        sizes.forEach((size, count) -> result.put(Integer.toString(size), count));
        return result;
    }
}
