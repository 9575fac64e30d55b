package ifold.cli;

import ifold.job.InfoJob;
import ifold.job.Json;
import ifold.job.ModelFiles;
import java.io.PrintWriter;
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
        PrintWriter err = spec.commandLine().getErr();
        Map<String, Object> report;
        try {
            report = InfoJob.run(new InfoJob.Request(model, strict), LoadedModel.printingNotes(err));
        } catch (ModelFiles.LoadFailure e) {
            throw LoadedModel.refusal(e);
        }
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
