package ifold.cli;

import ifold.foldfile.FoldFile;
import ifold.geom.ParameterException;
import ifold.io.AtomicFile;
import ifold.job.Json;
import ifold.job.ModelFiles;
import ifold.job.PrintJob;
import ifold.job.Scenes;
import ifold.job.WrapJob;
import ifold.job.WrapPath;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.io.MeshWriters;
import ifold.scene.Animation;
import ifold.scene.Scene;
import ifold.wrap.LayerFloor;
import ifold.wrap.PaperInSpace;
import ifold.wrap.Seam;
import ifold.wrap.Wrap;
import ifold.wrap.WrapAnalysis;
import ifold.wrap.WrapExport;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code ifold wrap MODEL}: one strip of paper per component, folded over every triangle of the Hamiltonian path. */
@Command(name = "wrap", mixinStandardHelpOptions = true,
        description = {"Wraps a model in one strip of paper per component, the zig-zag way along the Hamiltonian path of its "
            + "refinement (Demaine, Demaine and Mitchell): passes across each triangle, a turn gadget and a fold over the "
            + "shared edge to the next. The paper rests on the model's flat convex pieces (a cube's face is one): it runs flat "
            + "over the edges inside one, and the excess beyond a piece's edges is tucked under it. Faces whose triangles have an "
            + "angle under 20 degrees are triangulated again, and followed where that makes less paper, or fewer layers where "
            + "thin triangles fan in a plane (a cone's base; the report's otherPath). The path is a cycle: "
            + "where it has at most 1,000 triangles in all and is likely to make at most 100,000 faces, the strip is tried beginning at four places round it and the wrap with "
            + "the fewest layers kept, of those whose paper the collision check finds sound where any is (the report's seam). An open surface is covered on the side its faces face. The animation plays the folds with the camera following the strip, then turns once around "
            + "the model; it takes two minutes unless --seconds says otherwise. In a window where there is a display; as "
            + "one movie, wrap.mp4, where there is none (--frames DIR for PNGs). The OBJ holds each strip as an object strip-K. "
            + "With --method hinge, a grid polyhedron (every face square to the axes, every corner on a lattice of cubes: a "
            + "polycube, a box) is wrapped by the hinge strip instead (Benbernou, Demaine, Demaine and Lubiw): a strip of squares "
            + "as wide as the lattice's, folded along the squares' sides and diagonals, twice the surface's area, two layers "
            + "everywhere."})
final class WrapCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MODEL", description = "an .off, .obj, .ply or .stl model")
    Path model;

    @Option(names = "--method", paramLabel = "METHOD", defaultValue = "zigzag",
            description = "zigzag (any polyhedron; the default) or hinge (a grid polyhedron)")
    String method;

    @Option(names = "--width", paramLabel = "W",
            description = "the strip's width (default and most: a third of the widest every triangle of the path takes, its smallest "
                + "altitude from the corner the strip enters by, wider strips' paper crossing itself; for the hinge strip, the "
                + "lattice's square, or that over a whole number)")
    Double width;

    @Option(names = "--thickness", paramLabel = "T", description = "the paper's thickness (default: the width / " + Wrap.WIDTHS_A_THICKNESS + ")")
    Double thickness;

    @Option(names = "--max-faces", paramLabel = "N", defaultValue = "" + Wrap.DEFAULT_MAX_FACES,
            description = "the most faces of paper the wrap may make, about " + Wrap.BYTES_PER_FACE + " bytes of memory each (default ${DEFAULT-VALUE}: a gibibyte's worth;"
                + " a default width that would pass it widens to fit, up to the widest)")
    int maxFaces;

    @Option(names = "--strict", description = "refuse defective input instead of repairing it")
    boolean strict;

    @Mixin
    PaperOutputs outputs = new PaperOutputs();

    @Mixin
    DiagramOutput diagrams = new DiagramOutput();

    @Override
    public Integer call() {
        Wrap.Method how = switch (method) {
            case "zigzag" -> Wrap.Method.ZIGZAG;
            case "hinge" -> Wrap.Method.HINGE;
            default -> throw new CommandLine.ParameterException(spec.commandLine(),
                    "Invalid value for option '--method': '" + method + "' (zigzag or hinge)");
        };
        Wrap.Options options;
        try { // checked before the model is read: what can be checked without it
            options = new Wrap.Options(Defaults.orDefault(width, "width"), Defaults.orDefault(thickness, "thickness"), null, maxFaces);
        } catch (ParameterException e) {
            throw UserError.usage(e);
        }
        // The model first: a movie said to be rendered for a model that is not there was one line too many.
        if (java.nio.file.Files.isDirectory(model)) {
            throw new UserError(model + ": is a folder, expected a model file"); // as the loader says it
        }
        LoadedModel.requireRegularFile(model);
        if (java.nio.file.Files.notExists(model)) {
            throw new UserError(model + ": no such file");
        }
        outputs.check("wrap", spec.commandLine().getErr(), true);
        diagrams.check(outputs);
        try {
            return wrap(options, how);
        } catch (UserError | CommandLine.ParameterException e) {
            outputs.discardWritten(); // the frames folder check() made, or files written before the failure
            throw e;
        }
    }

    private int wrap(Wrap.Options options, Wrap.Method how) {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Path exportObj = outputs.exportObj;
        Path report = outputs.report;
        WrapJob.Outcome wrapped;
        ProgressBar.WrapBar bar = ProgressBar.wrapping(err);
        try {
            wrapped = WrapJob.run(new WrapJob.Request(model, new MeshBuilder.Options(strict, true), options, how), new WrapJob.Watcher() {
                @Override
                public void wrapped(int done, int total) {
                    bar.wrapped(done, total);
                }

                @Override
                public boolean stopped() {
                    return false;
                }

                @Override
                public void stage(String what) {
                    bar.stage(what);
                }

                @Override
                public void note(String line) {
                    bar.wipe();
                    err.println("ifold: " + line);
                    err.flush();
                }
            });
        } catch (ModelFiles.LoadFailure e) {
            throw LoadedModel.refusal(e);
        } catch (ParameterException e) {
            throw UserError.usage(e);
        } catch (Wrap.FaceLimitException e) {
            throw new UserError(model + ": cannot wrap: " + e.getMessage() + " (--max-faces raises the limit)");
        } catch (Wrap.WrapException | WrapJob.Refused e) {
            throw new UserError(model + ": cannot wrap: " + e.getMessage());
        } finally {
            bar.wipe(); // before the summary or the error
        }
        HalfedgeMesh mesh = wrapped.mesh();
        Wrap.Result result = wrapped.result();
        List<PaperInSpace> geometries = wrapped.geometries();
        Map<String, Object> figures = wrapped.figures();
        long analysedAt = System.nanoTime();
        List<Path> written = new ArrayList<>();
        try {
            // Each stage in place of the bar where the run is long: a big model's checks take as long as its folds.
            if (exportObj != null) {
                bar.stage("writing " + exportObj.getFileName());
                WrapExport.writeObj(exportObj, WrapExport.aboutCentre(model.toString(), wrapped.movedBy()), result, geometries);
                written.add(exportObj);
                outputs.wrote(exportObj);
            }
            if (outputs.exportMesh != null) {
                bar.stage("writing " + outputs.exportMesh.getFileName());
                MeshWriters.write(WrapExport.paperMesh(geometries), outputs.exportMesh);
                written.add(outputs.exportMesh);
                outputs.wrote(outputs.exportMesh);
            }
            List<FoldFile.Folded> sheets = new ArrayList<>();
            for (Wrap.Strip strip : result.strips()) {
                sheets.add(new FoldFile.Folded(strip.sheet(), result.frames()));
            }
            if (outputs.checksLayerOrder()) {
                bar.stage("checking the layer order");
            }
            outputs.exportFold(sheets, "ifold wrap " + model, figures);
            if (outputs.exportFold != null) {
                written.add(outputs.exportFold);
            }
            outputs.exportPrint(sheets, model.getFileName().toString(), PrintJob.wrap(result.method()) + ", "
                    + result.strips().size() + (result.strips().size() == 1 ? " strip" : " strips"));
            diagrams.write(outputs, model.getFileName().toString(), PrintJob.wrap(result.method()), in -> Scenes.wrap(in, mesh, result, geometries));
            long exportedAt = System.nanoTime();
            if (exportObj != null || outputs.exportMesh != null || report != null) {
                bar.stage("checking the paper for collisions");
            }
            outputs.checkCollisions(geometries, result.thickness(), mesh, figures);
            long writtenAt = System.nanoTime();
            Map<String, Object> seconds = new LinkedHashMap<>();
            seconds.put("load", wrapped.seconds().load());
            seconds.put("refine", wrapped.seconds().refine());
            seconds.put("wrap", wrapped.seconds().wrap());
            seconds.put("analyse", wrapped.seconds().analyse());
            seconds.put("export", (exportedAt - analysedAt) * 1e-9 - outputs.layerOrderSeconds);
            seconds.put("layerOrder", outputs.layerOrderSeconds);
            seconds.put("collisions", (writtenAt - exportedAt) * 1e-9);
            figures.put("seconds", seconds);
            if (report != null) {
                String json = Json.write(figures);
                AtomicFile.write(report, stream -> stream.write(json.getBytes(StandardCharsets.UTF_8)), true);
                written.add(report);
                outputs.wrote(report);
            }
        } catch (IOException e) {
            throw new UserError("cannot write: " + e.getMessage());
        } finally {
            bar.wipe(); // before the summary or the error
        }
        out.println(summary(model, mesh, wrapped.path(), result, wrapped.analysis()));
        outputs.printChecksAndFiles(out);
        out.flush();
        String hinge = WrapJob.hingeInstead(model.toString(), mesh, result.method(), outputs.collided());
        if (hinge != null) {
            err.println("ifold: " + hinge + " (--method hinge)");
        }
        if (outputs.frameOptions.frames != null || !outputs.noView) {
            show(mesh, result, geometries, written);
        }
        return 0;
    }

    /** The model, solid, and the strips laid over it along the path; then a turn around it. */
    private void show(HalfedgeMesh mesh, Wrap.Result result, List<PaperInSpace> geometries, List<Path> written) {
        Scene scene = new Scene();
        Animation animation = Scenes.wrap(scene, mesh, result, geometries);
        if (!outputs.frameOptions.renders()) { // a window, where C shows them
            Scenes.collisions(scene, geometries, result.thickness(), mesh);
        }
        // Layer on layer of paper makes multisampling dear on a software renderer (4 samples a
        // pixel: 16 frames/s for the cube; none: 60), and the layers' edges are what the eye follows.
        outputs.show(scene, animation, model.getFileName() + ": " + result.strips().size() + (result.strips().size() == 1 ? " strip" : " strips"), 120, true, spec, 0);
    }

    /** The hinge strip's line: squares and passes, the strip, its folds by kind, layers, efficiency, coverage. */
    static String hingeSummary(Path model, HalfedgeMesh mesh, WrapPath path, Wrap.Result result, WrapAnalysis analysis) {
        return String.format(Locale.ROOT, "%s: %d %s -> %d squares of side %.4g, %d passes (%d turning), %s, "
                + "%d diagonal turns, %d edge crossings, %d layers at most (a stack of %d), paper efficiency %.3f, coverage %s, "
                + "isometry error %.1e", model, mesh.faceCount(), mesh.faceCount() == 1 ? "triangle" : "triangles",
                path.squares().count(), path.squares().spacing(), path.tour().passes(), path.tour().turnCount(), paper(result),
                result.count(Wrap.Kind.DIAGONAL_TURN), result.count(Wrap.Kind.EDGE_CROSSING), analysis.maxLayers(),
                analysis.stackLevels(), analysis.surfaceArea() / analysis.paperArea(), coverage(analysis.coverage()), analysis.isometryError());
    }

    /** The strips' sizes: one as its size, several as their width and lengths, not as one strip as long as all. */
    private static String paper(Wrap.Result result) {
        double length = 0;
        double longest = 0;
        for (Wrap.Strip strip : result.strips()) {
            length += strip.sheet().length();
            longest = Math.max(longest, strip.sheet().length());
        }
        int strips = result.strips().size();
        return strips == 1
                ? String.format(Locale.ROOT, "1 strip %.4g x %.4g (L/w %.1f)", length, result.width(), length / result.width())
                : String.format(Locale.ROOT, "%d strips %.4g wide, %.4g long in all (the longest %.4g, L/w %.1f)", strips,
                        result.width(), length, longest, longest / result.width());
    }

    static String summary(Path model, HalfedgeMesh mesh, WrapPath path, Wrap.Result result, WrapAnalysis analysis) {
        if (path.hinge()) {
            return hingeSummary(model, mesh, path, result, analysis);
        }
        String paper = paper(result);
        // Faces triangulated again say so: the path's triangles then come from those.
        String prepared = !path.prepared() ? "" : String.format(Locale.ROOT, " -> %d prepared (%d of %d planar regions)",
                path.preparation().trianglesAfter(), path.preparation().prepared(), path.preparation().regions());
        // A floor of one says nothing; a sharper vertex's floor tells which layers no strip avoids.
        LayerFloor floor = LayerFloor.of(result.mesh());
        String atLeast = floor.layers() < 2 ? "" : String.format(Locale.ROOT, "; at least %d for any strip, at a vertex of %.3g degrees",
                floor.layers(), Math.toDegrees(floor.angleSum()));
        // Thick layers standing back from concave edges say how far: the OBJ's faces there are not their paper's shape.
        String creep = !(analysis.creep() > 0) ? ""
                : String.format(Locale.ROOT, " (layers creep up to %.1f T at concave edges)", analysis.creep() / result.thickness());
        return String.format(Locale.ROOT, "%s: %d %s%s -> %d on the path, %s, "
                + "%d turn folds, %d gadget folds, %d edge crossings, %d tucks, %d layers at most (a stack of %d%s), "
                + "paper efficiency %.3f, coverage %s, isometry error %.1e%s", model, mesh.faceCount(),
                mesh.faceCount() == 1 ? "triangle" : "triangles", prepared, result.mesh().faceCount(),
                paper, result.count(Wrap.Kind.ZIGZAG_TURN),
                result.count(Wrap.Kind.TURN_GADGET), result.count(Wrap.Kind.EDGE_CROSSING), result.count(Wrap.Kind.TUCK),
                analysis.maxLayers(), analysis.stackLevels(), atLeast, analysis.surfaceArea() / analysis.paperArea(),
                coverage(analysis.coverage()), analysis.isometryError(), creep);
    }

    /**
     * The share of the surface the paper covers: 1.000 where it is whole but for rounding, else
     * with as many digits as show what is bare, and how much (a scan's 0.99997 was "1.000").
     */
    static String coverage(double coverage) {
        double bare = 1 - coverage;
        if (!(bare > Seam.COVERAGE_TOLERANCE)) {
            return String.format(Locale.ROOT, "%.3f", Math.min(coverage, 1));
        }
        int digits = Math.max(3, (int) Math.ceil(-Math.log10(bare)) + 1);
        return String.format(Locale.ROOT, "%." + digits + "f (%.2g %% of the surface bare)", coverage, 100 * bare);
    }
}
