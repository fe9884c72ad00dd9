package raylab.hidden;

import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Surface;
import raylab.testing.Check;

/**
 * Calls the student's code the way a render does (grader only): on a worker thread named like the
 * renderer's ({@code raylab-render}), whose stack holds only JDK frames above the student's method
 * ({@link Check#intersect}, which the visible tests use too). A submission that inspects its
 * caller's stack, to answer correctly only under a test, cannot tell a graded check from a render,
 * so it is graded on what it renders. Exceptions and errors of the student's code are rethrown
 * unchanged; a method that never returns leaves a daemon thread behind and the test fails by its
 * timeout.
 */
public final class Calls {
    private Calls() {
    }

    /** {@code s.intersect(rec, ray)}, run on a worker thread; its result. */
    public static boolean intersect(Surface s, IntersectionRecord rec, Ray ray) {
        return Check.intersect(s, rec, ray);
    }
}
