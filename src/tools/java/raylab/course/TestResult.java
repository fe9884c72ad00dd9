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
 */
public record TestResult(String id, String className, String method, String displayName, Status status,
        String message, String output, long millis) {

    /**
     * How the message of a test begins when the grading failed in it, not the student's code
     * (the trusted side's {@code raylab.boundary.GradingFailure}, or a time limit that fired on
     * time that was not the student's): no points are decided by such a test.
     */
    public static final String GRADING_FAILED = "GradingFailure: ";

    /** Whether this test's outcome is a failure of the grading itself ({@link #GRADING_FAILED}). */
    public boolean gradingFailed() {
        return status != Status.PASSED && message != null && message.startsWith(GRADING_FAILED);
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
        return new TestResult(id, className, method, displayName, s, why, output, millis);
    }
}
