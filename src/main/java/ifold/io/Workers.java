package ifold.io;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.io.UncheckedIOException;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

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
