package ifold.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.image.FrameWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Temporary files a killed run left are swept by the next run that writes there; a running run's own stay. */
class AtomicFileTest {
    @TempDir
    Path dir;

    private Path stale(String name) throws Exception {
        Path file = Files.writeString(dir.resolve(name), "half");
        Files.setLastModifiedTime(file, FileTime.from(Instant.now().minusSeconds(3600)));
        return file;
    }

    /** What an interrupted run says it left is what is there: a file written and deleted since is not named. */
    @Test
    void theFilesWrittenAreThoseStillThere() throws Exception {
        Path kept = dir.resolve("kept.txt");
        Path taken = dir.resolve("taken.txt");
        AtomicFile.write(kept, out -> out.write(1), true);
        AtomicFile.write(taken, out -> out.write(2), true);
        assertTrue(AtomicFile.written().containsAll(List.of(kept, taken)), "setup: both written");
        Files.delete(taken);
        assertTrue(AtomicFile.written().contains(kept));
        assertFalse(AtomicFile.written().contains(taken), "taken back: no file left");
    }

    @Test
    void staleTemporaryFilesOfTheSameNameAreSwept() throws Exception {
        Path old = stale(".out.off.47e1c33894c13d2a.tmp");
        Path other = stale(".other.off.47e1c33894c13d2a.tmp");
        Path notOurs = stale(".out.off.notours.tmp");
        Path running = Files.writeString(dir.resolve(".out.off.00ff.tmp"), "a run writing now");
        AtomicFile.write(dir.resolve("out.off"), out -> out.write(1), false);
        assertFalse(Files.exists(old), "a killed run's temporary file is gone");
        assertTrue(Files.exists(running), "one younger than this run is another run's, writing now");
        assertTrue(Files.exists(other), "another file's is left for its own next writer");
        assertTrue(Files.exists(notOurs), "a name not of our making is left alone");
        assertEquals(1, Files.size(dir.resolve("out.off")));
    }

    /** A device or a pipe, or a link to one, is not replaced by a plain file: the window writes here without the command line's checks. */
    @Test
    void aDeviceOrAPipeIsRefusedAndLeftAsItWas() throws Exception {
        Path device = Files.createSymbolicLink(dir.resolve("null.pdf"), Path.of("/dev/null"));
        java.io.IOException refused = assertThrows(java.io.IOException.class, () -> AtomicFile.write(device, out -> out.write(1), true));
        assertTrue(refused.getMessage().contains("not a regular file"), refused.getMessage());
        assertTrue(Files.isSymbolicLink(device));
        assertFalse(Files.isRegularFile(Path.of("/dev/null")), "/dev/null is still a device");
        try (var left = Files.list(dir)) {
            assertEquals(List.of(device), left.toList(), "no temporary file left");
        }
    }

    /**
     * A file written through a symbolic link lands where the link points, and the link stays
     * (the rename put a plain file in the link's place, and the file it pointed to kept its old
     * content), as it does for a file written in steps and one another program writes; a link
     * to a file not there yet makes it, and links in a loop are refused naming the file.
     */
    @Test
    void aFileWrittenThroughALinkLandsWhereTheLinkPoints() throws Exception {
        Path models = Files.createDirectory(dir.resolve("models"));
        Path real = Files.writeString(models.resolve("cube.obj"), "old");
        Path link = Files.createSymbolicLink(dir.resolve("latest.obj"), Path.of("models/cube.obj"));
        Path chain = Files.createSymbolicLink(dir.resolve("chain.obj"), link.getFileName());
        AtomicFile.write(chain, out -> out.write("new".getBytes(java.nio.charset.StandardCharsets.UTF_8)), true);
        assertTrue(Files.isSymbolicLink(chain) && Files.isSymbolicLink(link), "both links stay links");
        assertEquals("new", Files.readString(real));
        try (AtomicFile.Pending pending = AtomicFile.begin(link)) {
            Files.writeString(pending.path(), "in steps");
            pending.commit();
        }
        assertTrue(Files.isSymbolicLink(link));
        assertEquals("in steps", Files.readString(real));
        try (AtomicFile.Pending pending = AtomicFile.beginForProgram(link)) {
            Files.writeString(pending.path(), "by a program");
            pending.commit();
        }
        assertTrue(Files.isSymbolicLink(link));
        assertEquals("by a program", Files.readString(real));
        assertEquals(List.of("cube.obj"), names(models), "no temporary file left beside the real one");

        Path dangling = Files.createSymbolicLink(dir.resolve("next.obj"), Path.of("models/next.obj"));
        AtomicFile.write(dangling, out -> out.write(7), false);
        assertTrue(Files.isSymbolicLink(dangling));
        assertEquals(1, Files.size(models.resolve("next.obj")));

        Path loop = Files.createSymbolicLink(dir.resolve("a.obj"), Path.of("b.obj"));
        Files.createSymbolicLink(dir.resolve("b.obj"), Path.of("a.obj"));
        java.io.IOException refused = assertThrows(java.io.IOException.class, () -> AtomicFile.write(loop, out -> out.write(1), false));
        assertTrue(refused.getMessage().contains("a.obj") && refused.getMessage().contains("symbolic links"), refused.getMessage());
    }

    private static List<String> names(Path folder) throws Exception {
        try (var files = Files.list(folder)) {
            return files.map(f -> f.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aFrameExportSweepsHalfWrittenFramesOfAKilledOne() throws Exception {
        Path frame = stale(".frame_00031.png.0a1b2c.tmp");
        Path whole = stale("frame_00031.png");
        new FrameWriter(dir).close(); // the sweep is the writer's first act
        assertFalse(Files.exists(frame));
        assertTrue(Files.exists(whole), "whole frames are the export's to replace, not the sweep's");
    }

    @Test
    void twoExportsCannotShareAFolderAndAFailedOneTakesBackItsFrames() throws Exception {
        Path frames = Files.createDirectory(dir.resolve("frames"));
        try (FrameWriter first = new FrameWriter(frames)) {
            java.io.IOException refused = org.junit.jupiter.api.Assertions.assertThrows(java.io.IOException.class,
                    () -> new FrameWriter(frames));
            assertTrue(refused.getMessage().contains("another export"), refused.getMessage());
            for (int i = 0; i < 3; i++) {
                first.write(i, 4, 4, new byte[48]);
            }
            // No finish: the export failed.
        }
        try (var files = Files.list(frames)) {
            assertEquals(0, files.count(), "its frames taken back, and its lock");
        }
        try (FrameWriter second = new FrameWriter(frames)) {
            second.write(0, 4, 4, new byte[48]);
            second.finish();
        }
        assertTrue(Files.exists(frames.resolve(FrameWriter.frameName(0))), "a finished export keeps its frames");
    }

    @Test
    void aPendingFileIsRenamedWhenWholeAndTakenBackOtherwise() throws Exception {
        Path movie = dir.resolve("m.gif");
        try (AtomicFile.Pending pending = AtomicFile.begin(movie)) {
            Files.writeString(pending.path(), "whole");
            pending.commit();
        }
        assertEquals("whole", Files.readString(movie));
        Path half = dir.resolve("half.gif");
        try (AtomicFile.Pending pending = AtomicFile.begin(half)) {
            Files.writeString(pending.path(), "half");
        }
        assertFalse(Files.exists(half));
        try (var files = Files.list(dir)) {
            assertEquals(1, files.count(), "only the whole movie: " + dir);
        }
    }

    @Test
    void aFileAnotherProgramWritesIsWrittenInAFolderOfItsOwn() throws Exception {
        Path movie = dir.resolve("m.mp4");
        try (AtomicFile.Pending pending = AtomicFile.beginForProgram(movie)) {
            assertEquals(dir, pending.path().getParent().getParent(), "in a folder beside the movie");
            assertTrue(pending.path().getParent().getFileName().toString().startsWith(".m.mp4."), "a hidden one");
            Files.writeString(pending.path(), "whole");
            pending.commit();
        }
        assertEquals("whole", Files.readString(movie));
        Path late = dir.resolve("late.mp4");
        Path written;
        try (AtomicFile.Pending pending = AtomicFile.beginForProgram(late)) {
            written = pending.path();
            Files.writeString(written, "half");
        }
        // A writer that outlives the export (ffmpeg, once iFold is stopped) cannot make the file again.
        assertThrows(java.nio.file.NoSuchFileException.class, () -> Files.writeString(written, "again"));
        try (var files = Files.list(dir)) {
            assertEquals(List.of("m.mp4"), files.map(p -> p.getFileName().toString()).toList(), "the whole movie alone");
        }
    }

    @Test
    void aSecondExportRefusedTheFolderLeavesTheFirstOnesLockToBeTakenBack() throws Exception {
        Path frames = Files.createDirectory(dir.resolve("held"));
        Path lock = frames.resolve(".ifold-frames.lock");
        FrameWriter first = new FrameWriter(frames);
        try {
            assertThrows(java.io.IOException.class, () -> new FrameWriter(frames).close(), "the folder is held");
            assertTrue(AtomicFile.deletedOnStop(lock), "a stop still takes the first export's lock back");
        } finally {
            first.close();
        }
        assertFalse(AtomicFile.deletedOnStop(lock));
        assertFalse(Files.exists(lock));
    }

    @Test
    void aFinishedExportRemovesTheFramesOfALongerOneAndAFailedOneLeavesThem() throws Exception {
        Path frames = Files.createDirectory(dir.resolve("frames"));
        for (int i = 0; i < 40; i++) {
            Files.writeString(frames.resolve(FrameWriter.frameName(i)), "old");
        }
        try (FrameWriter failed = new FrameWriter(frames)) {
            for (int i = 0; i < 5; i++) {
                failed.write(i, 4, 4, new byte[48]);
            }
            // No finish: it failed, and takes back only the frames it wrote.
        }
        for (int i = 5; i < 40; i++) {
            assertTrue(Files.exists(frames.resolve(FrameWriter.frameName(i))), "the earlier export's frame " + i + " stays");
        }
        try (FrameWriter shorter = new FrameWriter(frames)) {
            for (int i = 0; i < 10; i++) {
                shorter.write(i, 4, 4, new byte[48]);
            }
            shorter.finish();
        }
        try (var files = Files.list(frames)) {
            assertEquals(List.of(), files.map(p -> p.getFileName().toString())
                    .filter(name -> name.compareTo(FrameWriter.frameName(10)) >= 0).toList(), "only this export's ten frames");
        }
    }
}
