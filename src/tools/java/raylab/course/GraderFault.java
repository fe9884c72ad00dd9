package raylab.course;

/**
 * Marks an exception that reports a failure of the grading itself, not of the student's code
 * (the grader's {@code raylab.boundary.GradingFailure}): the test JVM reports a test that ends
 * with one as {@link TestResult#gradingFailed()}, a value, whatever its message says.
 */
public interface GraderFault {
}
