package ifold.image;

import ifold.io.AtomicFile;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.Semaphore;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * Writes a numbered sequence of frames, {@code frame_00000.png}, {@code frame_00001.png}, ...,
 * encoding on background threads while the caller renders the next frame. Each frame is written
 * under a temporary name and renamed when whole, so a killed export leaves only whole frames.
 * A bounded number of frames wait for encoding at once, so memory stays flat however long the
 * sequence.
 */
public final class FrameWriter implements FrameSink {
    private final Path folder;
    private final ExecutorService encoders;
    private final Semaphore inFlight;
    private final List<Future<?>> pending = new ArrayList<>();
    /** Pictures whose frames are on disk, ready to be drawn into again: a long export allocates no more than a few. */
    private final ConcurrentLinkedQueue<byte[]> spare = new ConcurrentLinkedQueue<>();

    /** The export's hold on its folder: two exports into one folder would mix their frames. */
    private final FileChannel lockFile;
    private final FileLock lock;
    /** Frames this export wrote: a failed export takes them back. */
    private final Set<Path> written = ConcurrentHashMap.newKeySet();
    private boolean finished;

    /**
     * @param folder where the frames go; it must exist and be writable
     * @throws IOException if another export holds the folder, or it cannot be locked
     */
    public FrameWriter(Path folder) throws IOException {
        this.folder = folder;
        // The lock's file goes with the export, even one stopped by Ctrl-C or SIGTERM.
        Path lockPath = AtomicFile.createDeletedOnStop(() -> {
            Path made = folder.resolve(".ifold-frames.lock");
            try {
                Files.createFile(made);
            } catch (FileAlreadyExistsException e) {
                // Another export's, or one a killed run left: the lock below tells.
            }
            return made;
        });
        FileLock held;
        try {
            lockFile = FileChannel.open(lockPath, StandardOpenOption.WRITE);
        } catch (IOException e) {
            AtomicFile.cancelDeleteOnStop(lockPath);
            throw e;
        }
        try {
            held = lockFile.tryLock();
        } catch (OverlappingFileLockException e) {
            held = null;
        } catch (IOException e) {
            lockFile.close();
            AtomicFile.cancelDeleteOnStop(lockPath);
            throw e;
        }
        if (held == null) {
            lockFile.close();
            AtomicFile.cancelDeleteOnStop(lockPath); // this export's hold; the other export's stays
            throw new IOException("another export is writing frames into " + folder + ": wait for it, or choose another folder");
        }
        lock = held;
        // Frames a killed export left half-written, under their temporary names, go now:
        // whichever frames this export writes.
        AtomicFile.sweepStale(folder, ".frame_*.png.*.tmp", "\\.frame_[0-9]{5}\\.png\\.[0-9a-f]+\\.tmp");
        int threads = Math.max(1, Runtime.getRuntime().availableProcessors());
        this.encoders = new ThreadPoolExecutor(threads, threads, 0, TimeUnit.SECONDS, new LinkedBlockingQueue<>(), r -> {
            Thread thread = new Thread(r, "png-encoder");
            thread.setDaemon(true);
            return thread;
        });
        this.inFlight = new Semaphore(2 * threads + 2);
    }

    /** A picture of {@code size} bytes to draw the next frame into: one handed back by an earlier frame if there is one. */
    @Override
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
    @Override
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
                Path frame = folder.resolve(frameName(index));
                AtomicFile.write(frame, out -> PngEncoder.encode(width, height, rgb, out), false);
                written.add(frame);
                return null;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            } finally {
                spare.add(rgb);
                inFlight.release();
            }
        }));
        checkFailures(false);
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

    /**
     * Waits for every frame to be on disk, rethrowing the first failure; then removes the frames
     * of an earlier, longer export that this one did not write over, so that a movie made from
     * the folder is this export's alone.
     */
    @Override
    public void finish() throws IOException {
        checkFailures(true);
        try (DirectoryStream<Path> files = Files.newDirectoryStream(folder, "frame_[0-9][0-9][0-9][0-9][0-9].png*")) {
            for (Path file : files) {
                if (!written.contains(file)) {
                    Files.deleteIfExists(file);
                }
            }
        }
        finished = true;
    }

    /** Stops the encoders and lets the folder go; an export that did not finish takes back the frames it wrote. */
    @Override
    public void close() {
        encoders.shutdownNow();
        // A failed export takes back its frames; one stopped by Ctrl-C or SIGTERM leaves the
        // whole frames it made (only whole ones: the unfinished are taken back as it stops).
        if (!finished && !AtomicFile.stopping()) {
            try {
                encoders.awaitTermination(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            for (Path frame : written) {
                try {
                    Files.deleteIfExists(frame);
                } catch (IOException e) {
                    // Left, whole: the next export into the folder replaces it.
                }
            }
        }
        try {
            lock.release();
            lockFile.close();
            Path lockPath = folder.resolve(".ifold-frames.lock");
            Files.deleteIfExists(lockPath);
            AtomicFile.cancelDeleteOnStop(lockPath);
        } catch (IOException e) {
            // The lock goes with the process anyway.
        }
    }
}
