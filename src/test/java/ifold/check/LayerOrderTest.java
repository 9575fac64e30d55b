package ifold.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.check.LayerOrder.Kind;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The layer-order check on folded states whose answers are known, written as FOLD text here. */
class LayerOrderTest {
    /** A folded state: vertices in space, faces (counter-clockwise about their top normal), faceOrders. */
    private static final class Fold {
        final List<double[]> vertices = new ArrayList<>();
        final List<int[]> faces = new ArrayList<>();
        final List<int[]> orders = new ArrayList<>();

        int vertex(double x, double y, double z) {
            vertices.add(new double[] {x, y, z});
            return vertices.size() - 1;
        }

        int face(int... corners) {
            faces.add(corners);
            return faces.size() - 1;
        }

        /** A face of new vertices. */
        int quad(double[]... corners) {
            int[] loop = new int[corners.length];
            for (int i = 0; i < corners.length; i++) {
                loop[i] = vertex(corners[i][0], corners[i][1], corners[i][2]);
            }
            return face(loop);
        }

        /** f lies on the side g's normal points to (s = 1) or the other (s = -1). */
        void order(int f, int g, int s) {
            orders.add(new int[] {f, g, s});
        }

        String text() {
            StringBuilder json = new StringBuilder("{\"file_spec\": 1.2, \"faces_vertices\": [");
            for (int i = 0; i < faces.size(); i++) {
                json.append(i == 0 ? "" : ", ").append(java.util.Arrays.toString(faces.get(i)));
            }
            json.append("], \"file_frames\": [{\"frame_classes\": [\"foldedForm\"], \"frame_inherit\": true, \"vertices_coords\": [");
            for (int i = 0; i < vertices.size(); i++) {
                double[] p = vertices.get(i);
                json.append(i == 0 ? "" : ", ").append("[" + p[0] + ", " + p[1] + ", " + p[2] + "]");
            }
            json.append("], \"faceOrders\": [");
            for (int i = 0; i < orders.size(); i++) {
                json.append(i == 0 ? "" : ", ").append(java.util.Arrays.toString(orders.get(i)));
            }
            return json.append("]}]}").toString();
        }

        LayerOrder.Result check() throws IOException {
            return LayerOrder.check(text());
        }
    }

    private static double[] p(double x, double y, double z) {
        return new double[] {x, y, z};
    }

    private static Map<Kind, Integer> only(Kind kind, int count) {
        Map<Kind, Integer> expected = new java.util.EnumMap<>(Kind.class);
        for (Kind k : Kind.values()) {
            expected.put(k, k == kind ? count : 0);
        }
        return expected;
    }

    /**
     * A strip [0, 3] × [0, 1] folded in a zig-zag at x = 1 and x = 2 onto [0, 1] × [0, 1]: A on
     * the table (up), B turned over on it, C up again on top.
     */
    private static Fold zFold() {
        Fold fold = new Fold();
        int v0 = fold.vertex(0, 0, 0);
        int v1 = fold.vertex(1, 0, 0);
        int v2 = fold.vertex(0, 0, 0);
        int v3 = fold.vertex(1, 0, 0);
        int v4 = fold.vertex(0, 1, 0);
        int v5 = fold.vertex(1, 1, 0);
        int v6 = fold.vertex(0, 1, 0);
        int v7 = fold.vertex(1, 1, 0);
        fold.face(v0, v1, v5, v4); // A, normal +z
        fold.face(v1, v2, v6, v5); // B, normal -z
        fold.face(v2, v3, v7, v6); // C, normal +z
        return fold;
    }

    @Test
    void aZigZagFoldInItsOrderIsValid() throws IOException {
        Fold fold = zFold();
        fold.order(1, 0, 1); // B above A (A's normal up)
        fold.order(2, 1, -1); // C above B (B's normal down)
        fold.order(2, 0, 1);
        LayerOrder.Result result = fold.check();
        assertEquals(3, result.faces(), "setup: three faces");
        assertEquals(1, result.planes());
        assertEquals(3, result.layered(), "every two faces overlap");
        assertTrue(result.valid(), result.toString());
        assertTrue(result.summary().startsWith("layer order: valid"), result.summary());
    }

    @Test
    void aSpiralIsValidToo() throws IOException {
        // A below C below B: C lies inside the fold A/B, B folds down to C outside A.
        Fold fold = zFold();
        fold.order(1, 0, 1);
        fold.order(1, 2, 1);
        fold.order(2, 0, 1);
        assertTrue(fold.check().valid(), fold.check().toString());
    }

    @Test
    void twoOverlappingFacesWithNoOrderAreUnordered() throws IOException {
        Fold fold = zFold();
        fold.order(1, 0, 1);
        fold.order(2, 1, -1);
        assertEquals(only(Kind.UNORDERED, 1), fold.check().violations());
        assertEquals(List.of(0, 2), java.util.Arrays.stream(fold.check().first().get(0).faces()).sorted().boxed().toList());
    }

    @Test
    void aPairOrderedBothWaysIsContradictory() throws IOException {
        Fold fold = zFold();
        fold.order(1, 0, 1);
        fold.order(0, 1, -1); // A away from B's normal (down): above B
        fold.order(2, 1, -1);
        fold.order(2, 0, 1);
        assertEquals(only(Kind.CONTRADICTORY, 1), fold.check().violations());
    }

    @Test
    void threeLayersAtOnePointInACycleBreakTransitivity() throws IOException {
        Fold fold = zFold();
        fold.order(1, 0, 1); // B above A
        fold.order(2, 1, -1); // C above B
        fold.order(0, 2, 1); // A above C
        LayerOrder.Result result = fold.check();
        assertEquals(1, result.violations().get(Kind.CYCLE), result.toString());
    }

    @Test
    void threeStripsWovenInACycleWithNoCommonPointAreValid() throws IOException {
        Fold fold = new Fold();
        // Three separate bands crossing pairwise, no point in all three (a triangle of weave).
        int a = fold.quad(p(0, 0, 0), p(3, 0, 0), p(3, 0.5, 0), p(0, 0.5, 0));
        int b = fold.quad(p(2.5, -1, 0), p(3, -1, 0), p(1.75, 3, 0), p(1.25, 3, 0));
        int c = fold.quad(p(0, -1, 0), p(0.5, -1, 0), p(1.75, 3, 0), p(1.25, 3, 0));
        fold.order(b, a, 1);
        fold.order(c, b, 1);
        fold.order(a, c, 1);
        LayerOrder.Result result = fold.check();
        assertEquals(3, result.layered(), "setup: every two bands cross");
        assertTrue(result.valid(), result.toString());
    }

    @Test
    void paperThroughAFlatFoldFromBetweenItsLayersIsATacoTortilla() throws IOException {
        Fold fold = zFold();
        fold.order(1, 0, 1);
        fold.order(2, 1, -1);
        fold.order(2, 0, 1);
        // Another sheet, T, across the crease line x = 1 of A/B.
        int t = fold.quad(p(0.5, 0.2, 0), p(1.5, 0.2, 0), p(1.5, 0.8, 0), p(0.5, 0.8, 0));
        fold.order(t, 2, 1); // above C: outside every fold
        fold.order(t, 1, -1);
        fold.order(t, 0, 1);
        assertTrue(fold.check().valid(), "over everything it is free: " + fold.check());

        Fold through = zFold();
        through.order(1, 0, 1);
        through.order(2, 1, -1);
        through.order(2, 0, 1);
        int inside = through.quad(p(0.5, 0.2, 0), p(1.5, 0.2, 0), p(1.5, 0.8, 0), p(0.5, 0.8, 0));
        through.order(inside, 0, 1); // above A
        through.order(inside, 1, 1); // below B (B's normal is down)
        through.order(inside, 2, -1); // below C
        LayerOrder.Result result = through.check();
        assertEquals(only(Kind.TACO_TORTILLA, 1), result.violations(), result.toString());
        assertTrue(result.summary().contains("face 3 lies between faces 0 and 1"), result.summary());
    }

    /**
     * Paper between a taco's faces whose side runs along the crease's line touches the fold
     * from inside; a slant of rounding far along that side is not paper through the crease (the
     * 1.5 degree spike's wrap was flagged so: a side 12.6 long, 4e-8 across at its far end).
     */
    @Test
    void paperInsideAFlatFoldAlongItsCreaseLineIsNotThroughIt() throws IOException {
        for (double slant : new double[] {0, 5e-7, -5e-7}) {
            Fold fold = zFold();
            fold.order(1, 0, 1);
            fold.order(2, 1, -1);
            fold.order(2, 0, 1);
            // Inside the A/B taco, its right side on x = 1 at the crease, 100 long, leaning by the slant.
            int inside = fold.quad(p(0.5, 0.2, 0), p(1, 0.2, 0), p(1 + slant, 100, 0), p(0.5, 100, 0));
            fold.order(inside, 0, 1);
            fold.order(inside, 1, 1);
            fold.order(inside, 2, -1);
            LayerOrder.Result result = fold.check();
            assertTrue(result.valid(), "slant " + slant + ": " + result);
        }
        // The same a thousandth across the crease within its span: through it.
        Fold through = zFold();
        through.order(1, 0, 1);
        through.order(2, 1, -1);
        through.order(2, 0, 1);
        int inside = through.quad(p(0.5, 0.2, 0), p(1.001, 0.2, 0), p(1.001, 100, 0), p(0.5, 100, 0));
        through.order(inside, 0, 1);
        through.order(inside, 1, 1);
        through.order(inside, 2, -1);
        assertEquals(only(Kind.TACO_TORTILLA, 1), through.check().violations(), through.check().toString());
    }

    /** Two strips folded flat along the same line x = 1, both with their flaps on x < 1. */
    private static Fold twoTacos() {
        Fold fold = new Fold();
        for (int strip = 0; strip < 2; strip++) {
            int a = fold.vertex(0, 0, 0);
            int b = fold.vertex(1, 0, 0);
            int c = fold.vertex(1, 1, 0);
            int d = fold.vertex(0, 1, 0);
            int e = fold.vertex(0, 0, 0);
            int g = fold.vertex(0, 1, 0);
            fold.face(a, b, c, d); // lower, up
            fold.face(b, e, g, c); // folded back over, down
        }
        return fold;
    }

    @Test
    void flatFoldsOnOneLineNestOrTheyInterleave() throws IOException {
        // Faces 0/1 (strip 1) and 2/3 (strip 2); heights by rank.
        int[][] nested = {{0, 2, 3, 1}};
        int[][] interleaved = {{0, 2, 1, 3}};
        for (int[][] layout : new int[][][] {nested, interleaved}) {
            Fold fold = twoTacos();
            int[] bottomUp = layout[0];
            for (int i = 0; i < 4; i++) {
                for (int j = 0; j < i; j++) {
                    int upper = bottomUp[i];
                    int lower = bottomUp[j];
                    // upper above lower: on the side lower's normal points to where lower faces up (even faces).
                    fold.order(upper, lower, lower % 2 == 0 ? 1 : -1);
                }
            }
            LayerOrder.Result result = fold.check();
            if (layout == nested) {
                assertTrue(result.valid(), result.toString());
            } else {
                assertEquals(1, result.violations().get(Kind.TACO_TACO), result.toString());
            }
        }
    }

    /**
     * Two strips over a convex edge: on the top (z = 0, x in [-1, 0]) and down the side (x = 0,
     * z in [-1, 0]); faces 0 → 1 the inner strip, 2 → 3 the outer, as the top has them.
     */
    private static Fold overAnEdge(int sideOrder) {
        Fold fold = new Fold();
        for (int strip = 0; strip < 2; strip++) {
            int a = fold.vertex(-1, 0, 0);
            int b = fold.vertex(0, 0, 0);
            int c = fold.vertex(0, 1, 0);
            int d = fold.vertex(-1, 1, 0);
            int e = fold.vertex(0, 0, -1);
            int g = fold.vertex(0, 1, -1);
            fold.face(a, b, c, d); // normal +z
            fold.face(b, e, g, c); // normal +x
        }
        fold.order(2, 0, 1); // outer over inner on top
        fold.order(3, 1, sideOrder);
        return fold;
    }

    @Test
    void layersBentOverAnEdgeTogetherKeepTheirOrder() throws IOException {
        LayerOrder.Result kept = overAnEdge(1).check();
        assertEquals(2, kept.planes(), "setup: the top and the side");
        assertTrue(kept.valid(), kept.toString());
        LayerOrder.Result swapped = overAnEdge(-1).check();
        assertEquals(only(Kind.CROSSING, 1), swapped.violations(), swapped.toString());
    }

    @Test
    void paperLeavingThePlaneFromInsideAFlatFoldIsATacoTortilla() throws IOException {
        // A flat fold along the edge x = 0 of the top (faces 0 up, 1 turned back over it), and a
        // strip (2 → 3) going from the top over the edge and down the side.
        Fold fold = new Fold();
        int a = fold.vertex(-1, 0, 0);
        int b = fold.vertex(0, 0, 0);
        int c = fold.vertex(0, 1, 0);
        int d = fold.vertex(-1, 1, 0);
        int e = fold.vertex(-1, 0, 0);
        int g = fold.vertex(-1, 1, 0);
        fold.face(a, b, c, d);
        fold.face(b, e, g, c);
        int s0 = fold.vertex(-1, 0.25, 0);
        int s1 = fold.vertex(0, 0.25, 0);
        int s2 = fold.vertex(0, 0.75, 0);
        int s3 = fold.vertex(-1, 0.75, 0);
        int s4 = fold.vertex(0, 0.25, -1);
        int s5 = fold.vertex(0, 0.75, -1);
        int top = fold.face(s0, s1, s2, s3);
        fold.face(s1, s4, s5, s2);
        fold.order(1, 0, 1); // the flap over its base
        fold.order(top, 0, 1); // the strip over the base...
        fold.order(top, 1, 1); // ...and under the flap (its normal down): inside the fold
        LayerOrder.Result result = fold.check();
        assertEquals(only(Kind.TACO_TORTILLA, 1), result.violations(), result.toString());
        Fold outside = new Fold();
        outside.vertices.addAll(fold.vertices);
        outside.faces.addAll(fold.faces);
        outside.order(1, 0, 1);
        outside.order(top, 0, 1);
        outside.order(top, 1, -1); // over the flap
        assertTrue(outside.check().valid(), outside.check().toString());
    }

    /** Runs a command with --export-fold and checks the file it wrote, and that its report says what the check says. */
    private static LayerOrder.Result exported(java.nio.file.Path dir, String... args) throws Exception {
        java.nio.file.Path fold = dir.resolve("out.fold");
        java.nio.file.Path report = dir.resolve("out.json");
        List<String> all = new ArrayList<>(List.of(args));
        all.addAll(List.of("--no-view", "--export-fold", fold.toString(), "--report", report.toString()));
        java.io.StringWriter err = new java.io.StringWriter();
        int code = ifold.cli.Main.commandLine(new java.io.PrintWriter(new java.io.StringWriter()), new java.io.PrintWriter(err))
                .execute(all.toArray(String[]::new));
        assertEquals(0, code, err::toString);
        LayerOrder.Result result;
        try (java.io.Reader reader = java.nio.file.Files.newBufferedReader(fold)) {
            result = LayerOrder.check(reader);
        }
        String json = java.nio.file.Files.readString(report).replaceAll("\\s", "");
        assertTrue(json.contains(result.valid() ? "\"layerOrder\":\"valid\"" : "\"violations\":" + result.total()),
                "the report says what the check of its file says");
        return result;
    }

    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(strings = {"pleat20.fold", "square-quarters.fold", "strip-turn.fold", "zigzag-turn.fold"})
    void theFoldScriptsAreInAnOrderPaperCanHave(String script, @org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        LayerOrder.Result result = exported(dir, "fold", "models/scripts/" + script);
        assertTrue(result.layered() > 0, "setup: layers");
        assertTrue(result.valid(), result::summary);
    }

    @Test
    void theDemosAreInAnOrderPaperCanHave(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws Exception {
        LayerOrder.Result zigzag = exported(dir, "demo", "zigzag");
        assertTrue(zigzag.layered() > 10, "setup: the zig-zag's layers");
        assertTrue(zigzag.valid(), zigzag::summary);
        for (String angle : new String[] {"30", "90", "150"}) {
            LayerOrder.Result turn = exported(dir, "demo", "turn", "--angle", angle);
            assertTrue(turn.layered() > 0, "setup: the turn's layers");
            assertTrue(turn.valid(), turn::summary);
        }
    }

    @Test
    void notAFoldedStateIsRefusedInWords() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> LayerOrder.check("[1, 2]"));
        assertTrue(e.getMessage().contains("not a FOLD file"), e.getMessage());
        IllegalArgumentException flat = assertThrows(IllegalArgumentException.class,
                () -> LayerOrder.check("{\"vertices_coords\": [[0, 0], [1, 0], [0, 1]], \"faces_vertices\": [[0, 1, 2]]}"));
        assertTrue(flat.getMessage().contains("no folded state"), flat.getMessage());
        IllegalArgumentException order = assertThrows(IllegalArgumentException.class, () -> LayerOrder.check(
                "{\"faces_vertices\": [[0, 1, 2]], \"file_frames\": [{\"frame_classes\": [\"foldedForm\"], \"vertices_coords\":"
                        + " [[0, 0, 0], [1, 0, 0], [0, 1, 0]], \"faceOrders\": [[0, 5, 1]]}]}"));
        assertTrue(order.getMessage().contains("faceOrders entry 0"), order.getMessage());
    }
}
