package ifold.cli;

import ifold.job.Json;
import ifold.job.RefineJob;
import ifold.job.Reports;
import ifold.job.WrapPath;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.io.MeshWriters;
import ifold.refine.FacePreparation;
import ifold.refine.HamiltonianRefinement;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code ifold refine MODEL -o OUT}: the Hamiltonian refinement, faces written in path order. */
@Command(name = "refine", mixinStandardHelpOptions = true,
        description = {"Refines a model so that one path crosses every triangle once (Arkin, Held, Mitchell, Skiena).",
            "OUT lists the triangles in path order: consecutive faces share an edge, components one after another."})
final class RefineCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MODEL", description = "an .off, .obj, .ply or .stl model")
    Path model;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "OUT", description = "where to write the refined mesh (.off, .obj, .ply or .stl)")
    Path output;

    @Option(names = "--ascii", description = "write PLY and STL as text (they are binary by default; OFF and OBJ are text)")
    boolean ascii;

    @Option(names = "--json", description = "print counts, angles, repairs and timings as JSON")
    boolean json;

    @Option(names = "--strict", description = "refuse defective input instead of repairing it")
    boolean strict;

    @Option(names = "--prepare", description = "first triangulate again the faces whose triangles have an angle under "
            + FacePreparation.TARGET_ANGLE + " degrees, as ifold wrap does: the refinement is then the path the wrap follows (a cycle, which the wrap may begin "
            + "at another of its triangles)")
    boolean prepare;

    @Override
    public Integer call() throws IOException {
        OutputFiles.checkWritableFile(output, "-o", ".off", ".obj", ".ply", ".stl");
        LoadedModel loaded = LoadedModel.load(model, new MeshBuilder.Options(strict, true));
        loaded.requireFaces(model, "nothing to refine");
        loaded.reportRepairs(model, spec.commandLine().getErr());
        HalfedgeMesh mesh = loaded.built().mesh();
        if (mesh.faceCount() == 0) {
            throw new UserError(model + ": no faces left to refine");
        }
        long start = System.nanoTime();
        RefineJob.Outcome refined = RefineJob.run(mesh, prepare);
        WrapPath path = refined.prepared();
        HamiltonianRefinement.Result result = refined.refinement();
        String kept = path != null ? path.keptNote(model.toString()) : null;
        if (kept != null) {
            spec.commandLine().getErr().println("ifold: " + kept);
            spec.commandLine().getErr().flush();
        }
        long refinedAt = System.nanoTime();
        try {
            MeshWriters.write(result.mesh(), output, ascii);
        } catch (IOException e) {
            throw new UserError("cannot write " + e.getMessage());
        }
        long written = System.nanoTime();
        double minIn = refined.minAngleIn();
        double minOut = refined.minAngleOut();

        var out = spec.commandLine().getOut();
        if (json) {
            Map<String, Object> report = new LinkedHashMap<>();
            report.put("input", model.toString());
            report.put("output", output.toString());
            report.putAll(refined.figures());
            report.put("repairs", Reports.repairs(loaded.repairs()));
            Map<String, Object> seconds = new LinkedHashMap<>();
            seconds.put("parse", loaded.parseSeconds());
            seconds.put("build", loaded.buildSeconds());
            seconds.put("refine", (refinedAt - start) * 1e-9);
            seconds.put("write", (written - refinedAt) * 1e-9);
            report.put("seconds", seconds);
            out.print(Json.write(report));
        } else {
            String prepared = path == null ? "" : String.format(java.util.Locale.ROOT, " -> %d prepared (%d of %d planar regions, min angle %.3f)",
                    path.preparation().trianglesAfter(), path.preparation().prepared(), path.preparation().regions(),
                    path.preparation().minAngleAfter());
            out.printf(java.util.Locale.ROOT, "%s: %d %s in %d %s%s -> %d triangles (5n-2c), min angle %.3f -> %.3f degrees%n",
                    model, mesh.faceCount(), mesh.faceCount() == 1 ? "triangle" : "triangles", result.componentCount(),
                    result.componentCount() == 1 ? "component" : "components", prepared, result.mesh().faceCount(), minIn, minOut);
            out.println("wrote " + output + " (faces in path order)");
        }
        out.flush();
        return 0;
    }
}
