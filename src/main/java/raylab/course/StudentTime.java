package raylab.course;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A test's time limit through the process boundary, measured in the student's own time: the
 * CPU time of the student process during the test, or the wall time of its calls less the time
 * they waited for a CPU or for the grader's answers, whichever is more
 * ({@code raylab.boundary.StudentProcess#studentTimeNanos}). The student process's watchdog
 * stops a call at its own budget and at the test's limit ({@code StudentProcess#startTest});
 * JUnit's clock runs on wall time and is only a guard ({@link #guardSeconds}); when it fires,
 * this says whose time it was.
 */
final class StudentTime {
    private final int limitSeconds;
    private final Map<String, long[]> atStart = new ConcurrentHashMap<>();

    StudentTime(int limitSeconds) {
        this.limitSeconds = limitSeconds;
    }

    /** JUnit's wall-clock guard for a limit of {@code seconds} of the student's time. */
    static int guardSeconds(int seconds) {
        return 6 * seconds + 60;
    }

    /** A test begins: the student process stops a call once the test's student time passes the limit. */
    void start(String test) {
        atStart.put(test, now());
        try {
            Class.forName("raylab.boundary.Remote").getMethod("startTest", long.class).invoke(null,
                    limitSeconds * 1_000_000_000L);
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
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

    /** The message of a guard that fired on time that was not the student's: the grading failed. */
    String notTheStudents(long wallMillis) {
        return TestResult.GRADING_FAILED + "the test ran " + wallMillis / 1000 + " s of wall time while the"
                + " student's code used less than its " + limitSeconds + " s: the machine or the grader was too slow"
                + " (not the student's code)";
    }

    private static long[] now() {
        try {
            Class<?> remote = Class.forName("raylab.boundary.Remote");
            return new long[] {(long) remote.getMethod("studentNanos").invoke(null),
                (long) remote.getMethod("studentCpuNanos").invoke(null)};
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            return new long[2];
        }
    }
}
