package ifold.cli;

import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.io.MeshWriters;
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

    enum Shape { tetrahedron, cube, octahedron, icosahedron, icosphere, torus, triangle, figure3 }

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SHAPE", description = "one of: ${COMPLETION-CANDIDATES}")
    Shape shape;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT", description = "where to write it (.off or .obj)")
    Path output;

    @Option(names = "--around", defaultValue = "24", description = "torus: segments around the ring (default ${DEFAULT-VALUE})")
    int around;

    @Option(names = "--across", defaultValue = "12", description = "torus: segments around the tube (default ${DEFAULT-VALUE})")
    int across;

    @Option(names = "--subdivisions", defaultValue = "3", description = "icosphere: times each triangle is cut in four (default ${DEFAULT-VALUE}: 1,280 triangles)")
    int subdivisions;

    @Override
    public Integer call() {
        OutputFiles.checkWritableFile(output, "-o", ".off", ".obj");
        if (shape == Shape.torus && (around < 3 || across < 3 || (long) around * across > 50_000_000L)) {
            throw UserError.usage("options --around and --across: each must be at least 3, and their product at most 50000000");
        }
        if (shape == Shape.icosphere && (subdivisions < 0 || subdivisions > 8)) {
            throw new CommandLine.ParameterException(spec.commandLine(), "option --subdivisions: must be 0 to 8, got " + subdivisions);
        }
        PolygonSoup soup = switch (shape) {
            case tetrahedron -> Solids.tetrahedron();
            case cube -> Solids.cube();
            case octahedron -> Solids.octahedron();
            case icosahedron -> Solids.icosahedron();
            case icosphere -> Solids.icosphere(subdivisions);
            case torus -> Solids.torus(3, 1, around, across);
            case triangle -> Solids.triangle();
            case figure3 -> Solids.figure3();
        };
        try {
            MeshWriters.write(soup, output);
        } catch (IOException e) {
            throw new UserError(output + ": cannot write: " + e.getMessage());
        }
        spec.commandLine().getOut().println("wrote " + output + ": " + soup.vertexCount() + " vertices, "
                + soup.faceCount() + " faces");
        return 0;
    }
}
