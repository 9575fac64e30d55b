package ifold.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

class WorkersTest {
    @Test
    void everyIndexIsRunOnceWhateverThreadTakesIt() {
        int n = 100_003;
        int[] runs = new int[n];
        Set<Object> scratches = ConcurrentHashMap.newKeySet();
        Workers.forChunks(n, 1000, Object::new, (from, to, scratch) -> {
            scratches.add(scratch);
            for (int k = from; k < to; k++) {
                runs[k]++;
            }
        });
        int[] once = new int[n];
        java.util.Arrays.fill(once, 1);
        assertArrayEquals(once, runs);
        // One scratch for each thread that took part, never one for each chunk.
        assertTrue(scratches.size() <= Workers.threads(), scratches.size() + " scratches");
    }

    @Test
    @Timeout(20)
    void theCallerDoesNotWaitForAPoolBusyWithOtherWork() throws Exception {
        // Every thread of the pool held by another task: the caller does all the chunks itself.
        // (The pool was sized when first used, perhaps while another test asked for more threads.)
        int poolThreads = ((java.util.concurrent.ThreadPoolExecutor) Workers.pool()).getMaximumPoolSize();
        CountDownLatch release = new CountDownLatch(1);
        CountDownLatch held = new CountDownLatch(poolThreads);
        java.util.List<Future<?>> holding = new java.util.ArrayList<>();
        for (int t = 0; t < poolThreads; t++) {
            holding.add(Workers.pool().submit(() -> {
                held.countDown();
                release.await();
                return null;
            }));
        }
        try {
            assertTrue(held.await(10, TimeUnit.SECONDS));
            Thread caller = Thread.currentThread();
            long[] sum = new long[1];
            Workers.forChunks(10_000, 100, () -> null, (from, to, scratch) -> {
                assertSame(caller, Thread.currentThread());
                for (int k = from; k < to; k++) {
                    sum[0] += k;
                }
            });
            assertEquals(10_000L * 9_999 / 2, sum[0]);
        } finally {
            release.countDown();
            for (Future<?> f : holding) {
                f.get();
            }
        }
    }

    @Test
    void whatABodyThrowsIsThrownToTheCaller() {
        IllegalStateException thrown = assertThrows(IllegalStateException.class,
                () -> Workers.forChunks(50_000, 10, () -> null, (from, to, scratch) -> {
                    if (from <= 31_337 && 31_337 < to) {
                        throw new IllegalStateException("index 31337");
                    }
                }));
        assertEquals("index 31337", thrown.getMessage());
    }

    @Test
    void nothingToDoRunsNothing() {
        Workers.forChunks(0, 10, () -> {
            throw new AssertionError("no scratch is made for no work");
        }, (from, to, scratch) -> {
            throw new AssertionError("no chunk");
        });
    }
}
