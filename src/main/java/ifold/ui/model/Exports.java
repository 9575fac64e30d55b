package ifold.ui.model;

import ifold.image.FrameSink;
import ifold.image.FrameWriter;
import ifold.image.GifWriter;
import ifold.image.Mp4Writer;
import ifold.io.AtomicFile;
import ifold.job.CancellableMesh;
import ifold.job.Json;
import ifold.job.PrintJob;
import ifold.job.Scenes;
import ifold.job.TriangleText;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.io.MeshWriters;
import ifold.print.CreasePatternPages;
import ifold.refine.HamiltonianRefinement;
import ifold.scene.WrapPlayback;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Writing a plan out, as the command line's output options do: frames, a movie, OBJ, FOLD, the
 * report; and a model's refinement, as {@code ifold refine} does. Each is written whole or not
 * at all: the writers work under temporary names and a frame export that does not finish takes
 * back its frames, so a cancelled export (its progress's {@link Progress#check()} throws between
 * frames) leaves no file behind.
 */
public final class Exports {
    private Exports() {
    }

    /**
     * How frames and movies are rendered, as {@code --size --fps --seconds --no-captions} say.
     *
     * @param seconds the movie's length
     */
    public record FrameSettings(int width, int height, int fps, double seconds, boolean captions) {
        public static final FrameSettings DEFAULT = new FrameSettings(1280, 720, 30, 10, true);

        /** The frames in all. */
        public int frameCount() {
            return Math.max(1, (int) Math.round(fps * seconds));
        }

        /** What is wrong with these settings for {@code movie} (null for frames only), as the command line says it. */
        public List<Problem> check(Path movie) {
            List<Problem> problems = new ArrayList<>();
            if (width < 16 || height < 16 || width > 8192 || height > 8192) {
                problems.add(new Problem("size", "each side must be between 16 and 8192 pixels, got " + width + "x" + height));
            }
            if (fps < 1 || fps > 240) {
                problems.add(new Problem("fps", "must be between 1 and 240, got " + fps));
            }
            if (!(seconds > 0) || seconds > 3600) {
                problems.add(new Problem("seconds", "must be more than 0 and at most 3600, got " + seconds));
            }
            if (movie != null) {
                if (isGif(movie)) {
                    if (fps > GifWriter.MAX_FPS) {
                        problems.add(new Problem("fps", "a GIF keeps at most " + GifWriter.MAX_FPS + " frames a second, got " + fps
                                + "; write an .mp4 for more"));
                    }
                } else if (!isMp4(movie)) {
                    problems.add(new Problem("movie", "a movie is an .mp4 or a .gif, got " + movie.getFileName()));
                } else if (width % 2 != 0 || height % 2 != 0) {
                    problems.add(new Problem("size", "an MP4 needs an even width and height, got " + width + "x" + height));
                } else if (!Mp4Writer.available()) {
                    problems.add(new Problem("movie", "writing an .mp4 needs ffmpeg, which is not installed; or write a .gif"));
                }
            }
            return problems;
        }
    }

    /**
     * The file name a Save dialog suggests for an export of {@code job}'s result with {@code extension}:
     * the model's or the script's name (the demos': zigzag, turn) and the extension; where that
     * is the job's own file's name, with "-export" added, so that saving as suggested never
     * writes over what was opened.
     */
    public static String suggestedName(Job job, String extension) {
        Path source = job instanceof Job.WrapModel w ? w.model() : job instanceof Job.View v ? v.model()
                : job instanceof Job.Script s ? s.file() : null;
        String stem = job instanceof Job.ZigZag ? "zigzag" : job instanceof Job.Turn ? "turn" : source == null ? "ifold" : stem(source);
        String name = stem + "." + extension;
        return source != null && name.equals(source.getFileName().toString()) ? stem + "-export." + extension : name;
    }

    private static String stem(Path file) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return dot > 0 ? name.substring(0, dot) : name;
    }

    static boolean isGif(Path movie) {
        return movie.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gif");
    }

    static boolean isMp4(Path movie) {
        return movie.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".mp4");
    }

    /** Renders the plan into a movie (.mp4 through ffmpeg, or .gif), on a scene of its own. */
    public static Renderer.Rendered movie(Renderer renderer, Plan plan, Path movie, FrameSettings settings, Progress progress)
            throws JobFailure {
        requireValid(settings.check(movie));
        progress.stage("rendering " + movie.getFileName());
        try (FrameSink sink = isGif(movie) ? new GifWriter(movie, settings.width(), settings.height(), settings.fps())
                : new Mp4Writer(movie, settings.width(), settings.height(), settings.fps())) {
            return render(renderer, plan, sink, settings, progress);
        } catch (IOException e) {
            throw new JobFailure("cannot write " + movie + ": " + e.getMessage());
        }
    }

    /** Renders the plan into {@code folder}/frame_00000.png, ...; the folder is made if it is not there. */
    public static Renderer.Rendered frames(Renderer renderer, Plan plan, Path folder, FrameSettings settings, Progress progress)
            throws JobFailure {
        requireValid(settings.check(null));
        boolean made = false;
        try {
            if (!Files.isDirectory(folder)) {
                Files.createDirectory(folder);
                made = true;
            }
        } catch (IOException e) {
            throw new JobFailure("cannot make the folder " + folder + ": " + e.getMessage());
        }
        progress.stage("rendering frames into " + folder.getFileName());
        boolean finished = false;
        try (FrameSink sink = new FrameWriter(folder)) {
            Renderer.Rendered result = render(renderer, plan, sink, settings, progress);
            finished = true;
            return result;
        } catch (IOException e) {
            throw new JobFailure("cannot write frames to " + folder + ": " + e.getMessage());
        } finally {
            if (made && !finished) {
                try {
                    Files.deleteIfExists(folder); // empty again: the writer took back its frames
                } catch (IOException e) {
                    // Something else was put there meanwhile: it stays.
                }
            }
        }
    }

    private static Renderer.Rendered render(Renderer renderer, Plan plan, FrameSink sink, FrameSettings settings, Progress progress)
            throws IOException, JobFailure {
        Plan.Shown shown = plan.newScene();
        if (shown.animation() instanceof ifold.scene.WrapPlayback playback) {
            playback.pace(settings.seconds()); // as the command line's movies: every caption long enough to read
        }
        progress.check();
        try {
            // Unfinished, the sink is closed without finishing: its output is discarded.
            return renderer.frames(shown.scene(), shown.animation(), sink, settings.width(), settings.height(),
                    settings.frameCount(), settings.captions(), (done, total) -> {
                        progress.check();
                        progress.done(done, total);
                    });
        } catch (Renderer.Unavailable e) {
            throw new JobFailure(e.getMessage());
        }
    }

    /**
     * Writes the zig-zag demo's figure (the seed's Figure 11 re-made: four stages, 800 by 500
     * each), as {@code ifold demo zigzag --figure} does.
     */
    public static void figure(Renderer renderer, Plan plan, Path file, Progress progress) throws JobFailure {
        if (plan.figureStages() == null) {
            throw new JobFailure("the figure is the zig-zag demo's: Fold, Zig-zag a triangle first");
        }
        progress.stage("rendering " + file.getFileName());
        Plan.Shown shown = plan.newScene();
        progress.check();
        try {
            renderer.panel(shown.scene(), shown.animation(), plan.figureStages(), Scenes.FIGURE11_LABELS, 2, 800, 500, 4, file);
        } catch (Renderer.Unavailable e) {
            throw new JobFailure(e.getMessage());
        } catch (IOException e) {
            throw new JobFailure("cannot write " + file + ": " + e.getMessage());
        }
    }

    /** Writes the folded paper as OBJ. */
    public static void obj(Plan plan, Path file, Progress progress) throws JobFailure {
        requirePaper(plan);
        progress.stage("writing " + file.getFileName());
        try {
            plan.writeObj(file);
        } catch (IOException e) {
            throw new JobFailure("cannot write " + file + ": " + e.getMessage());
        }
    }

    /** Writes the crease pattern and folded state as FOLD. */
    public static void fold(Plan plan, Path file, Progress progress) throws JobFailure {
        requirePaper(plan);
        progress.stage("writing " + file.getFileName());
        try {
            plan.writeFold(file);
        } catch (IOException e) {
            throw new JobFailure("cannot write " + file + ": " + e.getMessage());
        }
    }

    /** A wrap checked: the check's lines, as {@code ifold check} prints them, and whether every check holds. */
    public record Checked(List<String> lines, boolean holds) {
    }

    /**
     * Checks a wrap as {@code ifold check} does, by the independent checkers alone: its paper
     * written as OBJ and FOLD into a folder of its own, read back against the model's file, the
     * folder taken back whatever happens.
     */
    public static Checked check(Plan plan, Progress progress) throws JobFailure {
        if (!(plan.job() instanceof Job.WrapModel wrap)) {
            throw new JobFailure("only a wrap of a model is checked: Fold, Wrap the model first");
        }
        Path folder;
        try {
            folder = Files.createTempDirectory("ifold-check");
        } catch (IOException e) {
            throw new JobFailure("cannot make a folder for the check's files: " + e.getMessage());
        }
        try {
            Path paper = folder.resolve(suggestedName(plan.job(), "obj"));
            Path fold = folder.resolve(suggestedName(plan.job(), "fold"));
            // Should the window close mid-check (its cancel is heard between the check's stages),
            // the files go as the program ends: the folder registered first, deleted last.
            folder.toFile().deleteOnExit();
            paper.toFile().deleteOnExit();
            fold.toFile().deleteOnExit();
            obj(plan, paper, progress);
            progress.check();
            fold(plan, fold, progress);
            progress.check();
            ifold.job.CheckJob.Checked checked = ifold.job.CheckJob.run(new ifold.job.CheckJob.Request(wrap.model(), paper, fold, Double.NaN, -1,
                    ifold.job.CheckJob.DEFAULT_SAMPLES, wrap.strict()), progress.watcher());
            List<String> lines = new ArrayList<>(ifold.job.CheckJob.lines(checked, wrap.model().getFileName().toString()));
            if (checked.failures().contains("collisions") && wrap.method() == ifold.wrap.Wrap.Method.ZIGZAG) {
                String hinge = ifold.job.WrapJob.hingeInstead(wrap.model().getFileName().toString(), ifold.job.ModelFiles.load(wrap.model(),
                        new ifold.mesh.MeshBuilder.Options(wrap.strict(), true)).built().mesh(), wrap.method(), true);
                if (hinge != null) {
                    lines.add(hinge + " (Method: Hinge strip)");
                }
            }
            return new Checked(lines, checked.holds());
        } catch (ifold.job.ModelFiles.LoadFailure e) {
            throw new JobFailure(e.getMessage());
        } catch (ifold.job.CheckJob.Unreadable e) {
            throw new JobFailure(e.getMessage());
        } finally {
            deleteAll(folder);
        }
    }

    /** Deletes a folder of files this class made; what cannot be deleted stays, as a temporary file would. */
    private static void deleteAll(Path folder) {
        try (var files = Files.list(folder)) {
            for (Path file : (Iterable<Path>) files::iterator) {
                Files.deleteIfExists(file);
            }
            Files.deleteIfExists(folder);
        } catch (IOException e) {
            // left in the temporary folder, where the system clears it
        }
    }

    /**
     * Prints the crease pattern at real size, as {@code --export-pdf} and {@code --export-svg} do:
     * PDF or SVG by the file's name, the strip {@code options} wide on its pages.
     */
    public static PrintJob.Printed creasePattern(Plan plan, Path file, CreasePatternPages.Options options, Progress progress)
            throws JobFailure {
        requirePaper(plan);
        try {
            CreasePatternPages.Template template = plan.job() instanceof Job.ZigZag zigzag && !plan.sheets().isEmpty()
                    ? PrintJob.triangle(TriangleText.parse(zigzag.triangle()), plan.sheets().get(0).frames()[0],
                            plan.sheets().get(0).sheet()) : null;
            return PrintJob.run(new PrintJob.Request(plan.sheets(), plan.source(), printedMethod(plan.job()), options, file, template),
                    progress.watcher());
        } catch (IllegalArgumentException e) {
            throw new JobFailure(new Problem("paperWidth", e.getMessage()));
        } catch (IOException e) {
            throw new JobFailure("cannot write " + file + ": " + e.getMessage());
        }
    }

    /**
     * Draws step diagrams of the plan, as {@code --export-diagrams} does: a title page and a panel
     * a fold (a wrap's: a triangle of its path), from a new scene of the result, on pages of
     * {@code page}'s size.
     */
    public static PrintJob.Printed diagrams(Plan plan, Path file, ifold.print.Page page, Progress progress) throws JobFailure {
        requirePaper(plan);
        Plan.Shown shown = plan.newScene();
        try {
            return PrintJob.diagrams(plan.source(), printedMethod(plan.job()), shown.scene(), shown.animation(), file, page,
                    progress.watcher());
        } catch (IOException e) {
            throw new JobFailure("cannot write " + file + ": " + e.getMessage());
        }
    }

    /** How the job folded, for a printed page's header. */
    static String printedMethod(Job job) {
        if (job instanceof Job.ZigZag) {
            return PrintJob.ZIGZAG;
        }
        if (job instanceof Job.Turn) {
            return PrintJob.TURN;
        }
        if (job instanceof Job.WrapModel w) {
            return PrintJob.wrap(w.method());
        }
        return PrintJob.SCRIPT;
    }

    /** Writes the plan's figures as the {@code --report} JSON. */
    public static void report(Plan plan, Path file, Progress progress) throws JobFailure {
        progress.stage("writing " + file.getFileName());
        String json = Json.write(plan.figures());
        try {
            AtomicFile.write(file, out -> out.write(json.getBytes(StandardCharsets.UTF_8)), true);
        } catch (IOException e) {
            throw new JobFailure("cannot write " + file + ": " + e.getMessage());
        }
    }

    /** A refinement written: the model's triangles, and the refinement's (5n - 2c for c components). */
    public record Refined(int inputTriangles, int components, int outputTriangles) {
    }

    /**
     * Writes the Hamiltonian refinement of {@code model} to {@code file} (.off, .obj, .ply or .stl; PLY and STL binary), its
     * triangles in path order, byte for byte as {@code ifold refine MODEL -o FILE} writes it.
     * Cancel is looked at while the file is written too: the writer then discards it.
     *
     * @param strict refuse defective input instead of repairing it, as {@code --strict}
     */
    public static Refined refinement(Path model, boolean strict, Path file, Progress progress) throws JobFailure {
        if (!ModelFile.isWritableModelName(file)) {
            throw new JobFailure(new Problem("file", "a refinement is written as .off, .obj, .ply or .stl, got " + file.getFileName()));
        }
        ModelFile loaded = ModelFile.load(model, new MeshBuilder.Options(strict, true), progress);
        loaded.requireFaces(model, "refine");
        HalfedgeMesh mesh = loaded.built().mesh();
        progress.check();
        progress.stage("refining " + mesh.faceCount() + " triangles");
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        progress.check();
        progress.stage("writing " + file.getFileName());
        try {
            MeshWriters.write(new CancellableMesh(result.mesh(), progress.watcher()), file);
        } catch (IOException e) {
            throw new JobFailure("cannot write " + e.getMessage());
        }
        return new Refined(mesh.faceCount(), result.componentCount(), result.mesh().faceCount());
    }

    private static void requirePaper(Plan plan) throws JobFailure {
        if (!plan.hasPaper()) {
            throw new JobFailure("a view folds no paper: Fold, Wrap the model to export it as OBJ or FOLD");
        }
    }

    private static void requireValid(List<Problem> problems) throws JobFailure {
        if (!problems.isEmpty()) {
            throw new JobFailure(problems.get(0));
        }
    }
}
