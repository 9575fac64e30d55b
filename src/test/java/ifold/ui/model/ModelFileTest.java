package ifold.ui.model;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.cli.Main;
import ifold.job.BuiltInModels;
import ifold.job.Json;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.io.MeshWriters;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CancellationException;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The window's work on a model file, against the command line's: Model information is
 * {@code ifold info --json}, Export refinement is {@code ifold refine -o}, New model is
 * {@code ifold generate}, byte for byte and message for message.
 */
class ModelFileTest {
    @TempDir
    Path dir;

    /** What the command line printed and its exit code. */
    private record Run(int code, String out, String err) {
    }

    private static Run cli(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int code = Main.commandLine(new PrintWriter(out), new PrintWriter(err)).execute(args);
        return new Run(code, out.toString(), err.toString());
    }

    /** A tetrahedron with its first face twice and a vertex no face uses: two repairs. */
    private Path defective() throws Exception {
        PolygonSoup soup = Solids.tetrahedron();
        soup.addTriangle(0, 1, 2);
        soup.addVertex(5, 5, 5);
        Path model = dir.resolve("defective.off");
        MeshWriters.write(soup, model);
        return model;
    }

    @Test
    void modelInformationHoldsTheFiguresOfInfoJson() throws Exception {
        Path torus = dir.resolve("torus.obj");
        MeshWriters.write(Solids.torus(3, 1, 8, 5), torus);
        for (Path model : List.of(Path.of("models", "cube.off"), Path.of("models", "figure3.obj"), torus, defective())) {
            Run run = cli("info", model.toString(), "--json");
            assertEquals(0, run.code(), run.err());
            Map<String, Object> figures = ModelFile.information(model, false, Progress.NONE);
            assertEquals(run.out(), Json.write(figures), model + ": the window's figures are ifold info --json's");
        }
        Map<String, Object> cube = ModelFile.information(Path.of("models", "cube.off"), false, Progress.NONE);
        assertEquals(Map.of("4", 6), cube.get("faceSizes"), "the cube's quads kept, as info keeps them");
        assertEquals(0, cube.get("genus"));
        Map<String, Object> repaired = ModelFile.information(defective(), false, Progress.NONE);
        assertEquals(Map.of("duplicate_face", 1, "unreferenced_vertex", 1), repaired.get("repairs"));
    }

    @Test
    void strictRefusesDefectiveInputWithTheCommandLinesMessage() throws Exception {
        Path model = defective();
        JobFailure refused = assertThrows(JobFailure.class, () -> ModelFile.information(model, true, Progress.NONE));
        assertEquals("model", refused.problem().field());
        Run run = cli("info", model.toString(), "--strict");
        assertEquals(1, run.code());
        String cli = run.err().strip();
        assertTrue(cli.endsWith(" (run without --strict to repair)"), cli);
        assertEquals(cli.replace(" (run without --strict to repair)", " (clear Strict to repair it)"), "ifold: " + refused.getMessage(),
                "the command line's message, with the window's way out");
        JobFailure wrap = assertThrows(JobFailure.class,
                () -> Planning.plan(new Job.WrapModel(model, "", "", "", true), Progress.NONE), "a strict wrap refuses it too");
        assertEquals("model", wrap.problem().field());
        assertEquals(4, Planning.plan(new Job.WrapModel(model, "", "", "", false), Progress.NONE).figures().get("inputTriangles"),
                "and repairs it when not strict");
    }

    @Test
    void theRefinementIsWrittenByteForByteAsRefineWritesIt() throws Exception {
        for (String name : List.of("icosahedron.off", "cube.obj", "torus.off")) {
            Path model = Path.of("models", name);
            for (String extension : List.of(".off", ".obj")) {
                Path cliFile = dir.resolve("cli-" + name + extension);
                Run run = cli("refine", model.toString(), "-o", cliFile.toString());
                assertEquals(0, run.code(), run.err());
                Path file = dir.resolve("window-" + name + extension);
                Exports.Refined refined = Exports.refinement(model, false, file, Progress.NONE);
                assertArrayEquals(Files.readAllBytes(cliFile), Files.readAllBytes(file), name + " refined to " + extension);
                assertEquals(5 * refined.inputTriangles() - 2 * refined.components(), refined.outputTriangles(), "5n - 2c");
            }
        }
    }

    @Test
    void aCancelledOrFailedRefinementLeavesNoFile() throws Exception {
        Path model = Path.of("models", "torus.off");
        boolean[] writing = {false};
        Progress cancelledWhileWriting = new Progress() {
            @Override
            public void stage(String what) {
                writing[0] |= what.startsWith("writing");
            }

            @Override
            public void done(int done, int total) {
            }

            @Override
            public boolean cancelled() {
                return writing[0];
            }
        };
        Path file = dir.resolve("cancelled.off");
        assertThrows(CancellationException.class, () -> Exports.refinement(model, false, file, cancelledWhileWriting));
        assertTrue(writing[0], "setup: cancelled once the writing began");
        JobFailure wrongName = assertThrows(JobFailure.class, () -> Exports.refinement(model, false, dir.resolve("torus.3mf"), Progress.NONE));
        assertEquals("file", wrongName.problem().field());
        JobFailure noFolder = assertThrows(JobFailure.class,
                () -> Exports.refinement(model, false, dir.resolve("none").resolve("t.off"), Progress.NONE));
        assertFalse(noFolder.getMessage().contains("\n"), "one line: " + noFolder.getMessage());
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(), files.toList(), "nothing written, whole or temporary");
        }
    }

    @Test
    void aNewModelIsRefusedWithGeneratesMessagesAtItsFields() {
        Run tooFew = cli("generate", "torus", "--around", "2", "-o", dir.resolve("t.off").toString());
        List<Problem> torus = new NewModel(BuiltInModels.Shape.torus, "2", "", "").check();
        assertEquals(List.of("around", "across"), torus.stream().map(Problem::field).toList(), "the pair refused together");
        assertEquals("ifold: options --around and --across: " + torus.get(0).message(), tooFew.err().strip());
        assertEquals(2, tooFew.code());
        Run tooFine = cli("generate", "icosphere", "--subdivisions", "9", "-o", dir.resolve("s.off").toString());
        List<Problem> icosphere = new NewModel(BuiltInModels.Shape.icosphere, "", "", "9").check();
        assertEquals("subdivisions", icosphere.get(0).field());
        assertEquals("ifold: option --subdivisions: " + icosphere.get(0).message(), tooFine.err().lines().findFirst().orElseThrow());
        assertEquals(List.of(new Problem("subdivisions", "'fine' is not a whole number")),
                new NewModel(BuiltInModels.Shape.icosphere, "", "", "fine").check());
        assertEquals(List.of(), new NewModel(BuiltInModels.Shape.cube, "2", "", "9").check(), "a cube takes none of them");
        assertEquals(List.of(), new NewModel(BuiltInModels.Shape.torus, " ", "", "").check(), "blank is the default");
    }

    @Test
    void aNewModelIsWhatGenerateWrites() throws Exception {
        String[][] cases = {
            {"torus", "7", "5", "", ".obj"},
            {"icosphere", "", "", "1", ".off"},
            {"figure3", "", "", "", ".off"},
        };
        for (String[] c : cases) {
            NewModel model = new NewModel(BuiltInModels.Shape.valueOf(c[0]), c[1], c[2], c[3]);
            Path cliFile = dir.resolve("cli-" + c[0] + c[4]);
            Run run = c[0].equals("torus") ? cli("generate", c[0], "--around", c[1], "--across", c[2], "-o", cliFile.toString())
                    : c[0].equals("icosphere") ? cli("generate", c[0], "--subdivisions", c[3], "-o", cliFile.toString())
                    : cli("generate", c[0], "-o", cliFile.toString());
            assertEquals(0, run.code(), run.err());
            Path file = dir.resolve("window-" + c[0] + c[4]);
            NewModel.Made made = model.write(file, Progress.NONE);
            assertArrayEquals(Files.readAllBytes(cliFile), Files.readAllBytes(file), c[0]);
            assertEquals("wrote " + cliFile + ": " + made.vertices() + " vertices, " + made.faces() + " faces", run.out().strip());
        }
        assertEquals("torus-7x5.off", new NewModel(BuiltInModels.Shape.torus, "7", "5", "").fileName());
        assertEquals("icosphere-3.off", new NewModel(BuiltInModels.Shape.icosphere, "", "", "").fileName());
        JobFailure refused = assertThrows(JobFailure.class,
                () -> new NewModel(BuiltInModels.Shape.icosphere, "", "", "9").write(dir.resolve("fine.off"), Progress.NONE));
        assertEquals("subdivisions", refused.problem().field());
        assertFalse(Files.exists(dir.resolve("fine.off")));
    }

    /** A folder or a pipe is refused at the model's field with the command line's own line, and a pipe never hangs the reading. */
    @Test
    void aFolderOrAPipeIsRefusedAsTheCommandLineRefusesIt() throws Exception {
        JobFailure folder = assertThrows(JobFailure.class, () -> ModelFile.load(dir, ifold.mesh.MeshBuilder.Options.REPAIR, Progress.NONE));
        assertEquals("model", folder.problem().field());
        assertEquals("ifold: " + folder.problem().message(), cli("info", dir.toString()).err().strip());
        Path pipe = dir.resolve("pipe.off");
        org.junit.jupiter.api.Assumptions.assumeTrue(new ProcessBuilder("mkfifo", pipe.toString()).start().waitFor() == 0, "no mkfifo here");
        JobFailure refused = org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(10),
                () -> assertThrows(JobFailure.class, () -> ModelFile.load(pipe, ifold.mesh.MeshBuilder.Options.REPAIR, Progress.NONE)));
        assertEquals("ifold: " + refused.problem().message(), cli("info", pipe.toString()).err().strip());
        assertTrue(refused.problem().message().contains("not a regular file"), refused.problem().message());
    }
}
