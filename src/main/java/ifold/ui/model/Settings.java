package ifold.ui.model;

import ifold.io.AtomicFile;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Properties;
import java.util.function.Function;

/**
 * What the window remembers between runs (the last folder, the window's size, the parameters,
 * the recent files), in a small properties file. The file is given, so that tests keep their
 * own and never touch the user's; {@link #defaultFile()} is the user's. A file that cannot be
 * read is as good as none: settings are a convenience, never a reason not to start; what was
 * wrong with it is {@link #problem()}, for the caller to say once.
 */
public final class Settings {
    /** The recent files the File menu lists. */
    public static final int RECENT = 8;

    /** More than settings ever hold: a file this large was put there by mistake. */
    private static final long LARGEST = 1 << 20;

    private final Path file;
    private final Properties values = new Properties();
    private final String problem;
    /** Whether the file is something other than a regular file (a FIFO, a device), left as it is. */
    private final boolean notAFile;

    public Settings(Path file) {
        this.file = file;
        String wrong = null;
        // Opening a FIFO waits for a writer, and the window would never open: only a regular file is read.
        boolean special = Files.exists(file) && !Files.isRegularFile(file);
        if (special) {
            wrong = "the settings file " + file + " is not a regular file: the window starts with its defaults and leaves it as it is";
        } else {
            try {
                if (Files.size(file) > LARGEST) {
                    throw new IOException("larger than " + LARGEST + " bytes");
                }
                byte[] bytes = Files.readAllBytes(file);
                for (byte b : bytes) {
                    if (b == 0) {
                        throw new IOException("binary content");
                    }
                }
                values.load(new ByteArrayInputStream(bytes));
            } catch (NoSuchFileException e) {
                // First run: nothing remembered yet.
            } catch (IOException | IllegalArgumentException e) {
                values.clear(); // start afresh, and write a good one on leaving
                wrong = "the settings file " + file + " is corrupt (" + e.getMessage() + "): the window starts with its defaults"
                        + " and writes it anew on closing";
            }
        }
        problem = wrong;
        notAFile = special;
    }

    /**
     * {@code $XDG_CONFIG_HOME/ifold/settings.properties}, or {@code $HOME/.config/ifold/settings.properties},
     * or under {@code user.home} where HOME is not set (Java takes user.home from the account, not from HOME).
     */
    public static Path defaultFile() {
        return defaultFile(System::getenv, System.getProperty("user.home"));
    }

    /** The settings file as {@link #defaultFile()} finds it, in the environment {@code env} with the account's home {@code userHome}. */
    static Path defaultFile(Function<String, String> env, String userHome) {
        // The XDG base directory specification: a relative path in these variables is to be ignored.
        String config = env.apply("XDG_CONFIG_HOME");
        if (config != null && Path.of(config).isAbsolute()) {
            return Path.of(config).resolve("ifold").resolve("settings.properties");
        }
        String home = env.apply("HOME");
        Path base = home != null && Path.of(home).isAbsolute() ? Path.of(home) : Path.of(userHome);
        return base.resolve(".config").resolve("ifold").resolve("settings.properties");
    }

    /** What was wrong with the file, or empty where it was read (or there was none). */
    public Optional<String> problem() {
        return Optional.ofNullable(problem);
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

    /** Takes {@code file} off the recent files, where it is among them. */
    public void removeRecent(Path file) {
        List<Path> recent = recent();
        if (!recent.remove(file.toAbsolutePath().normalize())) {
            return;
        }
        for (int i = 0; i < RECENT; i++) {
            if (i < recent.size()) {
                values.setProperty("recent." + i, recent.get(i).toString());
            } else {
                values.remove("recent." + i);
            }
        }
    }

    /** Writes the settings, whole; the folder is made if need be. A file that is not a regular file is left as it is. */
    public void save() throws IOException {
        if (notAFile) {
            return; // said when it was read: renaming over a FIFO would replace it
        }
        Path parent = file.toAbsolutePath().getParent();
        if (parent != null) {
            Files.createDirectories(parent);
        }
        AtomicFile.write(file, out -> values.store(out, "iFold's window settings"), false);
    }
}
