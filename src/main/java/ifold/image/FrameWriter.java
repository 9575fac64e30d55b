package ifold.image;

import ifold.io.AtomicFile;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.Semaphore;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.ExecutionException;
import java.util.ArrayList;
import java.util.List;

/**
 * Writes a numbered sequence of frames, {@code frame_00000.png}, {@code frame_00001.png}, ...,
 * encoding on background threads while the caller renders the next frame. Each frame is written
 * under a temporary name and renamed when whole, so a killed export leaves only whole frames.
 * A bounded number of frames wait for encoding at once, so memory stays flat however long the
 * sequence.
 */
public final class FrameWriter implements AutoCloseable {
    private final Path folder;
    private final int total;
    private final PrintWriter progress;
    /** Whether the progress bar goes to a terminal (the JVM has a console: stdin and stdout are one). */
    private static final boolean ON_TERMINAL = System.console() != null;
    private final ExecutorService encoders;
    private final Semaphore inFlight;
    private final List<Future<?>> pending = new ArrayList<>();
    /** Pictures whose frames are on disk, ready to be drawn into again: a long export allocates no more than a few. */
    private final ConcurrentLinkedQueue<byte[]> spare = new ConcurrentLinkedQueue<>();
    private final long start = System.nanoTime();
    private int submitted;
    private int lastPrinted = -1;

    /**
     * @param folder where the frames go; it must exist and be writable
     * @param total how many frames will come, for the progress bar
     * @param progress where the progress bar goes (stderr), or null for none
     */
    public FrameWriter(Path folder, int total, PrintWriter progress) {
        this.folder = folder;
        this.total = total;
        this.progress = progress;
        int threads = Math.max(1, Runtime.getRuntime().availableProcessors());
        this.encoders = new ThreadPoolExecutor(threads, threads, 0, TimeUnit.SECONDS, new LinkedBlockingQueue<>(), r -> {
            Thread thread = new Thread(r, "png-encoder");
            thread.setDaemon(true);
            return thread;
        });
        this.inFlight = new Semaphore(2 * threads + 2);
    }

    /** A picture of {@code size} bytes to draw the next frame into: one handed back by an earlier frame if there is one. */
    public byte[] buffer(int size) {
        byte[] recycled = spare.poll();
        return recycled != null && recycled.length == size ? recycled : new byte[size];
    }

    /** The file of frame {@code index}. */
    public static String frameName(int index) {
        return String.format(Locale.ROOT, "frame_%05d.png", index);
    }

    /**
     * Queues frame {@code index} (rows top first, 3 bytes a pixel) for encoding and writing. Blocks
     * while too many frames wait; rethrows the first failure of an earlier frame. The writer
     * owns {@code rgb} from now on, and hands it out again through {@link #buffer(int)}.
     */
    public void write(int index, int width, int height, byte[] rgb) throws IOException {
        try {
            inFlight.acquire();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while writing frames", e);
        }
        pending.add(encoders.submit(() -> {
            try {
                // Not forced to disk: a frame a second is not worth an fsync, and a killed export
                // still leaves only whole frames, since the rename comes after the last byte.
                AtomicFile.write(folder.resolve(frameName(index)), out -> PngEncoder.encode(width, height, rgb, out), false);
                return null;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            } finally {
                spare.add(rgb);
                inFlight.release();
            }
        }));
        submitted++;
        checkFailures(false);
        printProgress(submitted);
    }

    private void checkFailures(boolean wait) throws IOException {
        for (var iterator = pending.iterator(); iterator.hasNext(); ) {
            Future<?> future = iterator.next();
            if (!wait && !future.isDone()) {
                continue;
            }
            try {
                future.get();
            } catch (ExecutionException e) {
                Throwable cause = e.getCause() instanceof UncheckedIOException u ? u.getCause() : e.getCause();
                throw cause instanceof IOException io ? io : new IOException(cause);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while writing frames", e);
            }
            iterator.remove();
        }
    }

    private void printProgress(int done) {
        if (progress == null || done == lastPrinted) {
            return;
        }
        // Redrawn in place on a terminal; into a log or a pipe, a line every tenth of the way.
        if (!ON_TERMINAL && done != total && (long) done * 10 / Math.max(1, total) == (long) lastPrinted * 10 / Math.max(1, total)) {
            return;
        }
        lastPrinted = done;
        int width = 30;
        int filled = total == 0 ? width : (int) ((long) width * done / total);
        double seconds = (System.nanoTime() - start) * 1e-9;
        progress.printf(Locale.ROOT, "%s[%s%s] %d/%d frames, %.1f frames/s%s", ON_TERMINAL ? "\r" : "", "#".repeat(filled),
                " ".repeat(width - filled), done, total, seconds > 0 ? done / seconds : 0.0, ON_TERMINAL ? "" : "\n");
        progress.flush();
    }

    /** Frames per second so far, counting from the writer's creation. */
    public double framesPerSecond() {
        double seconds = (System.nanoTime() - start) * 1e-9;
        return seconds > 0 ? submitted / seconds : 0;
    }

    /** Waits for every frame to be on disk; rethrows the first failure. */
    public void finish() throws IOException {
        checkFailures(true);
        if (progress != null) {
            printProgress(submitted);
            if (ON_TERMINAL) {
                progress.println();
            }
            progress.flush();
        }
    }

    @Override
    public void close() {
        encoders.shutdownNow();
    }
}
