package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** On a full file system (a 1 MB tmpfs, where the test may mount one): a failed export takes back what it wrote and names the file. */
class FullDiskTest {
    @TempDir
    Path dir;

    private Path disk;

    private boolean mount() throws Exception {
        return mount("1m");
    }

    private boolean mount(String size) throws Exception {
        disk = Files.createDirectory(dir.resolve("disk"));
        Process mount = new ProcessBuilder("mount", "-t", "tmpfs", "-o", "size=" + size, "tmpfs", disk.toString())
                .redirectErrorStream(true).start();
        mount.getInputStream().readAllBytes();
        return mount.waitFor() == 0;
    }

    @AfterEach
    void unmount() throws Exception {
        if (disk != null) {
            new ProcessBuilder("umount", disk.toString()).redirectErrorStream(true).start().waitFor();
        }
    }

    @Test
    void aFailedExportTakesBackWhatItWroteAndNamesTheFile() throws Exception {
        assumeTrue(mount(), "cannot mount a small tmpfs here (not root, or no tmpfs)");
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty(), "no X display");
        Path frames = Files.createDirectory(disk.resolve("frames"));
        CliTest.Run view = CliTest.run("view", "models/torus.off", "--frames", frames.toString(), "--fps", "30", "--seconds", "2");
        assertEquals(1, view.code(), view.err());
        assertTrue(view.err().contains(frames.toString()) && view.err().contains("No space left on device"), view.err());
        try (var files = Files.list(frames)) {
            assertEquals(0, files.count(), "the frames it wrote are taken back");
        }
        Path big = disk.resolve("torus.off");
        CliTest.Run generate = CliTest.run("generate", "torus", "--around", "300", "--across", "300", "-o", big.toString());
        assertEquals(1, generate.code(), generate.err());
        assertTrue(generate.err().contains(big.toString()) && !generate.err().contains(".tmp"), "names the file asked for: " + generate.err());
        assertFalse(Files.exists(big));
        try (var files = Files.list(disk)) {
            assertEquals(1, files.count(), "nothing but the frames folder: no temporary file");
        }
    }

    @Test
    void aMovieCutShortByAFullDiskIsRefusedAndLeavesNothing() throws Exception {
        // 200 KiB: ffmpeg fills it, then exits 0 (ffmpeg 5.1) with a file no player opens, or
        // (depending on when the disk fills) exits 1 saying so: refused alike.
        assumeTrue(mount("200k"), "cannot mount a small tmpfs here (not root, or no tmpfs)");
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty(), "no X display");
        assumeTrue(ifold.image.Mp4Writer.available(), "no ffmpeg");
        Path movie = disk.resolve("m.mp4");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--movie", movie.toString(), "--size", "640x360", "--no-view");
        // The progress bar's line aside (one at the end, where stderr is no terminal).
        java.util.List<String> said = run.err().lines().filter(line -> !line.startsWith("[")).toList();
        assertEquals(1, run.code(), run.err());
        assertEquals(1, said.size(), "one line: " + run.err());
        assertTrue(said.get(0).startsWith("ifold: ") && said.get(0).contains(movie.toString()) && said.get(0).contains("incomplete"),
                said.get(0));
        assertFalse(run.err().contains(".tmp"), "names the movie, not its temporary file: " + run.err());
        assertFalse(run.out().contains("wrote"), run.out());
        try (var files = Files.list(disk)) {
            assertEquals(java.util.List.of(), files.toList(), "no movie, whole or in part, and no temporary folder");
        }
    }
}
