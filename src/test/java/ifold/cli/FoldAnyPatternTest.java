package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code ifold fold} on crease patterns of our own making, each with its expected outcome: the
 * flat bases folded with their layer order found (checked by the independent layer-order check
 * on the FOLD file written), a box's net folded by its angles, folded forms unfolded and folded
 * back, and the patterns that cannot fold refused naming the vertex or the faces.
 */
class FoldAnyPatternTest {
    @TempDir
    Path dir;

    /** A crease pattern as FOLD: vertices, and edges each with its assignment (and angle in degrees, or null). */
    private static final class Pattern {
        final List<double[]> vertices = new ArrayList<>();
        final Map<String, Integer> index = new LinkedHashMap<>();
        final List<int[]> edges = new ArrayList<>();
        final List<String> assignments = new ArrayList<>();
        final List<Double> angles = new ArrayList<>();

        int vertex(double x, double y) {
            String key = x + "," + y;
            return index.computeIfAbsent(key, k -> {
                vertices.add(new double[] {x, y});
                return vertices.size() - 1;
            });
        }

        Pattern edge(double x1, double y1, double x2, double y2, String assignment, Double angle) {
            edges.add(new int[] {vertex(x1, y1), vertex(x2, y2)});
            assignments.add(assignment);
            angles.add(angle);
            return this;
        }

        /** The square [0, 2]² with its border split at the middle of each side. */
        static Pattern square() {
            Pattern p = new Pattern();
            double[][] border = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
            for (int i = 0; i < border.length; i++) {
                double[] a = border[i];
                double[] b = border[(i + 1) % border.length];
                p.edge(a[0], a[1], b[0], b[1], "B", null);
            }
            return p;
        }

        String json() {
            StringBuilder text = new StringBuilder("{\"file_spec\": 1.1, \"frame_classes\": [\"creasePattern\"], \"vertices_coords\": [");
            for (int v = 0; v < vertices.size(); v++) {
                text.append(v > 0 ? ", " : "").append(String.format(Locale.ROOT, "[%s, %s]", vertices.get(v)[0], vertices.get(v)[1]));
            }
            text.append("], \"edges_vertices\": [");
            for (int e = 0; e < edges.size(); e++) {
                text.append(e > 0 ? ", " : "").append("[").append(edges.get(e)[0]).append(", ").append(edges.get(e)[1]).append("]");
            }
            text.append("], \"edges_assignment\": [");
            for (int e = 0; e < edges.size(); e++) {
                text.append(e > 0 ? ", " : "").append('"').append(assignments.get(e)).append('"');
            }
            text.append("]");
            if (angles.stream().anyMatch(a -> a != null)) {
                text.append(", \"edges_foldAngle\": [");
                for (int e = 0; e < edges.size(); e++) {
                    text.append(e > 0 ? ", " : "").append(angles.get(e) == null ? "null" : angles.get(e).toString());
                }
                text.append("]");
            }
            return text.append("}\n").toString();
        }
    }

    /** The square's centre joined to corners and side middles, each crease as given ("M", "V"). */
    private static Pattern star(String corners, String sides) {
        Pattern p = Pattern.square();
        double[][] cornerPoints = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
        double[][] sidePoints = {{1, 0}, {2, 1}, {1, 2}, {0, 1}};
        for (int k = 0; k < 4; k++) {
            if (corners.charAt(k) != '-') {
                p.edge(1, 1, cornerPoints[k][0], cornerPoints[k][1], String.valueOf(corners.charAt(k)), null);
            }
            if (sides.charAt(k) != '-') {
                p.edge(1, 1, sidePoints[k][0], sidePoints[k][1], String.valueOf(sides.charAt(k)), null);
            }
        }
        return p;
    }

    private CliTest.Run fold(String name, String json, String... more) throws Exception {
        Path file = Files.writeString(dir.resolve(name + ".fold"), json);
        List<String> args = new ArrayList<>(List.of("fold", file.toString(), "--no-view", "--export-fold", dir.resolve(name + "-out.fold").toString(),
                "--report", dir.resolve(name + ".json").toString()));
        args.addAll(List.of(more));
        return CliTest.run(args.toArray(new String[0]));
    }

    @Test
    void flatBasesFoldWithTheirLayerOrderFound() throws Exception {
        // name, corners (from (0,0) anticlockwise), sides (bottom, right, top, left), expected words
        String[][] cases = {
            // The waterbomb base: the diagonals valleys, one book fold a mountain: four layers.
            {"waterbomb", "VVVV", "-M-M", "6 creases folded at once (folded flat, its layer order found), 4 layers at most"},
            // The preliminary base: diagonals mountains, one book fold a mountain and three valleys: eight triangles stacked.
            {"preliminary", "MMMM", "VVMV", "8 creases folded at once (folded flat, its layer order found), 8 layers at most"},
            // Two diagonals as valleys, the book folds mountains: a blintz-like corner stack.
            {"diagonals", "V-V-", "MMMM", "6 creases folded at once (folded flat, its layer order found), 4 layers at most"},
        };
        for (String[] c : cases) {
            CliTest.Run run = fold(c[0], star(c[1], c[2]).json());
            assertEquals(0, run.code(), c[0] + ": " + run.err());
            assertTrue(run.out().contains(c[3]), c[0] + ": " + run.out());
            assertTrue(run.out().contains("layer order: valid"), c[0] + ": " + run.out());
        }
    }

    @Test
    void patternsThatCannotFoldFlatAreRefusedNamingTheVertex() throws Exception {
        String[][] cases = {
            {"maekawa", "----", "VVV-", "vertex 8 (1, 1) cannot fold flat: 0 mountains and 3 valleys meet there, and Maekawa's theorem"},
            // Creases at 0°, 45°, 90°, 180° round the centre: alternate angles 135° and 225°.
            {"kawasaki", "--M-", "VV-V", "cannot fold flat: the angles between its creases, taken alternately, sum to"},
        };
        for (String[] c : cases) {
            CliTest.Run run = fold(c[0], star(c[1], c[2]).json());
            CliTest.assertOneLineError(run, c[0] + ".fold: ", c[3]);
            assertTrue(run.err().contains("Kawasaki") || run.err().contains("Maekawa"), run.err());
            assertTrue(!Files.exists(dir.resolve(c[0] + "-out.fold")), "nothing written");
        }
    }

    /** The net of a cube, a cross of six squares, its five creases valleys of 90°: six faces on six planes, one layer. */
    @Test
    void aBoxsNetFoldsByItsAnglesIntoACube() throws Exception {
        double[][] squares = {{1, 1}, {0, 1}, {2, 1}, {3, 1}, {1, 2}, {1, 0}};
        Map<String, Integer> count = new LinkedHashMap<>();
        for (double[] s : squares) {
            double[][] corners = {{s[0], s[1]}, {s[0] + 1, s[1]}, {s[0] + 1, s[1] + 1}, {s[0], s[1] + 1}};
            for (int k = 0; k < 4; k++) {
                double[] a = corners[k];
                double[] b = corners[(k + 1) % 4];
                String key = Math.min(a[0], b[0]) + "," + Math.min(a[1], b[1]) + "," + Math.max(a[0], b[0]) + "," + Math.max(a[1], b[1]);
                count.merge(key, 1, Integer::sum);
            }
        }
        Pattern net = new Pattern();
        for (Map.Entry<String, Integer> edge : count.entrySet()) {
            String[] c = edge.getKey().split(",");
            boolean crease = edge.getValue() == 2;
            net.edge(Double.parseDouble(c[0]), Double.parseDouble(c[1]), Double.parseDouble(c[2]), Double.parseDouble(c[3]), crease ? "V" : "B",
                    crease ? 90.0 : 0.0);
        }
        CliTest.Run run = fold("cube-net", net.json());
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("5 creases folded at once (its fold angles), 1 layer at most"), run.out());
        String report = Files.readString(dir.resolve("cube-net.json"));
        assertEquals(6, CliTest.number(report, "planes"), 0, "each face on a plane of its own: a closed cube");
    }

    /** Four squares round a vertex, each crease at 90°: the fourth face cannot meet the first. */
    @Test
    void aCycleOfCreasesThatDoesNotCloseIsRefusedNamingItsVertex() throws Exception {
        Pattern p = star("----", "VVVV");
        for (int e = 0; e < p.angles.size(); e++) {
            if (p.assignments.get(e).equals("V")) {
                p.angles.set(e, 90.0);
            }
        }
        CliTest.Run run = fold("corner", p.json());
        CliTest.assertOneLineError(run, "corner.fold: the folds around vertex 8 (1, 1) do not close");
    }

    /** A folded form alone (3D vertices): an open box of five squares, unfolded onto one sheet and folded back. */
    @Test
    void aFoldedFormAloneIsUnfoldedAndFoldedBack() throws Exception {
        // Each wall its own top corners: the walls are cut apart where they meet.
        String openBox = "{\"frame_classes\": [\"foldedForm\"], \"vertices_coords\": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],"
                + "[0,0,1],[1,0,1],[1,0,1],[1,1,1],[1,1,1],[0,1,1],[0,1,1],[0,0,1]],"
                + " \"faces_vertices\": [[0,3,2,1],[0,1,5,4],[1,2,7,6],[2,3,9,8],[3,0,11,10]],"
                + " \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[1,5],[4,0],[2,7],[6,1],[3,9],[8,2],[0,11],[10,3],[5,4],[7,6],[9,8],[11,10]],"
                + " \"edges_assignment\": [\"V\",\"V\",\"V\",\"V\",\"B\",\"B\",\"B\",\"B\",\"B\",\"B\",\"B\",\"B\",\"B\",\"B\",\"B\",\"B\"]}";
        CliTest.Run run = fold("open-box", openBox);
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("4 creases folded at once (a folded form, unfolded onto one sheet)"), run.out());
        // Walls that share their top corners (a closed box's corner): they cannot all unfold onto one sheet.
        String closedCorner = "{\"frame_classes\": [\"foldedForm\"], \"vertices_coords\": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],"
                + "[0,0,1],[1,0,1],[1,1,1],[0,1,1]],"
                + " \"faces_vertices\": [[0,3,2,1],[0,1,5,4],[1,2,6,5],[2,3,7,6],[3,0,4,7]],"
                + " \"edges_vertices\": [[0,1],[1,2],[2,3],[3,0],[0,4],[1,5],[2,6],[3,7],[4,5],[5,6],[6,7],[7,4]],"
                + " \"edges_assignment\": [\"V\",\"V\",\"V\",\"V\",\"V\",\"V\",\"V\",\"V\",\"B\",\"B\",\"B\",\"B\"]}";
        CliTest.Run closed = fold("closed-corner", closedCorner);
        CliTest.assertOneLineError(closed, "closed-corner.fold: the folded form does not unfold onto one flat sheet");
    }

    /**
     * The FOLD repository's own examples (MIT; src/test/resources/fold-examples): folded forms
     * unfolded onto one sheet and folded back, a flat folded form with its paper coordinates,
     * and a crease pattern folded line by line; each with its layer order checked valid.
     */
    @Test
    void theFoldRepositorysExamplesFold() {
        String[][] cases = {
            {"box", "58 creases folded at once (a folded form, unfolded onto one sheet), 16 layers at most"},
            {"simple", "3 creases folded at once (a folded form, unfolded onto one sheet), 2 layers at most"},
            {"squaretwist", "12 creases folded at once (a folded form, unfolded onto one sheet), 1 layer at most"},
            {"diagonal-folded", "1 crease folded at once (a folded form, unfolded onto one sheet), 2 layers at most"},
            {"diagonal-cp", "1 fold, 2 layers at most"},
        };
        for (String[] c : cases) {
            CliTest.Run run = CliTest.run("fold", "src/test/resources/fold-examples/" + c[0] + ".fold", "--no-view", "--export-fold",
                    dir.resolve(c[0] + "-out.fold").toString());
            assertEquals(0, run.code(), c[0] + ": " + run.err());
            assertTrue(run.out().contains(c[0] + ".fold: " + c[1]), run.out());
            assertTrue(run.out().contains("layer order: valid"), run.out());
        }
    }

    /**
     * Traditional models from Flat-Folder's examples (MIT; src/test/resources/flat-folder-examples),
     * their mountains and valleys only: each folded flat with the layer order found, which the
     * independent check finds valid; a pinwheel, whose layers lie in a cycle, refused.
     */
    @Test
    void traditionalModelsFoldFlatWithTheirLayerOrderFound() {
        String[][] cases = {
            {"001_traditional_Sailboat", "28 creases folded at once (folded flat, its layer order found), 16 layers at most",
                "layer order: valid (20 faces on 1 plane"},
            {"002_traditional_Kabuto", "20 creases folded at once (folded flat, its layer order found), 12 layers at most",
                "layer order: valid (18 faces on 1 plane"},
            {"004_traditional_Crane", "99 creases folded at once (folded flat, its layer order found), 24 layers at most",
                "layer order: valid (72 faces on 1 plane"},
            {"038_traditionaloripa_Yakko", "53 creases folded at once (folded flat, its layer order found), 8 layers at most",
                "layer order: valid (38 faces on 1 plane"},
        };
        for (String[] c : cases) {
            CliTest.Run run = CliTest.run("fold", "src/test/resources/flat-folder-examples/" + c[0] + ".fold", "--no-view", "--export-fold",
                    dir.resolve(c[0] + "-out.fold").toString());
            assertEquals(0, run.code(), c[0] + ": " + run.err());
            assertTrue(run.out().contains(c[1]) && run.out().contains(c[2]), run.out());
        }
        // A rectangle creased border to border whose lines, folded one at a time, put a flap
        // through the paper: folded at once instead, its order found and valid.
        CliTest.Run grid = CliTest.run("fold", "src/test/resources/flat-folder-examples/003_brown_3x3_A2.fold", "--no-view", "--export-fold",
                dir.resolve("grid-out.fold").toString());
        assertEquals(0, grid.code(), grid.err());
        assertTrue(grid.out().contains("8 creases folded at once (folded flat, its layer order found)")
                && grid.out().contains("layer order: valid"), grid.out());
        CliTest.Run pinwheel = CliTest.run("fold", "src/test/resources/flat-folder-examples/006_ku_Thirds_Pinwheel.fold", "--no-view");
        CliTest.assertOneLineError(pinwheel, "no layer order without a cycle", "which iFold's stacks cannot hold");
    }

    /** A box's net is printed with its own outline cut, not the rectangle it spans, and named as a FOLD file's. */
    @Test
    void aSheetOfAnotherOutlineIsPrintedWithItsOwnOutline() throws Exception {
        Pattern net = new Pattern();
        // An L of three unit squares, one crease between each two.
        net.edge(0, 0, 1, 0, "B", null).edge(1, 0, 1, 1, "V", null).edge(1, 1, 0, 1, "V", null).edge(0, 1, 0, 0, "B", null);
        net.edge(1, 0, 2, 0, "B", null).edge(2, 0, 2, 1, "B", null).edge(2, 1, 1, 1, "B", null);
        net.edge(0, 1, 0, 2, "B", null).edge(0, 2, 1, 2, "B", null).edge(1, 2, 1, 1, "B", null);
        Path svg = dir.resolve("l.svg");
        CliTest.Run run = fold("l-sheet", net.json(), "--export-svg", svg.toString());
        assertEquals(0, run.code(), run.err());
        String page = Files.readString(svg);
        assertTrue(page.contains("a FOLD file's crease pattern"), page);
        assertTrue(!page.contains("<polygon class=\"cut\""), "no rectangle round the L");
        assertEquals(8 + 1, page.split("<line class=\"cut\"", -1).length - 1, "its eight border edges cut, and the legend's sample");
    }

    /** Hostile files: indices out of range, the wrong kinds of value, refused in one line. */
    @Test
    void hostileFilesAreRefusedInOneLine() throws Exception {
        String[][] cases = {
            {"crossing", Pattern.square().edge(0, 0, 2, 2, "V", null).edge(2, 0, 0, 2, "V", null).json(),
                "edges 8 and 9 cross with no vertex where they meet"},
            {"cut", Pattern.square().edge(1, 0, 1, 2, "C", null).json(), "edge 8 is C, a cut"},
            {"a-list", "[{\"vertices_coords\": [[0, 0]]}]", "not a FOLD file"},
            {"bad-face-on-a-rectangle", Pattern.square().edge(1, 0, 1, 2, "V", null).json().replace("}\n",
                ", \"faces_vertices\": [[0, 1, 9]]}\n"), "face 0: faces_vertices names 9"},
            {"thick", Pattern.square().edge(1, 0, 1, 2, "V", null).json().replace("}\n", ", \"frame_ifold:thickness\": -1}\n"),
                "frame_ifold:thickness gives -1"},
            {"out-of-range", "{\"vertices_coords\": [[0,0],[1,0],[1,1]], \"edges_vertices\": [[0,1],[1,2],[2,99]],"
                + " \"edges_assignment\": [\"B\",\"B\",\"B\"], \"faces_vertices\": [[0,1,2]]}", "edge 2: edges_vertices names 99, not one of the 3 vertices"},
            {"face-out-of-range", "{\"vertices_coords\": [[0,0],[1,0],[1,1]], \"edges_vertices\": [[0,1],[1,2],[2,0]],"
                + " \"edges_assignment\": [\"B\",\"B\",\"B\"], \"faces_vertices\": [[0,1,7]]}", "face 0: faces_vertices names 7"},
            {"order-out-of-range", "{\"vertices_coords\": [[0,0,1],[1,0,1],[1,1,1]], \"edges_vertices\": [[0,1],[1,2],[2,0]],"
                + " \"faces_vertices\": [[0,1,2]], \"faceOrders\": [[0, 5, 1]]}", "faceOrders entry 0: [0, 5, 1] names a face"},
        };
        for (String[] c : cases) {
            CliTest.Run run = fold(c[0], c[1]);
            CliTest.assertOneLineError(run, c[0] + ".fold: ", c[2]);
        }
    }
}
