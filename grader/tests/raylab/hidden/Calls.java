package raylab.hidden;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.function.BiFunction;

import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Surface;

/**
 * Calls the student's code the way a render does: on a worker thread named like the renderer's
 * ({@code raylab-render}), whose stack holds only JDK frames above the student's method. A
 * submission that inspects its caller's stack (to answer correctly only under a test) cannot
 * tell a graded check from a render, so it is graded on what it renders. Exceptions and errors
 * of the student's code are rethrown unchanged; a student method that never returns leaves a
 * daemon thread behind and the test fails by its timeout.
 */
public final class Calls {
    private static final ExecutorService WORKERS = Executors.newCachedThreadPool(r -> {
        Thread t = new Thread(r, "raylab-render");
        t.setDaemon(true);
        return t;
    });

    private Calls() {
    }

    /** {@code s.intersect(rec, ray)}, run on a worker thread; its result. */
    public static boolean intersect(Surface s, IntersectionRecord rec, Ray ray) {
        // A bound method reference: its adapter is a hidden class, so no frame of this class or
        // of a test sits on the worker's stack.
        BiFunction<IntersectionRecord, Ray, Boolean> call = s::intersect;
        CompletableFuture<Boolean> result = CompletableFuture.completedFuture(rec)
                .thenCombineAsync(CompletableFuture.completedFuture(ray), call, WORKERS);
        try {
            return result.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for intersect", e);
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof RuntimeException re) {
                throw re;
            }
            if (cause instanceof Error err) {
                throw err;
            }
            throw new IllegalStateException(cause);
        }
    }
}
