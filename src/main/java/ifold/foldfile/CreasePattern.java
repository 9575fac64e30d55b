package ifold.foldfile;

import ifold.geom.Tolerance;
import ifold.script.FoldScript;
import ifold.script.FoldScriptException;
import ifold.script.ScriptFolding;
import ifold.sheet.Sheet;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A FOLD crease pattern read to be folded, one crease line at a time: in the order the file
 * gives ({@code edges_ifold:foldStep}, each edge's fold; or, in older files, {@code edges_ifold:order},
 * a list of edge indices) or else in the order of its edges.
 * Each crease line is a flap fold of the paper beyond it (the side away from the sheet's first
 * corner), valley or mountain as the file says, by its fold angle or 180°. Once folded, every
 * crease of the file must come out as the file labels it; a pattern that cannot be folded that
 * way is refused, naming the edge.
 *
 * @param length the sheet's extent along u
 * @param width its extent along v
 * @param script the folds, as a fold script on a sheet with its corner at (0, 0)
 * @param creases each mountain or valley edge: u1, v1, u2, v2 (moved to the sheet's corner) and +1 (valley) or -1
 * @param lines the crease lines in the order they are folded, one a fold of the script: u1, v1, u2, v2, +1 (valley)
 *     or -1, the angle, and +1 where the paper right of the line moves (-1 left)
 * @param lineOfCrease for each crease, the line it lies on (its index in {@code lines}), or -1 where the file's
 *     order folds none of that line's creases
 * @param thickness the paper's
 */
public record CreasePattern(double length, double width, FoldScript script, List<double[]> creases, List<double[]> lines,
        int[] lineOfCrease, double thickness) {

    /**
     * The largest and smallest sheets (their diagonal) folded, as every size iFold computes
     * with ({@link Tolerance#SMALLEST_SIZE}): a sheet 1e85 across folded its valley as a mountain.
     */
    static final double LARGEST_SHEET = Tolerance.LARGEST_SIZE;

    /** See {@link #LARGEST_SHEET}. */
    static final double SMALLEST_SHEET = Tolerance.SMALLEST_SIZE;

    /** A crease pattern that cannot be read, or cannot be folded as iFold folds. */
    public static class Refused extends Exception {
        private static final long serialVersionUID = 1L;

        public Refused(String message) {
            super(message);
        }
    }

    /** A pattern whose lines, folded one at a time in its order, do not come out as it says: it may fold all at once. */
    public static final class NotInOrder extends Refused {
        private static final long serialVersionUID = 1L;

        NotInOrder(String message) {
            super(message);
        }
    }

    /**
     * Reads {@code file}, a FOLD file whose key frame is a crease pattern on a rectangle: its
     * border edges ({@code B}) run all round the rectangle its vertices span, and each mountain
     * or valley crease lies on a line that the file's creases cover from border to border, since
     * each line is folded across the whole sheet. The paper's thickness is the file's
     * {@code frame_ifold:thickness}, or a thousandth of the sheet's diagonal.
     *
     * @throws Refused naming the edge or the key, where the file is not such a crease pattern
     */
    public static CreasePattern read(Path file) throws IOException, Refused {
        return of(FoldJson.read(file));
    }

    /** As {@link #read(Path)}, from the file's content already read. */
    public static CreasePattern of(Map<String, Object> fold) throws Refused {
        List<double[]> vertices = points(fold, "vertices_coords");
        List<double[]> edges = points(fold, "edges_vertices");
        Object assignmentsValue = fold.get("edges_assignment");
        if (!(assignmentsValue instanceof List<?> assignments) || assignments.size() != edges.size()) {
            throw new Refused("edges_assignment must give each edge B, M, V or F");
        }
        List<?> angles = fold.get("edges_foldAngle") instanceof List<?> list ? list : null;
        if (angles != null && angles.size() != edges.size()) {
            throw new Refused(String.format(Locale.ROOT, "edges_foldAngle must give each edge its angle: it has %d for %d edges",
                    angles.size(), edges.size()));
        }
        double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int i = 0; i < vertices.size(); i++) {
            double[] v = vertices.get(i);
            if (v.length < 2 || !Double.isFinite(v[0]) || !Double.isFinite(v[1])) {
                throw new Refused("vertices_coords must hold finite 2D points");
            }
            for (int k = 2; k < v.length; k++) {
                if (v[k] != 0) {
                    // A crease pattern lies flat: a z of 0 is the same point, any other a folded state.
                    throw new Refused(String.format(Locale.ROOT, "vertex %d is %s: a crease pattern lies flat, its vertices 2D points"
                            + " (or with z = 0)", i, pointText(v)));
                }
            }
            box[0] = Math.min(box[0], v[0]);
            box[1] = Math.min(box[1], v[1]);
            box[2] = Math.max(box[2], v[0]);
            box[3] = Math.max(box[3], v[1]);
        }
        double length = box[2] - box[0];
        double width = box[3] - box[1];
        double size = Math.hypot(length, width);
        if (!(size <= LARGEST_SHEET)) {
            // Each coordinate may be finite and their differences not: no length on such a sheet can be measured.
            throw new Refused(String.format(Locale.ROOT, "the sheet is too large: its vertices run from x = %s to %s and y = %s to %s;"
                    + " iFold folds sheets from %.0e to %.0e across: scale the pattern down", fmt(box[0]), fmt(box[2]), fmt(box[1]),
                    fmt(box[3]), SMALLEST_SHEET, LARGEST_SHEET));
        }
        if (!(length > 0) || !(width > 0)) {
            throw new Refused("the crease pattern has no area");
        }
        if (size < SMALLEST_SHEET) {
            throw new Refused(String.format(Locale.ROOT, "the sheet is too small: %s across; iFold folds sheets from %.0e to %.0e across:"
                    + " scale the pattern up", fmt(size), SMALLEST_SHEET, LARGEST_SHEET));
        }
        double tolerance = Tolerance.ON_PLANE * Math.hypot(length, width);
        List<double[]> creases = new ArrayList<>();
        List<Integer> creaseEdges = new ArrayList<>();
        Border border = new Border(length, width, tolerance);
        for (int e = 0; e < edges.size(); e++) {
            double[] edge = edges.get(e);
            if (edge.length != 2) {
                throw new Refused("edge " + e + ": edges_vertices must name two vertices, it names " + edge.length);
            }
            int a = (int) edge[0];
            int b = (int) edge[1];
            if (a != edge[0] || b != edge[1] || a < 0 || b < 0 || a >= vertices.size() || b >= vertices.size()) {
                throw new Refused("edge " + e + ": edges_vertices must name two vertices");
            }
            double[] p = {vertices.get(a)[0] - box[0], vertices.get(a)[1] - box[1]};
            double[] q = {vertices.get(b)[0] - box[0], vertices.get(b)[1] - box[1]};
            if (!(assignments.get(e) instanceof String given)) {
                throw new Refused("edge " + e + ": edges_assignment gives it " + valueText(assignments.get(e))
                        + ", not one of B, M, V, F, U, C or J");
            }
            String assignment = given.toUpperCase(Locale.ROOT);
            switch (assignment) {
                case "B" -> {
                    if (!border.add(p, q)) {
                        throw new Refused("edge " + e + " is a border edge inside the sheet: iFold folds rectangular sheets");
                    }
                }
                case "M", "V" -> {
                    if (Math.hypot(q[0] - p[0], q[1] - p[1]) <= tolerance) {
                        throw new Refused("edge " + e + ": a crease of no length");
                    }
                    Object givenAngle = angles == null ? null : angles.get(e);
                    if (givenAngle != null && !(givenAngle instanceof Number)) {
                        throw new Refused("edge " + e + ": edges_foldAngle gives it " + valueText(givenAngle)
                                + ", not a number of degrees");
                    }
                    double angle = givenAngle instanceof Number n ? Math.abs(n.doubleValue()) : 180;
                    if (!(angle > 0 && angle <= 180)) {
                        throw new Refused("edge " + e + ": its fold angle must be more than 0 and at most 180 degrees");
                    }
                    creases.add(new double[] {p[0], p[1], q[0], q[1], assignment.equals("V") ? 1 : -1, angle});
                    creaseEdges.add(e);
                }
                case "F", "J", "C" -> {
                    // flat, joined or cut: nothing to fold
                }
                case "U" -> throw new Refused("edge " + e + " is U: iFold folds mountains and valleys (M, V), "
                        + "not unassigned creases");
                default -> throw new Refused("edge " + e + ": edges_assignment gives it " + valueText(given)
                        + ", not one of B, M, V, F, U, C or J");
            }
        }
        border.check(box);
        int[] lineOf = CreaseLines.group(creases, tolerance);
        CreaseLines.checkBorderToBorder(creases, lineOf, creaseEdges, length, width, tolerance, box);
        // The order of folding: the file's, or the edges'.
        List<Integer> order = new ArrayList<>();
        if (fold.get("edges_ifold:foldStep") instanceof List<?> steps) {
            if (steps.size() != edges.size()) {
                throw new Refused("edges_ifold:foldStep has " + steps.size() + " entries for " + edges.size() + " edges");
            }
            List<int[]> stepped = new ArrayList<>(); // {crease, step, edge}
            for (int k = 0; k < creaseEdges.size(); k++) {
                int e = creaseEdges.get(k);
                Object step = steps.get(e);
                if (!(step instanceof Number n) || n.doubleValue() != n.intValue() || n.intValue() < 1) {
                    throw new Refused("edge " + e + " is a crease, and edges_ifold:foldStep gives it " + step
                            + ", not the number of the fold that made it");
                }
                stepped.add(new int[] {k, n.intValue(), e});
            }
            stepped.sort(java.util.Comparator.<int[]>comparingInt(c -> c[1]).thenComparingInt(c -> c[2]));
            for (int[] c : stepped) {
                order.add(c[0]);
            }
        } else if (fold.get("edges_ifold:order") instanceof List<?> given) {
            // Files of iFold before edges_ifold:foldStep: the crease edges listed in folding order.
            Map<Integer, Integer> creaseOfEdge = new HashMap<>();
            for (int k = 0; k < creaseEdges.size(); k++) {
                creaseOfEdge.put(creaseEdges.get(k), k);
            }
            for (Object o : given) {
                Integer k = o instanceof Number n && n.doubleValue() == n.intValue() ? creaseOfEdge.get(n.intValue()) : null;
                if (k == null) {
                    throw new Refused("edges_ifold:order names " + o + ", which is not a mountain or valley edge");
                }
                order.add(k);
            }
        } else {
            for (int k = 0; k < creases.size(); k++) {
                order.add(k);
            }
        }
        double thickness = fold.get("frame_ifold:thickness") instanceof Number n && n.doubleValue() >= 0 ? n.doubleValue()
                : 1e-3 * Math.hypot(length, width);
        // Each line is folded once, as the first of its creases in the order says.
        List<double[]> folded = new ArrayList<>();
        int[] foldOfLine = new int[creases.size()];
        Arrays.fill(foldOfLine, -1);
        for (int k : order) {
            if (foldOfLine[lineOf[k]] >= 0) {
                continue; // folded with an earlier crease of its line
            }
            foldOfLine[lineOf[k]] = folded.size();
            double[] c = creases.get(k);
            // The paper beyond the line from the sheet's first corner (0, 0) moves; if the line
            // runs through that corner, from the opposite one.
            double[] corner = onLine(c, 0, 0, tolerance) ? new double[] {length, width} : new double[] {0, 0};
            double cross = (c[2] - c[0]) * (corner[1] - c[1]) - (c[3] - c[1]) * (corner[0] - c[0]);
            folded.add(new double[] {c[0], c[1], c[2], c[3], c[4], c[5], cross > 0 ? 1 : -1});
        }
        int[] foldOfCrease = new int[creases.size()];
        for (int k = 0; k < creases.size(); k++) {
            foldOfCrease[k] = foldOfLine[lineOf[k]];
        }
        return new CreasePattern(length, width, script(length, width, thickness, folded, new boolean[folded.size()]), creases,
                List.copyOf(folded), foldOfCrease, thickness);
    }

    /** The lines as flap folds of a script, each valley or mountain as its line says, the other way where {@code turned}. */
    private static FoldScript script(double length, double width, double thickness, List<double[]> lines, boolean[] turned) {
        FoldScript.Builder builder = FoldScript.builder().rectangle(length, width).thickness(thickness);
        for (int k = 0; k < lines.size(); k++) {
            double[] c = lines.get(k);
            boolean valley = (c[4] > 0) != turned[k];
            builder.flap(valley ? FoldScript.Kind.VALLEY : FoldScript.Kind.MOUNTAIN, c[5], c[0], c[1], c[2], c[3],
                    c[6] > 0 ? FoldScript.Side.RIGHT : FoldScript.Side.LEFT);
        }
        return builder.build();
    }

    /** A crease pattern folded: the script it was folded by, and what it made. */
    public record Folding(FoldScript script, ScriptFolding.Result result) {
    }

    /**
     * Folds the pattern line by line and checks that every crease comes out as the file labels
     * it. A fold through layers lying different sides up creases one line mountain on one layer
     * and valley on the other, and a flap fold along it is named by one of them: where a line's
     * creases come out the other way round, the line is folded the other way, once.
     *
     * @throws Refused if the pattern still does not come out as the file labels it
     */
    public Folding fold(long[] nanosPerFold, int maxFaces) throws Refused, FoldScriptException {
        if (lines.size() + 1L > maxFaces) {
            // Each line is folded across the whole sheet and cuts it once at least: known before
            // any fold (10,000 parallel creases were refused at the last, after half a minute).
            throw new Refused(String.format(Locale.ROOT, "its %,d crease lines cut the paper into at least %,d faces, more than the %d"
                    + " allowed (--max-faces raises the limit)", lines.size(), lines.size() + 1, maxFaces));
        }
        boolean[] turned = new boolean[lines.size()];
        FoldScript folds = script;
        while (true) {
            ScriptFolding.Result result = folds.play(nanosPerFold, maxFaces);
            int wrong = firstWrongCrease(result);
            if (wrong < 0) {
                return new Folding(folds, result);
            }
            int line = lineOfCrease[wrong];
            if (line < 0 || turned[line]) {
                throw refusal(result, wrong);
            }
            turned[line] = true;
            folds = script(length, width, thickness, lines, turned);
        }
    }

    /**
     * Refuses a folding whose creases do not come out as the pattern labels them: the pattern
     * cannot be folded one crease line at a time in its order.
     */
    public void verify(ScriptFolding.Result result) throws Refused {
        int wrong = firstWrongCrease(result);
        if (wrong >= 0) {
            throw refusal(result, wrong);
        }
    }

    /** The first crease that does not come out as the pattern labels it, or -1. */
    private int firstWrongCrease(ScriptFolding.Result result) {
        Creased creased = new Creased(result, lines.size());
        for (int k = 0; k < creases.size(); k++) {
            double found = creased.angle(k);
            if (Double.isNaN(found) || found == 0 || Math.signum(found) != creases.get(k)[4]) {
                return k;
            }
        }
        return -1;
    }

    private Refused refusal(ScriptFolding.Result result, int k) {
        double[] c = creases.get(k);
        double found = new Creased(result, lines.size()).angle(k);
        return new NotInOrder(String.format(Locale.ROOT, "cannot be folded one crease line at a time in this order: the crease"
                + " (%.6g, %.6g)-(%.6g, %.6g) comes out %s, the file says %s", c[0], c[1], c[2], c[3],
                Double.isNaN(found) || found == 0 ? "flat" : found > 0 ? "a valley" : "a mountain", c[4] > 0 ? "valley" : "mountain"));
    }

    /**
     * The fold angles a folding made where the pattern's creases lie. Each crease is looked for
     * first among the sheet edges creased by the fold of its line (the script's folds are its
     * lines, one each), then, where it is not found there, on every edge of the sheet: a pattern
     * of n parallel creases folds into n faces, and looking at every edge for every crease
     * would cost n².
     */
    private final class Creased {
        private final Sheet sheet;
        private final FoldFile.Folded folded;
        private final int[] levels;
        /** For each fold, the edges it creased: face, a, b (the edge a → b of the face, with a face across). */
        private final List<List<int[]>> byFold = new ArrayList<>();
        private final double tolerance = Tolerance.FILE_PRECISION * Math.hypot(length, width);

        Creased(ScriptFolding.Result result, int folds) {
            sheet = result.sheet();
            folded = new FoldFile.Folded(sheet, result.frames());
            levels = sheet.levels();
            for (int j = 0; j < folds; j++) {
                byFold.add(new ArrayList<>());
            }
            for (int f = 0; f < sheet.faceCount(); f++) {
                int[] loop = sheet.loop(f);
                for (int i = 0; i < loop.length; i++) {
                    int a = loop[i];
                    int b = loop[(i + 1) % loop.length];
                    int fold = sheet.creaseFold(a, b);
                    if (fold >= 0 && fold < folds && sheet.faceAcross(a, b) >= 0) {
                        byFold.get(fold).add(new int[] {f, a, b});
                    }
                }
            }
        }

        /** The fold angle where crease k lies (0 where flat, NaN where no edge runs there). */
        double angle(int k) {
            double[] c = creases.get(k);
            double mu = (c[0] + c[2]) / 2;
            double mv = (c[1] + c[3]) / 2;
            if (lineOfCrease[k] >= 0) {
                for (int[] edge : byFold.get(lineOfCrease[k])) {
                    if (onSegment(sheet, edge[1], edge[2], mu, mv, tolerance)) {
                        return angle(edge[0], edge[1], edge[2]);
                    }
                }
            }
            for (int f = 0; f < sheet.faceCount(); f++) {
                int[] loop = sheet.loop(f);
                for (int i = 0; i < loop.length; i++) {
                    int a = loop[i];
                    int b = loop[(i + 1) % loop.length];
                    if (sheet.faceAcross(a, b) >= 0 && onSegment(sheet, a, b, mu, mv, tolerance)) {
                        return angle(f, a, b);
                    }
                }
            }
            return Double.NaN;
        }

        private double angle(int f, int a, int b) {
            return sheet.crease(a, b) == null ? 0 : FoldFile.foldAngle(folded, levels, f, sheet.faceAcross(a, b), a, b);
        }
    }

    private static boolean onSegment(Sheet sheet, int a, int b, double u, double v, double tolerance) {
        double du = sheet.u(b) - sheet.u(a);
        double dv = sheet.v(b) - sheet.v(a);
        double length = Math.hypot(du, dv);
        // By the unit direction: squared lengths overflow on a sheet 1e155 across, and vanish on one 1e-160 across.
        double ex = du / length;
        double ey = dv / length;
        double across = ex * (v - sheet.v(a)) - ey * (u - sheet.u(a));
        double along = (ex * (u - sheet.u(a)) + ey * (v - sheet.v(a))) / length;
        return Math.abs(across) <= tolerance && along > 0 && along < 1;
    }

    private static boolean onLine(double[] line, double u, double v, double tolerance) {
        return CreaseLines.onLine(line, u, v, tolerance);
    }

    private static List<double[]> points(Map<String, Object> fold, String key) throws Refused {
        if (!(fold.get(key) instanceof List<?> list) || list.isEmpty()) {
            throw new Refused("no " + key + ": a crease pattern needs vertices_coords, edges_vertices and edges_assignment");
        }
        List<double[]> points = new ArrayList<>();
        for (Object item : list) {
            if (!(item instanceof List<?> coords)) {
                throw new Refused(key + " must be a list of lists of numbers");
            }
            double[] p = new double[coords.size()];
            for (int i = 0; i < p.length; i++) {
                if (!(coords.get(i) instanceof Number n)) {
                    throw new Refused(key + " must be a list of lists of numbers");
                }
                p[i] = n.doubleValue();
            }
            points.add(p);
        }
        return points;
    }

    /** A value of the file as a message quotes it: a string in quotes, a number as {@link #fmt}, anything else as JSON would. */
    private static String valueText(Object value) {
        if (value instanceof String text) {
            return "\"" + (text.length() > 20 ? text.substring(0, 20) + "…" : text) + "\"";
        }
        if (value instanceof Number n) {
            return fmt(n.doubleValue());
        }
        if (value instanceof List<?>) {
            return "a list";
        }
        if (value instanceof Map<?, ?>) {
            return "an object";
        }
        return String.valueOf(value); // true, false, null
    }

    private static String pointText(double[] p) {
        StringBuilder text = new StringBuilder("(");
        for (int k = 0; k < p.length; k++) {
            text.append(k > 0 ? ", " : "").append(fmt(p[k]));
        }
        return text.append(")").toString();
    }

    /** A coordinate as a message gives it: a whole number without its ".0", else the shortest decimal that reads back. */
    static String fmt(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value) : Double.toString(value);
    }
}
