package ifold.io;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.io.UncheckedIOException;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Supplier;

/**
 * The threads that iFold's data-parallel steps (reading and writing big models) share: one per
 * core, or as many as the system property {@code ifold.threads} says, which the tests set to
 * show that the output does not depend on it. Daemon threads, so that they never keep the
 * program alive.
 */
public final class Workers {
    private static volatile ExecutorService pool;

    private Workers() {
    }

    /** How many threads parallel steps use: at least 1. */
    public static int threads() {
        Integer asked = Integer.getInteger("ifold.threads");
        return Math.max(1, asked != null ? asked : Runtime.getRuntime().availableProcessors());
    }

    /** The pool, sized by {@link #threads()} when first used. */
    public static ExecutorService pool() {
        ExecutorService p = pool;
        if (p == null) {
            synchronized (Workers.class) {
                p = pool;
                if (p == null) {
                    p = Executors.newFixedThreadPool(threads(), task -> {
                        Thread thread = new Thread(task, "ifold-worker");
                        thread.setDaemon(true);
                        return thread;
                    });
                    pool = p;
                }
            }
        }
        return p;
    }

    /** A loop's body over indices {@code from} (inclusive) to {@code to}, with its thread's own scratch. */
    @FunctionalInterface
    public interface Chunk<S> {
        void run(int from, int to, S scratch);
    }

    /**
     * Runs {@code body} over the indices 0 to {@code n} in chunks of {@code size}, on the calling
     * thread and on whichever of the pool's threads come free to join in: each chunk is taken by
     * the first to ask, so the caller never waits for a thread busy with other work (the pool may
     * be analysing a wrap's hosts meanwhile), only for the chunks already taken. Each thread taking
     * part gets its own scratch from {@code scratch}. The body must write only what belongs to its
     * own indices: then the result does not depend on which thread ran which chunk.
     */
    public static <S> void forChunks(int n, int size, Supplier<S> scratch, Chunk<S> body) {
        if (size < 1) {
            throw new IllegalArgumentException("chunks of at least one index, got " + size);
        }
        if (n <= size || threads() == 1) {
            if (n > 0) {
                body.run(0, n, scratch.get());
            }
            return;
        }
        AtomicInteger next = new AtomicInteger();
        // Helpers count themselves in before they take a chunk: a chunk taken is then always
        // counted when the caller, having found none left, waits for the count to fall to 0.
        AtomicInteger helping = new AtomicInteger();
        AtomicReference<Throwable> failed = new AtomicReference<>();
        Object done = new Object();
        Runnable help = () -> {
            helping.incrementAndGet();
            try {
                S own = null;
                for (int from = next.getAndAdd(size); from < n && failed.get() == null; from = next.getAndAdd(size)) {
                    if (own == null) {
                        own = scratch.get();
                    }
                    body.run(from, Math.min(n, from + size), own);
                }
            } catch (Throwable t) {
                failed.compareAndSet(null, t);
                next.set(n); // the others stop at their next chunk
            } finally {
                synchronized (done) {
                    helping.decrementAndGet();
                    done.notifyAll();
                }
            }
        };
        for (int t = 1; t < threads(); t++) {
            pool().execute(help);
        }
        help.run();
        boolean interrupted = false;
        synchronized (done) {
            while (helping.get() > 0) {
                try {
                    done.wait();
                } catch (InterruptedException e) {
                    interrupted = true; // the chunks taken finish quickly; the interrupt is kept for the caller
                }
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        Throwable t = failed.get();
        if (t instanceof RuntimeException runtime) {
            throw runtime;
        }
        if (t instanceof Error error) {
            throw error;
        }
    }

    /**
     * The result of {@code future}, with what its task threw thrown again as itself (an
     * unchecked exception or error, or an IOException) so that a parallel step fails as the
     * sequential one would.
     */
    public static <T> T await(Future<T> future) throws IOException {
        try {
            return result(future);
        } catch (UncheckedIOException io) {
            throw io.getCause();
        } catch (CancellationException e) {
            if (Thread.currentThread().isInterrupted()) {
                throw new InterruptedIOException("interrupted"); // the waiting thread's interrupt
            }
            throw e;
        }
    }

    /**
     * The result of {@code future} whose task throws no checked exception (a computation, as
     * the wrap's analysis of each host), with what it threw thrown again as itself; an
     * IOException as an UncheckedIOException, an interrupt of the waiting thread as a
     * CancellationException (the interrupt kept).
     */
    public static <T> T result(Future<T> future) {
        try {
            return future.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new CancellationException("interrupted");
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof IOException io) {
                throw new UncheckedIOException(io);
            }
            if (cause instanceof RuntimeException runtime) {
                throw runtime;
            }
            if (cause instanceof Error error) {
                throw error;
            }
            throw new IllegalStateException(cause);
        }
    }
}
