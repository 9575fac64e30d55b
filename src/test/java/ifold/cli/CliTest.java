package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.io.MeshReaders;
import ifold.mesh.io.MeshWriters;
import ifold.testing.SharedMeshes;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** The command line through picocli's execute: exit codes, one-line errors, no partial output. */
class CliTest {
    @TempDir
    Path dir;

    record Run(int code, String out, String err) {
    }

    static Run run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(args);
        return new Run(code, out.toString(), err.toString());
    }

    private Path write(PolygonSoup soup, String name) throws Exception {
        Path file = dir.resolve(name);
        MeshWriters.write(soup, file);
        return file;
    }

    /** The number a report gives for {@code key} (its first occurrence). */
    static double number(String json, String key) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\"" + key + "\": ([-0-9.eE+]+)").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        return Double.parseDouble(m.group(1));
    }

    static void assertOneLineError(Run run, String... fragments) {
        String[] lines = run.err().strip().split("\n");
        // What the user typed (an option's value) exits 2; what the data holds exits 1.
        boolean usage = lines[0].startsWith("ifold: option ") && !lines[0].contains("cannot ");
        assertEquals(usage ? UserError.USAGE_EXIT_CODE : UserError.EXIT_CODE, run.code(), run.err());
        assertEquals(1, lines.length, "one line: " + run.err());
        assertTrue(lines[0].startsWith("ifold: "), lines[0]);
        for (String fragment : fragments) {
            assertTrue(lines[0].contains(fragment), "'" + fragment + "' in: " + lines[0]);
        }
        assertFalse(run.err().contains("\tat "), "no stack trace");
    }

    /** What the user typed wrong is said in iFold's words, with what was meant, and a hint to the help. */
    @Test
    void mistypedCommandsAndOptionsAreNamedWithWhatWasMeant() {
        String[][] cases = {
            {"wrap models/cube.off --widht 1", "ifold: unknown option '--widht': did you mean --width?"},
            {"wrap models/cube.off --width abc", "ifold: option --width: 'abc' is not a number"},
            {"wrap models/cube.off --max-faces 1.5", "ifold: option --max-faces: '1.5' is not a whole number"},
            {"demo zigzag --fps 99999999999", "ifold: option --fps: '99999999999' is out of range"},
            {"demo zigzg", "ifold: unknown command 'zigzg': did you mean zigzag?"},
            {"wrapp models/cube.off", "ifold: unknown command 'wrapp': did you mean wrap"},
            {"info models/cube.off models/cube.off", "ifold: unexpected argument 'models/cube.off'"},
        };
        for (String[] c : cases) {
            Run run = run(c[0].split(" "));
            assertEquals(UserError.USAGE_EXIT_CODE, run.code(), c[0]);
            String[] lines = run.err().strip().split("\n");
            assertEquals(2, lines.length, c[0] + ": the error and the hint: " + run.err());
            assertTrue(lines[0].startsWith(c[1]), c[0] + ": " + lines[0]);
            assertTrue(lines[1].startsWith("Try 'ifold") && lines[1].endsWith(" --help' for more."), lines[1]);
        }
    }

    /** Every command's help lists --version, and each prints the program's (the subcommands printed nothing). */
    @Test
    void everyCommandPrintsTheVersion() {
        for (String[] args : new String[][] {{"--version"}, {"wrap", "--version"}, {"check", "-V"}, {"demo", "zigzag", "--version"},
            {"demo", "--version"}}) {
            Run run = run(args);
            assertEquals(0, run.code(), String.join(" ", args) + ": " + run.err());
            assertEquals("ifold 0.1.0", run.out().strip(), String.join(" ", args));
        }
    }

    /** main() builds only the subcommands a run needs (picocli's annotation reading is most of start-up). */
    @Test
    void aRunBuildsOnlyTheSubcommandItNeeds() {
        PrintWriter sink = new PrintWriter(new StringWriter());
        assertEquals(java.util.Set.of("info"), Main.commandLineFor(sink, sink, new String[] {"info", "x.off", "--json"})
                .getSubcommands().keySet());
        assertEquals(java.util.Set.of(), Main.commandLineFor(sink, sink, new String[] {"--version"}).getSubcommands().keySet());
        java.util.Set<String> all = Main.commandLine(sink, sink).getSubcommands().keySet();
        assertTrue(all.containsAll(java.util.List.of("wrap", "view", "fold", "demo", "refine", "info", "generate", "help")), all.toString());
        for (String[] args : new String[][] {{"--help"}, {"wrapp", "x.off"}, {"help", "info"}}) {
            assertEquals(all, Main.commandLineFor(sink, sink, args).getSubcommands().keySet(), String.join(" ", args));
        }
        StringWriter help = new StringWriter();
        Main.commandLineFor(new PrintWriter(help), sink, new String[] {"--help"}).execute("--help");
        assertTrue(help.toString().contains("generate") && help.toString().contains("wrap"), help.toString());
    }

    @Test
    void refineWritesFacesInPathOrder() throws Exception {
        Path model = write(Solids.icosahedron(), "ico.off");
        Path out = dir.resolve("ico-refined.obj");
        Run run = run("refine", model.toString(), "-o", out.toString());
        assertEquals(0, run.code(), run.err());
        PolygonSoup refined = MeshReaders.read(out);
        assertEquals(98, refined.faceCount());
        for (int t = 0; t + 1 < refined.faceCount(); t++) {
            int shared = 0;
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    shared += refined.faceVertex(t, i) == refined.faceVertex(t + 1, j) ? 1 : 0;
                }
            }
            assertEquals(2, shared, "faces " + t + " and " + (t + 1) + " share an edge");
        }
    }

    @Test
    void refineJsonReportsCountsAnglesAndPhases() throws Exception {
        Path model = write(Solids.torus(3, 1, 10, 6), "torus.off");
        Run run = run("refine", model.toString(), "-o", dir.resolve("t.off").toString(), "--json");
        assertEquals(0, run.code(), run.err());
        for (String key : new String[] {"\"inputTriangles\": 120", "\"components\": 1", "\"outputTriangles\": 598",
            "\"minAngleInDegrees\"", "\"minAngleOutDegrees\"", "\"repairs\": {}", "\"parse\"", "\"build\"", "\"refine\"", "\"write\""}) {
            assertTrue(run.out().contains(key), key + " in " + run.out());
        }
    }

    @Test
    void refinePreparesTheFacesAsTheWrapDoesOnlyWhenAsked() throws Exception {
        Path model = write(Solids.box(30, 1, 1), "box.off");
        Run plain = run("refine", model.toString(), "-o", dir.resolve("plain.off").toString());
        assertEquals(0, plain.code(), plain.err());
        assertEquals(58, MeshReaders.read(dir.resolve("plain.off")).faceCount(), "the seed's refinement: 5n - 2");
        Run prepared = run("refine", model.toString(), "-o", dir.resolve("prepared.off").toString(), "--prepare", "--json");
        assertEquals(0, prepared.code(), prepared.err());
        int triangles = MeshReaders.read(dir.resolve("prepared.off")).faceCount();
        assertTrue(prepared.out().contains("\"preparedRegions\": 4"), prepared.out());
        assertTrue(prepared.out().contains("\"outputTriangles\": " + triangles), prepared.out());
        assertTrue(triangles > 58 * 5, "the long faces cut into well-shaped triangles: " + triangles);
    }

    @Test
    void repairsAreReportedOnStderrAndStrictRefuses() throws Exception {
        PolygonSoup soup = Solids.tetrahedron();
        soup.addTriangle(0, 1, 2); // a duplicate face
        Path model = write(soup, "dup.off"); // OFF, counts, 4 vertices, then faces on lines 7 to 11
        Run repaired = run("info", model.toString());
        assertEquals(0, repaired.code());
        assertTrue(repaired.err().contains("repaired: dropped 1 duplicate face"), repaired.err());
        assertTrue(repaired.out().contains("faces: 4"), repaired.out());
        assertTrue(repaired.out().contains("genus: 0"), repaired.out());
        Path out = dir.resolve("strict.off");
        Run strict = run("refine", model.toString(), "-o", out.toString(), "--strict");
        assertOneLineError(strict, "dup.off:11:", "duplicates an earlier face", "--strict");
        assertFalse(Files.exists(out));
    }

    @Test
    void infoJsonDescribesATorus() throws Exception {
        Path model = write(Solids.torus(3, 1, 8, 5), "torus.obj");
        Run run = run("info", model.toString(), "--json");
        assertEquals(0, run.code(), run.err());
        for (String key : new String[] {"\"faces\": 80", "\"vertices\": 40", "\"edges\": 120", "\"genus\": 1",
            "\"boundaryLoops\": 0", "\"components\": 1", "\"manifold\": true", "\"valid\": true"}) {
            assertTrue(run.out().contains(key), key + " in " + run.out());
        }
    }

    /** refine writes PLY and STL, binary unless --ascii; info names the format read and, for STL, the corners welded. */
    @Test
    void refineWritesPlyAndStlThatInfoReads() throws Exception {
        Path model = write(Solids.cube(), "cube.off");
        String[][] cases = {{"c.ply", "", "binary little-endian PLY"}, {"a.ply", "--ascii", "ASCII PLY"}, {"c.stl", "", "binary STL"},
            {"a.stl", "--ascii", "ASCII STL"}};
        Run reference = run("info", "--json", model.toString());
        for (String[] c : cases) {
            Path out = dir.resolve(c[0]);
            Run refine = c[1].isEmpty() ? run("refine", model.toString(), "-o", out.toString())
                    : run("refine", model.toString(), "-o", out.toString(), c[1]);
            assertEquals(0, refine.code(), refine.err());
            PolygonSoup refined = MeshReaders.read(out);
            assertEquals(MeshReaders.read(dir.resolve("c.ply")).faceCount(), refined.faceCount(), c[0]);
            Run info = run("info", "--json", out.toString());
            assertEquals(0, info.code(), info.err());
            assertTrue(info.out().contains("\"format\": \"" + c[2] + "\""), info.out());
            assertEquals(c[0].endsWith(".stl"), info.out().contains("\"weldedCorners\""), info.out());
            assertTrue(info.out().contains("\"genus\": 0") && info.out().contains("\"boundaryLoops\": 0"), info.out());
        }
        assertTrue(reference.out().contains("\"format\": \"OFF\""), reference.out());
    }

    @Test
    void badOptionsGetOneLineAndNoOutput() throws Exception {
        Path model = write(Solids.cube(), "cube.off");
        assertOneLineError(run("refine", model.toString(), "-o", dir.resolve("x.3mf").toString()), "-o", ".off or .obj or .ply or .stl");
        assertOneLineError(run("refine", model.toString(), "-o", dir.resolve("nope/x.off").toString()), "-o", "does not exist");
        assertOneLineError(run("refine", dir.resolve("missing.off").toString(), "-o", dir.resolve("x.off").toString()),
                "missing.off", "no such file");
        Run usage = run("refine", model.toString());
        assertEquals(2, usage.code());
        assertTrue(usage.err().startsWith("ifold: missing required option"), usage.err());
        assertEquals(2, run("refine", model.toString(), "-o", "x.off", "--bogus").code());
        // 'ifold' alone opens the window where there is a display (as here, under Xvfb); without
        // one it is still this usage error: AppCommandTest runs it so.
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(1, files.count(), "nothing but the model was written");
        }
    }

    @Test
    void unwritableFolderIsRefused() throws Exception {
        Path model = write(Solids.cube(), "cube.off");
        Path locked = Files.createDirectory(dir.resolve("locked"));
        assumeTrue(locked.toFile().setWritable(false, false));
        assumeTrue(!Files.isWritable(locked), "running as root: folders are always writable");
        assertOneLineError(run("refine", model.toString(), "-o", locked.resolve("x.off").toString()), "not writable");
    }

    /** An option the shape does not take is refused, naming the shape that takes it (they were ignored in silence). */
    @Test
    void generateRefusesAnOptionTheShapeDoesNotTake() {
        String[][] cases = {{"cube", "--size", "3x3x3", "option --size: only box takes it, not cube"},
            {"icosahedron", "--cubes", "5", "option --cubes: only polycube takes it, not icosahedron"},
            {"box", "--around", "5", "option --around: only torus takes it, not box"},
            {"torus", "--subdivisions", "2", "option --subdivisions: only icosphere takes it, not torus"}};
        for (String[] c : cases) {
            Path out = dir.resolve(c[0] + "-refused.off");
            Run run = run("generate", c[0], c[1], c[2], "-o", out.toString());
            assertEquals(2, run.code(), run.err());
            assertTrue(run.err().startsWith("ifold: " + c[3]), run.err());
            assertFalse(Files.exists(out), "nothing written");
        }
        assertEquals(0, run("generate", "torus", "--around", "8", "--across", "4", "-o", dir.resolve("t.off").toString()).code());
    }

    /** Every option's value shows as N, not as picocli's placeholder made of the field's name. */
    @Test
    void generateHelpNamesItsValues() {
        Run help = run("help", "generate");
        assertEquals(0, help.code(), help.err());
        for (String option : new String[] {"--around=N", "--across=N", "--subdivisions=N", "--size=AxBxC", "--cubes=N", "--seed=S"}) {
            assertTrue(help.out().contains(option), option + " in " + help.out());
        }
        assertFalse(help.out().contains("<"), "no placeholder: " + help.out());
    }

    @Test
    void generateWritesEveryShape() throws Exception {
        Map<String, Integer> faces = new java.util.HashMap<>(Map.of("tetrahedron", 4, "cube", 6, "octahedron", 8, "icosahedron", 20,
                "triangle", 1, "figure3", 12, "torus", 2 * 24 * 12, "icosphere", 20 * 64));
        // The polycubes, their unit squares: a 2 x 1 x 1 box, the l and t (four cubes), the plus (five), a staircase (six).
        faces.putAll(Map.of("box", 10, "l", 18, "t", 18, "plus", 22, "staircase", 24));
        for (Map.Entry<String, Integer> shape : faces.entrySet()) {
            Path out = dir.resolve(shape.getKey() + ".off");
            assertEquals(0, run("generate", shape.getKey(), "-o", out.toString()).code());
            assertEquals(shape.getValue(), MeshReaders.read(out).faceCount(), shape.getKey());
        }
        assertEquals(2, run("generate", "dodecahedron", "-o", dir.resolve("d.off").toString()).code());
        Path sphere = dir.resolve("sphere.off");
        assertEquals(0, run("generate", "icosphere", "--subdivisions", "1", "-o", sphere.toString()).code());
        assertEquals(80, MeshReaders.read(sphere).faceCount(), "20 triangles, each cut in four");
        Run tooFine = run("generate", "icosphere", "--subdivisions", "9", "-o", dir.resolve("fine.off").toString());
        assertEquals(2, tooFine.code(), tooFine.err());
        assertTrue(tooFine.err().startsWith("ifold: option --subdivisions: must be 0 to 8"), tooFine.err());
        assertFalse(Files.exists(dir.resolve("fine.off")));
        // A box of any size; a random polycube, its surface a sphere of genus 0, the same from the same seed.
        Path box = dir.resolve("box.off");
        assertEquals(0, run("generate", "box", "--size", "3x2x1", "-o", box.toString()).code());
        assertEquals(22, MeshReaders.read(box).faceCount());
        Path one = dir.resolve("one.off");
        Path two = dir.resolve("two.off");
        assertEquals(0, run("generate", "polycube", "--cubes", "40", "--seed", "5", "-o", one.toString()).code());
        assertEquals(0, run("generate", "polycube", "--cubes", "40", "--seed", "5", "-o", two.toString()).code());
        assertEquals(Files.readString(one), Files.readString(two), "the same seed, the same polycube");
        Run info = run("info", one.toString());
        assertTrue(info.out().contains("genus: 0") || info.out().contains("genus 0"), info.out());
        assertOneLineError(run("generate", "box", "--size", "2x1", "-o", dir.resolve("b.off").toString()), "option --size");
        assertOneLineError(run("generate", "box", "--size", "ax1x1", "-o", dir.resolve("b.off").toString()), "option --size");
        assertOneLineError(run("generate", "polycube", "--cubes", "0", "-o", dir.resolve("b.off").toString()),
                "option --cubes: must be 1 to 5000, got 0");
        Run seed = run("generate", "polycube", "--seed", "abc", "-o", dir.resolve("b.off").toString());
        assertEquals(2, seed.code(), seed.err());
        assertTrue(seed.err().startsWith("ifold: option --seed: 'abc' is not a whole number"), seed.err());
        assertFalse(Files.exists(dir.resolve("b.off")));
    }

    static Stream<String> invalid() {
        return SharedMeshes.names("invalid");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("invalid")
    void everyBrokenSharedModelIsTurnedAway(String name) {
        assumeTrue(SharedMeshes.present(), "../shared/meshes is absent");
        Path model = SharedMeshes.ROOT.resolve("invalid").resolve(name);
        Path out = dir.resolve("out.off");
        Run run = run("refine", model.toString(), "-o", out.toString());
        assertOneLineError(run, name);
        assertFalse(Files.exists(out), "no output file");
    }

    static Stream<String> valid() {
        return SharedMeshes.names("valid");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("valid")
    void everyValidSharedModelRefines(String name) throws Exception {
        assumeTrue(SharedMeshes.present(), "../shared/meshes is absent");
        Path model = SharedMeshes.ROOT.resolve("valid").resolve(name);
        Path out = dir.resolve("out.off");
        Run run = run("refine", model.toString(), "-o", out.toString(), "--json");
        assertEquals(0, run.code(), run.err());
        assertTrue(Files.size(out) > 0);
        assertFalse(run.err().contains("\tat "));
    }

    @Test
    void pipesAndFoldersAreRefusedAtOnceNotReadForEver() throws Exception {
        Path pipe = dir.resolve("model.off");
        Process mkfifo = new ProcessBuilder("mkfifo", pipe.toString()).start();
        org.junit.jupiter.api.Assumptions.assumeTrue(mkfifo.waitFor() == 0, "mkfifo is not here");
        long start = System.nanoTime();
        for (String[] args : new String[][] {{"info", pipe.toString()}, {"refine", pipe.toString(), "-o", dir.resolve("o.off").toString()},
            {"wrap", pipe.toString(), "--no-view"}, {"view", pipe.toString(), "--frames", dir.resolve("f").toString()},
            {"fold", pipe.toString(), "--no-view"}}) {
            assertOneLineError(run(args), "not a regular file");
        }
        for (String name : new String[] {"model.ply", "model.stl"}) {
            Path other = dir.resolve(name);
            org.junit.jupiter.api.Assumptions.assumeTrue(new ProcessBuilder("mkfifo", other.toString()).start().waitFor() == 0);
            assertOneLineError(run("info", other.toString()), "not a regular file");
        }
        assertTrue((System.nanoTime() - start) * 1e-9 < 60, "none waited for a writer");
        assertOneLineError(run("fold", dir.toString(), "--no-view"), "is a folder");
        assertOneLineError(run("info", dir.toString()), "is a folder");
    }

    @Test
    void tinyAndHugeModelsKeepTheirFacesAndAngles() throws Exception {
        for (double scale : new double[] {1e-300, 1e-100, 1, 1e80, 1e154, 1e300}) {
            StringBuilder off = new StringBuilder("OFF\n8 6 0\n");
            int[][] corners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
            for (int[] c : corners) {
                off.append(c[0] * scale).append(' ').append(c[1] * scale).append(' ').append(c[2] * scale).append('\n');
            }
            off.append("4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
            Path model = Files.writeString(dir.resolve("cube.off"), off.toString());
            Run info = run("info", model.toString(), "--json");
            assertEquals(0, info.code(), scale + ": " + info.err());
            assertEquals(6, number(info.out(), "faces"), 0, scale + ": no face dropped as without area");
            assertTrue(info.out().contains("\"valid\": true"), info.out());
            Run refine = run("refine", model.toString(), "-o", dir.resolve("r.off").toString(), "--json");
            assertEquals(0, refine.code(), scale + ": " + refine.err());
            assertEquals(45, number(refine.out(), "minAngleInDegrees"), 1e-9, "the faces' triangles, at " + scale);
            assertEquals(22.5, number(refine.out(), "minAngleOutDegrees"), 1e-9, "half of it, at " + scale);
        }
        Path empty = Files.writeString(dir.resolve("flat.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n");
        assertOneLineError(run("info", empty.toString()), "no faces left");
    }
}
