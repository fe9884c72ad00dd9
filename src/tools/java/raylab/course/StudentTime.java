package raylab.course;

import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A test's time limit through the process boundary, measured in the student's own time: the
 * CPU time of the student process during the test, or the wall time of its calls less the time
 * they waited for a CPU or for the grader's answers, whichever is more
 * ({@link BoundaryHooks#studentNanos}, {@link BoundaryHooks#studentCpuNanos}). The student process's watchdog
 * stops a call at its own budget and at the test's limit ({@link BoundaryHooks#startTest});
 * JUnit's clock runs on wall time and is only a guard ({@link #guardSeconds}); when it fires,
 * this says whose time it was.
 */
final class StudentTime {
    private final int limitSeconds;
    /** The student process's clocks; empty: no student process (nothing to limit, times 0). */
    private final Optional<BoundaryHooks> boundary;
    private final Map<String, long[]> atStart = new ConcurrentHashMap<>();

    StudentTime(int limitSeconds, Optional<BoundaryHooks> boundary) {
        this.limitSeconds = limitSeconds;
        this.boundary = boundary;
    }

    /** JUnit's wall-clock guard for a limit of {@code seconds} of the student's time. */
    static int guardSeconds(int seconds) {
        return 6 * seconds + 60;
    }

    /** A test begins: the student process stops a call once the test's student time passes the limit. */
    void start(String test) {
        atStart.put(test, now());
        try {
            boundary.ifPresent(b -> b.startTest(limitSeconds * 1_000_000_000L));
        } catch (RuntimeException | LinkageError e) {
            // no student process: nothing to limit
        }
    }

    /** Why the student's code is at fault after the guard fired (its own time reached the limit), or null. */
    String overLimit(String test, long wallMillis) {
        long[] a = atStart.getOrDefault(test, new long[2]);
        long[] b = now();
        long own = Math.max(b[0] - a[0], b[1] - a[1]);
        if (own >= limitSeconds * 1_000_000_000L) {
            return "your code took longer than " + limitSeconds + " s in this test (an endless loop?)";
        }
        return null;
    }

    /** The cause of a guard that fired on time that was not the student's: the grading failed. */
    String notTheStudents(long wallMillis) {
        return "the test ran " + wallMillis / 1000 + " s of wall time while the"
                + " student's code used less than its " + limitSeconds + " s: the machine or the grader was too slow"
                + " (not the student's code)";
    }

    private long[] now() {
        try {
            return boundary.map(b -> new long[] {b.studentNanos(), b.studentCpuNanos()}).orElseGet(() -> new long[2]);
        } catch (RuntimeException | LinkageError e) {
            return new long[2];
        }
    }
}
