package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.check.WrapTruths;
import ifold.mesh.GridSquares;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.Polycubes;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The hinge strip on polycubes: its tour crosses every side once, and its paper, read back from
 * the OBJ and FOLD files it writes, tiles the strip, is congruent to it, covers the surface with
 * exactly two layers everywhere and twice the surface's area, in a valid layer order.
 */
class HingeStripTest {
    @TempDir
    Path dir;

    static Stream<Object[]> polycubes() {
        return Stream.of(new Object[] {"cube", Polycubes.box(1, 1, 1)}, new Object[] {"2 x 1 x 1 box", Polycubes.box(2, 1, 1)},
                new Object[] {"3 x 2 x 2 box", Polycubes.box(3, 2, 2)}, new Object[] {"L", Polycubes.l()},
                new Object[] {"T", Polycubes.t()}, new Object[] {"plus", Polycubes.plus()},
                new Object[] {"staircase", Polycubes.staircase()}, new Object[] {"saddle", SADDLE},
                new Object[] {"cube on a slab", CUBE_ON_A_SLAB}, new Object[] {"50 random cubes", Polycubes.random(50, 1)},
                new Object[] {"200 random cubes", Polycubes.random(200, 6)});
    }

    /**
     * Three cubes in an L on the floor and one on top of an end of the L: round the corner of the
     * surface at (1, 1, 1) two convex edges run on as concave ones, and paper bent over each would
     * run into the layers of the face across the corner.
     */
    static final List<int[]> SADDLE = List.of(new int[] {1, 0, 0}, new int[] {0, 1, 0}, new int[] {1, 1, 0}, new int[] {1, 0, 1});

    /** A cube on the middle of a 3 x 3 slab: its four upright convex edges run into the slab's top. */
    static final List<int[]> CUBE_ON_A_SLAB;

    static {
        List<int[]> cubes = new ArrayList<>(Polycubes.box(3, 3, 1));
        cubes.add(new int[] {1, 1, 1});
        CUBE_ON_A_SLAB = List.copyOf(cubes);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("polycubes")
    void theTourCrossesEverySideOnceAndPassesTwiceThroughEachSquare(String name, List<int[]> cubes) throws Exception {
        GridSquares squares = GridSquares.of(mesh(cubes), Double.NaN);
        HingeTour tour = HingeTour.of(squares);
        int n = squares.count();
        assertEquals(2 * n, tour.passes());
        boolean[] crossed = new boolean[4 * n];
        int[] passesThrough = new int[n];
        for (int i = 0; i < tour.passes(); i++) {
            int q = tour.square(i);
            passesThrough[q]++;
            for (int side : new int[] {tour.entry(i), tour.exit(i)}) {
                assertTrue(!crossed[4 * q + side], name + ": square " + q + " side " + side + " crossed twice");
                crossed[4 * q + side] = true;
            }
            // The next pass (the first, after the last) is across the side this one leaves by.
            int next = i + 1 == tour.passes() ? 0 : i + 1;
            assertEquals(tour.square(next), squares.across(q, tour.exit(i)));
            assertEquals(tour.entry(next), squares.acrossSide(q, tour.exit(i)));
        }
        for (int q = 0; q < n; q++) {
            assertEquals(2, passesThrough[q], name + ": passes through square " + q);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("polycubes")
    void thePaperCoversEverySquareWithTwoLayersInAValidOrder(String name, List<int[]> cubes) throws Exception {
        check(name, mesh(cubes));
    }

    /** Two solids apart: a strip each, and their FOLD file, two pieces of paper, folds back (it had been refused as one piece). */
    @org.junit.jupiter.api.Test
    void twoSolidsTakeAStripEachAndTheirFileFoldsBack() throws Exception {
        HalfedgeMesh mesh = mesh(List.of(new int[] {0, 0, 0}, new int[] {3, 0, 0}));
        GridSquares squares = GridSquares.of(mesh, Double.NaN);
        assertEquals(2, squares.components(), "setup: two pieces");
        Wrap.Result result = HingeStrip.wrap(squares, HingeTour.of(squares), Double.NaN, Wrap.DEFAULT_MAX_FACES, Wrap.Watcher.NONE);
        assertEquals(2, result.strips().size());
        List<ifold.foldfile.FoldFile.Folded> sheets = new ArrayList<>();
        int faces = 0;
        for (Wrap.Strip strip : result.strips()) {
            sheets.add(new ifold.foldfile.FoldFile.Folded(strip.sheet(), result.frames()));
            faces += strip.sheet().faceCount();
        }
        Path fold = dir.resolve("two.fold");
        ifold.foldfile.FoldFile.write(fold, "test", sheets);
        ifold.job.ScriptJob.Outcome back = ifold.job.ScriptJob.run(fold, Wrap.DEFAULT_MAX_FACES, stage -> { });
        assertEquals(faces, back.figures().get("faces"));
        assertEquals(2, back.figures().get("maxLayers"));
        // Its thick layers on the side the file says is out (faces_ifold:facing): none crosses
        // (without it, each plane's layers stood on its first face's side, 180 pairs crossing).
        ifold.check.PaperCollisions.Result collisions = ifold.job.Collisions.forScene(List.of(back.folded()), result.thickness(),
                new ifold.mesh.PolygonSoup());
        assertTrue(collisions.isClean(), collisions.summary());
    }

    /** A surface of genus 1 (the shared square frame, 720 squares of 0.2): the tour needs only a closed surface. */
    @org.junit.jupiter.api.Test
    void aFrameOfGenusOneIsWrappedToo() throws Exception {
        Path frame = Path.of("..", "shared", "meshes", "polyhedra", "square_frame.off");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(frame), "../shared/meshes is not here");
        HalfedgeMesh mesh = MeshBuilder.build(ifold.mesh.io.OffReader.read(frame), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        assertEquals(0.2, GridSquares.of(mesh, Double.NaN).spacing(), 1e-12);
        check("square_frame", mesh);
    }

    private void check(String name, HalfedgeMesh mesh) throws Exception {
        GridSquares squares = GridSquares.of(mesh, Double.NaN);
        HingeTour tour = HingeTour.of(squares);
        Wrap.Result result = HingeStrip.wrap(squares, tour, Double.NaN, Wrap.DEFAULT_MAX_FACES, Wrap.Watcher.NONE);
        assertEquals(1, result.strips().size());
        Wrap.Strip strip = result.strips().get(0);
        // Two squares of strip a square of surface: the strip is 2N squares long.
        assertEquals(2.0 * squares.count() * squares.spacing(), strip.sheet().length(), 1e-9);
        assertEquals(tour.turnCount(), result.count(Wrap.Kind.DIAGONAL_TURN));
        List<PaperInSpace> geometries = new ArrayList<>();
        geometries.add(PaperInSpace.of(strip.sheet(), result.frames()));
        WrapAnalysis analysis = WrapAnalysis.of(result, geometries);
        assertEquals(2, analysis.maxLayers(), name + ": layers");
        assertEquals(0.5, analysis.surfaceArea() / analysis.paperArea(), 1e-9, name + ": paper efficiency");
        assertTrue(analysis.coverage() > 1 - 1e-9, "coverage " + analysis.coverage());
        assertTrue(analysis.isometryError() <= 1e-9, "isometry " + analysis.isometryError());
        // The independent checks, reading the files written.
        Path obj = dir.resolve("hinge.obj");
        WrapExport.writeObj(obj, "test", result, geometries);
        WrapTruths truths = WrapTruths.read(Files.readString(obj));
        List<double[]> triangles = WrapTest.triangles(mesh);
        List<WrapTruths.Violation> violations = truths.check(triangles, result.thickness(), analysis.stackLevels(), 2000, 7);
        assertTrue(violations.isEmpty(), () -> name + ": " + violations.size() + " violations, the first: "
                + violations.subList(0, Math.min(5, violations.size())));
        assertEquals(strip.sheet().length(), truths.length(0), 1e-9);
        // No paper crosses paper or the model (the project's collision checker, reading the OBJ).
        ifold.check.PaperCollisions.Result collisions = collisions(obj, triangles, result.thickness());
        assertTrue(collisions.isClean(), name + ": " + collisions.summary());
        Path fold = dir.resolve("hinge.fold");
        ifold.foldfile.FoldFile.write(fold, "test", List.of(new ifold.foldfile.FoldFile.Folded(strip.sheet(), result.frames())));
        ifold.check.LayerOrder.Result order;
        try (java.io.Reader reader = Files.newBufferedReader(fold)) {
            order = ifold.check.LayerOrder.check(reader);
        }
        assertTrue(order.layered() > 0, "setup: layers were found");
        assertTrue(order.valid(), order::summary);
        // Its FOLD file folds back to its two layers (line by line, or as the file has it where
        // its lines folded one at a time would stack the paper higher).
        ifold.job.ScriptJob.Outcome back = ifold.job.ScriptJob.run(fold, Wrap.DEFAULT_MAX_FACES, stage -> { });
        assertEquals(2, back.figures().get("maxLayers"), name + " folded back: " + back.figures());
    }

    /**
     * The cube's turning squares fold twice along one diagonal, back to back: each fold's layers
     * stand back half a thickness, their bends meeting on the crease, and the checker lets them
     * (0 violations above); a bend moved off the other's (half a thickness up), or a corner
     * standing back three thicknesses, it does not.
     */
    @org.junit.jupiter.api.Test
    void foldsBackToBackStandBackHalfAThicknessAndTheCheckerKnowsHowFar() throws Exception {
        HalfedgeMesh mesh = mesh(Polycubes.box(1, 1, 1));
        GridSquares squares = GridSquares.of(mesh, Double.NaN);
        Wrap.Result result = HingeStrip.wrap(squares, HingeTour.of(squares), Double.NaN, Wrap.DEFAULT_MAX_FACES, Wrap.Watcher.NONE);
        List<PaperInSpace> geometries = List.of(PaperInSpace.of(result.strips().get(0).sheet(), result.frames()));
        Path obj = dir.resolve("cube.obj");
        WrapExport.writeObj(obj, "test", result, geometries);
        String text = Files.readString(obj);
        List<double[]> triangles = WrapTest.triangles(mesh);
        double t = result.thickness();
        assertTrue(WrapTruths.read(text).check(triangles, t, 2, 2000, 7).isEmpty(), "setup: the wrap keeps every truth");
        // The apex of a bend: a cap's edge that another cap, sharing no vertex, runs along too.
        List<String> lines = new ArrayList<>(text.lines().toList());
        List<double[]> v = new ArrayList<>();
        List<Integer> vLine = new ArrayList<>();
        List<int[]> caps = new ArrayList<>();
        boolean inCaps = false;
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.startsWith("v ")) {
                String[] p = line.split(" ");
                v.add(new double[] {Double.parseDouble(p[1]), Double.parseDouble(p[2]), Double.parseDouble(p[3])});
                vLine.add(i);
            } else if (line.startsWith("g ")) {
                inCaps = line.equals("g cap");
            } else if (line.startsWith("f ") && inCaps) {
                String[] p = line.substring(2).split(" ");
                int[] cap = new int[p.length];
                for (int k = 0; k < p.length; k++) {
                    cap[k] = Integer.parseInt(p[k].split("/")[0]) - 1;
                }
                caps.add(cap);
            }
        }
        int[] apex = null;
        for (int i = 0; i < caps.size() && apex == null; i++) {
            for (int j = i + 1; j < caps.size() && apex == null; j++) {
                apex = sharedSegment(caps.get(i), caps.get(j), v);
            }
        }
        assertTrue(apex != null, "setup: two bends meet back to back");
        // One bend's apex moved half a thickness off the other's: its layers' creep is unexplained.
        List<String> moved = new ArrayList<>(lines);
        for (int a : apex) {
            moved.set(vLine.get(a), String.format(java.util.Locale.ROOT, "v %s %s %s", v.get(a)[0] + t / 2, v.get(a)[1] + t / 2,
                    v.get(a)[2] + t / 2));
        }
        List<WrapTruths.Violation> apart = WrapTruths.read(String.join("\n", moved) + "\n").check(triangles, t, 2, 2000, 7);
        assertTrue(apart.stream().anyMatch(x -> x.truth().equals(WrapTruths.ISOMETRIC) && x.message().contains("stretched")), apart::toString);
        // A corner of a fold's layer (a cap's vertex off its apex) three thicknesses in along its crease: too far.
        int corner = -1;
        int other = -1;
        for (int[] cap : caps) {
            List<Integer> vertices = java.util.Arrays.stream(cap).boxed().toList();
            if (vertices.contains(apex[0]) && vertices.contains(apex[1])) {
                for (int x : cap) {
                    if (x != apex[0] && x != apex[1]) {
                        other = corner;
                        corner = x;
                    }
                }
            }
        }
        double[] c = v.get(corner);
        double[] a = v.get(other);
        double length = Math.sqrt(Math.pow(c[0] - a[0], 2) + Math.pow(c[1] - a[1], 2) + Math.pow(c[2] - a[2], 2));
        List<String> far = new ArrayList<>(lines);
        far.set(vLine.get(corner), String.format(java.util.Locale.ROOT, "v %s %s %s", c[0] - 3 * t * (c[0] - a[0]) / length,
                c[1] - 3 * t * (c[1] - a[1]) / length, c[2] - 3 * t * (c[2] - a[2]) / length));
        List<WrapTruths.Violation> tooFar = WrapTruths.read(String.join("\n", far) + "\n").check(triangles, t, 2, 2000, 7);
        assertTrue(tooFar.stream().anyMatch(x -> x.truth().equals(WrapTruths.ISOMETRIC) && x.message().contains("stretched")), tooFar::toString);
    }

    /**
     * Where a convex edge ends at a face across the corner (a saddle's, a cube standing on a
     * slab), its hosts stop paper bent over it short of the corner, as high as that face's stack
     * ({@link ifold.sheet.HostFrame.Stop}): the paper is clean. Without the stops the bends over
     * those edges run into the layers across: the checker finds them.
     */
    @org.junit.jupiter.api.Test
    void paperOverAConvexEdgeStopsShortOfAFaceAcrossItsEnd() throws Exception {
        for (List<int[]> cubes : List.of(SADDLE, CUBE_ON_A_SLAB)) {
            HalfedgeMesh mesh = mesh(cubes);
            GridSquares squares = GridSquares.of(mesh, Double.NaN);
            Wrap.Result result = HingeStrip.wrap(squares, HingeTour.of(squares), Double.NaN, Wrap.DEFAULT_MAX_FACES, Wrap.Watcher.NONE);
            ifold.sheet.HostFrame[] frames = result.frames();
            long stops = java.util.Arrays.stream(frames).filter(f -> f.stops() != null).count();
            assertTrue(stops > 0, "setup: hosts with stops");
            List<double[]> triangles = WrapTest.triangles(mesh);
            Path obj = dir.resolve("stopped.obj");
            Wrap.Strip strip = result.strips().get(0);
            WrapExport.writeObj(obj, "test", result, List.of(PaperInSpace.of(strip.sheet(), frames)));
            assertTrue(collisions(obj, triangles, result.thickness()).isClean());

            ifold.sheet.HostFrame[] unstopped = java.util.Arrays.stream(frames).map(f -> f.withStops(null))
                    .toArray(ifold.sheet.HostFrame[]::new);
            Path bare = dir.resolve("unstopped.obj");
            WrapExport.writeObj(bare, "test", result, List.of(PaperInSpace.of(strip.sheet(), unstopped)));
            ifold.check.PaperCollisions.Result crossing = collisions(bare, triangles, result.thickness());
            assertTrue(crossing.crossingPairs() > 0, crossing::summary);
            assertEquals(crossing.crossingPairs(), crossing.capPairs(), "bends over the edges cross: " + crossing.summary());
        }
    }

    /** The collision checker's verdict on the OBJ written, against the model's triangles. */
    private static ifold.check.PaperCollisions.Result collisions(Path obj, List<double[]> triangles, double thickness) throws Exception {
        double[] model = new double[9 * triangles.size()];
        for (int i = 0; i < triangles.size(); i++) {
            System.arraycopy(triangles.get(i), 0, model, 9 * i, 9);
        }
        return ifold.check.PaperCollisions.check(Files.readString(obj), thickness, model);
    }

    /** The two vertices of cap a's edge that cap b also has an edge along (in space), where the two caps share no vertex; else null. */
    private static int[] sharedSegment(int[] a, int[] b, List<double[]> v) {
        for (int x : a) {
            for (int y : b) {
                if (x == y) {
                    return null;
                }
            }
        }
        for (int i = 0; i < a.length; i++) {
            int p = a[i];
            int q = a[(i + 1) % a.length];
            for (int j = 0; j < b.length; j++) {
                int r = b[j];
                int s = b[(j + 1) % b.length];
                if (near(v.get(p), v.get(s)) && near(v.get(q), v.get(r)) || near(v.get(p), v.get(r)) && near(v.get(q), v.get(s))) {
                    return new int[] {p, q};
                }
            }
        }
        return null;
    }

    private static boolean near(double[] a, double[] b) {
        return Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]) < 1e-9;
    }

    static HalfedgeMesh mesh(List<int[]> cubes) throws Exception {
        return MeshBuilder.build(Polycubes.surface(cubes), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
    }
}
