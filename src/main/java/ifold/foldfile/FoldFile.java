package ifold.foldfile;

import static ifold.geom.Vectors.dot;
import static ifold.geom.Vectors.sub;
import static ifold.geom.Vectors.unit;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.StreamWriteFeature;
import ifold.geom.Tolerance;
import ifold.io.AtomicFile;
import ifold.script.FoldScript;
import ifold.script.FoldScriptException;
import ifold.script.ScriptFolding;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Polygons2;
import ifold.sheet.Sheet;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * A folded sheet (or several: a wrap's strips) as a FOLD file.
 *
 * <p><b>The crease pattern</b> (the key frame, {@code frame_classes: ["creasePattern"]}): each
 * sheet's paper vertices at their paper coordinates (strips one above another, a width apart),
 * its faces counter-clockwise, and every edge with its assignment: {@code B} on the border,
 * {@code M} or {@code V} where the paper is creased, {@code F} where a crease lies flat again;
 * {@code edges_foldAngle} in degrees, positive for valley.
 *
 * <p><b>Mountain and valley</b> are the paper's own, as an origamist reads them on the crease
 * pattern: a fold is a valley where it brings the two faces' top sides towards each other. The
 * angle is found on the folded state: between the faces' top normals, its sign from whether
 * the second face rises on the first face's top side; for a flat fold (180°), from which of the
 * two lies on the other's top side in the stack.
 *
 * <p><b>The folded state</b> ({@code file_frames[0]}, {@code frame_classes: ["foldedForm"]},
 * inheriting the crease pattern's faces and edges): each vertex in space where the paper lies,
 * paper of no thickness as FOLD means it ({@link Folded#ofScript}; layers of a stack share their
 * place: FOLD orders them by {@code faceOrders}, [f, g, s] with
 * s = +1 where face f lies on the side g's normal points to); the paper's thickness in
 * {@code frame_ifold:thickness} and each face's level in its stack in {@code faces_ifold:level},
 * from which its height above its plane is (level + ½) × thickness, on the side of each face that
 * {@code faces_ifold:facing} says is out (+1: the side its own normal points to, its corners
 * counter-clockwise on the paper; -1: the other).
 *
 * <p>Written with jackson-core's streaming generator: every number is the shortest decimal that
 * reads back as the same double. Written under a temporary name and renamed when whole.
 */
public final class FoldFile {
    private static final JsonFactory JSON = JsonFactory.builder().enable(StreamWriteFeature.USE_FAST_DOUBLE_WRITER)
            .disable(StreamWriteFeature.AUTO_CLOSE_TARGET).build();

    private FoldFile() {
    }

    /**
     * One sheet and the planes (or triangles) its hosts are; and where the folded state of ideal
     * paper is another folding of it, that folding's sheet and planes (null where this one's is).
     */
    public record Folded(Sheet sheet, HostFrame[] frames, Sheet idealSheet, HostFrame[] idealFrames) {
        public Folded(Sheet sheet, HostFrame[] frames) {
            this(sheet, frames, null, null);
        }

        /**
         * A fold script's folding, for a FOLD file. FOLD's folded state is of paper with no
         * thickness; with thickness, a fold other than flat turns the paper about a line lifted
         * by its layers, onto a plane offset from the one it left, so that no one place for a
         * crease's vertex keeps both faces' edges their length. The script is folded again on
         * ideal paper, and its places written, where it folds to the same faces (it may not: a
         * fold line given in space can lie off the paper once the layers have no thickness).
         */
        public static Folded ofScript(FoldScript script, ScriptFolding.Result result, int maxFaces) {
            Sheet sheet = result.sheet();
            if (!(script.thickness() > 0)) {
                return new Folded(sheet, result.frames());
            }
            ScriptFolding.Result ideal;
            try {
                ideal = script.withThickness(0).play(new long[script.steps().size()], maxFaces);
            } catch (FoldScriptException e) {
                return new Folded(sheet, result.frames());
            }
            return sameFaces(sheet, ideal.sheet()) ? new Folded(sheet, result.frames(), ideal.sheet(), ideal.frames())
                    : new Folded(sheet, result.frames());
        }

        /** Whether two foldings made the same faces of the same vertices, at the same places on the paper. */
        private static boolean sameFaces(Sheet a, Sheet b) {
            if (a.vertexCount() != b.vertexCount() || a.faceCount() != b.faceCount()) {
                return false;
            }
            for (int v = 0; v < a.vertexCount(); v++) {
                if (Math.abs(a.u(v) - b.u(v)) > a.tolerance() || Math.abs(a.v(v) - b.v(v)) > a.tolerance()) {
                    return false;
                }
            }
            for (int f = 0; f < a.faceCount(); f++) {
                if (!Arrays.equals(a.loop(f), b.loop(f))) {
                    return false;
                }
            }
            return true;
        }
    }

    /** What the crease pattern holds, for the report and tests: counts by assignment. */
    public record Counts(int vertices, int faces, int edges, int mountains, int valleys, int flat, int border, int faceOrders) {
    }

    /**
     * Writes the sheets to {@code file}.
     *
     * @param title the frame's title (what was folded)
     */
    public static Counts write(Path file, String title, List<Folded> sheets) throws IOException {
        return write(file, title, sheets, null);
    }

    /** As {@link #write(Path, String, List)}, with {@code steps} (or none) as frames after the folded state, a frame a fold. */
    public static Counts write(Path file, String title, List<Folded> sheets, FoldSteps steps) throws IOException {
        Pattern pattern = new Pattern(sheets);
        pattern.steps = steps;
        AtomicFile.write(file, stream -> {
            try (JsonGenerator json = JSON.createGenerator(stream)) {
                pattern.writeTo(json, title);
            }
        }, true);
        return pattern.counts;
    }

    /** The FOLD file's text, as {@link #write} writes it, made in memory (for a check of what would be written). */
    public static String text(String title, List<Folded> sheets) throws IOException {
        Pattern pattern = new Pattern(sheets);
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        try (JsonGenerator json = JSON.createGenerator(bytes)) {
            pattern.writeTo(json, title);
        }
        return bytes.toString(java.nio.charset.StandardCharsets.UTF_8);
    }

    /**
     * One sheet's crease pattern as its FOLD file has it, for drawing: the paper rectangle
     * [0, length] × [0, width], its vertices in paper coordinates (u, v pairs), and each edge's
     * two vertices, its assignment (B, M, V or F, as {@code edges_assignment}) and its fold step
     * (from 1, as {@code edges_ifold:foldStep}; 0 for the border and flat edges).
     */
    public record SheetCreases(double length, double width, double[] uv, int[][] edges, char[] assignments, int[] steps) {
    }

    /** The crease patterns of {@code sheets}, one a sheet, their fold steps counted over all of them as the FOLD file counts them. */
    public static List<SheetCreases> creases(List<Folded> sheets) {
        Pattern pattern = new Pattern(sheets, false); // the faces' order in the folded state: not drawn
        List<SheetCreases> all = new ArrayList<>();
        for (int k = 0; k < sheets.size(); k++) {
            Sheet sheet = sheets.get(k).sheet();
            double[] uv = new double[2 * sheet.vertexCount()];
            for (int v = 0; v < sheet.vertexCount(); v++) {
                uv[2 * v] = sheet.u(v);
                uv[2 * v + 1] = sheet.v(v);
            }
            // A sheet of another tool's crease pattern lies where its file puts it: drawn from its
            // corner, as a strip is from (0, 0).
            double[] box = ifold.sheet.Polygons2.bounds(uv);
            for (int i = 0; i < uv.length; i += 2) {
                uv[i] -= box[0];
                uv[i + 1] -= box[1];
            }
            List<int[]> edges = new ArrayList<>();
            StringBuilder assignments = new StringBuilder();
            List<Integer> steps = new ArrayList<>();
            for (int e = 0; e < pattern.edges.size(); e++) {
                int[] edge = pattern.edges.get(e);
                if (edge[4] != k) {
                    continue;
                }
                edges.add(new int[] {edge[0] - pattern.vertexBase[k], edge[1] - pattern.vertexBase[k]});
                assignments.append(pattern.assignments.get(e).charAt(0));
                steps.add(pattern.foldStep[e] == null ? 0 : pattern.foldStep[e]);
            }
            all.add(new SheetCreases(sheet.length(), sheet.width(), uv, edges.toArray(new int[0][]), assignments.toString().toCharArray(),
                    steps.stream().mapToInt(Integer::intValue).toArray()));
        }
        return all;
    }

    /** The crease pattern and folded state, found once and written after. */
    static final class Pattern {
        final List<Folded> sheets;
        final int[] vertexBase;
        final int[] faceBase;
        int vertexCount;
        int faceCount;
        /** Edges: vertices (global), left face and right face (global, -1 for none), sheet. */
        final List<int[]> edges = new ArrayList<>();
        final List<String> assignments = new ArrayList<>();
        final List<Double> angles = new ArrayList<>();
        final List<int[]> orders = new ArrayList<>();
        final List<int[]> levels = new ArrayList<>();
        /** The frames a fold, written after the folded state; null where none were asked for. */
        FoldSteps steps;
        /**
         * Each edge's fold step, from 1, sheet by sheet, fold by fold: the fold that made the
         * crease (the creases of one fold share it); null for the border and flat edges.
         */
        Integer[] foldStep;
        Counts counts;

        Pattern(List<Folded> sheets) {
            this(sheets, true);
        }

        /** With {@code withOrders}, the folded state's face orders too (a FOLD file's); without, the crease pattern alone. */
        Pattern(List<Folded> sheets, boolean withOrders) {
            this.sheets = sheets;
            vertexBase = new int[sheets.size()];
            faceBase = new int[sheets.size()];
            for (int k = 0; k < sheets.size(); k++) {
                Sheet sheet = sheets.get(k).sheet();
                vertexBase[k] = vertexCount;
                faceBase[k] = faceCount;
                vertexCount += sheet.vertexCount();
                faceCount += sheet.faceCount();
                levels.add(sheet.levels());
            }
            int mountains = 0;
            int valleys = 0;
            int flat = 0;
            int border = 0;
            List<long[]> folds = new ArrayList<>(); // {sheet, fold, edge} of each mountain and valley
            for (int k = 0; k < sheets.size(); k++) {
                Folded folded = sheets.get(k);
                Sheet sheet = folded.sheet();
                Map<Long, Integer> seen = new HashMap<>();
                for (int f = 0; f < sheet.faceCount(); f++) {
                    int[] loop = sheet.loop(f);
                    for (int i = 0; i < loop.length; i++) {
                        int a = loop[i];
                        int b = loop[(i + 1) % loop.length];
                        long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
                        if (seen.containsKey(key)) {
                            continue;
                        }
                        seen.put(key, edges.size());
                        int g = sheet.faceAcross(a, b);
                        edges.add(new int[] {vertexBase[k] + a, vertexBase[k] + b, faceBase[k] + f, g < 0 ? -1 : faceBase[k] + g, k});
                        if (g < 0) {
                            assignments.add("B");
                            angles.add(0.0);
                            border++;
                            continue;
                        }
                        double angle = sheet.crease(a, b) == null ? 0 : foldAngle(folded, levels.get(k), f, g, a, b);
                        if (Math.abs(angle) < Tolerance.RELATIVE_EQUALITY) {
                            assignments.add("F");
                            angles.add(0.0);
                            flat++;
                        } else {
                            folds.add(new long[] {k, sheet.creaseFold(a, b), edges.size() - 1});
                            assignments.add(angle > 0 ? "V" : "M");
                            angles.add(angle);
                            if (angle > 0) {
                                valleys++;
                            } else {
                                mountains++;
                            }
                        }
                    }
                }
                if (withOrders) {
                    findOrders(k);
                }
            }
            folds.sort(Comparator.<long[]>comparingLong(f -> f[0]).thenComparingLong(f -> f[1])
                    .thenComparingLong(f -> f[2]));
            foldStep = new Integer[edges.size()];
            int step = 0;
            for (int i = 0; i < folds.size(); i++) {
                long[] fold = folds.get(i);
                if (i == 0 || fold[0] != folds.get(i - 1)[0] || fold[1] != folds.get(i - 1)[1]) {
                    step++; // the creases of one fold (a crease later folds cut in pieces) share its step
                }
                foldStep[(int) fold[2]] = step;
            }
            counts = new Counts(vertexCount, faceCount, edges.size(), mountains, valleys, flat, border, orders.size());
        }

        /** Every pair of faces of one sheet that overlap on one host, ordered as the stack has them. */
        private void findOrders(int k) {
            Folded folded = sheets.get(k);
            Sheet sheet = folded.sheet();
            int[] level = levels.get(k);
            Map<Integer, List<Integer>> byHost = new HashMap<>();
            for (int f = 0; f < sheet.faceCount(); f++) {
                byHost.computeIfAbsent(sheet.host(f), h -> new ArrayList<>()).add(f);
            }
            double tolerance = sheet.tolerance();
            for (List<Integer> faces : byHost.values()) {
                int n = faces.size();
                double[][] placed = new double[n][];
                double[][] boxes = new double[n][];
                // By the grid cells their polygons meet: a pair is tried only where they share
                // one, which on a host of many long passes is a few neighbours of each face.
                for (int i = 0; i < n; i++) {
                    placed[i] = sheet.placed(faces.get(i));
                    boxes[i] = Polygons2.bounds(placed[i]);
                }
                ifold.sheet.FaceGrid grid = new ifold.sheet.FaceGrid(ifold.sheet.FaceGrid.cellFor(placed, n, 2 * sheet.width()));
                for (int i = 0; i < n; i++) {
                    grid.add(i, placed[i]);
                }
                for (int i = 0; i < n; i++) {
                    int[] near = grid.near(placed[i]); // null: a face too big for the grid, tried with all
                    for (int c = 0; c < (near == null ? n : near.length); c++) {
                        int j = near == null ? c : near[c];
                        if (j <= i) {
                            continue; // each pair once
                        }
                        if (boxes[i][0] >= boxes[j][2] - tolerance || boxes[j][0] >= boxes[i][2] - tolerance
                                || boxes[i][1] >= boxes[j][3] - tolerance || boxes[j][1] >= boxes[i][3] - tolerance) {
                            continue;
                        }
                        if (!Polygons2.overlap(placed[i], placed[i].length / 2, placed[j], placed[j].length / 2, tolerance)) {
                            continue;
                        }
                        int f = faces.get(i);
                        int g = faces.get(j);
                        if (level[f] == level[g]) {
                            continue; // not stacked: cannot happen on a sound sheet
                        }
                        // +1 where f lies on the side g's (top) normal points to.
                        int side = (level[f] > level[g] ? 1 : -1) * (sheet.pose(g).mirrors() ? -1 : 1);
                        orders.add(new int[] {faceBase[k] + f, faceBase[k] + g, side});
                    }
                }
            }
        }

        void writeTo(JsonGenerator json, String title) throws IOException {
            json.writeStartObject();
            json.writeNumberField("file_spec", 1.2);
            json.writeStringField("file_creator", "iFold");
            json.writeFieldName("file_classes");
            json.writeStartArray();
            json.writeString("singleModel");
            json.writeEndArray();
            json.writeStringField("frame_title", title);
            stringArray(json, "frame_classes", "creasePattern");
            stringArray(json, "frame_attributes", "2D");
            json.writeStringField("frame_unit", "unit");
            json.writeNumberField("frame_ifold:thickness", sheets.isEmpty() ? 0 : sheets.get(0).sheet().thickness());
            json.writeFieldName("vertices_coords");
            json.writeStartArray();
            double offset = 0;
            for (Folded folded : sheets) {
                Sheet sheet = folded.sheet();
                for (int v = 0; v < sheet.vertexCount(); v++) {
                    json.writeStartArray();
                    json.writeNumber(sheet.u(v));
                    json.writeNumber(sheet.v(v) + offset);
                    json.writeEndArray();
                }
                offset += 2 * sheet.width(); // the next strip a width above
            }
            json.writeEndArray();
            json.writeFieldName("edges_vertices");
            json.writeStartArray();
            for (int[] edge : edges) {
                json.writeStartArray();
                json.writeNumber(edge[0]);
                json.writeNumber(edge[1]);
                json.writeEndArray();
            }
            json.writeEndArray();
            json.writeFieldName("edges_assignment");
            json.writeStartArray();
            for (String assignment : assignments) {
                json.writeString(assignment);
            }
            json.writeEndArray();
            json.writeFieldName("edges_foldAngle");
            json.writeStartArray();
            for (double angle : angles) {
                json.writeNumber(angle);
            }
            json.writeEndArray();
            // Per edge, as FOLD's edges_ keys are: the step of the fold that made it, which
            // `ifold fold` folds the creases back in; null where no fold did.
            json.writeFieldName("edges_ifold:foldStep");
            json.writeStartArray();
            for (Integer step : foldStep) {
                if (step == null) {
                    json.writeNull();
                } else {
                    json.writeNumber(step);
                }
            }
            json.writeEndArray();
            json.writeFieldName("faces_vertices");
            json.writeStartArray();
            for (int k = 0; k < sheets.size(); k++) {
                Sheet sheet = sheets.get(k).sheet();
                for (int f = 0; f < sheet.faceCount(); f++) {
                    json.writeStartArray();
                    for (int v : sheet.loop(f)) {
                        json.writeNumber(vertexBase[k] + v);
                    }
                    json.writeEndArray();
                }
            }
            json.writeEndArray();

            json.writeFieldName("file_frames");
            json.writeStartArray();
            json.writeStartObject();
            stringArray(json, "frame_classes", "foldedForm");
            stringArray(json, "frame_attributes", "3D");
            json.writeNumberField("frame_parent", 0);
            json.writeBooleanField("frame_inherit", true);
            List<double[]> placed = new ArrayList<>();
            for (Folded folded : sheets) {
                placed.addAll(foldedVertices(folded));
            }
            points(json, "vertices_coords", placed);
            json.writeFieldName("faceOrders");
            json.writeStartArray();
            for (int[] order : orders) {
                json.writeStartArray();
                json.writeNumber(order[0]);
                json.writeNumber(order[1]);
                json.writeNumber(order[2]);
                json.writeEndArray();
            }
            json.writeEndArray();
            json.writeFieldName("faces_ifold:level");
            json.writeStartArray();
            for (int[] level : levels) {
                for (int l : level) {
                    json.writeNumber(l);
                }
            }
            json.writeEndArray();
            // Which side of each face is out, away from what it rests on: a folded state without
            // thickness cannot say (paper turned over, and paper on two sides of one plane, look alike).
            json.writeFieldName("faces_ifold:facing");
            json.writeStartArray();
            for (Folded folded : sheets) {
                for (int f = 0; f < folded.sheet().faceCount(); f++) {
                    json.writeNumber(folded.sheet().pose(f).mirrors() ? -1 : 1);
                }
            }
            json.writeEndArray();
            json.writeEndObject();
            if (steps != null) {
                steps.writeTo(json);
            }
            json.writeEndArray();
            json.writeEndObject();
        }

        /** Writes {@code field}: the points, each a list of x, y, z. */
        static void points(JsonGenerator json, String field, List<double[]> points) throws IOException {
            json.writeFieldName(field);
            json.writeStartArray();
            for (double[] p : points) {
                json.writeStartArray();
                json.writeNumber(p[0]);
                json.writeNumber(p[1]);
                json.writeNumber(p[2]);
                json.writeEndArray();
            }
            json.writeEndArray();
        }

        static void stringArray(JsonGenerator json, String field, String value) throws IOException {
            json.writeFieldName(field);
            json.writeStartArray();
            json.writeString(value);
            json.writeEndArray();
        }
    }

    /**
     * Each paper vertex in space, on the planes its faces rest on (their mean, where layers of
     * different planes meet), on ideal paper where the folding has it.
     */
    static List<double[]> foldedVertices(Folded given) {
        Folded folded = given.idealSheet() != null ? new Folded(given.idealSheet(), given.idealFrames()) : given;
        Sheet sheet = folded.sheet();
        double[][] sum = new double[sheet.vertexCount()][3];
        int[] count = new int[sheet.vertexCount()];
        double[] point = new double[3];
        for (int f = 0; f < sheet.faceCount(); f++) {
            HostFrame frame = folded.frames()[sheet.host(f)];
            Isometry2 pose = sheet.pose(f);
            for (int v : sheet.loop(f)) {
                frame.toSpace(pose.x(sheet.u(v), sheet.v(v)), pose.y(sheet.u(v), sheet.v(v)), 0, point, 0);
                for (int axis = 0; axis < 3; axis++) {
                    sum[v][axis] += point[axis];
                }
                count[v]++;
            }
        }
        List<double[]> points = new ArrayList<>();
        for (int v = 0; v < sheet.vertexCount(); v++) {
            int n = Math.max(1, count[v]);
            points.add(new double[] {sum[v][0] / n, sum[v][1] / n, sum[v][2] / n});
        }
        return points;
    }

    /**
     * The fold angle in degrees along paper edge a → b between face f (left of it on the sheet)
     * and face g: positive for a valley, negative for a mountain, measured on the folded state
     * against the paper's top side.
     */
    static double foldAngle(Folded folded, int[] levels, int f, int g, int a, int b) {
        Sheet sheet = folded.sheet();
        double[] nf = topNormal(folded, f);
        double[] ng = topNormal(folded, g);
        double cos = Math.max(-1, Math.min(1, dot(nf, ng)));
        // atan2 of the cross and dot products, not acos of the dot: near 0 acos turns a rounding
        // of 1e-16 into 1e-6 degrees, and coplanar faces (a strip crossing between two triangles
        // of one face of the model) would come out creased.
        double[] cross = {nf[1] * ng[2] - nf[2] * ng[1], nf[2] * ng[0] - nf[0] * ng[2], nf[0] * ng[1] - nf[1] * ng[0]};
        double degrees = Math.toDegrees(Math.atan2(Math.sqrt(dot(cross, cross)), dot(nf, ng)));
        if (degrees < Tolerance.FILE_PRECISION) {
            return 0;
        }
        if (cos < -1 + Tolerance.COPLANAR_COSINE && sheet.host(f) == sheet.host(g)) {
            // Flat: a valley lays g on f's top side.
            double[] hostNormal = folded.frames()[sheet.host(f)].normal();
            double side = (levels[g] - levels[f]) * dot(hostNormal, nf);
            return side > 0 ? 180 : -180;
        }
        double[] pa = onPlane(folded, g, a);
        double[] pb = onPlane(folded, g, b);
        double[] d = unit(sub(pb, pa));
        double[] centre = new double[3];
        int[] loop = sheet.loop(g);
        for (int v : loop) {
            double[] p = onPlane(folded, g, v);
            for (int axis = 0; axis < 3; axis++) {
                centre[axis] += p[axis] / loop.length;
            }
        }
        double[] into = sub(centre, pa);
        double along = dot(into, d);
        for (int axis = 0; axis < 3; axis++) {
            into[axis] -= along * d[axis];
        }
        return dot(into, nf) > 0 ? degrees : -degrees;
    }

    /** The normal of face f's top side (the side up on the unfolded sheet), in space. */
    private static double[] topNormal(Folded folded, int f) {
        double[] n = folded.frames()[folded.sheet().host(f)].normal();
        double sign = folded.sheet().pose(f).mirrors() ? -1 : 1;
        return new double[] {sign * n[0], sign * n[1], sign * n[2]};
    }

    private static double[] onPlane(Folded folded, int f, int v) {
        Sheet sheet = folded.sheet();
        Isometry2 pose = sheet.pose(f);
        double[] p = new double[3];
        folded.frames()[sheet.host(f)].toSpace(pose.x(sheet.u(v), sheet.v(v)), pose.y(sheet.u(v), sheet.v(v)), 0, p, 0);
        return p;
    }
}
