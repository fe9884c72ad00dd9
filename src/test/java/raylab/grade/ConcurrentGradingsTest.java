package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.opentest4j.AssertionFailedError;

/**
 * What the attack tests rely on when they grade concurrently: each grading runs once per key
 * however many tests ask for it, a test never waits behind a grading it does not need, a
 * failure inside a grading reaches each test that asks for it as it was thrown, and gradings no
 * test asked for are dropped at the end. Ordered by latches and thread states, not by time.
 */
class ConcurrentGradingsTest {

    @Test
    void aGradingRunsOncePerKeyForEveryTestThatAsks() throws Exception {
        AtomicInteger runs = new AtomicInteger();
        try (ConcurrentGradings<String> g = new ConcurrentGradings<>("test-grading", 2)) {
            g.start("a", () -> "graded " + runs.incrementAndGet());
            assertEquals("graded 1", g.get("a", () -> "graded " + runs.incrementAndGet()));
            assertEquals("graded 1", g.get("a", () -> "graded " + runs.incrementAndGet()));
        }
        assertEquals(1, runs.get(), "runs of the grading under key a");
    }

    @Test
    void aTestRunsAQueuedGradingItselfWhenThePoolIsBusy() throws Exception {
        CountDownLatch release = new CountDownLatch(1);
        CountDownLatch busy = new CountDownLatch(1);
        List<String> threads = new CopyOnWriteArrayList<>();
        try (ConcurrentGradings<String> g = new ConcurrentGradings<>("test-grading", 1)) {
            g.start("slow", () -> {
                busy.countDown();
                release.await();
                return "slow";
            });
            busy.await();
            g.start("queued", () -> {
                threads.add(Thread.currentThread().getName());
                return "queued";
            });
            // The one pool thread is held by "slow": a test asking for "queued" runs it itself.
            List<String> got = new CopyOnWriteArrayList<>();
            Thread test = new Thread(() -> {
                try {
                    got.add(g.get("queued", () -> "not this one"));
                } catch (Exception e) {
                    got.add(e.toString());
                }
            }, "the test");
            test.start();
            // Done, or (wrongly) waiting behind "slow".
            while (test.isAlive() && test.getState() != Thread.State.WAITING) {
                Thread.onSpinWait();
            }
            release.countDown();
            test.join();
            assertEquals(List.of("the test"), threads, "threads that ran the queued grading before \"slow\" ended");
            assertEquals(List.of("queued"), got);
            assertEquals("slow", g.get("slow", () -> "not this one"));
        }
        assertEquals(1, threads.size(), "runs of the queued grading (the pool's turn came after the test's)");
    }

    @Test
    void aFailureReachesEveryTestThatAsksAsItWasThrown() throws Exception {
        IOException io = new IOException("no results.json");
        AssertionFailedError failed = new AssertionFailedError("graded ==> expected: <0> but was: <1>");
        try (ConcurrentGradings<String> g = new ConcurrentGradings<>("test-grading", 2)) {
            g.start("io", () -> {
                throw io;
            });
            g.start("assertion", () -> {
                throw failed;
            });
            assertSame(io, assertThrows(IOException.class, () -> g.get("io", () -> "x")));
            assertSame(io, assertThrows(IOException.class, () -> g.get("io", () -> "x")));
            assertSame(failed, assertThrows(AssertionFailedError.class, () -> g.get("assertion", () -> "x")));
        }
    }

    @Test
    void closeDropsTheGradingsNotBegunAndWaitsForTheRunningOnes() throws Exception {
        CountDownLatch release = new CountDownLatch(1);
        CountDownLatch busy = new CountDownLatch(1);
        AtomicInteger finished = new AtomicInteger();
        AtomicInteger dropped = new AtomicInteger();
        ConcurrentGradings<String> g = new ConcurrentGradings<>("test-grading", 1);
        g.start("running", () -> {
            busy.countDown();
            release.await();
            finished.incrementAndGet();
            return "running";
        });
        busy.await();
        g.start("queued", () -> {
            dropped.incrementAndGet();
            return "queued";
        });
        Thread closer = new Thread(() -> {
            try {
                g.close();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        closer.start();
        // close() has dropped what was queued once it waits for the pool (its only timed wait).
        while (closer.getState() != Thread.State.TIMED_WAITING) {
            Thread.onSpinWait();
        }
        release.countDown();
        closer.join();
        assertEquals(1, finished.get(), "the running grading finished before close returned");
        assertEquals(0, dropped.get(), "runs of the grading no test asked for");
    }
}
