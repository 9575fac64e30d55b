package ifold.job;

import ifold.check.LayerOrder;
import ifold.check.PaperCollisions;
import ifold.check.WrapTruths;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.wrap.Wrap;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * An exported wrap checked against its model by the independent checkers alone, as
 * {@code ifold check} runs it: the five truths of a wrap ({@link WrapTruths}: the paper tiles its
 * strips, is not stretched, not torn, covers the model and lies on it), the collisions
 * ({@link PaperCollisions}) of the same OBJ file, and where a FOLD file of the wrap is given, its
 * layer order ({@link LayerOrder}). Nothing of the engine is asked: the thickness and the stack's
 * height come from the OBJ's header (or the request), the model from its own file. Unlike the
 * wrap's report, no check is skipped for the paper's size: a scan's half a million faces take
 * minutes and gigabytes, which the one who asks for them has chosen to spend.
 */
public final class CheckJob {
    private CheckJob() {
    }

    /**
     * What to check.
     *
     * @param model the model the paper wraps, read and repaired as the wrap reads it
     * @param paper the OBJ that {@code --export-obj} wrote
     * @param fold the FOLD file that {@code --export-fold} wrote of the same wrap, or null
     * @param thickness the paper's thickness, NaN for the OBJ header's
     * @param stack the levels of the deepest stack, -1 for the OBJ header's
     * @param samples how many random points of the model the coverage truth tries
     * @param strict whether a model defect that could be repaired is refused instead
     */
    public record Request(Path model, Path paper, Path fold, double thickness, int stack, int samples, boolean strict) {
    }

    /**
     * The figures of a check, and whether everything checked holds.
     *
     * @param truths the violations of each truth broken, counted ({@link WrapTruths#violationCounts}); empty where every one holds
     * @param collisions what the collision check found; null for paper of no thickness, not checked
     * @param layerOrder what the layer-order check found; null where no FOLD file was given
     */
    public record Checked(Map<String, Object> figures, Map<String, Integer> truths, PaperCollisions.Result collisions,
            LayerOrder.Result layerOrder) {
        /**
         * Whether every truth holds, no paper crosses itself or the model (where it has a
         * thickness: {@code collisions} is null where it has none), and the layer order (where
         * checked, else null) is valid.
         */
        public boolean holds() {
            return failures().isEmpty();
        }

        /** The checks that fail, in words ("truths", "collisions", "layer order"); empty where every one holds. */
        public List<String> failures() {
            List<String> failed = new ArrayList<>();
            if (!truths.isEmpty()) {
                failed.add("truths");
            }
            if (collisions != null && !collisions.isClean()) {
                failed.add("collisions");
            }
            if (layerOrder != null && !layerOrder.valid()) {
                failed.add("layer order");
            }
            return failed;
        }
    }

    /** A request the files cannot answer: an OBJ that is no wrap's, a FOLD file that is none, a header without what the check needs. */
    public static class Unreadable extends Exception {
        private static final long serialVersionUID = 1L;

        Unreadable(String message) {
            super(message);
        }
    }


    /**
     * Paper too thick for the model: its stack, (levels + 1) thicknesses, as high as the model
     * is big (its bounding box's diagonal). No wrap makes it; checked, the creep zones would
     * cover the model and the check take for ever.
     */
    public static final class TooThick extends Unreadable {
        private static final long serialVersionUID = 1L;

        TooThick(String message) {
            super(message);
        }
    }

    /** The most random points of the model the coverage truth tries: ten million take minutes. */
    public static final int MOST_SAMPLES = 10_000_000;

    /** How many random points of the model the coverage truth tries unless told: {@code ifold check}'s and the window's. */
    public static final int DEFAULT_SAMPLES = 2000;

    /** How many violations of each truth the figures list in words. */
    static final int LISTED = 5;

    private static final Pattern THICKNESS = Pattern.compile("thickness ([-+0-9.eE]+)");
    private static final Pattern STACK = Pattern.compile("a stack of (\\d+) levels");
    private static final Pattern MOVED = Pattern.compile("coordinates about \\(([^,()]+), ([^,()]+), ([^,()]+)\\)");

    /**
     * Checks the paper.
     *
     * @throws ModelFiles.LoadFailure where the model cannot be read or built
     * @throws Unreadable where the OBJ or FOLD file cannot be read as a wrap, or lacks what the check needs
     * @throws java.util.concurrent.CancellationException once the watcher says stop
     */
    public static Checked run(Request request, JobWatcher watcher) throws ModelFiles.LoadFailure, Unreadable {
        ModelFiles.Loaded loaded = ModelFiles.loadSurface(request.model(), new MeshBuilder.Options(request.strict(), true), "check against",
                watcher);
        HalfedgeMesh mesh = loaded.built().mesh();
        String text = readText(request.paper());
        if (text.isBlank()) {
            throw new Unreadable(request.paper() + ": the file is empty");
        }
        String header = text.startsWith("#") ? text.substring(0, Math.max(0, text.indexOf('\n'))) : "";
        double thickness = Double.isNaN(request.thickness()) ? headerNumber(THICKNESS, header, request.paper(), "--thickness")
                : request.thickness();
        int stack = request.stack() >= 0 ? request.stack() : (int) headerNumber(STACK, header, request.paper(), "--stack");
        double[] movedBy = movedBy(header, request.paper());
        double size = Wrap.modelSize(mesh);
        if (!((stack + 1.0) * thickness < size)) {
            throw new TooThick("a stack of " + stack + " levels of paper " + thickness + " thick stands " + (stack + 1.0) * thickness
                    + " high, higher than the model is big (" + size + " across): no wrap of it is that thick");
        }
        watcher.stopIfAsked();

        watcher.stage("reading " + request.paper().getFileName());
        double[] flat = Collisions.modelTriangles(mesh);
        for (int i = 0; i < flat.length; i++) {
            flat[i] -= movedBy[i % 3];
        }
        Truths truths = truths(text, flat, thickness, stack, request, watcher);
        watcher.stopIfAsked();
        PaperCollisions.Result collisions = null;
        if (thickness > 0) { // paper of no thickness: every two layers that overlap touch, and the layer order is the check
            watcher.stage("checking " + request.paper().getFileName() + " for collisions");
            collisions = PaperCollisions.check(text, thickness, flat);
            watcher.stopIfAsked();
        }
        text = null; // half a gigabyte for a scan's paper: not held through the layer order
        LayerOrder.Result layerOrder = null;
        if (request.fold() != null) {
            watcher.stage("checking the layer order of " + request.fold().getFileName());
            try (Reader reader = Files.newBufferedReader(request.fold(), StandardCharsets.UTF_8)) {
                layerOrder = LayerOrder.check(reader);
            } catch (java.nio.file.NoSuchFileException | java.nio.file.AccessDeniedException e) {
                throw new Unreadable(ModelFiles.readError(request.fold(), e));
            } catch (IOException | RuntimeException e) {
                throw new Unreadable(notFold(request.fold(), e));
            }
        }

        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("model", request.model().toString());
        figures.put("paper", request.paper().toString());
        figures.put("strips", truths.strips());
        figures.put("paperFaces", truths.paperFaces());
        figures.put("capFaces", truths.capFaces());
        figures.put("thickness", thickness);
        figures.put("stackLayers", stack);
        figures.put("truths", truthFigures(truths.counts(), truths.violations()));
        figures.put("collisions", collisions == null ? Map.of("notChecked", Collisions.NO_THICKNESS) : Collisions.figures(collisions));
        if (layerOrder != null) {
            figures.put("layerOrder", LayerOrders.figures(layerOrder));
        }
        return new Checked(figures, truths.counts(), collisions, layerOrder);
    }

    /** What the truths found, and the paper's counts, without the checker's arrays: a scan's take gigabytes, wanted back before the collisions. */
    private record Truths(int strips, int paperFaces, int capFaces, Map<String, Integer> counts, List<WrapTruths.Violation> violations) {
    }

    /** The five truths of the paper of {@code text} on the model's {@code triangles} (nine numbers each, moved as the paper). */
    private static Truths truths(String text, double[] triangles, double thickness, int stack, Request request, JobWatcher watcher)
            throws Unreadable {
        WrapTruths truths;
        try {
            truths = WrapTruths.read(text);
        } catch (IllegalArgumentException e) {
            throw new Unreadable(request.paper() + ": " + e.getMessage());
        }
        if (truths.paperFaces() == 0) {
            throw new Unreadable(request.paper() + ": no faces of paper (an OBJ cut short?)");
        }
        watcher.stopIfAsked();
        watcher.stage("checking the truths of " + request.paper().getFileName());
        List<double[]> model = new ArrayList<>();
        for (int t = 0; t < triangles.length / 9; t++) {
            model.add(Arrays.copyOfRange(triangles, 9 * t, 9 * t + 9));
        }
        try {
            List<WrapTruths.Violation> violations = truths.check(model, thickness, stack, request.samples(), 1);
            return new Truths(truths.strips(), truths.paperFaces(), truths.capFaces(), truths.violationCounts(), violations);
        } catch (IllegalArgumentException e) {
            throw new Unreadable(request.model() + ": " + e.getMessage()); // a model of no size or area
        }
    }

    /**
     * The check in lines, as {@code ifold check} prints them and the window shows them: what was
     * checked ({@code what}: the files' names) and the paper's counts; the truths; the
     * collisions; the layer order where a FOLD file was checked; and where one fails, which.
     */
    public static List<String> lines(Checked checked, String what) {
        Map<String, Object> figures = checked.figures();
        List<String> lines = new ArrayList<>();
        lines.add(what + ": " + figures.get("strips") + (figures.get("strips").equals(1) ? " strip, " : " strips, ")
                + String.format(java.util.Locale.ROOT, "%,d faces of paper and %,d caps, thickness %.4g, a stack of %s levels",
                        (Integer) figures.get("paperFaces"), (Integer) figures.get("capFaces"), ((Number) figures.get("thickness")).doubleValue(),
                        figures.get("stackLayers")));
        lines.add("truths: " + truthsLine(checked.truths(), figures.get("truths")));
        lines.add(checked.collisions() == null ? "collisions: not checked: " + Collisions.NO_THICKNESS
                : checked.collisions().summary()); // "collisions: ..."
        if (checked.layerOrder() != null) {
            lines.add(checked.layerOrder().summary()); // "layer order: ..."
        }
        if (!checked.holds()) {
            // Said in one line: a run whose first line of checks is "truths: every one holds"
            // and whose collisions fail was read as one that passed.
            lines.add("failed: " + String.join(", ", checked.failures()));
        }
        return lines;
    }

    /** A truth's name without its number: "isometric" for "2 isometric". */
    private static String name(String truth) {
        return truth.replaceFirst("^\\d+ ", "");
    }

    /** The truths' line: all hold, or each broken one counted, and the first violation in words. */
    private static String truthsLine(Map<String, Integer> counts, Object figures) {
        if (counts.isEmpty()) {
            List<String> names = new ArrayList<>();
            for (String truth : List.of(WrapTruths.TILED, WrapTruths.ISOMETRIC, WrapTruths.NOT_TORN, WrapTruths.COVERED, WrapTruths.ON_SURFACE)) {
                names.add(name(truth));
            }
            return "every one holds (" + String.join(", ", names) + ")";
        }
        int total = 0;
        List<String> broken = new ArrayList<>();
        String first = null;
        for (Map.Entry<String, Integer> count : counts.entrySet()) {
            total += count.getValue();
            broken.add(name(count.getKey()) + " " + String.format(java.util.Locale.ROOT, "%,d", count.getValue()));
            if (first == null && figures instanceof Map<?, ?> map && map.get(count.getKey()) instanceof Map<?, ?> truth
                    && truth.get("first") instanceof List<?> listed && !listed.isEmpty()) {
                first = listed.get(0).toString();
            }
        }
        return String.format(java.util.Locale.ROOT, "%,d %s: %s", total, total == 1 ? "violation" : "violations",
                String.join(", ", broken)) + (first == null ? "" : "; the first: " + first);
    }

    /** {@code "hold"}, or the violations of each truth counted and the first few in words. */
    static Object truthFigures(Map<String, Integer> counts, List<WrapTruths.Violation> violations) {
        if (counts.isEmpty()) {
            return "hold";
        }
        Map<String, Object> figures = new LinkedHashMap<>();
        int total = 0;
        for (int n : counts.values()) {
            total += n;
        }
        figures.put("violations", total);
        for (Map.Entry<String, Integer> count : counts.entrySet()) {
            List<String> first = new ArrayList<>();
            for (WrapTruths.Violation v : violations) {
                if (v.truth().equals(count.getKey()) && first.size() < LISTED) {
                    first.add(v.message());
                }
            }
            Map<String, Object> truth = new LinkedHashMap<>();
            truth.put("count", count.getValue());
            truth.put("first", first);
            figures.put(count.getKey(), truth);
        }
        return figures;
    }

    /** Why {@code fold} is no FOLD file the layer-order check can read, in one line, its line and column where the parser says them. */
    static String notFold(Path fold, Exception e) {
        String message = e.getMessage() == null ? e.toString() : e.getMessage();
        Matcher at = Pattern.compile("line: (\\d+), column: (\\d+)").matcher(message);
        String where = at.find() ? fold + ":" + at.group(1) + ":" + at.group(2) : fold.toString();
        // The parser's first line, without where it says it is reading (its location, given above).
        String said = message.lines().findFirst().orElse(message).replaceAll("\\s*\\(start marker at \\[Source.*$", "").replaceAll("\\s*at \\[Source.*$", "");
        return where + ": not a FOLD file the layer order can be read from: " + said;
    }

    private static String readText(Path file) throws Unreadable {
        try {
            return Files.readString(file, StandardCharsets.UTF_8);
        } catch (java.nio.charset.CharacterCodingException e) {
            throw new Unreadable(file + ": not a text file (not UTF-8): an OBJ is text");
        } catch (IOException | RuntimeException e) {
            throw new Unreadable(ModelFiles.readError(file, e instanceof IOException io ? io : new IOException(e.getMessage(), e)));
        }
    }

    private static double headerNumber(Pattern pattern, String header, Path paper, String option) throws Unreadable {
        // The last match: the header names the model first, whose name may hold the words.
        Matcher m = pattern.matcher(header);
        String found = null;
        while (m.find()) {
            found = m.group(1);
        }
        if (found == null) {
            throw new Unreadable(paper + ": its first line names no " + option.substring(2) + " (an OBJ that 'ifold wrap --export-obj' wrote does): give "
                    + option);
        }
        try {
            return Double.parseDouble(found);
        } catch (NumberFormatException e) {
            throw new Unreadable(paper + ": line 1: not a number: " + found);
        }
    }

    /** Where the wrap moved the model to lie near its centre, as the header says: (0, 0, 0) where it says nothing. */
    private static double[] movedBy(String header, Path paper) throws Unreadable {
        Matcher m = MOVED.matcher(header);
        if (!m.find()) {
            return new double[3];
        }
        try {
            return new double[] {Double.parseDouble(m.group(1).trim()), Double.parseDouble(m.group(2).trim()), Double.parseDouble(m.group(3).trim())};
        } catch (NumberFormatException e) {
            throw new Unreadable(paper + ": line 1: not a point: " + m.group());
        }
    }
}
