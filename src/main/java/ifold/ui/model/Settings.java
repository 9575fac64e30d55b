package ifold.ui.model;

import ifold.io.AtomicFile;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;

/**
 * What the window remembers between runs (the last folder, the window's size, the parameters,
 * the recent files), in a small properties file. The file is given, so that tests keep their
 * own and never touch the user's; {@link #defaultFile()} is the user's. A file that cannot be
 * read is as good as none: settings are a convenience, never a reason not to start.
 */
public final class Settings {
    /** The recent files the File menu lists. */
    public static final int RECENT = 8;

    private final Path file;
    private final Properties values = new Properties();

    public Settings(Path file) {
        this.file = file;
        try (InputStream in = Files.newInputStream(file)) {
            values.load(in);
        } catch (NoSuchFileException e) {
            // First run: nothing remembered yet.
        } catch (IOException | IllegalArgumentException e) {
            values.clear(); // unreadable: start afresh, and write a good one on leaving
        }
    }

    /** {@code $XDG_CONFIG_HOME/ifold/settings.properties}, or {@code ~/.config/ifold/settings.properties}. */
    public static Path defaultFile() {
        String config = System.getenv("XDG_CONFIG_HOME");
        Path base = config != null && !config.isEmpty() ? Path.of(config) : Path.of(System.getProperty("user.home"), ".config");
        return base.resolve("ifold").resolve("settings.properties");
    }

    public Path file() {
        return file;
    }

    public String get(String key, String fallback) {
        return values.getProperty(key, fallback);
    }

    public void put(String key, String value) {
        if (value == null) {
            values.remove(key);
        } else {
            values.setProperty(key, value);
        }
    }

    public int getInt(String key, int fallback) {
        try {
            return Integer.parseInt(values.getProperty(key, ""));
        } catch (NumberFormatException e) {
            return fallback;
        }
    }

    public void putInt(String key, int value) {
        values.setProperty(key, Integer.toString(value));
    }

    /** The recent files, newest first. */
    public List<Path> recent() {
        List<Path> recent = new ArrayList<>();
        for (int i = 0; i < RECENT; i++) {
            String name = values.getProperty("recent." + i);
            if (name != null) {
                recent.add(Path.of(name));
            }
        }
        return recent;
    }

    /** Puts {@code file} first among the recent files, once. */
    public void addRecent(Path file) {
        List<Path> recent = recent();
        Path absolute = file.toAbsolutePath().normalize();
        recent.remove(absolute);
        recent.add(0, absolute);
        for (int i = 0; i < RECENT; i++) {
            if (i < recent.size()) {
                values.setProperty("recent." + i, recent.get(i).toString());
            } else {
                values.remove("recent." + i);
            }
        }
    }

    /** Writes the settings, whole; the folder is made if need be. */
    public void save() throws IOException {
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        AtomicFile.write(file, out -> values.store(out, "iFold's window settings"), false);
    }
}
