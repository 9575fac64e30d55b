package ifold.ui.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Settings kept in the file given, read back the next run; a bad file is no file. */
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
    }
}
