package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code ifold} alone and {@code ifold app} where there is no display: a usage error saying
 * how to open the window and list the commands, and one line saying the window needs a
 * display; neither waits for a window.
 */
class AppCommandTest {
    private static final Path LAUNCHER = Path.of("build", "install", "ifold", "bin", "ifold");

    @TempDir
    Path dir;

    private record Ended(int code, String output) {
    }

    private Ended runWithoutDisplay(String... args) throws Exception {
        assertTrue(Files.isExecutable(LAUNCHER), "setup: the launcher is installed (gradle installDist)");
        String[] command = new String[args.length + 1];
        command[0] = LAUNCHER.toString();
        System.arraycopy(args, 0, command, 1, args.length);
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(dir.resolve("log").toFile());
        builder.environment().remove("DISPLAY");
        builder.environment().remove("IFOLD_IN_XVFB");
        Process process = builder.start();
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new AssertionError("still running after 60 s: " + Files.readString(dir.resolve("log")));
        }
        return new Ended(process.exitValue(), Files.readString(dir.resolve("log")));
    }

    @Test
    void ifoldAloneWithoutADisplaySaysHowToOpenTheWindowAndListTheCommands() throws Exception {
        Ended ended = runWithoutDisplay();
        assertEquals(2, ended.code(), ended.output());
        assertEquals("ifold: missing command: 'ifold' alone opens the window, and there is no display here (where there is one:"
                + " 'ifold', or 'ifold app FILE'); 'ifold --help' lists the commands", ended.output().strip(), "one line");
    }

    @Test
    void theAppWithoutADisplaySaysSoInOneLine() throws Exception {
        Ended ended = runWithoutDisplay("app", "models/cube.off", "--settings", dir.resolve("s.properties").toString());
        assertEquals(1, ended.code(), ended.output());
        assertEquals("ifold: no display: the window needs one (the command line works without: try 'ifold --help')", ended.output().strip());
        assertTrue(!Files.exists(dir.resolve("s.properties")), "no settings written by a window that never opened");
        Ended missing = runWithoutDisplay("app", dir.resolve("none.off").toString());
        assertEquals(1, missing.code(), "a file that cannot be read exits 1, as for every command: " + missing.output());
        assertTrue(missing.output().contains("none.off: no such file"), missing.output());
        Ended folder = runWithoutDisplay("app", dir.toString());
        assertEquals(1, folder.code(), folder.output());
        assertTrue(folder.output().contains("is a folder"), folder.output());
    }
}
