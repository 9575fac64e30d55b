package ifold.ui.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Background work: results, failures in one line, cancelling and superseding. */
@Timeout(30)
class WorkerTest {
    /** Records what a listener hears. */
    private static final class Heard implements Worker.Listener<String> {
        final List<String> events = new CopyOnWriteArrayList<>();
        final CountDownLatch ended = new CountDownLatch(1);

        @Override
        public void stage(String what) {
            events.add("stage " + what);
        }

        @Override
        public void done(int done, int total) {
            events.add("done " + done + "/" + total);
        }

        @Override
        public void succeeded(String value) {
            events.add("ok " + value);
            ended.countDown();
        }

        @Override
        public void failed(Problem problem) {
            events.add("failed " + problem.field() + ": " + problem.message());
            ended.countDown();
        }
    }

    @Test
    void aTaskReportsItsStagesAndItsResult() throws Exception {
        Worker worker = new Worker("test", Runnable::run);
        Heard heard = new Heard();
        worker.submit(progress -> {
            progress.stage("working");
            progress.done(1, 2);
            return "result";
        }, heard);
        assertTrue(heard.ended.await(10, TimeUnit.SECONDS));
        assertEquals(List.of("stage working", "done 1/2", "ok result"), heard.events);
    }

    @Test
    void failuresAreOneLineAndBugsSaySo() throws Exception {
        Worker worker = new Worker("test", Runnable::run);
        Heard bad = new Heard();
        worker.submit(progress -> {
            throw new JobFailure(new Problem("width", "too wide"));
        }, bad);
        assertTrue(bad.ended.await(10, TimeUnit.SECONDS));
        assertEquals(List.of("failed width: too wide"), bad.events);
        Heard bug = new Heard();
        worker.submit(progress -> {
            throw new IllegalStateException("oops");
        }, bug);
        assertTrue(bug.ended.await(10, TimeUnit.SECONDS));
        assertEquals(List.of("failed null: internal error: java.lang.IllegalStateException: oops (please report it)"), bug.events);
    }

    @Test
    void aCancelledTaskSaysNothingMoreAndStopsAtItsNextCheck() throws Exception {
        Worker worker = new Worker("test", Runnable::run);
        Heard heard = new Heard();
        CountDownLatch started = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        boolean[] stoppedByCheck = {false};
        worker.submit(progress -> {
            started.countDown();
            release.await();
            try {
                progress.check();
            } catch (java.util.concurrent.CancellationException e) {
                stoppedByCheck[0] = true;
                throw e;
            }
            return "too late";
        }, heard);
        assertTrue(started.await(10, TimeUnit.SECONDS));
        assertTrue(worker.isBusy());
        assertTrue(worker.cancel());
        assertFalse(worker.isBusy());
        assertFalse(worker.cancel(), "nothing left to cancel");
        Thread thread = findThread("test 1");
        release.countDown();
        thread.join(10_000);
        assertTrue(stoppedByCheck[0], "the task's check threw");
        assertEquals(List.of(), heard.events, "a cancelled task reports nothing");
    }

    @Test
    void aNewTaskSupersedesTheOneRunning() throws Exception {
        Worker worker = new Worker("test", Runnable::run);
        Heard first = new Heard();
        CountDownLatch release = new CountDownLatch(1);
        worker.submit(progress -> {
            release.await();
            return "old";
        }, first);
        Heard second = new Heard();
        worker.submit(progress -> "new", second);
        assertTrue(second.ended.await(10, TimeUnit.SECONDS), "the new one does not wait for the old");
        release.countDown();
        Thread.sleep(100);
        assertEquals(List.of(), first.events, "the superseded result is dropped");
        assertEquals(List.of("ok new"), second.events);
    }

    private static Thread findThread(String name) {
        for (Thread thread : Thread.getAllStackTraces().keySet()) {
            if (thread.getName().equals(name)) {
                return thread;
            }
        }
        throw new AssertionError("no thread " + name);
    }
}
