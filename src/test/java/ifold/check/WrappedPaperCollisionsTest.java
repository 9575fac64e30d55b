package ifold.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.check.PaperCollisions.Crossing;
import ifold.check.PaperCollisions.Kind;
import ifold.check.PaperCollisions.Result;
import ifold.cli.Main;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.io.MeshReaders;
import ifold.refine.HamiltonianRefinement;
import ifold.script.FoldScript;
import ifold.script.ScriptFolding;
import ifold.wrap.Wrap;
import ifold.wrap.WrapExport;
import ifold.wrap.WrapGeometry;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The collision checker on what iFold folds: the project's models wrapped as WrapTest wraps
 * them, the fold scripts, and the demos, each exported to OBJ and checked from the file alone.
 *
 * <p>The wraps collide today (caps bent through the layers they join), so their counts are
 * printed, not asserted, except for one crossing found by hand in the cube's wrap. The scripts
 * and the demos are clean.
 */
class WrappedPaperCollisionsTest {
    /** The counts of each case, printed as a table once all have run. */
    private static final Map<String, String> TABLE = new TreeMap<>();

    @TempDir
    Path dir;

    @AfterAll
    static void printTable() {
        System.out.println(String.format(Locale.ROOT, "%-26s %7s %8s %9s %9s %7s %7s %7s %s",
                "case", "faces", "pairs", "cap pairs", "face prs", "copl.", "model", "inside", "deepest (T, faces)"));
        TABLE.forEach((name, row) -> System.out.println(String.format(Locale.ROOT, "%-26s %s", name, row)));
    }

    private static void report(String name, Result result) {
        Crossing d = result.deepest();
        TABLE.put(name, String.format(Locale.ROOT, "%7d %8d %9d %9d %7d %7d %7d %s", result.faces(), result.crossingPairs(),
                result.capPairs(), result.facePairs(), result.coplanarPairs(), result.modelCrossings(), result.pointsInside(),
                d == null ? "-" : String.format(Locale.ROOT, "%.4g (%d, %d)", d.depth(), d.faceA(), d.faceB())));
    }

    /** The model's triangles as numbers, 9 each. */
    private static double[] triangles(HalfedgeMesh mesh) {
        double[] out = new double[9 * mesh.faceCount()];
        for (int f = 0; f < mesh.faceCount(); f++) {
            for (int k = 0; k < 3; k++) {
                for (int axis = 0; axis < 3; axis++) {
                    out[9 * f + 3 * k + axis] = mesh.coordinate(mesh.faceVertex(f, k), axis);
                }
            }
        }
        return out;
    }

    /** Wraps a model file as WrapTest does, writes its OBJ and checks it against the model. */
    private Result wrapAndCheck(String model) throws Exception {
        HalfedgeMesh mesh = MeshBuilder.build(MeshReaders.read(Path.of("models", model + ".off")), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        HamiltonianRefinement.Result refinement = HamiltonianRefinement.refine(mesh);
        Wrap.Result result = Wrap.wrap(refinement, new Wrap.Options(Double.NaN, Double.NaN));
        List<WrapGeometry> geometries = new ArrayList<>();
        for (Wrap.Strip strip : result.strips()) {
            geometries.add(WrapGeometry.of(strip.sheet(), result.frames()));
        }
        Path obj = dir.resolve(model + ".obj");
        WrapExport.writeObj(obj, "models/" + model + ".off", result, geometries);
        Result check = PaperCollisions.check(Files.readString(obj), result.thickness(), triangles(mesh));
        report("wrap " + model, check);
        return check;
    }

    @ParameterizedTest
    @ValueSource(strings = {"tetrahedron", "octahedron", "icosahedron", "triangle", "figure3"})
    void wrapsOfTheProjectsModelsAreCounted(String model) throws Exception {
        Result result = wrapAndCheck(model);
        assertTrue(result.faces() > 0, "setup: paper was exported");
        // Every crossing listed is deeper than touching, and the counts agree with each other.
        for (Crossing c : result.crossings()) {
            assertTrue(c.coplanar() ? c.depth() == 0 : c.depth() > PaperCollisions.TOUCH, c::toString);
        }
        assertTrue(result.capPairs() <= result.crossingPairs());
        assertTrue(result.facePairs() <= result.crossingPairs() + result.coplanarPairs());
    }

    /**
     * The cube's wrap: flat paper never crosses flat paper on a convex solid, and since a fold
     * lands just over (or under) the layer it is folded from, the bends at its flat folds join
     * neighbouring layers: every crossing left is a cap's, none deeper than 4 T (there were
     * 8,014 pairs, a cap joining level 1 to level 23 going 4 T through face 3, before).
     */
    @Test
    void theCubesWrapCollidesOnlyAtCaps() throws Exception {
        Result result = wrapAndCheck("cube");
        assertTrue(result.crossingPairs() > 0, result::summary);
        assertEquals(result.crossingPairs(), result.capPairs(), result::summary);
        assertEquals(0, result.coplanarPairs(), result::summary);
        assertEquals(0, result.modelCrossings() + result.pointsInside(), result::summary);
        assertTrue(result.crossingPairs() < 8014, result::summary);
        assertTrue(result.deepest().depth() <= 4 + 1e-9, result::summary);
    }

    static Stream<Path> scripts() throws Exception {
        return Files.list(Path.of("models", "scripts")).filter(p -> p.toString().endsWith(".fold")).sorted();
    }

    @ParameterizedTest
    @MethodSource("scripts")
    void foldScriptsAreClean(Path script) throws Exception {
        ScriptFolding.Result result = FoldScript.read(script).play();
        WrapGeometry geometry = WrapGeometry.of(result.sheet(), result.frames());
        Path obj = dir.resolve("folded.obj");
        WrapExport.writeObj(obj, script.toString(), List.of(geometry));
        Result check = PaperCollisions.check(Files.readString(obj), result.sheet().thickness());
        report("fold " + script.getFileName(), check);
        assertTrue(check.faces() > 1, "setup: folded paper");
        assertTrue(check.isClean(), check::summary);
    }

    /** Runs {@code ifold demo ...} with --export-obj and checks the file, the thickness read from its header. */
    private Result demo(String name, double[] model, String... args) throws Exception {
        Path obj = dir.resolve("demo.obj");
        List<String> all = new ArrayList<>(List.of(args));
        all.addAll(List.of("--no-view", "--export-obj", obj.toString()));
        StringWriter err = new StringWriter();
        int code = Main.commandLine(new PrintWriter(new StringWriter()), new PrintWriter(err)).execute(all.toArray(String[]::new));
        assertEquals(0, code, err::toString);
        String text = Files.readString(obj);
        Matcher thickness = Pattern.compile("thickness ([0-9.Ee+-]+)").matcher(text.lines().findFirst().orElse(""));
        assertTrue(thickness.find(), "setup: the header names the thickness");
        Result check = PaperCollisions.check(text, Double.parseDouble(thickness.group(1)), model);
        report(name, check);
        return check;
    }

    @Test
    void theZigzagDemoIsClean() throws Exception {
        // The demo's triangle, which the paper wraps on both sides.
        Result result = demo("demo zigzag", new double[] {0, 0, 0, 10, 0, 0, 3.5, 8, 0}, "demo", "zigzag");
        assertTrue(result.capFaces() > 0, "setup: folded paper");
        assertTrue(result.isClean(), result::summary);
    }

    @ParameterizedTest
    @ValueSource(ints = {30, 90, 150})
    void theTurnDemosAreClean(int angle) throws Exception {
        Result result = demo("demo turn " + angle, new double[0], "demo", "turn", "--angle", Integer.toString(angle));
        assertTrue(result.capFaces() > 0, "setup: folded paper");
        assertTrue(result.isClean(), result::summary);
    }
}
