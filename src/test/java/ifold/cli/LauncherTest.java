package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The installed launcher without a display: it starts a virtual display of its own and becomes
 * iFold (exec). SIGINT or SIGTERM, on it or on its process group, stops iFold, which takes back
 * what it had begun, says so in one line, and leaves its display to end; SIGKILL on it, the
 * display ends too. Launchers run at once each get a display of their own.
 */
class LauncherTest {
    private static final Path LAUNCHER = Path.of("build", "install", "ifold", "bin", "ifold");

    @TempDir
    Path dir;

    private static boolean hasXvfb() throws Exception {
        return new ProcessBuilder("sh", "-c", "command -v Xvfb").start().waitFor() == 0;
    }

    /** The installed launcher run with {@code args} and no display, its output into the log. */
    private Process launch(String... args) throws Exception {
        List<String> command = new java.util.ArrayList<>(List.of(LAUNCHER.toString()));
        command.addAll(List.of(args));
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(dir.resolve("log").toFile());
        builder.environment().remove("DISPLAY");
        builder.environment().remove("IFOLD_IN_XVFB");
        return builder.start();
    }

    /** Starts a long headless export, and waits for its first frames; returns the launcher and everything it started. */
    private Process start(Path frames) throws Exception {
        Process launcher = launch("demo", "zigzag", "--frames", frames.toString(), "--size", "1280x720", "--fps", "30", "--seconds", "300");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            if (Files.isDirectory(frames)) {
                try (var files = Files.list(frames)) {
                    if (files.count() > 20) {
                        return launcher;
                    }
                }
            }
            Thread.sleep(100);
        }
        launcher.destroyForcibly();
        throw new AssertionError("no frames after 60 s: " + Files.readString(dir.resolve("log")));
    }

    private static void assertAllGone(List<ProcessHandle> started) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (System.nanoTime() < deadline && started.stream().anyMatch(ProcessHandle::isAlive)) {
            Thread.sleep(100);
        }
        for (ProcessHandle process : started) {
            assertFalse(process.isAlive() && !process.info().command().orElse("").isEmpty(),
                    "still running: " + process.pid() + " " + process.info().commandLine().orElse(""));
        }
    }

    @Test
    void sigtermStopsIfoldAndItsDisplayAndLeavesNoTemporaryFiles() throws Exception {
        assumeTrue(Files.isExecutable(LAUNCHER) && hasXvfb(), "no installed launcher or no Xvfb");
        Path frames = dir.resolve("frames");
        Process launcher = start(frames);
        List<ProcessHandle> started = launcher.descendants().toList();
        assertTrue(started.stream().anyMatch(p -> p.info().command().orElse("").contains("Xvfb")), "its own display");
        assertTrue(launcher.info().command().orElse("").contains("java"), "the launcher became iFold (exec)");
        launcher.destroy(); // SIGTERM
        assertTrue(launcher.waitFor(30, TimeUnit.SECONDS), "the launcher stops");
        assertEquals(143, launcher.exitValue());
        assertAllGone(started);
        try (var files = Files.list(frames)) {
            assertEquals(0, files.filter(p -> p.getFileName().toString().endsWith(".tmp")).count(), "no temporary frames");
        }
        assertFalse(Files.exists(frames.resolve(".ifold-frames.lock")), "the folder's lock goes with the export");
        try (var files = Files.list(frames)) {
            assertTrue(files.count() < 9000, "it stopped before the end");
        }
    }

    @Test
    void aMovieStoppedAsItBeginsLeavesNoFile() throws Exception {
        // SIGTERM just after the movie's temporary file is made, before ffmpeg has had a frame:
        // ffmpeg, left alone, would write its file again after iFold deleted it.
        assumeTrue(Files.isExecutable(LAUNCHER) && hasXvfb(), "no installed launcher or no Xvfb");
        assumeTrue(new ProcessBuilder("sh", "-c", "command -v ffmpeg").start().waitFor() == 0, "no ffmpeg");
        Path out = Files.createDirectory(dir.resolve("out"));
        Process launcher = launch("demo", "zigzag", "--movie", out.resolve("m.mp4").toString(), "--size", "320x180");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        boolean begun = false;
        while (!begun && System.nanoTime() < deadline && launcher.isAlive()) {
            try (var files = Files.list(out)) {
                begun = files.anyMatch(p -> p.getFileName().toString().endsWith(".tmp"));
            }
            Thread.sleep(begun ? 0 : 5);
        }
        List<ProcessHandle> started = launcher.descendants().toList();
        launcher.destroy(); // SIGTERM
        assertTrue(begun, "the movie was begun: " + Files.readString(dir.resolve("log")));
        assertTrue(launcher.waitFor(30, TimeUnit.SECONDS), "the launcher stops");
        assertAllGone(started);
        Thread.sleep(500); // time for a surviving writer to write
        try (var files = Files.list(out)) {
            assertEquals(List.of(), files.map(p -> p.getFileName().toString()).toList(), "no movie, whole or in part");
        }
    }

    /**
     * SIGTERM once the frames' folder is made, before its first frame: the folder iFold made
     * goes too (an interrupted export left it, empty).
     */
    @Test
    void framesStoppedAsTheyBeginLeaveNoFolder() throws Exception {
        assumeTrue(Files.isExecutable(LAUNCHER) && hasXvfb(), "no installed launcher or no Xvfb");
        Path frames = dir.resolve("fr");
        Process launcher = launch("demo", "zigzag", "--frames", frames.toString(), "--size", "320x180");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!Files.isDirectory(frames) && System.nanoTime() < deadline && launcher.isAlive()) {
            Thread.sleep(2);
        }
        List<ProcessHandle> started = launcher.descendants().toList();
        launcher.destroy(); // SIGTERM
        assertTrue(launcher.waitFor(30, TimeUnit.SECONDS), "the launcher stops");
        assertAllGone(started);
        String log = Files.readString(dir.resolve("log"));
        assertTrue(log.contains("ifold: interrupted: "), log);
        if (log.contains("interrupted: nothing written")) {
            assertFalse(Files.exists(frames), "nothing written, and no folder: " + log);
        } else { // the first frames were quicker than the signal: they stay, whole, in their folder
            try (var files = Files.list(frames)) {
                assertTrue(files.allMatch(p -> p.getFileName().toString().matches("frame_\\d{5}\\.png")), log);
            }
        }
    }

    /**
     * Signals at moments picked at random (seeded: the same every run), to the launcher or its
     * process group, during headless movies, GIFs and frame exports of a wrap or the zig-zag:
     * each run ends with the signal's status (128 + its number) and one line saying what was
     * left, or, where the signal came after the end, exit 0 and the whole output; never a
     * trace, a temporary file, a lock or a process left running.
     */
    @Test
    void signalsAtRandomMomentsEndEveryRunCleanly() throws Exception {
        assumeTrue(Files.isExecutable(LAUNCHER) && hasXvfb(), "no installed launcher or no Xvfb");
        assumeTrue(new ProcessBuilder("sh", "-c", "command -v ffmpeg && command -v setsid").start().waitFor() == 0, "no ffmpeg or setsid");
        java.util.Random random = new java.util.Random(20261203);
        String[] signals = {"INT", "TERM", "HUP"};
        int[] codes = {130, 143, 129};
        int interrupted = 0;
        for (int k = 0; k < 6; k++) {
            Path out = Files.createDirectory(dir.resolve("run" + k));
            int kind = random.nextInt(3);
            List<String> command = new java.util.ArrayList<>(List.of("setsid", LAUNCHER.toString()));
            command.addAll(random.nextBoolean() ? List.of("demo", "zigzag") : List.of("wrap", "models/tetrahedron.off"));
            command.addAll(switch (kind) {
                case 0 -> List.of("--movie", out.resolve("m.mp4").toString());
                case 1 -> List.of("--movie", out.resolve("m.gif").toString());
                default -> List.of("--frames", out.resolve("frames").toString());
            });
            command.addAll(List.of("--size", "640x360", "--seconds", "60", "--fps", "10"));
            ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(dir.resolve("log").toFile());
            builder.environment().remove("DISPLAY");
            builder.environment().remove("IFOLD_IN_XVFB");
            Process launcher = builder.start();
            Thread.sleep(200 + random.nextInt(3500));
            List<ProcessHandle> started = launcher.descendants().toList();
            int which = random.nextInt(3);
            boolean group = random.nextBoolean();
            String what = "run " + k + ": " + String.join(" ", command.subList(2, command.size())) + ", SIG" + signals[which]
                    + (group ? " to the group" : " to the launcher");
            if (launcher.isAlive()) {
                new ProcessBuilder("kill", "-" + signals[which], "--", (group ? "-" : "") + launcher.pid()).start().waitFor();
            }
            assertTrue(launcher.waitFor(30, TimeUnit.SECONDS), what + ": it stops");
            assertAllGone(started);
            String log = Files.readString(dir.resolve("log"));
            assertFalse(log.contains("\tat ") || log.contains("Exception") || log.contains("FATAL"), what + ": " + log);
            if (launcher.exitValue() == 0) {
                assertTrue(log.contains("wrote "), what + ": finished first: " + log);
            } else {
                interrupted++;
                assertEquals(codes[which], launcher.exitValue(), what + ": " + log);
                List<String> said = said();
                // A signal that lands while the JVM is still starting (seconds, on a loaded
                // machine) ends it before the program has anything to say, or to leave behind.
                assertTrue(said.isEmpty() || said.get(said.size() - 1).startsWith("ifold: interrupted: "), what + ": " + said);
            }
            try (var files = Files.walk(out)) {
                List<String> left = files.map(p -> p.getFileName().toString())
                        .filter(name -> name.endsWith(".tmp") || name.startsWith(".") || name.contains(".ifold")).toList();
                assertEquals(List.of(), left, what + ": temporary files or locks left");
            }
        }
        assertTrue(interrupted >= 2, "most runs were stopped by their signal: " + interrupted + " of 6");
    }

    /** The lines of the log but the progress bar's. */
    private List<String> said() throws Exception {
        return Files.readAllLines(dir.resolve("log")).stream().filter(line -> !line.startsWith("[")).toList();
    }

    /** Starts a movie of the cube's wrap in a session of its own (its process group is its pid), and waits for ffmpeg to write. */
    private Process startMovie(Path out) throws Exception {
        ProcessBuilder builder = new ProcessBuilder("setsid", LAUNCHER.toString(), "wrap", "models/cube.off", "--movie",
                out.resolve("z.mp4").toString(), "--size", "320x180").redirectErrorStream(true).redirectOutput(dir.resolve("log").toFile());
        builder.environment().remove("DISPLAY");
        builder.environment().remove("IFOLD_IN_XVFB");
        Process launcher = builder.start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline && launcher.isAlive()) {
            try (var files = Files.walk(out)) {
                if (files.anyMatch(p -> p.getFileName().toString().equals("z.mp4") && p.toFile().length() > 0)) {
                    return launcher;
                }
            }
            Thread.sleep(100);
        }
        launcher.destroyForcibly();
        throw new AssertionError("ffmpeg wrote nothing in 60 s: " + Files.readString(dir.resolve("log")));
    }

    private static void signal(String signal, String target) throws Exception {
        assertEquals(0, new ProcessBuilder("kill", "-" + signal, "--", target).inheritIO().start().waitFor());
    }

    /**
     * Ctrl-C as a terminal sends it: to the whole process group, ffmpeg included. Before, Xvfb
     * died of it first and the X libraries aborted iFold ("FATAL ERROR in native method ...",
     * a Java trace), leaving the movie's hidden folder and a defunct ffmpeg.
     */
    @ParameterizedTest
    @ValueSource(strings = {"INT", "TERM"})
    void aSignalToTheProcessGroupStopsEverythingAndSaysSoInOneLine(String signal) throws Exception {
        assumeTrue(Files.isExecutable(LAUNCHER) && hasXvfb(), "no installed launcher or no Xvfb");
        assumeTrue(new ProcessBuilder("sh", "-c", "command -v ffmpeg && command -v setsid").start().waitFor() == 0, "no ffmpeg or setsid");
        Path out = Files.createDirectory(dir.resolve("out"));
        Process launcher = startMovie(out);
        List<ProcessHandle> started = launcher.descendants().toList();
        assertTrue(started.stream().anyMatch(p -> p.info().command().orElse("").contains("ffmpeg")), "ffmpeg runs");
        signal(signal, "-" + launcher.pid());
        assertTrue(launcher.waitFor(30, TimeUnit.SECONDS), "iFold stops");
        assertEquals(signal.equals("INT") ? 130 : 143, launcher.exitValue(), Files.readString(dir.resolve("log")));
        assertAllGone(started);
        List<String> said = said();
        assertEquals("ifold: interrupted: nothing written", said.get(said.size() - 1), "the last line: " + said);
        assertEquals(2, said.size(), "the summary and that line alone: " + said);
        try (var files = Files.list(out)) {
            assertEquals(List.of(), files.map(p -> p.getFileName().toString()).toList(), "no movie, whole or in part");
        }
    }

    /**
     * SIGINT on the launcher alone: before, the JVM ran as a job in the background of the
     * launcher's shell, which starts such jobs with SIGINT ignored, and ran to the end.
     */
    @Test
    void sigintOnTheLauncherAloneStopsIfold() throws Exception {
        assumeTrue(Files.isExecutable(LAUNCHER) && hasXvfb(), "no installed launcher or no Xvfb");
        assumeTrue(new ProcessBuilder("sh", "-c", "command -v ffmpeg && command -v setsid").start().waitFor() == 0, "no ffmpeg or setsid");
        Path out = Files.createDirectory(dir.resolve("out"));
        Process launcher = startMovie(out);
        List<ProcessHandle> started = launcher.descendants().toList();
        signal("INT", Long.toString(launcher.pid()));
        assertTrue(launcher.waitFor(15, TimeUnit.SECONDS), "iFold stops, not at the end of its movie");
        assertEquals(130, launcher.exitValue(), Files.readString(dir.resolve("log")));
        assertAllGone(started);
        try (var files = Files.list(out)) {
            assertEquals(List.of(), files.map(p -> p.getFileName().toString()).toList(), "no movie, whole or in part");
        }
    }

    /**
     * Six launchers at once, each its own display. Before, each looked for a free number and
     * took :99 while another's Xvfb was still starting there: some lost their display ("Can't
     * connect to X11 window server using ':99'") or aborted (exit 134), leaving their lock.
     */
    @Test
    void launchersRunAtOnceEachHaveADisplayOfTheirOwn() throws Exception {
        assumeTrue(Files.isExecutable(LAUNCHER) && hasXvfb(), "no installed launcher or no Xvfb");
        List<Process> launchers = new java.util.ArrayList<>();
        for (int k = 0; k < 6; k++) {
            Path frames = dir.resolve("frames" + k);
            ProcessBuilder builder = new ProcessBuilder(LAUNCHER.toString(), "view", "models/tetrahedron.off", "--frames", frames.toString(),
                    "--seconds", "1", "--fps", "5", "--size", "64x48").redirectErrorStream(true).redirectOutput(dir.resolve("log" + k).toFile());
            builder.environment().remove("DISPLAY");
            builder.environment().remove("IFOLD_IN_XVFB");
            launchers.add(builder.start());
        }
        for (int k = 0; k < launchers.size(); k++) {
            assertTrue(launchers.get(k).waitFor(120, TimeUnit.SECONDS), "launcher " + k + " ends");
            assertEquals(0, launchers.get(k).exitValue(), Files.readString(dir.resolve("log" + k)));
            try (var files = Files.list(dir.resolve("frames" + k))) {
                assertEquals(5, files.count(), "five frames and no lock: " + Files.readString(dir.resolve("log" + k)));
            }
        }
    }

    @Test
    void sigkillOnTheLauncherStopsIfoldToo() throws Exception {
        assumeTrue(Files.isExecutable(LAUNCHER) && hasXvfb(), "no installed launcher or no Xvfb");
        Path frames = dir.resolve("frames");
        Process launcher = start(frames);
        List<ProcessHandle> started = launcher.descendants().toList();
        // SIGKILL: the launcher is iFold (exec), killed outright; its display, in a session of its
        // own, ends with its last client, or by its watcher. The whole frames stay, and the next
        // export into the folder sweeps the temporary ones and the lock.
        launcher.destroyForcibly();
        launcher.waitFor(10, TimeUnit.SECONDS);
        assertAllGone(started);
    }

    /** What the launcher at {@code launcher} prints for {@code ifold info models/cube.off --json}: stdout, then stderr. */
    private String info(Path launcher, boolean noArchive) throws Exception {
        ProcessBuilder builder = new ProcessBuilder(launcher.toString(), "info", Path.of("models", "cube.off").toAbsolutePath().toString(),
                "--json").redirectOutput(dir.resolve("out").toFile()).redirectError(dir.resolve("err").toFile());
        if (noArchive) {
            builder.environment().put("IFOLD_NO_CDS", "1");
        } else {
            builder.environment().remove("IFOLD_NO_CDS");
        }
        Process process = builder.start();
        assertTrue(process.waitFor(60, TimeUnit.SECONDS), "ended");
        assertEquals(0, process.exitValue());
        return Files.readString(dir.resolve("out")) + "\n--- stderr ---\n" + Files.readString(dir.resolve("err"));
    }

    /** Output that cannot be written is a failure in one line: '> /dev/full' exited 0 with the summary lost. */
    @Test
    void aStandardOutputThatCannotBeWrittenFailsInOneLine() throws Exception {
        assumeTrue(Files.isWritable(Path.of("/dev/full")), "no /dev/full here");
        ProcessBuilder builder = new ProcessBuilder(LAUNCHER.toString(), "info", "models/cube.off")
                .redirectOutput(new java.io.File("/dev/full")).redirectError(dir.resolve("err").toFile());
        assertEquals(UserError.EXIT_CODE, builder.start().waitFor());
        assertEquals("ifold: cannot write to the standard output (a full disk, or a pipe closed): its lines are lost\n",
                Files.readString(dir.resolve("err")));
    }

    /**
     * The class-data-sharing archive installDist makes is used where it fits and quietly
     * ignored where it does not (another install directory, a jar changed): the output is the
     * same byte for byte, with nothing on stderr.
     */
    @Test
    void theStartUpArchiveNeverShowsInTheOutput() throws Exception {
        Path archive = LAUNCHER.getParent().getParent().resolve("lib").resolve("ifold.jsa");
        assumeTrue(Files.isRegularFile(archive), "installDist made no class-data-sharing archive here");
        String without = info(LAUNCHER, true);
        assertTrue(without.endsWith("--- stderr ---\n"), without);
        assertEquals(without, info(LAUNCHER, false));
        // A copy elsewhere, one of its jars touched: the archive is stale twice over.
        Path copy = dir.resolve("install");
        try (var files = Files.walk(LAUNCHER.getParent().getParent())) {
            for (Path from : (Iterable<Path>) files::iterator) {
                Path to = copy.resolve(LAUNCHER.getParent().getParent().relativize(from).toString());
                if (Files.isDirectory(from)) {
                    Files.createDirectories(to);
                } else {
                    Files.copy(from, to, java.nio.file.StandardCopyOption.COPY_ATTRIBUTES);
                }
            }
        }
        Path jar;
        try (var jars = Files.list(copy.resolve("lib"))) {
            jar = jars.filter(p -> p.getFileName().toString().startsWith("picocli")).findFirst().orElseThrow();
        }
        Files.setLastModifiedTime(jar, java.nio.file.attribute.FileTime.fromMillis(System.currentTimeMillis()));
        assertEquals(without, info(copy.resolve("bin").resolve("ifold"), false));
    }
}
