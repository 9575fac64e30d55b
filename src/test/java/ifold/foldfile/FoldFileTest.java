package ifold.foldfile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import ifold.geom.Triangle;
import ifold.mesh.PolygonSoup;
import ifold.script.FoldScript;
import ifold.script.ScriptFolding;
import ifold.sheet.Sheet;
import ifold.wrap.TurnGadget;
import ifold.wrap.Wrap;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * FOLD files read back by an independent reader (jackson's parser into plain lists and maps):
 * the crease pattern is the sheet, every number as computed, and every flat-folded crease
 * pattern satisfies Maekawa and Kawasaki at every interior vertex.
 */
public class FoldFileTest {
    @TempDir
    Path dir;

    /** Reads JSON into maps, lists, doubles, strings and booleans: the tests' own reader, independent of iFold's. */
    public static Object read(Path file) throws Exception {
        try (JsonParser parser = new JsonFactory().createParser(file.toFile())) {
            parser.nextToken();
            return value(parser);
        }
    }

    private static Object value(JsonParser parser) throws Exception {
        JsonToken token = parser.currentToken();
        switch (token) {
            case START_OBJECT -> {
                Map<String, Object> map = new LinkedHashMap<>();
                while (parser.nextToken() != JsonToken.END_OBJECT) {
                    String name = parser.currentName();
                    parser.nextToken();
                    map.put(name, value(parser));
                }
                return map;
            }
            case START_ARRAY -> {
                List<Object> list = new ArrayList<>();
                while (parser.nextToken() != JsonToken.END_ARRAY) {
                    list.add(value(parser));
                }
                return list;
            }
            case VALUE_NUMBER_INT, VALUE_NUMBER_FLOAT -> {
                return parser.getDoubleValue();
            }
            case VALUE_STRING -> {
                return parser.getText();
            }
            case VALUE_TRUE, VALUE_FALSE -> {
                return parser.getBooleanValue();
            }
            default -> {
                return null;
            }
        }
    }

    @SuppressWarnings("unchecked")
    private static List<List<Double>> numbers(Map<String, Object> fold, String key) {
        return (List<List<Double>>) fold.get(key);
    }

    /**
     * Maekawa (|M - V| = 2) and Kawasaki (alternate angles sum to 180°) at every vertex of the
     * crease pattern that is not on its border and has creases; returns the number checked.
     */
    @SuppressWarnings("unchecked")
    static int assertFlatFoldable(Map<String, Object> fold) {
        List<List<Double>> coords = numbers(fold, "vertices_coords");
        List<List<Double>> edges = numbers(fold, "edges_vertices");
        List<String> assignment = (List<String>) fold.get("edges_assignment");
        int n = coords.size();
        boolean[] border = new boolean[n];
        List<List<Integer>> creases = new ArrayList<>();
        for (int v = 0; v < n; v++) {
            creases.add(new ArrayList<>());
        }
        for (int e = 0; e < edges.size(); e++) {
            int a = edges.get(e).get(0).intValue();
            int b = edges.get(e).get(1).intValue();
            if (assignment.get(e).equals("B")) {
                border[a] = true;
                border[b] = true;
            } else if (assignment.get(e).equals("M") || assignment.get(e).equals("V")) {
                creases.get(a).add(e);
                creases.get(b).add(e);
            }
        }
        int checked = 0;
        for (int v = 0; v < n; v++) {
            if (border[v] || creases.get(v).isEmpty()) {
                continue;
            }
            int mountains = 0;
            int valleys = 0;
            List<Double> angles = new ArrayList<>();
            for (int e : creases.get(v)) {
                int a = edges.get(e).get(0).intValue();
                int w = a == v ? edges.get(e).get(1).intValue() : a;
                angles.add(Math.atan2(coords.get(w).get(1) - coords.get(v).get(1), coords.get(w).get(0) - coords.get(v).get(0)));
                mountains += assignment.get(e).equals("M") ? 1 : 0;
                valleys += assignment.get(e).equals("V") ? 1 : 0;
            }
            assertEquals(2, Math.abs(mountains - valleys), "Maekawa at vertex " + v + " " + coords.get(v));
            angles.sort(Double::compare);
            double alternate = 0;
            for (int i = 0; i < angles.size(); i++) {
                double next = i + 1 < angles.size() ? angles.get(i + 1) : angles.get(0) + 2 * Math.PI;
                alternate += (i % 2 == 0 ? 1 : -1) * (next - angles.get(i));
            }
            assertEquals(0, alternate, 1e-7, "Kawasaki at vertex " + v + " " + coords.get(v));
            checked++;
        }
        return checked;
    }

    @SuppressWarnings("unchecked")
    private Map<String, Object> writeAndRead(List<FoldFile.Folded> sheets) throws Exception {
        Path file = dir.resolve("out.fold");
        FoldFile.Counts counts = FoldFile.write(file, "test", sheets);
        Map<String, Object> fold = (Map<String, Object>) read(file);
        assertEquals(1.2, fold.get("file_spec"));
        assertEquals(List.of("creasePattern"), fold.get("frame_classes"));
        assertEquals(counts.vertices(), numbers(fold, "vertices_coords").size());
        assertEquals(counts.edges(), numbers(fold, "edges_vertices").size());
        assertEquals(counts.faces(), numbers(fold, "faces_vertices").size());
        List<Map<String, Object>> frames = (List<Map<String, Object>>) fold.get("file_frames");
        assertEquals(List.of("foldedForm"), frames.get(0).get("frame_classes"));
        assertEquals(true, frames.get(0).get("frame_inherit"));
        assertEquals(counts.vertices(), numbers(frames.get(0), "vertices_coords").size());
        // The crease pattern is the sheet: every coordinate read back is the one the sheet holds.
        int base = 0;
        double offset = 0;
        List<List<Double>> coords = numbers(fold, "vertices_coords");
        for (FoldFile.Folded folded : sheets) {
            Sheet sheet = folded.sheet();
            for (int v = 0; v < sheet.vertexCount(); v++) {
                assertEquals(sheet.u(v), coords.get(base + v).get(0), 0);
                assertEquals(sheet.v(v) + offset, coords.get(base + v).get(1), 0);
            }
            base += sheet.vertexCount();
            offset += 2 * sheet.width();
        }
        // Faces counter-clockwise in the crease pattern.
        for (List<Double> face : numbers(fold, "faces_vertices")) {
            double twice = 0;
            for (int i = 0; i < face.size(); i++) {
                List<Double> p = coords.get(face.get(i).intValue());
                List<Double> q = coords.get(face.get((i + 1) % face.size()).intValue());
                twice += p.get(0) * q.get(1) - q.get(0) * p.get(1);
            }
            assertTrue(twice > 0, "a face runs counter-clockwise");
        }
        // Angles agree with assignments.
        List<String> assignment = (List<String>) fold.get("edges_assignment");
        List<Double> angles = (List<Double>) fold.get("edges_foldAngle");
        for (int e = 0; e < assignment.size(); e++) {
            String a = assignment.get(e);
            double angle = angles.get(e);
            assertTrue(a.equals("V") ? angle > 0 : a.equals("M") ? angle < 0 : angle == 0, "edge " + e + ": " + a + " " + angle);
        }
        return fold;
    }

    static Stream<String> scripts() {
        return Stream.of("pleat20.fold", "square-quarters.fold", "strip-turn.fold", "zigzag-turn.fold");
    }

    @ParameterizedTest
    @MethodSource("scripts")
    void everyExampleScriptIsAFlatFoldableCreasePattern(String name) throws Exception {
        ScriptFolding.Result result = FoldScript.read(Path.of("models", "scripts", name)).play();
        Map<String, Object> fold = writeAndRead(List.of(new FoldFile.Folded(result.sheet(), result.frames())));
        assertFlatFoldable(fold);
    }

    @Test
    @SuppressWarnings("unchecked")
    void mountainAndValleyAreThePapersOwn() throws Exception {
        // The zig-zag turn: two valleys of the paper (the second on the flap lying back up).
        ScriptFolding.Result turn = FoldScript.read(Path.of("models", "scripts", "zigzag-turn.fold")).play();
        Map<String, Object> fold = writeAndRead(List.of(new FoldFile.Folded(turn.sheet(), turn.frames())));
        List<String> assignment = (List<String>) fold.get("edges_assignment");
        assertEquals(2, assignment.stream().filter("V"::equals).count());
        assertEquals(0, assignment.stream().filter("M"::equals).count());
        // A Z as a crease pattern labels it: a valley, then a mountain; the script says the same.
        for (String second : new String[] {"valley", "mountain"}) {
            ScriptFolding.Result z = FoldScript.parse("paper strip 12 1\nthickness 0\nfold valley 180 paper 4 0 4 1 right\n"
                    + "fold " + second + " 180 flap 8 0 8 1 right\n").play();
            List<String> labels = (List<String>) writeAndRead(List.of(new FoldFile.Folded(z.sheet(), z.frames())))
                    .get("edges_assignment");
            assertEquals(second.equals("valley") ? 2 : 1, labels.stream().filter("V"::equals).count(), second + ": " + labels);
            assertEquals(second.equals("valley") ? 0 : 1, labels.stream().filter("M"::equals).count(), second + ": " + labels);
        }
    }

    @Test
    void theZigZagOfAHundredRandomTrianglesIsFlatFoldable() throws Exception {
        Random random = new Random(20261201);
        int vertices = 0;
        for (int i = 0; i < 100; i++) {
            Triangle triangle;
            do {
                triangle = Triangle.planar(10 * random.nextDouble(), 10 * random.nextDouble(), 10 * random.nextDouble(),
                        10 * random.nextDouble(), 10 * random.nextDouble(), 10 * random.nextDouble());
            } while (triangle.smallestAngle() < 12);
            int start = random.nextInt(3);
            PolygonSoup path = new PolygonSoup();
            for (int k = 0; k < 3; k++) {
                path.addVertex(triangle.corner(k).x(), triangle.corner(k).y(), 0);
            }
            path.addTriangle(0, 1, 2);
            double width = triangle.height(start) / (1 + 9 * random.nextDouble());
            Wrap.Result result = Wrap.wrap(path, new int[] {0, 1}, new Wrap.Options(width, width / 80,
                    new Wrap.Ends(start, (start + 1) % 3, random.nextBoolean() ? -1 : (start + 2) % 3)));
            Map<String, Object> fold = writeAndRead(List.of(new FoldFile.Folded(result.strips().get(0).sheet(), result.frames())));
            vertices += assertFlatFoldable(fold);
        }
        assertTrue(vertices > 100, "interior crease vertices checked: " + vertices);
    }

    @Test
    void theTurnGadgetAndAWrapAreWrittenWhole() throws Exception {
        TurnGadget.Result gadget = TurnGadget.turn(70, 0.5, 1, 0.02, 4, 6);
        assertFlatFoldable(writeAndRead(List.of(new FoldFile.Folded(gadget.sheet(), gadget.wrap().frames()))));
        PolygonSoup square = new PolygonSoup();
        square.addVertex(0, 0, 0);
        square.addVertex(4, 0, 0);
        square.addVertex(4, 4, 1);
        square.addVertex(0, 4, 0);
        square.addTriangle(0, 1, 2);
        square.addTriangle(0, 2, 3);
        Wrap.Result wrap = Wrap.wrap(square, new int[] {0, 2}, new Wrap.Options(Wrap.widest(square, new int[] {0, 2}) / 3, 0));
        Map<String, Object> fold = writeAndRead(List.of(new FoldFile.Folded(wrap.strips().get(0).sheet(), wrap.frames())));
        // The folded state is the crease pattern moved rigidly: every edge keeps its length.
        assertEquals(0, worstStretch(fold), 1e-9);
    }

    @Test
    void aStripRunsFlatAcrossTrianglesOfOneFace() throws Exception {
        // The refinement cuts each face of the tetrahedron into coplanar triangles: the strip
        // runs over the spokes between them unfolded (one host a face), so that every crease of
        // the file bends the paper, none is a valley of 1e-6 degrees, and it crosses an edge only
        // between faces.
        ifold.mesh.HalfedgeMesh tetrahedron = ifold.mesh.MeshBuilder.build(ifold.mesh.Solids.tetrahedron()).mesh();
        ifold.refine.HamiltonianRefinement.Result refinement = ifold.refine.HamiltonianRefinement.refine(tetrahedron);
        Wrap.Result wrap = Wrap.wrap(refinement, new Wrap.Options(Double.NaN, Double.NaN));
        assertEquals(4, wrap.frames().length, "one host a face");
        int faceChanges = 0;
        for (int t = 0; t + 1 < wrap.hostOf().length; t++) {
            faceChanges += wrap.hostOf()[t] != wrap.hostOf()[t + 1] ? 1 : 0;
        }
        assertEquals(faceChanges, wrap.count(Wrap.Kind.EDGE_CROSSING));
        assertTrue(faceChanges < refinement.mesh().faceCount() - 1, faceChanges + " crossings between faces");
        Map<String, Object> fold = writeAndRead(List.of(new FoldFile.Folded(wrap.strips().get(0).sheet(), wrap.frames())));
        @SuppressWarnings("unchecked")
        List<String> assignments = (List<String>) fold.get("edges_assignment");
        List<Double> angles = new ArrayList<>();
        for (Object angle : (List<?>) fold.get("edges_foldAngle")) {
            angles.add(((Number) angle).doubleValue());
        }
        int bends = 0;
        for (int e = 0; e < assignments.size(); e++) {
            if (!assignments.get(e).equals("B") && !assignments.get(e).equals("F")) {
                assertTrue(Math.abs(angles.get(e)) > 1, "edge " + e + " is " + assignments.get(e) + " by " + angles.get(e) + " degrees");
                bends += Math.abs(Math.abs(angles.get(e)) - 180) > 1 ? 1 : 0;
            }
        }
        assertTrue(bends > 0, "folds over the tetrahedron's edges: " + bends);
    }

    @Test
    @SuppressWarnings("unchecked")
    void theCreasesAreListedInTheOrderTheyWereFolded() throws Exception {
        // Folded along x = 5 first, then along y = 5 through both layers: the second fold cuts
        // the first crease in two, and both halves still come first.
        FoldScript script = FoldScript.builder().square(10).thickness(0.01)
                .foldOnPaper(FoldScript.Kind.VALLEY, 180, 5, 0, 5, 10, FoldScript.Side.RIGHT)
                .foldOnPaper(FoldScript.Kind.VALLEY, 180, 0, 5, 5, 5, FoldScript.Side.LEFT).build();
        ScriptFolding.Result result = script.play();
        Map<String, Object> fold = writeAndRead(List.of(new FoldFile.Folded(result.sheet(), result.frames())));
        List<String> assignments = (List<String>) fold.get("edges_assignment");
        List<List<Double>> vertices = numbers(fold, "vertices_coords");
        List<List<Double>> edges = numbers(fold, "edges_vertices");
        // edges_ifold:foldStep is per edge, as FOLD's edges_ keys are: a step for each crease, null elsewhere.
        List<?> steps = (List<?>) fold.get("edges_ifold:foldStep");
        assertEquals(edges.size(), steps.size(), "one entry an edge");
        List<Integer> order = new ArrayList<>();
        for (int e = 0; e < steps.size(); e++) {
            boolean crease = assignments.get(e).equals("M") || assignments.get(e).equals("V");
            assertEquals(crease, steps.get(e) != null, "edge " + e + " (" + assignments.get(e) + ") has a step only if it is a crease");
            if (crease) {
                order.add(e);
            }
        }
        order.sort(java.util.Comparator.<Integer>comparingDouble(e -> ((Number) steps.get(e)).doubleValue()).thenComparing(e -> e));
        int creases = 0;
        for (String a : assignments) {
            creases += a.equals("M") || a.equals("V") ? 1 : 0;
        }
        assertEquals(creases, order.size(), "every mountain and valley, once");
        assertEquals(creases, new java.util.HashSet<>(order).size());
        List<String> lines = new ArrayList<>();
        for (int e : order) {
            List<Double> a = vertices.get(edges.get(e).get(0).intValue());
            List<Double> b = vertices.get(edges.get(e).get(1).intValue());
            lines.add(Math.abs(a.get(0) - 5) < 1e-9 && Math.abs(b.get(0) - 5) < 1e-9 ? "x=5" : "y=5");
        }
        assertEquals(List.of("x=5", "x=5", "y=5", "y=5"), lines, "the first fold's two halves, then the second's creases");
    }

    @Test
    @SuppressWarnings("unchecked")
    void aScriptsFoldedStateIsOfIdealPaperEvenWhereItsLayersAreThick() throws Exception {
        // Three halvings stack 8 layers of thickness 0.05; a fold of 90° through them turns the
        // paper about a line lifted by the stack, onto a plane off the one it left. The folded
        // state of ideal paper still keeps every edge its length.
        FoldScript script = FoldScript.builder().rectangle(16, 4).thickness(0.05)
                .foldOnPaper(FoldScript.Kind.VALLEY, 180, 8, 0, 8, 4, FoldScript.Side.RIGHT)
                .foldOnPaper(FoldScript.Kind.VALLEY, 180, 4, 0, 4, 4, FoldScript.Side.RIGHT)
                .foldOnPaper(FoldScript.Kind.VALLEY, 180, 2, 0, 2, 4, FoldScript.Side.RIGHT)
                .foldOnPaper(FoldScript.Kind.VALLEY, 90, 0, 2, 2, 2, FoldScript.Side.LEFT).build();
        ScriptFolding.Result result = script.play();
        FoldFile.Folded thick = new FoldFile.Folded(result.sheet(), result.frames());
        FoldFile.Folded ideal = FoldFile.Folded.ofScript(script, result, ScriptFolding.DEFAULT_MAX_FACES);
        assertTrue(ideal.idealSheet() != null, "folded again on ideal paper, to the same faces");
        assertTrue(worstStretch(writeAndRead(List.of(thick))) > 0.1, "setup: the thick places stretch the creases' edges");
        Map<String, Object> fold = writeAndRead(List.of(ideal));
        assertEquals(0, worstStretch(fold), 1e-12, "every edge keeps its length");
        assertEquals(0.05, fold.get("frame_ifold:thickness"), "the paper's thickness is still the script's");
        FoldScript thin = script.withThickness(0);
        assertEquals(null, FoldFile.Folded.ofScript(thin, thin.play(), ScriptFolding.DEFAULT_MAX_FACES).idealSheet(),
                "ideal paper is folded once");
    }

    /** The most an edge's length in the folded state differs from its length on the paper. */
    @SuppressWarnings("unchecked")
    private static double worstStretch(Map<String, Object> fold) {
        List<List<Double>> folded = numbers(((List<Map<String, Object>>) fold.get("file_frames")).get(0), "vertices_coords");
        List<List<Double>> flat = numbers(fold, "vertices_coords");
        double worst = 0;
        for (List<Double> edge : numbers(fold, "edges_vertices")) {
            int a = edge.get(0).intValue();
            int b = edge.get(1).intValue();
            double paper = Math.hypot(flat.get(a).get(0) - flat.get(b).get(0), flat.get(a).get(1) - flat.get(b).get(1));
            double space = Math.sqrt(Math.pow(folded.get(a).get(0) - folded.get(b).get(0), 2)
                    + Math.pow(folded.get(a).get(1) - folded.get(b).get(1), 2) + Math.pow(folded.get(a).get(2) - folded.get(b).get(2), 2));
            worst = Math.max(worst, Math.abs(paper - space));
        }
        return worst;
    }
}
