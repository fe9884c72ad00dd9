package raylab.boundary;

/**
 * The grading itself failed, not the student's code: something the student's code did not cause
 * (the machine's memory or load, the trusted side) stopped a call twice in a row. No points are
 * decided by it; the grader reports the milestone as "the autograder failed"
 * ({@code raylab.grade.GradingStatus}), never as the student's failure. A test that ends with it is
 * {@code TestResult.gradingFailed()} ({@link raylab.course.GraderFault}).
 */
public final class GradingFailure extends RuntimeException implements raylab.course.GraderFault {
    private static final long serialVersionUID = 1L;

    /**
     * The file beside a scene's PNG that says its render's error ({@code .err}) is a grading
     * failure, not the student's: the status as a value, whatever the error's text.
     */
    public static final String RENDER_MARKER = ".grading-failed";

    public GradingFailure(String message) {
        super(message);
    }
}
