package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.mesh.Solids;
import ifold.mesh.io.MeshWriters;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code ifold view}: option checks (no display needed) and frame export (under Xvfb). */
class ViewCommandTest {
    @TempDir
    Path dir;

    private Path model() throws Exception {
        Path file = dir.resolve("ico.off");
        MeshWriters.write(Solids.icosahedron(), file);
        return file;
    }

    /** An option's value refused: what the user typed, exit 2. */
    private static void assertRefused(CliTest.Run run, String fragment) {
        assertEquals(UserError.USAGE_EXIT_CODE, run.code(), run.err());
        assertEquals(1, run.err().strip().split("\n").length, run.err());
        assertTrue(run.err().contains(fragment), fragment + " in " + run.err());
    }

    @Test
    void badFrameOptionsAreRefusedBeforeAnyWork() throws Exception {
        String model = model().toString();
        String frames = dir.resolve("frames").toString();
        assertRefused(CliTest.run("view", model, "--frames", frames, "--size", "big"), "option --size");
        assertRefused(CliTest.run("view", model, "--frames", frames, "--size", "8x8"), "option --size");
        assertRefused(CliTest.run("view", model, "--frames", frames, "--fps", "0"), "option --fps");
        assertRefused(CliTest.run("view", model, "--path", "--colors", "purple", "--frames", frames), "option --colors");
        assertRefused(CliTest.run("view", model, "--frames", frames, "--seconds", "-1"), "option --seconds");
        assertRefused(CliTest.run("view", model, "--frames", dir.resolve("no/such/folder").toString()), "does not exist");
        Path file = Files.writeString(dir.resolve("a-file"), "x");
        assertRefused(CliTest.run("view", model, "--frames", file.toString()), "is a file");
        assertFalse(Files.exists(dir.resolve("frames")), "no folder made for a refused run");
        assertEquals(2, CliTest.run("view", model, "--fps", "many").code());
    }

    @Test
    void aRunThatFailsOnItsInputMakesNoFramesFolder() throws Exception {
        Path frames = dir.resolve("frames");
        Path empty = Files.writeString(dir.resolve("empty.off"), "");
        Path badScript = Files.writeString(dir.resolve("bad.fold"), "paper square 1\nfold sideways\n");
        List<List<String>> runs = List.of(
                List.of("view", dir.resolve("nothere.off").toString()),
                List.of("view", empty.toString()),
                List.of("view", "--path", empty.toString()),
                List.of("fold", dir.resolve("nothere.fold").toString()),
                List.of("fold", badScript.toString()),
                List.of("wrap", empty.toString()),
                List.of("demo", "zigzag", "--triangle", "0,0,1,0,2,0"));
        for (List<String> command : runs) {
            List<String> args = new java.util.ArrayList<>(command);
            args.addAll(List.of("--frames", frames.toString()));
            CliTest.Run run = CliTest.run(args.toArray(String[]::new));
            assertTrue(run.code() == 1 || run.code() == 2, command + ": " + run.code() + " " + run.err());
            assertFalse(Files.exists(frames), command + " made the folder it never wrote into");
        }
    }

    @Test
    void framesAreWrittenWholeAndNumbered() throws Exception {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty(), "no X display (run the tests under xvfb-run)");
        Path frames = dir.resolve("frames");
        Files.createDirectory(frames);
        Files.writeString(frames.resolve("frame_00099.png"), "stale"); // left by a longer export
        CliTest.Run run = CliTest.run("view", model().toString(), "--path", "--frames", frames.toString(),
                "--size", "96x64", "--fps", "4", "--seconds", "1.5");
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("wrote 6 frames of 96x64"), run.out());
        try (Stream<Path> files = Files.list(frames)) {
            assertEquals(6, files.count(), "six whole frames, no stale or partial files");
        }
        for (int i = 0; i < 6; i++) {
            byte[] png = Files.readAllBytes(frames.resolve(String.format("frame_%05d.png", i)));
            assertEquals((byte) 0x89, png[0]);
            assertEquals('P', png[1]);
        }
        assertTrue(run.err().contains("6/6 frames"), "progress bar: " + run.err());
    }
}
