package ifold.ui.model;

import java.util.concurrent.CancellationException;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Runs one kind of background work (planning, or exporting) off the window's event thread, one
 * task at a time as the user sees it: a new task supersedes the one running, whose result is
 * then dropped, and {@link #cancel()} drops it too (and its output: a task checks for cancelling
 * before it commits a file). What a task reports (its stage, progress,
 * result or failure) reaches the listener through {@code deliver}, which in the window is the
 * event thread; a superseded or cancelled task reports nothing more.
 *
 * <p>A superseded task may go on working on its own thread until it next looks at its
 * {@link Progress}: a wrap does at every fold ({@link ifold.wrap.Wrap.Watcher}), other stages
 * (reading, refining, analysing) between them. It never delays the next.
 */
public final class Worker {
    /** Work done in the background. */
    @FunctionalInterface
    public interface Task<T> {
        T run(Progress progress) throws Exception;
    }

    /** What the window hears of a task, on the delivering thread. */
    public interface Listener<T> {
        void stage(String what);

        void done(int done, int total);

        void succeeded(T value);

        /** The task failed: the problem to show (at a field, or as one message). */
        void failed(Problem problem);
    }

    private final String name;
    private final Executor deliver;
    private final AtomicLong generation = new AtomicLong();
    /** The ticket of the task whose outcome the listener has yet to hear, or 0. */
    private volatile long busy;
    /** The thread of the latest task, for {@link #await}. */
    private volatile Thread running;

    /**
     * @param name the name of the worker's threads
     * @param deliver where the listener is called: the event thread in the window
     */
    public Worker(String name, Executor deliver) {
        this.name = name;
        this.deliver = deliver;
    }

    /** Starts {@code task}, superseding the one running (if any). */
    public <T> void submit(Task<T> task, Listener<T> listener) {
        long ticket = generation.incrementAndGet();
        Progress progress = new Progress() {
            @Override
            public void stage(String what) {
                deliverIfCurrent(ticket, () -> listener.stage(what));
            }

            @Override
            public void done(int done, int total) {
                deliverIfCurrent(ticket, () -> listener.done(done, total));
            }

            @Override
            public boolean cancelled() {
                return generation.get() != ticket;
            }
        };
        Thread thread = new Thread(() -> {
            Runnable outcome;
            try {
                T value = task.run(progress);
                outcome = () -> listener.succeeded(value);
            } catch (CancellationException e) {
                // Cancelled or superseded (cancel() said so, or the next task speaks now); or the
                // task gave up by itself, which is a cancel too.
                outcome = () -> listener.failed(Problem.of("cancelled"));
            } catch (JobFailure e) {
                outcome = () -> listener.failed(e.problem());
            } catch (OutOfMemoryError e) {
                outcome = () -> listener.failed(Problem.of("out of memory: give iFold more, e.g. JAVA_OPTS=-Xmx8g"));
            } catch (Exception | LinkageError | AssertionError e) {
                // A bug, not bad input: still one line, with the kind of failure so it can be reported.
                outcome = () -> listener.failed(Problem.of("internal error: " + e + " (please report it)"));
            }
            Runnable told = outcome;
            if (generation.get() == ticket) {
                deliver.execute(() -> {
                    if (generation.get() == ticket) {
                        busy = 0; // busy until the listener hears: the window's state and the worker's agree
                        told.run();
                    }
                });
            }
        }, name + " " + ticket);
        thread.setDaemon(true);
        busy = ticket;
        running = thread;
        thread.start();
    }

    /**
     * Cancels the task running, if any: it reports nothing more, and its
     * {@link Progress#check()} throws from now on.
     *
     * @return whether a task was cancelled
     */
    public boolean cancel() {
        if (!isBusy()) {
            return false;
        }
        generation.incrementAndGet();
        busy = 0;
        return true;
    }

    /** Whether a task runs, not superseded nor cancelled, or its outcome is yet to be heard. */
    public boolean isBusy() {
        long ticket = busy;
        return ticket != 0 && ticket == generation.get();
    }

    /** Waits up to {@code millis} for the latest task's thread to end, cancelled or not: for tests. */
    public boolean await(long millis) throws InterruptedException {
        Thread thread = running;
        if (thread != null) {
            thread.join(millis);
            return !thread.isAlive();
        }
        return true;
    }

    private void deliverIfCurrent(long ticket, Runnable report) {
        if (generation.get() == ticket) {
            deliver.execute(() -> {
                if (generation.get() == ticket) {
                    report.run();
                }
            });
        }
    }
}
