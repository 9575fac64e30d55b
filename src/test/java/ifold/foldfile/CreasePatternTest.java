package ifold.foldfile;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.script.ScriptFolding;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Crease patterns of many parallel creases fold at a cost that grows with the creases, not with their cube. */
public class CreasePatternTest {
    @TempDir
    Path dir;

    /**
     * A FOLD file of {@code n} parallel creases, mountain and valley in turn, across a strip
     * n + 1 long and 10 wide: it folds into a pile of n + 1 layers, each fold landing on the pile.
     */
    public static Path parallelCreases(Path dir, int n) throws Exception {
        StringBuilder vertices = new StringBuilder();
        StringBuilder edges = new StringBuilder();
        StringBuilder assignments = new StringBuilder();
        for (int k = 0; k <= n + 1; k++) {
            vertices.append(k == 0 ? "" : ", ").append('[').append(k).append(", 0], [").append(k).append(", 10]");
        }
        // Vertex 2k is (k, 0), 2k + 1 is (k, 10): the border along both long sides, the two ends, then the creases.
        for (int k = 0; k <= n; k++) {
            edges.append(k == 0 ? "" : ", ").append('[').append(2 * k).append(", ").append(2 * k + 2).append("], [")
                    .append(2 * k + 1).append(", ").append(2 * k + 3).append(']');
            assignments.append(k == 0 ? "" : ", ").append("\"B\", \"B\"");
        }
        edges.append(", [0, 1], [").append(2 * n + 2).append(", ").append(2 * n + 3).append(']');
        assignments.append(", \"B\", \"B\"");
        for (int k = 1; k <= n; k++) {
            edges.append(", [").append(2 * k).append(", ").append(2 * k + 1).append(']');
            assignments.append(k % 2 == 1 ? ", \"V\"" : ", \"M\"");
        }
        return Files.writeString(dir.resolve("parallel" + n + ".fold"), "{\"frame_classes\": [\"creasePattern\"],\n \"vertices_coords\": ["
                + vertices + "],\n \"edges_vertices\": [" + edges + "],\n \"edges_assignment\": [" + assignments + "]}\n");
    }

    /** Two creases across a 3 x 1 strip at x = 1 and x = 2, with the order key given (or none). */
    private Path twoCreases(String orderKey) throws Exception {
        return Files.writeString(dir.resolve("two.fold"), "{\"vertices_coords\": [[0, 0], [1, 0], [2, 0], [3, 0], [3, 1], [2, 1], [1, 1], [0, 1]],"
                + " \"edges_vertices\": [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 6], [6, 7], [7, 0], [2, 5], [1, 6]],"
                + " \"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"V\", \"V\"]"
                + (orderKey.isEmpty() ? "" : ", " + orderKey) + "}");
    }

    /** The crease at x = 1 is edge 9, at x = 2 edge 8: the lines in the order folded. */
    private static java.util.List<Double> foldedAt(CreasePattern pattern) {
        java.util.List<Double> at = new java.util.ArrayList<>();
        for (double[] line : pattern.lines()) {
            at.add(Math.rint(line[0]));
        }
        return at;
    }

    @Test
    void theFoldStepOfEachEdgeOrdersTheFoldsAndOlderFilesStillFold() throws Exception {
        assertEquals(java.util.List.of(2.0, 1.0), foldedAt(CreasePattern.read(twoCreases(""))), "setup: by default, in the edges' order");
        String steps = "\"edges_ifold:foldStep\": [null, null, null, null, null, null, null, null, 2, 1]";
        assertEquals(java.util.List.of(1.0, 2.0), foldedAt(CreasePattern.read(twoCreases(steps))));
        assertEquals(java.util.List.of(1.0, 2.0), foldedAt(CreasePattern.read(twoCreases("\"edges_ifold:order\": [9, 8]"))),
                "a file of an earlier iFold");
        CreasePattern.Refused missing = org.junit.jupiter.api.Assertions.assertThrows(CreasePattern.Refused.class,
                () -> CreasePattern.read(twoCreases("\"edges_ifold:foldStep\": [null, null, null, null, null, null, null, null, 2, null]")));
        assertTrue(missing.getMessage().contains("edge 9 is a crease"), missing.getMessage());
        CreasePattern.Refused shorter = org.junit.jupiter.api.Assertions.assertThrows(CreasePattern.Refused.class,
                () -> CreasePattern.read(twoCreases("\"edges_ifold:foldStep\": [1, 2]")));
        assertTrue(shorter.getMessage().contains("2 entries for 10 edges"), shorter.getMessage());
    }

    /**
     * Each fold lands on the pile's top layer: the order of the pile is n relations, not one
     * for every pair of layers (n² / 2: 80,000 here), which every later fold would walk.
     */
    @Test
    void aPileOfParallelFoldsKeepsOneRelationALayer() throws Exception {
        int n = 400;
        CreasePattern pattern = CreasePattern.read(parallelCreases(dir, n));
        assertEquals(n, pattern.lines().size(), "setup: one line a crease");
        CreasePattern.Folding folding = pattern.fold(new long[n], ScriptFolding.DEFAULT_MAX_FACES);
        assertEquals(n + 1, folding.result().sheet().faceCount());
        assertEquals(n + 1, folding.result().sheet().stackLevels(), "a pile of n + 1 layers");
        int relations = folding.result().sheet().orderRelations();
        assertTrue(relations <= 2 * n, "relations: " + relations);
    }

    /**
     * 2,000 parallel creases folded in 77 s (cubic: 500 took 3.5 s), then in 24 s for 10,000:
     * each fold tested its polygon against every layer of the pile. A layer whose neighbour above
     * holds all of it is passed over, so the polygon tests per fold stay the same however tall
     * the pile (the seconds are bench/folds's: the bookkeeping each fold does over the sheet's
     * faces still grows with them, a few nanoseconds a face).
     */
    @Test
    void polygonTestsPerFoldDoNotGrowWithThePile() throws Exception {
        double[] perFold = new double[2];
        int[] sizes = {500, 2000};
        for (int k = 0; k < 2; k++) {
            int n = sizes[k];
            CreasePattern pattern = CreasePattern.read(parallelCreases(dir, n));
            CreasePattern.Folding folding = pattern.fold(new long[n], ScriptFolding.DEFAULT_MAX_FACES);
            assertEquals(n + 1, folding.result().sheet().stackLevels());
            perFold[k] = (double) folding.result().sheet().polygonTests() / n;
        }
        assertTrue(perFold[1] < 1.5 * perFold[0], "polygon tests a fold: " + perFold[0] + " for 500 creases, " + perFold[1] + " for 2,000");
    }

    /**
     * A file as another tool writes it (the FOLD spec's keys beside the crease pattern: its
     * spec, creator, title, faces and vertex neighbours, fold angles, a flat fold F) is read for
     * its crease pattern alone, the other keys passed over: a 10 × 4 sheet with a valley at
     * x = 4 and a mountain at x = 7, which fold into three layers.
     */
    @Test
    void aFileOfAnotherToolIsReadForItsCreasePattern() throws Exception {
        Path file = Files.writeString(dir.resolve("foreign.fold"), """
                {"file_spec": 1.1, "file_creator": "another tool", "file_classes": ["singleModel"],
                 "frame_title": "two pleats", "frame_classes": ["creasePattern"], "frame_attributes": ["2D"],
                 "vertices_coords": [[0, 0], [4, 0], [7, 0], [10, 0], [10, 4], [7, 4], [4, 4], [0, 4], [2, 0], [2, 4]],
                 "vertices_vertices": [[1, 7], [0, 2, 6], [1, 3, 5], [2, 4], [3, 5], [4, 2, 6], [5, 1, 7], [6, 0], [], []],
                 "edges_vertices": [[0, 8], [8, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 6], [6, 9], [9, 7], [7, 0], [1, 6], [2, 5], [8, 9]],
                 "edges_assignment": ["B", "B", "B", "B", "B", "B", "B", "B", "B", "B", "V", "M", "F"],
                 "edges_foldAngle": [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 180, -180, 0],
                 "faces_vertices": [[0, 1, 6, 7], [1, 2, 5, 6], [2, 3, 4, 5]]}
                """);
        CreasePattern pattern = CreasePattern.read(file);
        assertEquals(10, pattern.length(), 1e-12);
        assertEquals(4, pattern.width(), 1e-12);
        assertEquals(2, pattern.creases().size(), "the valley and the mountain; the flat fold creases nothing");
        assertEquals(java.util.List.of(4.0, 7.0), foldedAt(pattern));
        CreasePattern.Folding folding = pattern.fold(new long[2], ScriptFolding.DEFAULT_MAX_FACES);
        assertEquals(3, folding.result().sheet().faceCount());
        assertEquals(3, folding.result().sheet().stackLevels(), "a pleat: three layers");
    }

    /** What is not a crease pattern iFold folds is refused, naming the key or the edge. */
    @Test
    void malformedFilesAreRefusedNamingTheKeyOrTheEdge() throws Exception {
        String square = "\"vertices_coords\": [[0, 0], [4, 0], [4, 4], [0, 4], [2, 0], [2, 4]], "
                + "\"edges_vertices\": [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]], ";
        String[][] cases = {
            {"{" + square + "\"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"B\", \"B\"]}",
                "edges_assignment must give each edge B, M, V or F"},
            {"{\"edges_vertices\": [[0, 1]], \"edges_assignment\": [\"B\"]}", "no vertices_coords: a crease pattern needs"},
            {"{" + square.replace("[0, 4], [2, 0]", "[0, 4], \"x\"") + "\"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"V\"]}",
                "vertices_coords must be a list of lists of numbers"},
            {"{" + square.replace("[4, 5]]", "[4, 4]]") + "\"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"V\"]}",
                "edge 6: a crease of no length"},
            {"{" + square + "\"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"U\"]}", "edge 6 is U"},
            {"{" + square + "\"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"B\"]}",
                "edge 6 is a border edge inside the sheet"},
            {"{" + square + "\"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"V\"],"
                + " \"edges_foldAngle\": [0, 0, 0, 0, 0, 0, 200]}", "edge 6: its fold angle must be more than 0 and at most 180 degrees"},
        };
        for (String[] c : cases) {
            Path file = Files.writeString(dir.resolve("bad.fold"), c[0]);
            CreasePattern.Refused refused = org.junit.jupiter.api.Assertions.assertThrows(CreasePattern.Refused.class,
                    () -> CreasePattern.read(file), c[1]);
            assertTrue(refused.getMessage().contains(c[1]), "expected '" + c[1] + "', got: " + refused.getMessage());
        }
        // The same square with its crease valid folds: the cases above fail for what they say.
        Path good = Files.writeString(dir.resolve("good.fold"),
                "{" + square + "\"edges_assignment\": [\"B\", \"B\", \"B\", \"B\", \"B\", \"B\", \"V\"]}");
        assertEquals(1, CreasePattern.read(good).creases().size());
    }
}
