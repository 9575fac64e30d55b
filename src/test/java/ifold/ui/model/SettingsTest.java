package ifold.ui.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Settings kept in the file given, read back the next run; a bad file is no file, and said to be. */
class SettingsTest {
    @TempDir
    Path dir;

    @Test
    void settingsAndRecentFilesComeBack() throws Exception {
        Path file = dir.resolve("sub").resolve("settings.properties");
        Settings settings = new Settings(file);
        assertEquals("none", settings.get("zigzag.width", "none"), "setup: a first run remembers nothing");
        settings.put("zigzag.width", "1.2");
        settings.putInt("window.width", 900);
        for (int i = 0; i < Settings.RECENT + 2; i++) {
            settings.addRecent(dir.resolve("m" + i + ".off"));
        }
        settings.addRecent(dir.resolve("m3.off"));
        settings.save();
        Settings again = new Settings(file);
        assertEquals("1.2", again.get("zigzag.width", ""));
        assertEquals(900, again.getInt("window.width", 0));
        List<Path> recent = again.recent();
        assertEquals(Settings.RECENT, recent.size());
        assertEquals(dir.resolve("m3.off"), recent.get(0), "the latest first, once");
        assertEquals(dir.resolve("m9.off"), recent.get(1));
        assertEquals(1, recent.stream().filter(p -> p.endsWith("m3.off")).count());
    }

    @Test
    void anUnreadableFileIsAFreshStart() throws Exception {
        Path file = dir.resolve("settings.properties");
        Files.write(file, new byte[] {'a', '=', '\\', 'u', 'z', 'z'}); // a broken escape
        Settings settings = new Settings(file);
        assertEquals("x", settings.get("a", "x"));
        assertEquals(7, settings.getInt("missing", 7));
        // Reset, and said: the window's caller prints it once.
        String problem = settings.problem().orElseThrow(() -> new AssertionError("a corrupt file is said to be corrupt"));
        assertTrue(problem.contains(file + " is corrupt") && problem.contains("writes it anew"), problem);
        Files.write(file, new byte[] {'a', '=', '1', 0, 0, 7});
        assertTrue(new Settings(file).problem().orElse("").contains("is corrupt (binary content)"));
        assertTrue(new Settings(dir.resolve("none.properties")).problem().isEmpty(), "no file is a first run, not a problem");
        settings.save();
        assertTrue(new Settings(file).problem().isEmpty(), "written anew, it reads");
    }

    /** A FIFO in the settings' place would block the window's start for ever: it is not read, nor replaced. */
    @Test
    void aFifoIsNotReadNorReplaced() throws Exception {
        Path fifo = dir.resolve("settings.properties");
        Process mkfifo = new ProcessBuilder("mkfifo", fifo.toString()).inheritIO().start();
        assertEquals(0, mkfifo.waitFor(), "setup: mkfifo");
        assertTrue(Files.exists(fifo) && !Files.isRegularFile(fifo), "setup: a FIFO");
        Settings settings = assertTimeoutPreemptively(Duration.ofSeconds(10), () -> new Settings(fifo), "read without waiting on the FIFO");
        assertTrue(settings.problem().orElse("").contains(fifo + " is not a regular file"), settings.problem().toString());
        settings.put("zigzag.width", "1.2");
        settings.save();
        assertTrue(Files.exists(fifo) && !Files.isRegularFile(fifo), "the FIFO left as it is");
        Path folder = Files.createDirectory(dir.resolve("folder.properties"));
        assertTrue(new Settings(folder).problem().orElse("").contains("not a regular file"));
    }

    /** The file's folder: XDG_CONFIG_HOME, then HOME (which Java's user.home does not follow), then user.home. */
    @Test
    void theDefaultFileFollowsXdgConfigHomeThenHome() {
        String account = "/home/account";
        Path tail = Path.of("ifold", "settings.properties");
        assertEquals(Path.of("/xdg").resolve(tail), Settings.defaultFile(env(Map.of("XDG_CONFIG_HOME", "/xdg", "HOME", "/elsewhere")), account));
        assertEquals(Path.of("/elsewhere/.config").resolve(tail), Settings.defaultFile(env(Map.of("HOME", "/elsewhere")), account));
        assertEquals(Path.of("/elsewhere/.config").resolve(tail),
                Settings.defaultFile(env(Map.of("XDG_CONFIG_HOME", "relative", "HOME", "/elsewhere")), account),
                "a relative XDG_CONFIG_HOME is ignored, as the specification says");
        assertEquals(Path.of("/home/account/.config").resolve(tail), Settings.defaultFile(env(Map.of()), account));
        assertEquals(Path.of("/home/account/.config").resolve(tail), Settings.defaultFile(env(Map.of("HOME", "")), account));
    }

    private static Function<String, String> env(Map<String, String> variables) {
        return variables::get;
    }
}
