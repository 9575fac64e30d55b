package ifold.cli;

import ifold.check.LayerOrder;
import ifold.check.PaperCollisions;
import ifold.foldfile.FoldFile;
import ifold.io.AtomicFile;
import ifold.job.Collisions;
import ifold.job.JobWatcher;
import ifold.job.Json;
import ifold.job.LayerOrders;
import ifold.job.PrintJob;
import ifold.mesh.IndexedPolygons;
import ifold.print.CreasePatternPages;
import ifold.print.Lengths;
import ifold.print.Page;
import ifold.render.RenderUnavailableException;
import ifold.render.ViewerWindow;
import ifold.scene.Animation;
import ifold.scene.Player;
import ifold.scene.Scene;
import ifold.scene.WrapPlayback;
import ifold.wrap.PaperInSpace;
import ifold.wrap.Wrap;
import ifold.wrap.WrapExport;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/**
 * What the commands that fold paper share: the folded paper as OBJ, the figures as JSON, and
 * the animation in a window or as frames ({@code --export-obj --report --no-view} and the frame
 * options). Every output is checked before any work, and written whole or not at all.
 */
final class PaperOutputs {
    @Option(names = "--export-obj", paramLabel = "FILE", description = "write the folded paper as OBJ: vt = paper coordinates, caps in group 'cap'; the paper written is checked for layers out of order and for collisions, a line each after the summary")
    Path exportObj;

    @Option(names = "--export-mesh", paramLabel = "FILE", description = "write the folded paper, caps included, as one mesh for"
            + " printing and other tools: .ply or .stl (binary), .off or .obj by its name")
    Path exportMesh;

    @Option(names = "--export-fold", paramLabel = "FILE.fold", description = "write the crease pattern and the folded state as a "
            + "FOLD file (docs/fold-format.md): Origami Simulator, Rabbit Ear and ORIPA read it")
    Path exportFold;

    @Option(names = "--report", paramLabel = "FILE", description = "write the figures of the result as JSON, the layer order and collisions of the paper among them (checked as for --export-obj)")
    Path report;

    @Option(names = "--export-pdf", paramLabel = "FILE.pdf", description = "print the crease pattern at real size as PDF: the"
            + " strip cut into numbered pieces a page wide, glue tabs and marks where they join, valleys dashed, mountains"
            + " dash-dot-dot, each crease numbered in folding order, a 5 cm scale bar (--paper-width, --page)")
    Path exportPdf;

    @Option(names = "--export-svg", paramLabel = "FILE.svg", description = "the same as SVG in millimetres, a file a page"
            + " (FILE-01.svg, ...) or one long strip with --page none; the lines' kinds are CSS classes (cut, valley,"
            + " mountain, flat, tab) for cutting machines")
    Path exportSvg;

    @Option(names = "--paper-width", paramLabel = "LENGTH",
            description = "how wide --export-pdf and --export-svg print the strip (or the sheet): 2cm, 20mm, 0.8in, or auto: 2cm for"
            + " a strip, a sheet (a fold script's square) as large as fits the page (default auto)")
    String paperWidth;

    @Option(names = "--page", paramLabel = "PAGE",
            description = "the page --export-pdf, --export-svg and --export-diagrams print on: a4, a4-landscape, letter,"
            + " letter-landscape, or none for one page as long as the strip (default a4)")
    String page;

    @Option(names = "--no-view", description = "do not open the viewer, nor render frames unless --frames asks")
    boolean noView;

    @Mixin
    FrameOptions frameOptions = new FrameOptions();

    /**
     * The movie a command writes where no window can open and neither frames nor a movie were
     * asked for, {@code name.mp4} ({@code name.gif} without ffmpeg), said on {@code err} with how
     * to get frames instead.
     */
    static Path movieWithoutDisplay(String name, PrintWriter err) {
        Path movie = Path.of(name + (ifold.image.Mp4Writer.available() ? ".mp4" : ".gif"));
        err.println("ifold: no display: rendering the animation into " + movie.toAbsolutePath()
                + " instead (--frames DIR for PNG frames, --movie FILE for another name)");
        return movie;
    }

    /** The page step diagrams and crease patterns are printed on. */
    Page printPage() {
        return printOptions.page();
    }

    /**
     * Refuses a print option given with nothing to print ({@code diagrams}: --export-diagrams, or
     * null): it would be ignored without a word.
     */
    void checkPrintOptionsUsed(Path diagrams) {
        if (paperWidth != null && !prints()) {
            throw UserError.usage("option --paper-width: only with --export-pdf or --export-svg, which print the crease pattern");
        }
        if (page != null && !prints() && diagrams == null) {
            throw UserError.usage("option --page: only with --export-pdf, --export-svg or --export-diagrams, which print pages");
        }
    }

    /**
     * Refuses two outputs that name one file, with {@code diagrams} (--export-diagrams, or null):
     * the second written would overwrite the first.
     */
    void checkDistinct(Path diagrams) {
        Object[][] named = {{"--export-obj", exportObj}, {"--export-mesh", exportMesh}, {"--report", report}, {"--export-fold", exportFold},
            {"--export-pdf", exportPdf}, {"--export-svg", exportSvg}, {"--movie", frameOptions.movie}, {"--export-diagrams", diagrams}};
        java.util.Map<Path, String> seen = new java.util.HashMap<>();
        for (Object[] output : named) {
            if (output[1] == null) {
                continue;
            }
            Path file = ((Path) output[1]).toAbsolutePath().normalize();
            String before = seen.putIfAbsent(file, (String) output[0]);
            if (before != null) {
                throw UserError.usage("option " + output[0] + ": " + output[1] + " is the file " + before
                        + " writes too: the second would overwrite the first");
            }
        }
    }

    /**
     * Checks every output before any work. With {@code movieWithoutDisplay}, where no window
     * can open and neither --frames nor --movie was given, the animation goes into one movie,
     * {@code name.mp4} ({@code name.gif} without ffmpeg), and it says where and how to get frames
     * instead: a first run on a server wants something to open, not thousands of PNGs.
     */
    void check(String name, PrintWriter err, boolean movieWithoutDisplay) {
        if (exportObj != null) {
            OutputFiles.checkWritableFile(exportObj, "--export-obj", ".obj");
        }
        if (exportMesh != null) {
            OutputFiles.checkWritableFile(exportMesh, "--export-mesh", ".ply", ".stl", ".off", ".obj");
        }
        if (report != null) {
            OutputFiles.checkWritableFile(report, "--report", ".json");
        }
        if (exportFold != null) {
            OutputFiles.checkWritableFile(exportFold, "--export-fold", ".fold");
        }
        if (exportPdf != null) {
            OutputFiles.checkWritableFile(exportPdf, "--export-pdf", ".pdf");
        }
        if (exportSvg != null) {
            OutputFiles.checkWritableFile(exportSvg, "--export-svg", ".svg");
        }
        try {
            printOptions = new CreasePatternPages.Options(Lengths.millimetres(paperWidth == null ? Lengths.AUTOMATIC : paperWidth),
                    Page.of(page == null ? Page.A4.optionName() : page));
        } catch (IllegalArgumentException e) {
            throw UserError.usage("option --" + (e.getMessage().startsWith("expected a4") ? "page" : "paper-width") + ": "
                    + e.getMessage());
        }
        if (movieWithoutDisplay && !frameOptions.renders() && !noView && !hasDisplay()) {
            frameOptions.movie = movieWithoutDisplay(name, err);
        }
        frameOptions.check();
    }

    /** The files this run wrote, to take back if a later output fails. */
    private final List<Path> written = new ArrayList<>();

    /**
     * Notes a file this run wrote, so that a later failure takes it back too, and says so once the
     * summary is out ({@link #printFiles}).
     */
    void wrote(Path file) {
        wrote(file, "wrote " + file);
    }

    /** As {@link #wrote(Path)}, said in {@code line}. */
    void wrote(Path file, String line) {
        written.add(file);
        wroteLines.add(line);
    }

    /**
     * Writes the sheets as a FOLD file if asked, and adds what its crease pattern holds to the
     * figures ({@code creasePattern}: mountains, valleys, flat creases, border edges); where
     * paper is exported at all (FOLD, OBJ, a mesh or a report), checks its layer order with the
     * independent checker, reading the FOLD file written (or its text), and adds
     * {@code layerOrder}.
     */
    void exportFold(List<FoldFile.Folded> sheets, String title, Map<String, Object> figures) {
        exportFold(sheets, title, figures, null);
    }

    /** As {@link #exportFold(List, String, Map)}, with a frame after each fold ({@code --fold-frames}), or none. */
    void exportFold(List<FoldFile.Folded> sheets, String title, Map<String, Object> figures, ifold.foldfile.FoldSteps steps) {
        writeFold(sheets, title, figures, steps);
        if (!checksLayerOrder()) {
            return;
        }
        long started = System.nanoTime();
        try {
            LayerOrder.Result result = LayerOrders.addTo(figures, sheets, title, exportFold);
            layerOrder = result != null ? result.summary() : "layer order: not checked: " + LayerOrders.notChecked(sheets);
        } catch (IOException e) {
            discardWritten();
            throw new UserError("option --export-fold: cannot read back " + exportFold + ": " + e.getMessage());
        }
        layerOrderSeconds = (System.nanoTime() - started) * 1e-9;
    }

    /** The strip's width on paper and the page, checked by {@link #check}. */
    private CreasePatternPages.Options printOptions;

    /** Whether the crease pattern is printed (PDF or SVG). */
    boolean prints() {
        return exportPdf != null || exportSvg != null;
    }

    /**
     * Prints the sheets' crease pattern as asked (PDF, SVG), {@code title} naming what was folded
     * and {@code method} how.
     */
    void exportPrint(List<FoldFile.Folded> sheets, String title, String method) {
        exportPrint(sheets, title, method, null);
    }

    /** As {@link #exportPrint(List, String, String)}, with a shape to print beside the strip (the demo's triangle). */
    void exportPrint(List<FoldFile.Folded> sheets, String title, String method, CreasePatternPages.Template template) {
        if (!prints()) {
            return;
        }
        CreasePatternPages pages;
        try {
            // Laid out once for both files: the crease pattern is the same.
            pages = PrintJob.layOut(new PrintJob.Request(sheets, title, method, printOptions, exportPdf != null ? exportPdf : exportSvg,
                    template), JobWatcher.NONE);
        } catch (IllegalArgumentException e) {
            discardWritten();
            throw UserError.usage((e.getMessage().startsWith("--page none") ? "option --page: " : "option --paper-width: ") + e.getMessage());
        }
        for (Path file : new Path[] {exportPdf, exportSvg}) {
            if (file == null) {
                continue;
            }
            try {
                PrintJob.Printed printed = PrintJob.write(pages, file, JobWatcher.NONE);
                written.addAll(printed.files());
                wroteLines.add(printed.summary());
            } catch (IOException e) {
                discardWritten();
                throw new UserError("cannot print the crease pattern: " + e.getMessage());
            }
        }
    }

    /** Whether the layer order is checked: where the paper is exported or reported. */
    boolean checksLayerOrder() {
        return exportFold != null || exportObj != null || exportMesh != null || report != null;
    }

    /** The layer-order check's line, once made; null before. */
    private String layerOrder;

    /** The seconds the layer-order check took, 0 where none was made. */
    double layerOrderSeconds;

    private void writeFold(List<FoldFile.Folded> sheets, String title, Map<String, Object> figures, ifold.foldfile.FoldSteps steps) {
        if (exportFold == null) {
            return;
        }
        try {
            FoldFile.Counts counts = FoldFile.write(exportFold, title, sheets, steps);
            wrote(exportFold);
            Map<String, Object> pattern = new java.util.LinkedHashMap<>();
            pattern.put("vertices", counts.vertices());
            pattern.put("faces", counts.faces());
            pattern.put("edges", counts.edges());
            pattern.put("mountains", counts.mountains());
            pattern.put("valleys", counts.valleys());
            pattern.put("flat", counts.flat());
            pattern.put("border", counts.border());
            pattern.put("faceOrders", counts.faceOrders());
            if (steps != null) {
                pattern.put("stepFrames", steps.size());
            }
            figures.put("creasePattern", pattern);
        } catch (IOException e) {
            discardWritten();
            throw new UserError("option --export-fold: cannot write " + exportFold + ": " + e.getMessage());
        }
    }

    /**
     * Writes folded paper (a fold script's, {@code thickness} thick, on planes of no model) as
     * OBJ under {@code header}, and its figures as JSON with its collisions, as asked.
     */
    void write(List<PaperInSpace> folded, double thickness, String header, Map<String, Object> figures) {
        try {
            if (exportObj != null) {
                WrapExport.writeObj(exportObj, header, folded);
                wrote(exportObj);
            }
            writeMesh(folded);
            checkCollisions(folded, thickness, null, figures);
            writeReport(figures);
        } catch (IOException e) {
            discardWritten();
            throw new UserError("cannot write: " + e.getMessage());
        }
    }

    /** Writes a wrap (or any folding on the sheet engine) as OBJ and its figures as JSON, as asked. */
    void write(Wrap.Result result, List<PaperInSpace> geometries, String source, Map<String, Object> figures) {
        try {
            if (exportObj != null) {
                WrapExport.writeObj(exportObj, source, result, geometries);
                wrote(exportObj);
            }
            writeMesh(geometries);
            checkCollisions(geometries, result.thickness(), result.mesh(), figures);
            writeReport(figures);
        } catch (IOException e) {
            discardWritten();
            throw new UserError("cannot write: " + e.getMessage());
        }
    }

    /** Writes the folded paper as one mesh ({@code --export-mesh}), where asked. */
    private void writeMesh(List<PaperInSpace> folded) throws IOException {
        if (exportMesh == null) {
            return;
        }
        ifold.mesh.io.MeshWriters.write(WrapExport.paperMesh(folded), exportMesh);
        wrote(exportMesh);
    }

    /** The collision check's line, once a run that exports paper has made it; null before. */
    private String collisions;

    /**
     * Where paper is exported (an OBJ, a mesh or a report), checks it for collisions with the
     * independent checker, reading the OBJ written (or its text), and adds {@code collisions}
     * to the figures; {@code model} is the surface it rests on, or null for none.
     */
    void checkCollisions(List<PaperInSpace> strips, double thickness, IndexedPolygons model, Map<String, Object> figures)
            throws IOException {
        if (exportObj == null && exportMesh == null && report == null) {
            return;
        }
        PaperCollisions.Result result = Collisions.addTo(figures, strips, thickness, model, exportObj);
        collisions = result != null ? result.summary() : "collisions: not checked: " + Collisions.notChecked(strips, thickness);
        collided = result != null && !result.isClean();
    }

    /** Whether the collision check ran and found paper crossing itself or the model. */
    boolean collided() {
        return collided;
    }

    private boolean collided;

    /**
     * The lines saying which files were written, kept for after the summary: what was made comes
     * first, then its checks, then where it went (and a failure, which takes the files back,
     * prints none of them).
     */
    private final List<String> wroteLines = new ArrayList<>();

    /**
     * Prints, after the command's summary line, the lines of the checks of the paper (its layer
     * order, its collisions), where they were made, then the files written.
     */
    void printChecksAndFiles(PrintWriter out) {
        if (layerOrder != null) {
            out.println(layerOrder);
        }
        if (collisions != null) {
            out.println(collisions);
        }
        printFiles(out);
    }

    /** Prints the files written since the last call, one line each. */
    void printFiles(PrintWriter out) {
        for (String line : wroteLines) {
            out.println(line);
        }
        wroteLines.clear();
    }

    private void writeReport(Map<String, Object> figures) throws IOException {
        if (report != null) {
            String json = Json.write(figures);
            AtomicFile.write(report, stream -> stream.write(json.getBytes(StandardCharsets.UTF_8)), true);
            wrote(report);
        }
    }

    /**
     * After a failure: removes what this run wrote and the frames folder it made (if still
     * empty), so that a failed run leaves nothing behind but frames already rendered.
     */
    void discardWritten() {
        for (Path file : written) {
            try {
                Files.deleteIfExists(file);
            } catch (IOException e) {
                // Nothing more to do: the error that brought us here is the one to report.
            }
        }
        written.clear();
        frameOptions.removeFolderIfUnused();
    }

    /**
     * Shows the animation in a window (playing at once if {@code autoplay}), or renders it into
     * frames; {@code defaultSeconds} is its length unless --seconds says otherwise.
     */
    void show(Scene scene, Animation animation, String title, double defaultSeconds, boolean autoplay, CommandSpec spec) {
        show(scene, animation, title, defaultSeconds, autoplay, spec, 4);
    }

    /** As {@link #show(Scene, Animation, String, double, boolean, CommandSpec)}, with {@code samples} per pixel of antialiasing. */
    void show(Scene scene, Animation animation, String title, double defaultSeconds, boolean autoplay, CommandSpec spec, int samples) {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        boolean secondsGiven = spec.commandLine().getParseResult().hasMatchedOption("--seconds");
        double seconds = secondsGiven ? frameOptions.seconds : defaultSeconds;
        if (animation instanceof ifold.scene.WrapPlayback playback) {
            playback.pace(seconds); // its folds laid out so that every caption can be read in the time it has
        }
        if (frameOptions.renders()) {
            frameOptions.export(scene, animation, Math.max(1, (int) Math.round(frameOptions.fps * seconds)), samples, out, err);
        } else if (!noView) {
            Player player = new Player(animation, seconds);
            if (autoplay) {
                player.togglePlaying(); // space pauses it
            }
            try {
                new ViewerWindow(scene, player, title, err, samples).show("iFold - " + title, 1280, 720, 0);
            } catch (RenderUnavailableException e) {
                discardWritten();
                throw new UserError(e.getMessage() + "; or render frames with --frames DIR or a movie with --movie FILE, or pass --no-view");
            }
        }
        out.flush();
    }

    /**
     * Whether a window can open: a display is set, and it is not the virtual one the launcher
     * started only to render frames.
     */
    static boolean hasDisplay() {
        String display = System.getenv("DISPLAY");
        return display != null && !display.isEmpty() && System.getenv("IFOLD_IN_XVFB") == null;
    }
}
