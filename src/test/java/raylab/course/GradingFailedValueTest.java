package raylab.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.platform.engine.TestExecutionResult;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Whether the grading failed in a test is a value set where that is known (the test JVM that
 * caught the grader's fault, the launcher whose guard fired), carried through the protocol's JSON,
 * never read from the message: a message that merely begins as a grader's did is the student's.
 */
class GradingFailedValueTest {
    private static final class Fault extends RuntimeException implements GraderFault {
        private static final long serialVersionUID = 1L;

        Fault(String m) {
            super(m);
        }
    }

    private static final TestResult EXPECTED = new TestResult("id", "raylab.surface.SphereTest", "hits", "hits()",
            TestResult.Status.MISSING, "", "", 0);

    @Test
    void aMessageThatLooksLikeTheGradersIsStillTheStudents() {
        TestResult r = EXPECTED.with(TestResult.Status.FAILED, "GradingFailure: the student wrote this");
        assertFalse(r.gradingFailed(), "a student's text decides no status: " + r);
    }

    @Test
    void aGradingFailureIsAFailedTestThatSaysSo() {
        TestResult r = EXPECTED.gradingFailure("the machine was too slow");
        assertEquals(TestResult.Status.FAILED, r.status());
        assertEquals("the machine was too slow", r.message());
        assertTrue(r.gradingFailed(), r.toString());
        assertFalse(r.with(TestResult.Status.MISSING, "not run").gradingFailed(), "a new verdict is the student's");
    }

    @Test
    void theValueCrossesTheProtocolsJson() throws Exception {
        ObjectMapper json = new ObjectMapper();
        for (boolean failed : new boolean[] {false, true}) {
            TestResult r = failed ? EXPECTED.gradingFailure("cause") : EXPECTED.with(TestResult.Status.FAILED, "cause");
            TestResult back = json.readValue(json.writeValueAsString(r), TestResult.class);
            assertEquals(r, back, "expected " + r + ", read back " + back);
        }
    }

    @Test
    void aGradersFaultIsReportedAsItsCauseWithoutAnExceptionName() {
        String fault = TestMain.firstLines(TestExecutionResult.failed(new Fault("killed twice")));
        assertTrue(fault.startsWith("killed twice"), fault);
        String student = TestMain.firstLines(TestExecutionResult.failed(new IllegalStateException("killed twice")));
        assertTrue(student.startsWith("IllegalStateException: killed twice"), student);
    }
}
