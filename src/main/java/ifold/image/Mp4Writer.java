package ifold.image;

import ifold.io.AtomicFile;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
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
    /** The movie asked for: ffmpeg's messages name it, not the temporary file it writes. */
    private final Path movie;
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
        this.movie = movie;
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
        // On a full disk ffmpeg 5.1 can exit 0 having written the movie's start and neither the
        // size of its frames' box nor the index (moov) that players need: look before the rename.
        String incomplete = incomplete(file.path());
        if (incomplete != null) {
            throw failure("ffmpeg left the movie incomplete (" + incomplete + "; " + freeSpace(file.path()) + ")");
        }
        file.commit();
        finished = true;
    }

    /**
     * Why {@code movie} is not a whole MP4 file, or null: its top-level boxes must follow each
     * other to its last byte, each with its size written (ffmpeg writes a size of 0, "to the
     * end", until it finishes the box), and hold both the frames (mdat) and their index (moov).
     */
    static String incomplete(Path movie) throws IOException {
        boolean frames = false;
        boolean index = false;
        try (FileChannel channel = FileChannel.open(movie, StandardOpenOption.READ)) {
            long length = channel.size();
            long at = 0;
            ByteBuffer header = ByteBuffer.allocate(16);
            while (at < length) {
                header.clear();
                header.limit((int) Math.min(16, length - at));
                channel.read(header, at);
                if (header.position() < 8) {
                    return "a box cut short at byte " + at;
                }
                long size = Integer.toUnsignedLong(header.getInt(0));
                String type = new String(new byte[] {header.get(4), header.get(5), header.get(6), header.get(7)}, StandardCharsets.ISO_8859_1);
                int headerSize = 8;
                if (size == 1) {
                    if (header.position() < 16) {
                        return "a box cut short at byte " + at;
                    }
                    size = header.getLong(8);
                    headerSize = 16;
                }
                if (size == 0) {
                    return "its '" + type + "' box was never closed";
                }
                if (size < headerSize || size > length - at) {
                    return "its '" + type + "' box is cut short: " + (length - at) + " of its " + size + " bytes written";
                }
                frames |= type.equals("mdat");
                index |= type.equals("moov");
                at += size;
            }
        }
        return !frames ? "no frames (mdat box)" : !index ? "no index (moov box)" : null;
    }

    private static String freeSpace(Path file) {
        try {
            return Files.getFileStore(file).getUsableSpace() + " bytes free on its disk";
        } catch (IOException e) {
            return "its disk's free space unknown";
        }
    }

    private IOException failure(String what) {
        String said = messages.toString(StandardCharsets.UTF_8).strip().replace('\n', ' ')
                .replace(file.path().toString(), movie.toString());
        if (said.contains("No space left on device")) {
            // Whether ffmpeg noticed (exit 1) or not (exit 0, the movie cut short), the cause in words.
            return new IOException("the disk is full: the movie is incomplete (" + freeSpace(file.path()) + ")");
        }
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
