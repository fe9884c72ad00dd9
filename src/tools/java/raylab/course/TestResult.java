package raylab.course;

/**
 * The result of one test, as the test runner reported it (or as the launcher concluded when the
 * runner could not report: timed out, crashed, missing).
 *
 * @param id          JUnit unique id
 * @param className   test class
 * @param method      test method (or the dynamic test's display name)
 * @param displayName name for people
 * @param status      what happened
 * @param message     the failure message (first lines), empty when passed
 * @param output      what the test printed (capped)
 * @param millis      duration
 * @param gradingFailed whether the grading failed in this test, not the student's code (the trusted
 *                    side's {@link GraderFault}, or a time limit that fired on time that was not the
 *                    student's): no points are decided by it; set where that is known, never read
 *                    from the message
 */
public record TestResult(String id, String className, String method, String displayName, Status status,
        String message, String output, long millis, boolean gradingFailed) {

    /** A result of the student's code (not a failure of the grading). */
    public TestResult(String id, String className, String method, String displayName, Status status,
            String message, String output, long millis) {
        this(id, className, method, displayName, status, message, output, millis, false);
    }

    /** What happened to a test. */
    public enum Status {
        PASSED, FAILED, ABORTED, TIMED_OUT, CRASHED, MISSING;

        public boolean passed() {
            return this == PASSED;
        }
    }

    /** A copy with another status and message (used by the launcher when it knows more). */
    public TestResult with(Status s, String why) {
        return new TestResult(id, className, method, displayName, s, why, output, millis, false);
    }

    /** A copy that failed because the grading failed, not the student's code: {@code why} is the cause. */
    public TestResult gradingFailure(String why) {
        return new TestResult(id, className, method, displayName, Status.FAILED, why, output, millis, true);
    }
}
