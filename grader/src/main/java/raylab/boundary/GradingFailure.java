package raylab.boundary;

/**
 * The grading itself failed, not the student's code: something the student's code did not cause
 * (the machine's memory or load, the trusted side) stopped a call twice in a row. No points are
 * decided by it; the grader reports the milestone as "the autograder failed"
 * ({@code raylab.grade.GradingStatus}), never as the student's failure.
 */
public final class GradingFailure extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** How a test's message that reports one begins (JUnit's listener writes the simple class name first). */
    public static final String PREFIX = raylab.course.TestResult.GRADING_FAILED;

    public GradingFailure(String message) {
        super(message);
    }
}
