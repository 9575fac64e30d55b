package ifold.cli;

import ifold.image.FrameSink;
import ifold.image.FrameWriter;
import ifold.image.GifWriter;
import ifold.image.Mp4Writer;
import ifold.io.AtomicFile;
import ifold.render.FrameExport;
import ifold.render.RenderUnavailableException;
import ifold.scene.Animation;
import ifold.scene.Scene;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine.Option;

/**
 * The options every command that shows something takes to render frames or a movie instead of
 * opening a window: {@code --frames DIR --movie FILE [--size WxH] [--fps N] [--seconds S]
 * [--no-captions]}. Checked before any work.
 */
final class FrameOptions {
    private static final Pattern SIZE = Pattern.compile("(\\d+)x(\\d+)");

    @Option(names = "--frames", paramLabel = "DIR", description = "render offscreen into DIR/frame_00000.png, ... instead of opening a window")
    Path frames;

    /** The size and rate of frames and MP4s unless --size and --fps say otherwise: HD, smooth. */
    static final String SIZE_DEFAULT = "1280x720";
    static final int FPS_DEFAULT = 30;
    /**
     * A GIF's: fit for a web page. GIF compresses moving pictures poorly (the cube's two-minute
     * wrap at 1280x720 and 30 frames/s is 30 MB); a quarter of the pixels at 12 frames/s, still
     * smooth enough to follow a fold, is a few MB.
     */
    static final String GIF_SIZE_DEFAULT = "640x360";
    static final int GIF_FPS_DEFAULT = 12;

    @Option(names = "--size", paramLabel = "WxH", description = "frame size (default " + SIZE_DEFAULT + "; " + GIF_SIZE_DEFAULT
            + " for a GIF)")
    String size;

    @Option(names = "--fps", paramLabel = "N", description = "frames per second of animation (default " + FPS_DEFAULT + "; "
            + GIF_FPS_DEFAULT + " for a GIF)")
    Integer fps;

    @Option(names = "--seconds", paramLabel = "S", defaultValue = "10", description = "length of the animation in seconds "
            + "(default: as the command's description above says)")
    double seconds;

    @Option(names = "--movie", paramLabel = "FILE", description = "render offscreen into a movie instead of opening a window: "
            + "FILE.mp4 (H.264, through ffmpeg) or FILE.gif (looping, at most 50 frames/s); with --frames, both")
    Path movie;

    @Option(names = "--no-captions", description = "no caption naming the step along the bottom of frames and movies")
    boolean noCaptions;

    int width;
    int height;
    /** Whether the export made the folder, so that a failed one can take it away again. */
    private boolean createdFolder;

    /**
     * Checks the values, and that the folder can be made or written into (it is made only when
     * the frames are written, so that a run that fails before leaves nothing); throws a
     * {@link UserError} naming the option.
     */
    void check() {
        // Left out, they suit what is written: a GIF is for the web, frames and MP4s for a class.
        boolean gifOnly = movie != null && isGif() && frames == null;
        if (size == null) {
            size = gifOnly ? GIF_SIZE_DEFAULT : SIZE_DEFAULT;
        }
        if (fps == null) {
            fps = gifOnly ? GIF_FPS_DEFAULT : FPS_DEFAULT;
        }
        Matcher m = SIZE.matcher(size);
        if (!m.matches()) {
            throw UserError.usage("option --size: '" + size + "' is not WIDTHxHEIGHT, e.g. 1280x720");
        }
        // A side of any number of digits is a size, too big or not: the range below names it.
        width = m.group(1).length() > 6 ? Integer.MAX_VALUE : Integer.parseInt(m.group(1));
        height = m.group(2).length() > 6 ? Integer.MAX_VALUE : Integer.parseInt(m.group(2));
        if (width < 16 || height < 16 || width > 8192 || height > 8192) {
            throw UserError.usage("option --size: each side must be between 16 and 8192 pixels, got " + size);
        }
        if (fps < 1 || fps > 240) {
            throw UserError.usage("option --fps: must be between 1 and 240, got " + fps);
        }
        if (!(seconds > 0) || seconds > 3600) {
            throw UserError.usage("option --seconds: must be more than 0 and at most 3600, got " + seconds);
        }
        if (movie != null) {
            checkMovie();
        }
        if (frames != null) {
            checkFolder();
        }
    }

    /** Whether frames or a movie are asked for: rendered offscreen rather than shown. */
    boolean renders() {
        return frames != null || movie != null;
    }

    private boolean isGif() {
        return movie.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".gif");
    }

    private void checkMovie() {
        OutputFiles.checkWritableFile(movie, "--movie", ".mp4", ".gif");
        if (isGif()) {
            if (fps > GifWriter.MAX_FPS) {
                throw UserError.usage("option --fps: a GIF keeps at most " + GifWriter.MAX_FPS + " frames a second, got " + fps
                        + "; write an .mp4 for more");
            }
            return;
        }
        if (width % 2 != 0 || height % 2 != 0) {
            throw UserError.usage("option --size: an MP4 needs an even width and height, got " + size);
        }
        if (!Mp4Writer.available()) {
            throw UserError.usage("option --movie: writing an .mp4 needs ffmpeg, which is not installed (scripts/setup installs it);"
                    + " or write a .gif");
        }
    }

    /**
     * Renders {@code frameCount} frames of the animation into the folder and the movie asked
     * for, with a progress bar on {@code err}, and says what it wrote on {@code out}. A failure
     * is a {@link UserError}; a movie not finished is not left behind.
     */
    void export(Scene scene, Animation animation, int frameCount, int samples, PrintWriter out, PrintWriter err) {
        List<FrameSink> sinks = new ArrayList<>();
        FrameExport.Result result;
        try {
            try {
                if (frames != null) {
                    makeFolder();
                    sinks.add(new FrameWriter(frames));
                }
                if (movie != null) {
                    sinks.add(isGif() ? new GifWriter(movie, width, height, fps) : new Mp4Writer(movie, width, height, fps));
                }
                result = FrameExport.export(scene, animation, FrameSink.all(sinks), width, height, frameCount, samples, !noCaptions,
                        new ProgressBar(err));
            } finally {
                for (FrameSink sink : sinks) {
                    sink.close();
                }
            }
        } catch (RenderUnavailableException e) {
            removeFolderIfUnused();
            throw new UserError(e.getMessage());
        } catch (IOException e) {
            removeFolderIfUnused();
            throw new UserError((movie != null ? "option --movie: cannot write " + movie : "option --frames: cannot write frames to "
                    + frames) + ": " + e.getMessage());
        }
        if (frames != null) {
            out.printf(Locale.ROOT, "wrote %d %s of %dx%d to %s in %.1f s (%.1f frames/s)%n", result.frames(),
                    result.frames() == 1 ? "frame" : "frames", width, height, frames.toAbsolutePath(), result.seconds(),
                    result.framesPerSecond());
        }
        if (movie != null) {
            long bytes;
            try {
                bytes = Files.size(movie);
            } catch (IOException e) {
                bytes = -1;
            }
            out.printf(Locale.ROOT, "wrote %s: %d %s of %dx%d at %d frames/s (%.1f s), %.2f MB, in %.1f s (%.1f frames/s)%n",
                    movie, result.frames(), result.frames() == 1 ? "frame" : "frames", width, height, fps, (double) result.frames() / fps, bytes / 1e6, result.seconds(),
                    result.framesPerSecond());
        }
        out.flush();
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

    private void checkFolder() {
        if (Files.exists(frames) && !Files.isDirectory(frames)) {
            throw UserError.usage("option --frames: " + frames + " is a file, not a folder");
        }
        Path existing = frames;
        if (!Files.exists(frames)) {
            existing = frames.toAbsolutePath().getParent();
            if (existing == null || !Files.isDirectory(existing)) {
                throw UserError.usage("option --frames: folder " + existing + " does not exist");
            }
        }
        if (!Files.isWritable(existing)) {
            throw UserError.usage("option --frames: folder " + existing + " is not writable");
        }
    }

    private void makeFolder() {
        if (!Files.exists(frames)) {
            try {
                AtomicFile.createFolderRemovedIfEmptyOnStop(frames); // an interrupted run leaves no empty folder
                createdFolder = true;
            } catch (IOException e) {
                throw new UserError("option --frames: cannot create " + frames + ": " + e.getMessage());
            }
        }
    }
}
