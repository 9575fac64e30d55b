package ifold.cli;

import ifold.job.BuiltInModels;
import ifold.job.GenerateJob;
import ifold.job.JobWatcher;
import ifold.geom.ParameterException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code ifold generate SHAPE -o OUT}: the models iFold makes itself (those in models/, and big tori for benchmarks). */
@Command(name = "generate", mixinStandardHelpOptions = true,
        description = "Writes one of the built-in models: tetrahedron, cube, octahedron, icosahedron, icosphere, torus, triangle,"
            + " figure3; or a polycube (unit cubes on the grid, its surface of unit squares): box (--size), the l, t and plus"
            + " shapes, a staircase, or a random polycube (--cubes, --seed).")
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

    @Option(names = "--size", paramLabel = "AxBxC", defaultValue = "2x1x1", description = "box: its sides in unit cubes (default ${DEFAULT-VALUE})")
    String size;

    @Option(names = "--cubes", paramLabel = "N", defaultValue = "50", description = "polycube: how many unit cubes, grown at random so"
            + " that its surface stays a sphere (default ${DEFAULT-VALUE}, at most " + BuiltInModels.MOST_RANDOM_CUBES + ")")
    int cubes;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1", description = "polycube: the seed it grows from; the same seed, the"
            + " same polycube (default ${DEFAULT-VALUE})")
    long seed;

    @Override
    public Integer call() {
        // An option the shape does not take was ignored in silence (generate cube --size 3x3x3).
        // Each shape's parameters are the options of the same names.
        for (BuiltInModels.Shape taker : BuiltInModels.Shape.values()) {
            for (String option : BuiltInModels.parametersOf(taker)) {
                if (spec.commandLine().getParseResult().hasMatchedOption("--" + option) && !BuiltInModels.parametersOf(shape).contains(option)) {
                    throw UserError.usage("option --" + option + ": only " + taker + " takes it, not " + shape);
                }
            }
        }
        OutputFiles.checkWritableFile(output, "-o", ".off", ".obj", ".ply", ".stl");
        String[] sides = size.strip().toLowerCase(java.util.Locale.ROOT).split("x", -1);
        int[] box = new int[sides.length];
        try {
            for (int k = 0; k < sides.length; k++) {
                box[k] = Integer.parseInt(sides[k].strip());
            }
        } catch (NumberFormatException e) {
            throw UserError.usage("option --size: expected three whole numbers AxBxC, such as 3x2x1, got '" + size + "'");
        }
        GenerateJob.Made made;
        try {
            made = GenerateJob.run(new GenerateJob.Request(shape, around, across, subdivisions, new BuiltInModels.Grid(box, cubes, seed), output,
                    ascii), JobWatcher.NONE);
        } catch (ParameterException e) {
            if (e.parameter().equals(BuiltInModels.SEGMENTS)) {
                throw UserError.usage("options --around and --across: " + e.getMessage());
            }
            throw UserError.usage("option --" + e.parameter() + ": " + e.getMessage());
        } catch (IOException e) {
            throw new UserError(output + ": cannot write: " + e.getMessage());
        }
        spec.commandLine().getOut().println("wrote " + output + ": " + made.vertices() + " vertices, " + made.faces() + " faces");
        return 0;
    }
}
