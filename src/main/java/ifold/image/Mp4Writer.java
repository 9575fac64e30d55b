package ifold.image;

import ifold.io.AtomicFile;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Writes frames as an MP4 movie (H.264, yuv420p: it plays in browsers and on phones) through
 * {@code ffmpeg}, which reads the raw frames on a pipe. The movie is written under a temporary
 * name and renamed when whole; a failed or interrupted export leaves none.
 */
public final class Mp4Writer implements FrameSink {
    private final AtomicFile.Pending file;
    private final Process ffmpeg;
    private final OutputStream pipe;
    private final ByteArrayOutputStream messages = new ByteArrayOutputStream();
    private final Thread drain;
    private boolean finished;

    /** Whether {@code ffmpeg} can be run here. */
    public static boolean available() {
        try {
            Process probe = new ProcessBuilder("ffmpeg", "-version").redirectErrorStream(true).start();
            probe.getInputStream().transferTo(OutputStream.nullOutputStream());
            return probe.waitFor(20, TimeUnit.SECONDS) && probe.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    /**
     * @param width the frames' width, even (yuv420p halves the colour resolution)
     * @param height their height, even
     * @param fps frames per second, exactly
     */
    public Mp4Writer(Path movie, int width, int height, int fps) throws IOException {
        if (width % 2 != 0 || height % 2 != 0) {
            throw new IllegalArgumentException("an MP4 needs an even width and height, got " + width + "x" + height);
        }
        file = AtomicFile.beginForProgram(movie);
        List<String> command = new ArrayList<>(List.of("ffmpeg", "-hide_banner", "-loglevel", "error", "-y",
                "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", width + "x" + height, "-framerate", Integer.toString(fps), "-i", "-",
                "-c:v", "libx264", "-preset", "medium", "-tune", "animation", "-crf", "25", "-pix_fmt", "yuv420p", "-r", Integer.toString(fps),
                "-movflags", "+faststart", "-f", "mp4", file.path().toString()));
        try {
            ffmpeg = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.PIPE).start();
            file.writtenBy(ffmpeg);
        } catch (IOException e) {
            file.close();
            throw new IOException("cannot run ffmpeg (scripts/setup installs it; or write a .gif): " + e.getMessage(), e);
        }
        pipe = ffmpeg.getOutputStream();
        InputStream output = ffmpeg.getInputStream();
        drain = new Thread(() -> {
            try {
                output.transferTo(messages);
            } catch (IOException e) {
                // ffmpeg is gone: its exit status tells.
            }
        }, "ffmpeg-messages");
        drain.setDaemon(true);
        drain.start();
    }

    @Override
    public void write(int index, int width, int height, byte[] rgb) throws IOException {
        try {
            pipe.write(rgb);
        } catch (IOException e) {
            throw failure("ffmpeg stopped reading frames");
        }
    }

    @Override
    public void finish() throws IOException {
        try {
            pipe.close();
            if (!ffmpeg.waitFor(10, TimeUnit.MINUTES)) {
                throw new IOException("ffmpeg did not finish the movie");
            }
            drain.join(10_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while ffmpeg finished the movie", e);
        }
        if (ffmpeg.exitValue() != 0) {
            throw failure("ffmpeg failed (exit " + ffmpeg.exitValue() + ")");
        }
        file.commit();
        finished = true;
    }

    private IOException failure(String what) {
        String said = messages.toString(StandardCharsets.UTF_8).strip().replace('\n', ' ');
        return new IOException(what + (said.isEmpty() ? "" : ": " + (said.length() > 300 ? said.substring(0, 300) + "..." : said)));
    }

    @Override
    public void close() {
        if (!finished) {
            ffmpeg.destroyForcibly();
            try {
                ffmpeg.waitFor(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        file.close();
    }
}
