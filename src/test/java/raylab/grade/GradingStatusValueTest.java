package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.boundary.GradingFailure;

/**
 * A report's status is the value the grader set on its tests and scenes where it knew the grading
 * failed, not a match on their messages; a scene's render says it with a marker file beside its
 * error, whatever the error's text.
 */
class GradingStatusValueTest {
    private static GradeReport report(String message, GradingStatus status) {
        GradeReport.Test t = new GradeReport.Test("sphere", "hits", GradeReport.Kind.VISIBLE, 2, 0, false, message,
                "", "visible", 1, "SphereTest.java", null, "", status);
        return new GradeReport(List.of(new GradeReport.Milestone("sphere", "Sphere", List.of(), List.of(t))),
                List.of(), List.of(), List.of(), 1);
    }

    @Test
    void theStatusIsTheTestsValue() {
        assertEquals(GradingStatus.GRADED, GradingStatus.of(report(GradingStatus.STUDENT_MESSAGE + " (printed by"
                + " the student)", GradingStatus.GRADED)), "a student's text that looks like the grader's decides nothing");
        assertEquals(GradingStatus.GRADING_FAILED, GradingStatus.of(report(GradingStatus.message("too slow"),
                GradingStatus.GRADING_FAILED)));
        assertEquals(GradingStatus.GRADED, GradingStatus.of(null));
    }

    /**
     * grade-all reads a student's status from the Gradescope results.json the grading wrote: a
     * value in its {@code extra_data} (the failed parts' numbers), not the text of the tests,
     * which holds the student's output too.
     */
    @Test
    void gradescopesResultsCarryTheStatusAsAValue() throws Exception {
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        // The student's code printed the grader's sentence: its test failed, and was graded.
        GradeReport.Test printed = new GradeReport.Test("sphere", "hits", GradeReport.Kind.VISIBLE, 2, 0, false,
                "expected: <4.0> but was: <6.0>", GradingStatus.message("printed by the student"), "visible", 1,
                "SphereTest.java", null, "", GradingStatus.GRADED);
        GradeReport.Test passed = new GradeReport.Test("sphere", "misses", GradeReport.Kind.VISIBLE, 2, 2, true, "", "",
                "visible", 1, "SphereTest.java", null, "", GradingStatus.GRADED);
        GradeReport.Test failed = new GradeReport.Test("sphere", "scenes/spheres.json", GradeReport.Kind.SCENE, 2, 0, false,
                GradingStatus.message("the grader's render JVM ran out of its memory"), "", "visible", 1,
                "scenes/spheres.json", null, "", GradingStatus.GRADING_FAILED);
        com.fasterxml.jackson.databind.JsonNode graded = json.readTree(Reports.gradescope(new GradeReport(List.of(
                new GradeReport.Milestone("sphere", "Sphere", List.of(), List.of(printed, passed))), List.of(), List.of(),
                List.of(), 1)));
        assertTrue(graded.get("tests").get(0).get("output").asText().contains(GradingStatus.STUDENT_MESSAGE),
                "the student's output is shown: " + graded);
        assertEquals(GradingStatus.GRADED, GradingStatus.ofGradescope(graded), "its text decides nothing: " + graded);
        assertFalse(graded.has("extra_data"), "nothing failed: " + graded);
        com.fasterxml.jackson.databind.JsonNode partly = json.readTree(Reports.gradescope(new GradeReport(List.of(
                new GradeReport.Milestone("sphere", "Sphere", List.of(), List.of(passed, failed))), List.of(), List.of(),
                List.of(), 1)));
        assertEquals(GradingStatus.GRADING_FAILED, GradingStatus.ofGradescope(partly), partly.toString());
        assertEquals("[\"1.2\"]", partly.get("extra_data").get(GradingStatus.FAILED_TESTS).toString(), partly.toString());
        com.fasterxml.jackson.databind.JsonNode whole = json.readTree(Reports.gradescope(Grader.failed("no reference", 1)));
        assertEquals(GradingStatus.GRADING_FAILED, GradingStatus.ofGradescope(whole), whole.toString());
    }

    @Test
    void copiesKeepTheStatus() {
        GradeReport.Test t = report("m", GradingStatus.GRADING_FAILED).milestones().get(0).tests().get(0);
        assertEquals(GradingStatus.GRADING_FAILED, t.withNote("n").status());
        assertEquals(GradingStatus.GRADED, t.withStatus(GradingStatus.GRADED).status());
        assertEquals(GradingStatus.GRADED, new GradeReport.Test("s", "n", GradeReport.Kind.SCENE, 1, 0, false, "m", "",
                "visible", 0, "f", null).status(), "a test built without a status was graded");
    }

    @Test
    void aFailedGradingIsTheCauseTheGraderCarriedNotANotesText() {
        // A milestone note can quote the student's code or output: its text decides nothing.
        GradeReport.Milestone quoted = new GradeReport.Milestone("sphere", "Sphere",
                List.of(GradeReport.FAILED + "printed by the student"), List.of());
        GradeReport graded = new GradeReport(List.of(quoted), List.of(), List.of(),
                List.of(GradeReport.FAILED + "a general note of that text"), 1);
        assertFalse(graded.failed(), () -> "no cause was carried, yet failure() = " + graded.failure());

        GradeReport.Milestone cannot = new GradeReport.Milestone("box", "Box", List.of(GradeReport.FAILED + "no reference"),
                List.of(), "no reference");
        GradeReport oneMilestone = new GradeReport(List.of(quoted, cannot), List.of(), List.of(), List.of(), 1);
        assertEquals("box: no reference", oneMilestone.failure());

        GradeReport whole = Grader.failed("the hidden tests do not compile", 1);
        assertTrue(whole.failed());
        assertEquals("the hidden tests do not compile", whole.failure());
        assertEquals(List.of(), whole.studentNotes(), "the cause is for the course staff only");
    }

    @Test
    void aRenderSaysItsGradingFailedWithAMarkerNotItsText(@TempDir Path dir) throws Exception {
        Path graders = dir.resolve("scene0.png");
        Files.writeString(Path.of(graders + ".err"), "the student process was killed twice");
        Files.writeString(Path.of(graders + GradingFailure.RENDER_MARKER), "");
        Path students = dir.resolve("scene1.png");
        Files.writeString(Path.of(students + ".err"), "GradingFailure: thrown by the student's code");
        List<SceneGrading.Render> r = SceneGrading.read(List.of(graders, students));
        assertTrue(r.get(0).gradingFailed(), r.get(0).toString());
        assertEquals("the student process was killed twice", r.get(0).error());
        assertFalse(r.get(1).gradingFailed(), r.get(1).toString());
        assertEquals("GradingFailure: thrown by the student's code", r.get(1).error());
        assertTrue(SceneGrading.gradingsFailure(r.get(0)), "marked");
        assertFalse(SceneGrading.gradingsFailure(r.get(1)), "the student's error");
    }

    /**
     * A scene the render JVM left with neither an image nor an error (it crashed, ran out of its
     * own memory or was stopped by its guard: it runs no code of the student's) is the grading's
     * failure; one stopped at the renders' limit in the student's time stays the student's.
     */
    @Test
    void aSceneTheRenderJvmDidNotFinishIsTheGradingsFailure(@TempDir Path dir) throws Exception {
        Path unfinished = dir.resolve("scene0.png");
        Path late = dir.resolve("scene1.png");
        Files.writeString(Path.of(late + ".timeout"), "");
        List<SceneGrading.Render> r = SceneGrading.read(List.of(unfinished, late));
        assertEquals(null, r.get(0).image());
        assertTrue(SceneGrading.gradingsFailure(r.get(0)), r.get(0).toString());
        assertTrue(r.get(1).late(), r.get(1).toString());
        assertFalse(SceneGrading.gradingsFailure(r.get(1)), r.get(1).toString());
    }
}
