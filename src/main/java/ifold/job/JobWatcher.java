package ifold.job;

import java.util.concurrent.CancellationException;

/**
 * What a job tells as it goes, and asks: the stage it starts ("reading cube.off"), how far
 * along it is, notes on the data a user should read before the result (a repair made), and
 * whether to stop. The command line prints the notes; the window shows the stages and its
 * Cancel stops the job.
 */
public interface JobWatcher {
    /** Nobody watches and nothing stops: for tests and one-off calls. */
    JobWatcher NONE = new JobWatcher() {
    };

    /** A stage begins. */
    default void stage(String what) {
    }

    /** {@code done} of {@code total} units of the current stage are done. */
    default void done(int done, int total) {
    }

    /** A note on the data, in one line without a prefix: "models/x.off: repaired: dropped 1 zero-area face". */
    default void note(String line) {
    }

    /** Whether the job should stop. */
    default boolean stopped() {
        return false;
    }

    /** Stops the job once asked: throws {@link CancellationException}. */
    default void stopIfAsked() {
        if (stopped()) {
            throw new CancellationException("stopped");
        }
    }
}
