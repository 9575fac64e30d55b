package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code ifold fold}: the exported OBJ passes the isometry check read back from the file itself. */
class FoldCommandTest {
    @TempDir
    Path dir;

    @Test
    void exportedObjIsIsometricAndNamesItsCaps() throws Exception {
        Path obj = dir.resolve("pleat.obj");
        Path report = dir.resolve("pleat.json");
        CliTest.Run run = CliTest.run("fold", "models/scripts/pleat20.fold", "--no-view", "--export-obj", obj.toString(),
                "--report", report.toString());
        assertEquals(0, run.code(), run.err());
        ObjReadBack back = ObjReadBack.read(obj);
        assertEquals(21, back.paperFaces(), "21 pieces of strip");
        assertEquals(20, back.capFaces(), "one wall for each of 20 folds: a pleat wraps no fold about its crease");
        assertTrue(back.worstIsometry() <= 1e-9, "isometric as written: " + back.worstIsometry());
        String json = Files.readString(report);
        assertTrue(json.contains("\"maxLayers\": 21"), json);
        assertTrue(json.contains("\"folds\": 20"), json);
        assertTrue(run.out().contains("20 folds, 21 layers at most"), run.out());
        // What was made first, then its checks, then where it went: the files' lines came before the summary.
        String[] lines = run.out().split("\n");
        assertTrue(lines[0].startsWith("pleat20.fold: 20 folds"), run.out());
        assertTrue(lines[1].startsWith("layer order: ") && lines[2].startsWith("collisions: "), run.out());
        assertEquals(java.util.List.of("wrote " + obj, "wrote " + report), java.util.List.of(lines).subList(3, lines.length), run.out());
        // Checked without --export-fold as well: the audit found it checking no face ("0 faces on 0 planes").
        assertTrue(run.out().contains("layer order: valid (21 faces on 1 plane, 210 pairs of layers)"), run.out());
        assertTrue(json.contains("\"layerOrder\": \"valid\""), json);
    }

    @Test
    void scriptErrorsNameFileAndLineAndWriteNothing() throws Exception {
        Path script = Files.writeString(dir.resolve("bad.fold"), "paper strip 10 1\nthickness 0.01\nfold valley 180 paper 30 0 30 1 right\n");
        Path obj = dir.resolve("out.obj");
        CliTest.Run run = CliTest.run("fold", script.toString(), "--no-view", "--export-obj", obj.toString());
        assertEquals(UserError.EXIT_CODE, run.code());
        assertTrue(run.err().contains("bad.fold:3: paper point (30, 0) is not on the paper"), run.err());
        assertFalse(Files.exists(obj));
        CliTest.Run missing = CliTest.run("fold", dir.resolve("none.fold").toString(), "--no-view");
        assertTrue(missing.err().contains("no such file"), missing.err());
        CliTest.Run badOption = CliTest.run("fold", script.toString(), "--export-obj", dir.resolve("x.stl").toString());
        assertTrue(badOption.err().contains("--export-obj"), badOption.err());
    }

    /** A script of {@code folds} folds through every layer, each halving the square left: 2^folds faces. */
    private static String halvings(int folds) {
        StringBuilder script = new StringBuilder("paper square 1024\nthickness 0.0001\n");
        double x = 1024;
        double y = 1024;
        for (int k = 0; k < folds; k++) {
            if (k % 2 == 0) {
                x /= 2;
                script.append("fold valley 180 points ").append(x).append(" 0 0 ").append(x).append(" 1 0 right\n");
            } else {
                y /= 2;
                script.append("fold valley 180 points 0 ").append(y).append(" 0 1 ").append(y).append(" 0 left\n");
            }
        }
        return script.toString();
    }

    @Test
    void foldsThatHalveThePaperAgainAndAgainStopAtTheLimitOfFaces() throws Exception {
        Path file = Files.writeString(dir.resolve("halve.fold"), halvings(25));
        Path obj = dir.resolve("out.obj");
        long start = System.nanoTime();
        CliTest.Run run = CliTest.run("fold", file.toString(), "--no-view", "--max-faces", "1000", "--export-obj", obj.toString());
        CliTest.assertOneLineError(run, "halve.fold:12: fold 10", "more than the 1000 allowed", "--max-faces");
        assertTrue((System.nanoTime() - start) * 1e-9 < 30, "refused in bounded time");
        assertFalse(Files.exists(obj));
        CliTest.assertOneLineError(CliTest.run("fold", file.toString(), "--no-view", "--max-faces", "0"), "--max-faces");
    }

    /**
     * fold's limit on faces is its own, set for time (a fold through a pile costs the square of
     * its layers), not the wrap's, set for memory; its help says so, and a low limit still
     * refuses in one line.
     */
    @Test
    void theLimitOnFacesIsSetForTimeAndTheHelpSaysSo() throws Exception {
        CliTest.Run help = CliTest.run("fold", "--help");
        assertEquals(0, help.code(), help.err());
        String text = help.out().replaceAll("\\s+", " ");
        assertTrue(text.contains("(default " + ifold.script.ScriptFolding.DEFAULT_MAX_FACES + "): a fold that would make more is refused."
                + " Set for time, not memory as the wrap's is"), text);
        assertTrue(ifold.script.ScriptFolding.DEFAULT_MAX_FACES < ifold.wrap.Wrap.DEFAULT_MAX_FACES, "the wrap's limit is not the fold's");
        Path file = Files.writeString(dir.resolve("halve6.fold"), halvings(6));
        Path obj = dir.resolve("out.obj");
        CliTest.assertOneLineError(CliTest.run("fold", file.toString(), "--no-view", "--max-faces", "16", "--export-obj", obj.toString()),
                "halve6.fold:7: fold 5", "32 faces, more than the 16 allowed", "--max-faces raises the limit");
        assertFalse(Files.exists(obj));
        assertEquals(0, CliTest.run("fold", file.toString(), "--no-view", "--max-faces", "64").code(), "64 faces fold");
    }

    @Test
    void aCreasePatternExportedAsFoldFoldsBackToTheSamePattern() throws Exception {
        for (String name : new String[] {"square-quarters", "pleat20", "zigzag-turn"}) {
            Path pattern = dir.resolve(name + ".cp.fold");
            Path first = dir.resolve(name + ".json");
            Path second = dir.resolve(name + ".back.json");
            assertEquals(0, CliTest.run("fold", "models/scripts/" + name + ".fold", "--no-view", "--export-fold", pattern.toString(),
                    "--report", first.toString()).code());
            CliTest.Run back = CliTest.run("fold", pattern.toString(), "--no-view", "--export-fold", dir.resolve("again.fold").toString(),
                    "--report", second.toString());
            assertEquals(0, back.code(), name + ": " + back.err());
            String a = Files.readString(first);
            String b = Files.readString(second);
            for (String key : new String[] {"mountains", "valleys", "maxLayers"}) {
                assertEquals(CliTest.number(a, key), CliTest.number(b, key), 0, name + ": " + key);
            }
        }
        // Two folds along the diagonals, the second through both layers: its line comes out a
        // valley on one layer and a mountain on the other, and folds back the way that makes both.
        Path diagonals = Files.writeString(dir.resolve("diagonals.fold"),
                "paper square 10\nfold valley 180 paper 0 0 10 10 left\nfold valley 180 paper 10 0 5 5 right\n");
        Path diagonalsPattern = dir.resolve("diagonals-cp.fold");
        Path diagonalsReport = dir.resolve("diagonals.json");
        assertEquals(0, CliTest.run("fold", diagonals.toString(), "--no-view", "--export-fold", diagonalsPattern.toString(),
                "--report", diagonalsReport.toString()).code());
        Path diagonalsBack = dir.resolve("diagonals-back.json");
        CliTest.Run back = CliTest.run("fold", diagonalsPattern.toString(), "--no-view", "--export-fold",
                dir.resolve("diagonals-again.fold").toString(), "--report", diagonalsBack.toString());
        assertEquals(0, back.code(), back.err());
        for (String key : new String[] {"mountains", "valleys", "maxLayers"}) {
            assertEquals(CliTest.number(Files.readString(diagonalsReport), key), CliTest.number(Files.readString(diagonalsBack), key), 0,
                    "diagonals: " + key);
        }
        Path broken = Files.writeString(dir.resolve("broken.fold"), "{\"vertices_coords\": [[0, 0], [1, 0]],\n \"edges_vertices\": [[0, 1]");
        CliTest.assertOneLineError(CliTest.run("fold", broken.toString(), "--no-view"), "broken.fold", "JSON");
    }

    /** A square 10 x 10 whose border is four B edges, and what follows them: vertices 0-3 are its corners. */
    private static final String SQUARE = "\"vertices_coords\": [[0, 0], [10, 0], [10, 10], [0, 10]%s],\n"
            + " \"edges_vertices\": [[0, 1], [1, 2], [2, 3], [3, 0]%s],\n \"edges_assignment\": [\"B\", \"B\", \"B\", \"B\"%s]%s";

    private Path foldFile(String name, String text) throws Exception {
        return Files.writeString(dir.resolve(name), text);
    }

    private static String square(String vertices, String edges, String assignments, String more) {
        return "{" + String.format(SQUARE, vertices, edges, assignments, more) + "}\n";
    }

    /** A pattern whose lines alone cut more faces than allowed is refused before any fold (10,000 creases: at the last, after 31 s). */
    @Test
    void morePatternLinesThanFacesAllowedAreRefusedAtOnce() throws Exception {
        Path pattern = ifold.foldfile.CreasePatternTest.parallelCreases(dir, 30);
        CliTest.Run run = CliTest.run("fold", pattern.toString(), "--no-view", "--max-faces", "30");
        CliTest.assertOneLineError(run, "its 30 crease lines cut the paper into at least 31 faces, more than the 30 allowed",
                "--max-faces raises the limit");
        assertEquals(0, CliTest.run("fold", pattern.toString(), "--no-view", "--max-faces", "31").code(), "31 faces fold");
    }

    /**
     * A FOLD file iFold cannot fold is a data error: one line naming the file and what is wrong,
     * exit 1, nothing written; never an internal error.
     */
    @Test
    void aFoldFileThatCannotBeFoldedIsRefusedInOneLineNamingTheFile() throws Exception {
        String[][] cases = {
            {"edge-of-one.fold", square("", ", [0]", ", \"V\"", ""), "edge 4: edges_vertices must name two vertices"},
            {"edge-of-none.fold", square("", ", []", ", \"V\"", ""), "edge 4: edges_vertices must name two vertices"},
            {"no-angles.fold", square("", ", [0, 2]", ", \"V\"", ", \"edges_foldAngle\": []"), "edges_foldAngle must give each edge"},
            {"huge.fold", "{\"vertices_coords\": [[-1e308, -1e308], [1e308, -1e308], [1e308, 1e308], [-1e308, 1e308]],\n"
                + " \"edges_vertices\": [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]],\n"
                + " \"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"V\"]}\n", "the sheet is too large"},
            {"tiny.fold", square("", ", [0, 2]", ", \"V\"", "").replace("10", "1e-200"), "the sheet is too small"},
            // Within doubles, but past what folding computes: the valley came out a mountain ("cannot be folded ... in this order").
            {"huge-but-finite.fold", square("", ", [0, 2]", ", \"V\"", "").replace("10", "1e85"), "iFold folds sheets from 1e-60 to 1e+60 across"},
            {"tiny-but-normal.fold", square("", ", [0, 2]", ", \"V\"", "").replace("10", "1e-90"), "the sheet is too small"},
            // jackson's own words named its settings ("enable `JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS` to allow").
            {"nan.fold", square("", ", [0, 2]", ", \"V\"", "").replaceFirst("10", "NaN"), "line 1: not valid JSON: 'NaN' is not a number JSON allows"},
            {"deep.fold", "{\"a\": " + "[".repeat(1200) + "]".repeat(1200) + "}", "not a FOLD file: lists or objects nested more than 1,000 deep"},
            {"long-number.fold", "{\"vertices_coords\": [[0, " + "1".repeat(1200) + "]]}",
                "not a FOLD file: Number value length (1200) exceeds the maximum allowed (1000)"},
            {"twice.fold", square("", ", [0, 2]", ", \"V\"", ", \"edges_assignment\": []"), "the key 'edges_assignment' is given twice"},
            {"trailing.fold", square("", ", [0, 2]", ", \"V\"", "") + "garbage\n", "line 4: text after the FOLD object"},
            {"two-objects.fold", square("", ", [0, 2]", ", \"V\"", "") + "{}\n", "line 4: text after the FOLD object"},
            // Creases with no paper around them: no face to fold.
            {"triangle-creases-only.fold", "{\"vertices_coords\": [[0, 0], [10, 0], [0, 10], [5, 0], [5, 5]],"
                + " \"edges_vertices\": [[3, 4]], \"edges_assignment\": [\"V\"]}", "the edges enclose no face"},
            // A crease from (3, 3) to (7, 7), alone in the paper: neither end can fold flat.
            {"inner-crease.fold", square(", [3, 3], [7, 7]", ", [4, 5]", ", \"V\"", ""),
                "edge 4: the crease ends inside the paper at vertex 4 (3, 3)", "Maekawa"},
            // Values of the wrong kind, which were folded as 180 degrees or read as a 2D point.
            {"angle-text.fold", square("", ", [0, 2]", ", \"V\"", ", \"edges_foldAngle\": [0, 0, 0, 0, \"x\"]"),
                "edge 4: edges_foldAngle gives it \"x\", not a number of degrees"},
            {"angle-object.fold", square("", ", [0, 2]", ", \"V\"", ", \"edges_foldAngle\": [0, 0, 0, 0, {\"a\": 1}]"),
                "edge 4: edges_foldAngle gives it an object, not a number of degrees"},
            {"raised.fold", square(", [5, 10, 3]", ", [0, 2]", ", \"V\"", ""), "vertex 4 is (5, 10, 3): a crease pattern lies flat"},
            {"assigned-number.fold", square("", ", [0, 2]", ", 5", ""), "edge 4: edges_assignment gives it 5, not one of B, M, V, F, U, C or J"},
            {"assigned-x.fold", square("", ", [0, 2]", ", \"X\"", ""), "edge 4: edges_assignment gives it \"X\", not one of"},
            {"unassigned.fold", square("", ", [0, 2]", ", \"U\"", ""), "edge 4 is U: iFold folds mountains and valleys (M, V), not unassigned"},
            // Half a line creased, from the border to the middle.
            {"half-line.fold", square(", [5, 0], [5, 5]", ", [4, 5]", ", \"M\"", ""), "edge 4: the crease ends inside the paper at vertex 5 (5, 5)"},
            // Three valleys at one vertex: Maekawa wants mountains and valleys to differ by two.
            {"three-valleys.fold", square(", [5, 5], [5, 0], [10, 5], [5, 10]", ", [4, 5], [4, 6], [4, 7]", ", \"V\", \"V\", \"V\"", ""),
                "vertex 4 (5, 5) cannot fold flat: 0 mountains and 3 valleys meet there, and Maekawa's theorem wants them to differ by 2"},
        };
        Path obj = dir.resolve("out.obj");
        for (String[] c : cases) {
            Path file = foldFile(c[0], c[1]);
            CliTest.Run run = CliTest.run("fold", file.toString(), "--no-view", "--export-obj", obj.toString());
            CliTest.assertOneLineError(run, java.util.Arrays.copyOfRange(c, 2, c.length));
            assertTrue(run.err().contains(c[0] + ": "), run.err());
            assertFalse(Files.exists(obj), c[0] + ": nothing written");
        }
        // Any outline folds: a triangle whose hypotenuse is a flat edge, a square with a side left open.
        for (String[] sheet : new String[][] {
            {"triangle-f.fold", "{\"vertices_coords\": [[0, 0], [10, 0], [0, 10]], \"edges_vertices\": [[0, 1], [1, 2], [2, 0]],"
                + " \"edges_assignment\": [\"B\", \"F\", \"B\"]}", "0 creases folded at once"},
            {"open-side.fold", square("", "", "", "").replace("[3, 0]]", "[3, 0], [1, 3]]").replace("\"B\", \"B\", \"B\", \"B\"",
                "\"B\", \"F\", \"B\", \"B\", \"V\""), "1 crease folded at once (folded flat, its layer order found), 2 layers at most"}}) {
            CliTest.Run folded = CliTest.run("fold", foldFile(sheet[0], sheet[1]).toString(), "--no-view");
            assertEquals(0, folded.code(), folded.err());
            assertTrue(folded.out().contains(sheet[2]), folded.out());
        }
        // Pieces of one line that together run from border to border fold as one line.
        Path pieces = foldFile("pieces.fold", square(", [5, 0], [5, 4], [5, 10]", ", [4, 5], [5, 6]", ", \"V\", \"V\"", ""));
        CliTest.Run run = CliTest.run("fold", pieces.toString(), "--no-view");
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("1 fold, 2 layers at most"), run.out());
    }

    /**
     * iFold's own FOLD files fold back to the folded state they were written from: the demo's,
     * wraps' (the tetrahedron: 337 faces on 4 planes; an icosphere of 80), each creased where a line-at-a-time fold
     * cannot go; every vertex of the folded state within 1e-9 of where it was, the same faces
     * (by their corners), the same face orders, and the layer order checked valid.
     */
    @Test
    void iFoldsOwnFilesFoldBackToTheStateTheyWereWrittenFrom() throws Exception {
        // The icosphere's strip is long beside the sphere it wraps: its overlaps are measured against the sphere.
        Path ico = dir.resolve("ico80.off");
        assertEquals(0, CliTest.run("generate", "icosphere", "--subdivisions", "1", "-o", ico.toString()).code());
        String[][] sources = {{"demo", "zigzag"}, {"wrap", "models/tetrahedron.off"}, {"wrap", ico.toString()}};
        for (String[] source : sources) {
            Path written = dir.resolve(source[0] + source[1].hashCode() + ".fold");
            String[] args = java.util.stream.Stream.concat(java.util.Arrays.stream(source), java.util.stream.Stream.of("--no-view",
                    "--export-fold", written.toString())).toArray(String[]::new);
            assertEquals(0, CliTest.run(args).code(), String.join(" ", args));
            Path again = dir.resolve(source[0] + source[1].hashCode() + "-again.fold");
            CliTest.Run back = CliTest.run("fold", written.toString(), "--no-view", "--export-fold", again.toString());
            assertEquals(0, back.code(), back.err());
            assertTrue(back.out().contains("folded at once (its folded state as the file gives it)"), back.out());
            assertTrue(back.out().contains("layer order: valid"), back.out());
            Map<String, Object> a = ifold.foldfile.FoldJson.read(written);
            Map<String, Object> b = ifold.foldfile.FoldJson.read(again);
            assertEquals(a.get("vertices_coords"), b.get("vertices_coords"), "the crease pattern's vertices as they were");
            List<?> placedA = (List<?>) folded(a).get("vertices_coords");
            List<?> placedB = (List<?>) folded(b).get("vertices_coords");
            assertEquals(placedA.size(), placedB.size());
            double worst = 0;
            for (int v = 0; v < placedA.size(); v++) {
                for (int k = 0; k < 3; k++) {
                    worst = Math.max(worst, Math.abs(((Number) ((List<?>) placedA.get(v)).get(k)).doubleValue()
                            - ((Number) ((List<?>) placedB.get(v)).get(k)).doubleValue()));
                }
            }
            assertTrue(worst <= 1e-9, source[1] + ": a vertex moved " + worst);
            // Faces are renumbered (laid bottom up): matched by their corners, their orders the same.
            List<?> facesA = (List<?>) a.get("faces_vertices");
            List<?> facesB = (List<?>) b.get("faces_vertices");
            Map<java.util.Set<Object>, Integer> byCorners = new java.util.HashMap<>();
            for (int f = 0; f < facesA.size(); f++) {
                byCorners.put(new java.util.HashSet<>((List<?>) facesA.get(f)), f);
            }
            int[] toA = new int[facesB.size()];
            for (int f = 0; f < facesB.size(); f++) {
                Integer match = byCorners.get(new java.util.HashSet<>((List<?>) facesB.get(f)));
                assertTrue(match != null, source[1] + ": face " + f + " is one of the file's");
                toA[f] = match;
            }
            java.util.Set<List<Integer>> ordersA = new java.util.HashSet<>();
            for (Object o : (List<?>) folded(a).get("faceOrders")) {
                List<?> order = (List<?>) o;
                ordersA.add(List.of(((Number) order.get(0)).intValue(), ((Number) order.get(1)).intValue(), ((Number) order.get(2)).intValue()));
            }
            java.util.Set<List<Integer>> ordersB = new java.util.HashSet<>();
            for (Object o : (List<?>) folded(b).get("faceOrders")) {
                List<?> order = (List<?>) o;
                ordersB.add(List.of(toA[((Number) order.get(0)).intValue()], toA[((Number) order.get(1)).intValue()],
                        ((Number) order.get(2)).intValue()));
            }
            assertEquals(ordersA.size(), ordersB.size(), source[1]);
            for (List<Integer> order : ordersB) {
                // [f, g, s] and [g, f, s'] say the same where the faces face the same way or not.
                assertTrue(ordersA.contains(order) || ordersA.stream().anyMatch(o -> o.get(0).equals(order.get(1)) && o.get(1).equals(order.get(0))),
                        source[1] + ": the order " + order + " is the file's");
            }
        }
    }

    /**
     * {@code --fold-frames}: a frame after each fold, each with its own faces (as many as that fold
     * has cut), the last the folded state itself (the same vertices and face orders); the file
     * still folds back; refused without --export-fold, and for a file folded all at once.
     */
    @Test
    void foldFramesHoldAFrameAfterEachFold() throws Exception {
        Path file = dir.resolve("pleat.fold");
        CliTest.Run run = CliTest.run("fold", "models/scripts/pleat20.fold", "--no-view", "--export-fold", file.toString(), "--fold-frames");
        assertEquals(0, run.code(), run.err());
        Map<String, Object> fold = ifold.foldfile.FoldJson.read(file);
        List<?> frames = (List<?>) fold.get("file_frames");
        assertEquals(1 + 20, frames.size(), "the folded state, then a frame a fold");
        for (int k = 1; k <= 20; k++) {
            Map<?, ?> frame = (Map<?, ?>) frames.get(k);
            assertEquals("after fold " + k + " of 20", frame.get("frame_title"));
            assertEquals(k + 1, ((List<?>) frame.get("faces_vertices")).size(), "fold " + k + " cuts one face more");
            assertEquals(((List<?>) frame.get("edges_vertices")).size(), ((List<?>) frame.get("edges_foldAngle")).size());
        }
        Map<?, ?> last = (Map<?, ?>) frames.get(20);
        assertEquals(folded(fold).get("vertices_coords"), last.get("vertices_coords"), "the last frame is the folded state");
        assertEquals(((List<?>) folded(fold).get("faceOrders")).size(), ((List<?>) last.get("faceOrders")).size());
        assertEquals(0, CliTest.run("fold", file.toString(), "--no-view").code(), "a file with frames folds back");
        CliTest.assertOneLineError(CliTest.run("fold", "models/scripts/pleat20.fold", "--no-view", "--fold-frames"),
                "option --fold-frames: only with --export-fold");
        CliTest.Run once = CliTest.run("fold", "src/test/resources/fold-examples/simple.fold", "--no-view", "--export-fold",
                dir.resolve("simple-out.fold").toString(), "--fold-frames");
        CliTest.assertOneLineError(once, "option --fold-frames: simple.fold folds every crease at once, in one step");
        assertTrue(!Files.exists(dir.resolve("simple-out.fold")), "nothing written");
    }

    private static Map<String, Object> folded(Map<String, Object> fold) {
        for (Object frame : (List<?>) fold.get("file_frames")) {
            @SuppressWarnings("unchecked")
            Map<String, Object> state = (Map<String, Object>) frame;
            if (((List<?>) state.get("frame_classes")).contains("foldedForm")) {
                return state;
            }
        }
        throw new AssertionError("no folded state");
    }

    /** A FOLD file that begins with a UTF-8 byte order mark is FOLD, and a fold script that does is a fold script. */
    @Test
    void aByteOrderMarkIsSkipped() throws Exception {
        byte[] bom = {(byte) 0xEF, (byte) 0xBB, (byte) 0xBF};
        Path fold = dir.resolve("bom.fold");
        Files.write(fold, bom);
        Files.writeString(fold, square("", ", [0, 2]", ", \"V\"", ""), java.nio.file.StandardOpenOption.APPEND);
        CliTest.Run run = CliTest.run("fold", fold.toString(), "--no-view");
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("bom.fold: 1 fold, 2 layers at most, 1 crease"), run.out());
        Path script = dir.resolve("bom-script.fold");
        Files.write(script, bom);
        Files.writeString(script, "paper square 10\nfold valley 180 paper 0 5 10 5 right\n", java.nio.file.StandardOpenOption.APPEND);
        CliTest.Run played = CliTest.run("fold", script.toString(), "--no-view");
        assertEquals(0, played.code(), played.err());
        assertTrue(played.out().contains("bom-script.fold: 1 fold"), played.out());
    }

    @Test
    void helpSaysFoldTakesFoldFiles() {
        CliTest.Run help = CliTest.run("help", "fold");
        assertEquals(0, help.code(), help.err());
        String words = help.out().replaceAll("\\s+", " ");
        assertTrue(words.contains("Plays a fold script (docs/fold-scripts.md) or a FOLD file (JSON, as written by --export-fold or"),
                help.out());
        assertTrue(help.out().matches("(?s).*SCRIPT +a fold script, or a FOLD file.*"), help.out());
        // The list of commands gave the description's first line alone, cut at "as written by".
        CliTest.Run commands = CliTest.run("help");
        assertTrue(commands.out().replaceAll("\\s+", " ").contains("as written by --export-fold or another tool)."), commands.out());
        assertTrue(words.contains("any other FOLD file folds every crease at once"), help.out());
    }
}
