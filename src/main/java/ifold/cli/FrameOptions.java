package ifold.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.io.IOException;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine.Option;

/**
 * The options every command that shows something takes to render frames instead of opening a
 * window: {@code --frames DIR [--size WxH] [--fps N] [--seconds S]}. Checked before any work.
 */
final class FrameOptions {
    private static final Pattern SIZE = Pattern.compile("(\\d{1,5})x(\\d{1,5})");

    @Option(names = "--frames", paramLabel = "DIR", description = "render offscreen into DIR/frame_00000.png, ... instead of opening a window")
    Path frames;

    @Option(names = "--size", paramLabel = "WxH", defaultValue = "1280x720", description = "frame size (default ${DEFAULT-VALUE})")
    String size;

    @Option(names = "--fps", paramLabel = "N", defaultValue = "30", description = "frames per second of animation (default ${DEFAULT-VALUE})")
    int fps;

    @Option(names = "--seconds", paramLabel = "S", defaultValue = "10", description = "length of the animation in seconds (default ${DEFAULT-VALUE})")
    double seconds;

    int width;
    int height;
    /** Whether {@link #check()} made the folder, so that a failed export can take it away again. */
    private boolean createdFolder;

    /** Checks the values and prepares the folder; throws a {@link UserError} naming the option. */
    void check() {
        Matcher m = SIZE.matcher(size);
        if (!m.matches()) {
            throw new UserError("option --size: '" + size + "' is not WIDTHxHEIGHT, e.g. 1280x720");
        }
        width = Integer.parseInt(m.group(1));
        height = Integer.parseInt(m.group(2));
        if (width < 16 || height < 16 || width > 8192 || height > 8192) {
            throw new UserError("option --size: each side must be between 16 and 8192 pixels, got " + size);
        }
        if (fps < 1 || fps > 240) {
            throw new UserError("option --fps: must be between 1 and 240, got " + fps);
        }
        if (!(seconds > 0) || seconds > 3600) {
            throw new UserError("option --seconds: must be more than 0 and at most 3600, got " + seconds);
        }
        if (frames != null) {
            prepareFolder();
        }
    }

    /** After a failure: removes the folder if this run made it and left it empty. */
    void removeFolderIfUnused() {
        if (createdFolder) {
            try {
                Files.deleteIfExists(frames); // fails, harmlessly, if anything was written
            } catch (IOException e) {
                // Frames were written after all: they stay.
            }
        }
    }

    int frameCount() {
        return Math.max(1, (int) Math.round(fps * seconds));
    }

    private void prepareFolder() {
        if (Files.exists(frames) && !Files.isDirectory(frames)) {
            throw new UserError("option --frames: " + frames + " is a file, not a folder");
        }
        if (!Files.exists(frames)) {
            Path parent = frames.toAbsolutePath().getParent();
            if (parent == null || !Files.isDirectory(parent)) {
                throw new UserError("option --frames: folder " + parent + " does not exist");
            }
            try {
                Files.createDirectory(frames);
                createdFolder = true;
            } catch (IOException e) {
                throw new UserError("option --frames: cannot create " + frames + ": " + e.getMessage());
            }
        }
        if (!Files.isWritable(frames)) {
            throw new UserError("option --frames: folder " + frames + " is not writable");
        }
    }
}
