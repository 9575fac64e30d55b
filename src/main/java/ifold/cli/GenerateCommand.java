package ifold.cli;

import ifold.job.BuiltInModels;
import ifold.job.GenerateJob;
import ifold.job.JobWatcher;
import ifold.geom.ParameterException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code ifold generate SHAPE -o OUT}: the models iFold makes itself (those in models/, and big tori for benchmarks). */
@Command(name = "generate", mixinStandardHelpOptions = true,
        description = "Writes one of the built-in models: tetrahedron, cube, octahedron, icosahedron, icosphere, torus, triangle, figure3.")
final class GenerateCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SHAPE", description = "one of: ${COMPLETION-CANDIDATES}")
    BuiltInModels.Shape shape;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT", description = "where to write it (.off, .obj, .ply or .stl)")
    Path output;

    @Option(names = "--ascii", description = "write PLY and STL as text (they are binary by default; OFF and OBJ are text)")
    boolean ascii;

    @Option(names = "--around", paramLabel = "N", defaultValue = "" + BuiltInModels.DEFAULT_AROUND, description = "torus: segments around the ring (default ${DEFAULT-VALUE})")
    int around;

    @Option(names = "--across", paramLabel = "N", defaultValue = "" + BuiltInModels.DEFAULT_ACROSS, description = "torus: segments around the tube (default ${DEFAULT-VALUE})")
    int across;

    @Option(names = "--subdivisions", paramLabel = "N", defaultValue = "" + BuiltInModels.DEFAULT_SUBDIVISIONS, description = "icosphere: times each triangle is cut in four (default ${DEFAULT-VALUE}: 1,280 triangles)")
    int subdivisions;

    @Override
    public Integer call() {
        OutputFiles.checkWritableFile(output, "-o", ".off", ".obj", ".ply", ".stl");
        GenerateJob.Made made;
        try {
            made = GenerateJob.run(new GenerateJob.Request(shape, around, across, subdivisions, output, ascii), JobWatcher.NONE);
        } catch (ParameterException e) {
            if (e.parameter().equals(BuiltInModels.SEGMENTS)) {
                throw UserError.usage("options --around and --across: " + e.getMessage());
            }
            throw new CommandLine.ParameterException(spec.commandLine(), "option --" + e.parameter() + ": " + e.getMessage());
        } catch (IOException e) {
            throw new UserError(output + ": cannot write: " + e.getMessage());
        }
        spec.commandLine().getOut().println("wrote " + output + ": " + made.vertices() + " vertices, " + made.faces() + " faces");
        return 0;
    }
}
