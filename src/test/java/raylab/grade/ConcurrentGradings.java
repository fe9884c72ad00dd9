package raylab.grade;

import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Gradings a test class needs, run a few at a time in the background (docs/testing.md): a
 * grading is mostly its children's work under their own CPU limits and waits (render time-outs,
 * a detached forger's delay), so a class that queues all of them in its {@code @BeforeAll} (unless
 * {@link #oneTestSelected}) and has each test ask for the ones it asserts on takes about as long
 * as its longest few gradings instead of their sum. Each grading runs once per key, on a pool
 * thread or on the test's own if none has begun it; its failure (an assertion inside it
 * included) is rethrown, as it was, by {@link #get} in every test that asks for it.
 */
final class ConcurrentGradings<T> implements AutoCloseable {
    /** A grading: what it returns, or what it throws. */
    interface Grading<T> {
        T call() throws Exception;
    }

    private final ExecutorService pool;
    private final Map<String, Task<T>> started = new ConcurrentHashMap<>();

    /** One grading: run by whichever comes first, a pool thread or a test that needs it now. */
    private static final class Task<T> {
        final CompletableFuture<T> result = new CompletableFuture<>();
        final AtomicBoolean claimed = new AtomicBoolean();
        final Grading<T> grading;

        Task(Grading<T> grading) {
            this.grading = grading;
        }

        /** Runs the grading unless another thread has begun it (or it was dropped). */
        void runIfUnclaimed() {
            if (!claimed.compareAndSet(false, true)) {
                return;
            }
            try {
                result.complete(grading.call());
            } catch (Throwable e) {
                result.completeExceptionally(e);
            }
        }
    }

    /** A pool of {@code concurrent} daemon threads named {@code name}. */
    ConcurrentGradings(String name, int concurrent) {
        pool = Executors.newFixedThreadPool(concurrent, r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            return t;
        });
    }

    /** Queues the grading under {@code key} unless it was started before. */
    void start(String key, Grading<T> grading) {
        started.computeIfAbsent(key, k -> {
            Task<T> t = new Task<>(grading);
            pool.execute(t::runIfUnclaimed);
            return t;
        });
    }

    /**
     * The grading under {@code key}: run here and now if no pool thread has begun it (a test
     * never waits behind gradings it does not need), else awaited; its failure (an assertion
     * inside it included) is rethrown as it was.
     */
    T get(String key, Grading<T> grading) throws Exception {
        Task<T> t = started.computeIfAbsent(key, k -> new Task<>(grading));
        t.runIfUnclaimed();
        try {
            return t.result.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof Exception x) {
                throw x;
            }
            if (e.getCause() instanceof Error x) {
                throw x;
            }
            throw e;
        }
    }

    /**
     * Drops the gradings not yet begun (no selected test asked for them, as with
     * {@code -Dtest=Class#method}) and waits for those running, so that none outlives its class.
     */
    @Override
    public void close() throws InterruptedException {
        started.values().forEach(t -> t.claimed.set(true));
        pool.shutdown();
        pool.awaitTermination(15, TimeUnit.MINUTES);
    }

    /**
     * Whether single test methods were selected ({@code -Dtest=Class#method}, a Maven user
     * property that surefire passes to the test JVM): then queuing every grading of the class
     * would only delay the one asked for.
     */
    static boolean oneTestSelected() {
        return System.getProperty("test", "").contains("#");
    }
}
