package ifold.ui.model;

import ifold.job.BuiltInModels;
import ifold.job.GenerateJob;
import ifold.geom.ParameterException;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * A built-in model to make, as {@code ifold generate SHAPE --around --across --subdivisions}
 * would, with its parameters as typed: text, so that a value that is no number is its field's
 * problem. A blank field is the command line's default.
 *
 * @param around the torus's segments around the ring
 * @param across the torus's segments around the tube
 * @param subdivisions the times each of the icosphere's triangles is cut in four
 */
public record NewModel(BuiltInModels.Shape shape, String around, String across, String subdivisions) {

    /**
     * What is wrong with the parameters, field by field ({@code around}, {@code across},
     * {@code subdivisions}), with the command line's messages; the torus's two counts are refused
     * together, at both fields. Empty when the model can be made.
     */
    public List<Problem> check() {
        List<Problem> problems = new ArrayList<>();
        Counts counts = counts(problems);
        if (problems.isEmpty()) {
            try {
                BuiltInModels.check(shape, counts.around(), counts.across(), counts.subdivisions());
            } catch (ParameterException e) {
                if (e.parameter().equals(BuiltInModels.SEGMENTS)) {
                    problems.add(new Problem("around", e.getMessage()));
                    problems.add(new Problem("across", e.getMessage()));
                } else {
                    problems.add(new Problem(e.parameter(), e.getMessage()));
                }
            }
        }
        return problems;
    }

    /** The name it is saved under by default: {@code torus-24x12.off}. */
    public String fileName() {
        Counts counts = counts(new ArrayList<>());
        return BuiltInModels.name(shape, counts.around(), counts.across(), counts.subdivisions()) + ".off";
    }

    /** A model made: its counts, for the status line. */
    public record Made(Path file, int vertices, int faces) {
    }

    /**
     * Makes the model and writes it to {@code file} (.off, .obj, .ply or .stl), whole or not at all, as
     * {@code ifold generate -o FILE} does; Cancel is looked at while it is written.
     *
     * @throws JobFailure with the first problem of {@link #check()}, or why the file cannot be written
     */
    public Made write(Path file, Progress progress) throws JobFailure {
        List<Problem> problems = check();
        if (!problems.isEmpty()) {
            throw new JobFailure(problems.get(0));
        }
        if (!ModelFile.isWritableModelName(file)) {
            throw new JobFailure(new Problem("file", "a model is written as .off, .obj, .ply or .stl, got " + file.getFileName()));
        }
        Counts counts = counts(problems);
        try {
            GenerateJob.Made made = GenerateJob.run(new GenerateJob.Request(shape, counts.around(), counts.across(), counts.subdivisions(),
                    file, false), progress.watcher());
            return new Made(made.file(), made.vertices(), made.faces());
        } catch (IOException e) {
            throw new JobFailure(file + ": cannot write: " + e.getMessage());
        }
    }

    /** The parameters as numbers, the defaults where blank. */
    private record Counts(int around, int across, int subdivisions) {
    }

    /** The fields as numbers; a field that is none is a problem, and its default stands in. */
    private Counts counts(List<Problem> problems) {
        return new Counts(whole(around, "around", BuiltInModels.DEFAULT_AROUND, problems),
                whole(across, "across", BuiltInModels.DEFAULT_ACROSS, problems),
                whole(subdivisions, "subdivisions", BuiltInModels.DEFAULT_SUBDIVISIONS, problems));
    }

    /** A field as a whole number: blank is {@code blank}. */
    private static int whole(String text, String field, int blank, List<Problem> problems) {
        String value = text == null ? "" : text.strip();
        if (value.isEmpty()) {
            return blank;
        }
        try {
            return Integer.parseInt(value);
        } catch (NumberFormatException e) {
            problems.add(new Problem(field, "'" + value + "' is not a whole number"));
            return blank;
        }
    }
}
