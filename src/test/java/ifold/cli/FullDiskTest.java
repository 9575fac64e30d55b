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
        disk = Files.createDirectory(dir.resolve("disk"));
        Process mount = new ProcessBuilder("mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", disk.toString())
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
}
