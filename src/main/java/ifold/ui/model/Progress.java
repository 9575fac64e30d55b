package ifold.ui.model;

import ifold.job.JobWatcher;
import java.util.concurrent.CancellationException;

/**
 * What a background task tells the window while it works (its stage, how far it is), and how
 * it learns that it was cancelled: it calls {@link #check()} between steps, which throws once
 * Cancel is pressed.
 */
public interface Progress {
    /** A stage begins: "reading the model", "wrapping"; its length is not known. */
    void stage(String what);

    /** {@code done} of {@code total} units of the current stage are done. */
    void done(int done, int total);

    /** Whether the task was cancelled. */
    boolean cancelled();

    /** Throws {@link CancellationException} if the task was cancelled. */
    default void check() {
        if (cancelled()) {
            throw new CancellationException("cancelled");
        }
    }

    /** A progress that nobody watches and nothing cancels: for tests and the command line. */
    Progress NONE = new Progress() {
        @Override
        public void stage(String what) {
        }

        @Override
        public void done(int done, int total) {
        }

        @Override
        public boolean cancelled() {
            return false;
        }
    };

    /** This progress as a job's watcher: its stages and counts shown, Cancel stopping the job; notes go unshown. */
    default JobWatcher watcher() {
        Progress progress = this;
        return new JobWatcher() {
            @Override
            public void stage(String what) {
                progress.stage(what);
            }

            @Override
            public void done(int done, int total) {
                progress.done(done, total);
            }

            @Override
            public boolean stopped() {
                return progress.cancelled();
            }
        };
    }
}
