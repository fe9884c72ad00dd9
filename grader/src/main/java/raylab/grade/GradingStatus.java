package raylab.grade;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * Whether a grading decided the student's points, or failed on the grader's side: what each
 * platform's output renders ("the autograder failed" on Gradescope, {@code gradable: false} on
 * PrairieLearn, an infrastructure error on Classroom 50, grade-all's status column). A grading
 * failed when something the student's code did not cause stopped it: the machine's load or
 * memory (a student process killed from outside twice, a test's wall-clock guard fired while the
 * student's code had used less than its time), or the trusted side. Such a test or scene scores
 * 0 in the arithmetic, but no points were decided: the status says so, and the message is
 * {@link #STUDENT_MESSAGE} followed by the cause. A grading with one such part decided no grade
 * at all ({@link GradeReport#failed()}): a total that counts an undecided part as 0 is not the
 * student's grade, so every platform says the grading failed, and it is graded again.
 */
public enum GradingStatus {
    /** Every part ran to a verdict on the student's code. */
    GRADED("graded"),
    /** A part failed for a reason that is not the student's code: the course staff must look. */
    GRADING_FAILED("grading failed");

    /** What the student reads in place of a verdict; the cause follows it in parentheses. */
    public static final String STUDENT_MESSAGE = "The autograder failed here, not your code: no points were decided by"
            + " this part. The course staff must look at it and grade it again.";

    private final String label;

    GradingStatus(String label) {
        this.label = label;
    }

    /** The value of grade-all's status column. */
    public String label() {
        return label;
    }

    /** The message of a part whose grading failed, for {@code cause} (the trusted side's words, no student text). */
    static String message(String cause) {
        return STUDENT_MESSAGE + " (" + cause + ")";
    }

    /** The cause in a message made by {@link #message}; the message itself if it is not one. */
    static String cause(String message) {
        String prefix = STUDENT_MESSAGE + " (";
        return message.startsWith(prefix) && message.endsWith(")")
                ? message.substring(prefix.length(), message.length() - 1) : message;
    }

    /** The status of a report: failed if the grader marked any test or scene as failed on its side. */
    public static GradingStatus of(GradeReport report) {
        if (report != null) {
            for (GradeReport.Milestone m : report.milestones()) {
                for (GradeReport.Test t : m.tests()) {
                    if (t.status() == GRADING_FAILED) {
                        return GRADING_FAILED;
                    }
                }
            }
        }
        return GRADED;
    }

    /**
     * The key of a Gradescope results.json's {@code extra_data} ("Optional extra data to be
     * stored", Gradescope's autograder specification) that lists the numbers of the tests whose
     * grading failed; {@code raylab grade} writes it only when there is one.
     */
    public static final String FAILED_TESTS = "grading_failed_tests";

    /**
     * The status of a Gradescope results.json as {@code raylab grade} writes it, for grade-all,
     * which has only that file of each student's grading: the values in {@code extra_data} (the
     * whole grading failed: {@code grading_failed}; some of its parts: {@link #FAILED_TESTS}),
     * never the tests' messages, which hold the student's output too.
     */
    public static GradingStatus ofGradescope(JsonNode results) {
        JsonNode extra = results == null ? null : results.get("extra_data");
        if (extra != null && (extra.path("grading_failed").asBoolean(false) || extra.path(FAILED_TESTS).size() > 0)) {
            return GRADING_FAILED;
        }
        return GRADED;
    }
}
