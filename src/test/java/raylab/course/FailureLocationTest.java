package raylab.course;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import org.junit.platform.engine.TestExecutionResult;

/**
 * A failed test's message names where to look ("(at CLASS.METHOD:LINE)") in the student's code,
 * the framework or the test, never in the grading's machinery (the process boundary, the grader,
 * the test launcher), which a student cannot open and which would only show the grader's lines.
 */
class FailureLocationTest {
    private static StackTraceElement at(String cls, String method, int line) {
        return new StackTraceElement(cls, method, cls.substring(cls.lastIndexOf('.') + 1) + ".java", line);
    }

    private static String message(StackTraceElement... stack) {
        IllegalStateException e = new IllegalStateException("the student process ended");
        e.setStackTrace(stack);
        return TestMain.firstLines(TestExecutionResult.failed(e));
    }

    @Test
    void theFirstPlaceAStudentCanOpenIsNamed() {
        assertEquals("IllegalStateException: the student process ended (at raylab.surface.SphereTest.hitsFront:42)",
                message(at("java.lang.Thread", "run", 1), at("raylab.boundary.StudentProcess", "start", 179),
                        at("raylab.remote.Wire", "read", 88), at("raylab.grade.Grader", "grade", 5),
                        at("raylab.course.TestMain", "main", 9), at("raylab.cli.Main", "run", 3),
                        at("raylab.surface.SphereTest", "hitsFront", 42), at("raylab.surface.Sphere", "intersect", 30)));
        assertEquals("IllegalStateException: the student process ended (at raylab.surface.Sphere.intersect:31)",
                message(at("raylab.surface.Sphere", "intersect", 31), at("raylab.surface.SphereTest", "hitsFront", 42)));
    }

    @Test
    void onlyMachineryNamesNoPlace() {
        assertEquals("IllegalStateException: the student process ended",
                message(at("raylab.boundary.StudentProcess", "start", 179), at("org.junit.Foo", "x", 1)));
    }

    @Test
    void notImplementedIsTheStudentsOwnMarker() {
        assertEquals(false, TestMain.isMachinery(NotImplemented.class.getName()), "the starter's marker");
        assertEquals(true, TestMain.isMachinery("raylab.course.TestMain"));
        assertEquals(false, TestMain.isMachinery("raylab.shading.Shadows"));
    }
}
