package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.course.FileTrees;
import raylab.grade.GradeReport.Kind;
import raylab.grade.platform.PrairieLearn;

/**
 * Never a silent wrong grade (issue 36, items 1 and 3): a grading that failed says so on every
 * platform's student-facing fields, with no score, no cause, no instructor path and no hidden
 * name; the cause is in the instructors' report. And the instructor's notes (the variants' seed,
 * a scene graded as published that asks to narrow its bounds, the sandbox mode, the grader's
 * setup) are never on a student's page. Every student-visible field is read, as in
 * {@link BeforeDueDateTest}.
 */
class FailedGradingTest {
    static final ObjectMapper JSON = new ObjectMapper();
    /** A cause as the grader gives it: the instructor's path and a hidden test's file name. */
    static final String CAUSE = "the grader's tests do not compile (grader setup problem): "
            + "/home/prof/raylab/grader/tests/raylab/surface/SphereHiddenTest.java:12: cannot find symbol";
    static final List<String> SECRETS = List.of("/home/prof", "grader/tests", "SphereHiddenTest", "cannot find symbol",
            "scene variants: seed", "graded as published", "narrow its", "sandbox:", "grader setup");

    @TempDir
    Path dir;

    /** Every student-visible text of Gradescope's results.json: top-level fields and visible tests. */
    static String gradescopeShown(JsonNode root) {
        List<String> shown = new ArrayList<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = root.fields(); it.hasNext();) {
            Map.Entry<String, JsonNode> e = it.next();
            if (!e.getKey().equals("tests")) {
                shown.add(e.getKey() + "=" + (e.getValue().isTextual() ? e.getValue().asText() : e.getValue().toString()));
            }
        }
        for (JsonNode t : root.path("tests")) {
            if (t.path("visibility").asText().equals("visible")) {
                shown.add(t.toString());
            }
        }
        return String.join("\n", shown);
    }

    /** Every field of PrairieLearn's results.json (all of it is shown at once). */
    static String prairieLearnShown(JsonNode root) {
        return root.toString();
    }

    static void assertNoSecret(String shown, String where) {
        for (String s : SECRETS) {
            assertFalse(shown.contains(s), () -> where + " shows '" + s + "' to students:\n" + shown);
        }
    }

    @Test
    void aFailedGradingSaysSoOnEveryPlatformWithoutScoreOrCause() throws IOException {
        GradeReport r = Grader.failed(CAUSE, 1.5);
        assertTrue(r.failed());
        assertEquals(CAUSE, r.failure());

        JsonNode gs = JSON.readTree(Reports.gradescope(r));
        String shown = gradescopeShown(gs);
        assertFalse(gs.has("score"), "Gradescope: no score was decided: " + gs);
        assertEquals(0, gs.get("tests").size(), "Gradescope: no score table: " + gs);
        assertEquals(GradeReport.FAILED_FOR_STUDENTS, gs.get("output").asText());
        assertTrue(gs.path("extra_data").path("grading_failed").asBoolean(), gs.toString());
        assertNoSecret(shown, "Gradescope");
        assertFalse(shown.contains("Nothing to fix"), shown);

        JsonNode pl = JSON.readTree(PrairieLearn.results(r, false));
        assertFalse(pl.get("gradable").asBoolean(), "PrairieLearn: not gradable: " + pl);
        assertEquals(GradeReport.FAILED_FOR_STUDENTS, pl.get("message").asText());
        assertEquals(0, pl.get("tests").size(), pl.toString());
        assertNoSecret(prairieLearnShown(pl), "PrairieLearn");
        assertNoSecret(prairieLearnShown(JSON.readTree(PrairieLearn.results(r, true))), "PrairieLearn after the due date");

        String students = HtmlReport.forStudents(r);
        assertTrue(students.contains("The autograder failed"), students);
        assertFalse(students.contains("Nothing to fix"), students);
        assertNoSecret(students, "the students' page");

        String instructors = Reports.html(r);
        assertTrue(instructors.contains("SphereHiddenTest.java:12: cannot find symbol"),
                "the instructors' report has the cause: " + instructors);
        assertTrue(Reports.summary(r).contains(CAUSE), "the console summary has the cause");
    }

    /**
     * A part that failed on the grader's side (here a hidden test whose trusted JVM ran out of its
     * own memory) leaves no grade: a total that counts it as 0 is not the student's. Every
     * platform says the grading failed, as when the grading could not run; the instructors'
     * report names the part and its cause, and the other parts as graded.
     */
    @Test
    void aPartThatFailedOnTheGradersSideDecidesNoGrade() throws IOException {
        String cause = "the grader's test JVM ended early (exit status 3) during this test";
        List<GradeReport.Test> tests = List.of(
                new GradeReport.Test("sphere", "a ray that misses", Kind.VISIBLE, 1, 1, true, "", "", "visible", 3,
                        "SphereTest.java", null),
                new GradeReport.Test("sphere", "SphereHiddenTest: grazing rays", Kind.HIDDEN, 2, 0, false,
                        GradingStatus.message(cause), "", "after_due_date", 3, "SphereHiddenTest.java", null, "",
                        GradingStatus.GRADING_FAILED),
                new GradeReport.Test("sphere", "scenes/sphere.json", Kind.SCENE, 1, 1, true, "", "", "visible", 3,
                        "scenes/sphere.json", null));
        GradeReport r = new GradeReport(List.of(new GradeReport.Milestone("sphere", "Ray-sphere intersection",
                List.of(), tests)), List.of(), List.of(), List.of(), 2.0);
        assertTrue(r.failed(), "no grade was decided");
        assertEquals("sphere: the grading of SphereHiddenTest: grazing rays failed on the grader's side: " + cause,
                r.failure());

        JsonNode gs = JSON.readTree(Reports.gradescope(r));
        assertFalse(gs.has("score"), "Gradescope: no score, not 2 of 4: " + gs);
        assertEquals(0, gs.get("tests").size(), "Gradescope: no score table: " + gs);
        assertEquals(GradeReport.FAILED_FOR_STUDENTS, gs.get("output").asText());
        assertTrue(gs.path("extra_data").path("grading_failed").asBoolean(), gs.toString());
        assertEquals("[\"1.2\"]", gs.path("extra_data").path(GradingStatus.FAILED_TESTS).toString(),
                "the failed part, as a value: " + gs);
        assertEquals(GradingStatus.GRADING_FAILED, GradingStatus.ofGradescope(gs));
        assertNoSecret(gradescopeShown(gs), "Gradescope");

        for (boolean after : new boolean[] {false, true}) {
            JsonNode pl = JSON.readTree(PrairieLearn.results(r, after));
            assertFalse(pl.get("gradable").asBoolean(), "PrairieLearn: not gradable, no attempt charged: " + pl);
            assertEquals(GradeReport.FAILED_FOR_STUDENTS, pl.get("message").asText());
            assertNoSecret(prairieLearnShown(pl), "PrairieLearn");
        }

        String students = HtmlReport.forStudents(r);
        assertTrue(students.contains("The autograder failed"), students);
        assertNoSecret(students, "the students' page");
        String instructors = Reports.html(r);
        assertTrue(instructors.contains(HtmlReport.esc(cause)), "the instructors' report has the cause: " + instructors);
        assertTrue(instructors.contains("1 of 2 tests and data cases passed") && instructors.contains("scenes/sphere.json"),
                "and the parts that were graded: " + instructors);
        assertTrue(Reports.summary(r).startsWith("Grading failed, no points decided: sphere: the grading of"),
                Reports.summary(r));
    }

    /** A report with every instructor note the grader writes, and a student's own note. */
    static GradeReport withStaffNotes() {
        List<GradeReport.Test> tests = List.of(
                new GradeReport.Test("sphere", "a ray that misses", Kind.VISIBLE, 1, 0, false, "no hit expected", "",
                        "visible", 3, "SphereTest.java", null),
                new GradeReport.Test("sphere", "scenes/sphere.json", Kind.SCENE, 1, 1, true, "", "", "visible", 3,
                        "scenes/sphere.json", null));
        return new GradeReport(List.of(new GradeReport.Milestone("sphere", "Ray-sphere intersection", List.of(), tests)),
                List.of("src/main/java/raylab/surface/Sphere.java <- Sphere.java"), List.of(), List.of(
                        "sandbox: none (student code runs as prof; not isolated: network)",
                        "grader setup: raylab.surface.SphereHiddenTest.grazing fails on the reference solution",
                        GradeReport.SEED_NOTE + "12345 (grade with --seed 12345 to grade the same variants again)",
                        "scenes/spheres.json" + GradeReport.PUBLISHED_NOTE + "no variant of 8 kept its point (last: x);"
                                + " narrow its \"variant\" bounds",
                        "scenes/boxes.json" + GradeReport.REDRAWN_NOTE + "3 times to keep its point",
                        "STUDENT-NOTE the grader cache was changed while this submission was graded"),
                List.of("STUDENT-NOTE the grader cache was changed while this submission was graded"), 2.0, null);
    }

    @Test
    void instructorNotesStayInTheInstructorsReport() throws IOException {
        GradeReport r = withStaffNotes();
        assertFalse(r.failed());
        assertEquals(List.of("STUDENT-NOTE the grader cache was changed while this submission was graded"), r.studentNotes());
        String gs = gradescopeShown(JSON.readTree(Reports.gradescope(r)));
        assertNoSecret(gs, "Gradescope");
        assertTrue(gs.contains("STUDENT-NOTE"), "what the student's code caused is shown: " + gs);
        for (boolean after : new boolean[] {false, true}) {
            String pl = prairieLearnShown(JSON.readTree(PrairieLearn.results(r, after)));
            assertNoSecret(pl, "PrairieLearn");
        }
        String instructors = Reports.html(r);
        for (String n : r.notes()) {
            assertTrue(instructors.contains(HtmlReport.esc(n)), "the instructors' report has '" + n + "'");
        }
    }

    /** The first mistake: points that do not add up, graded anyway: exit 1 and a failed grading. */
    @Test
    void pointsThatDoNotAddUpFailTheGradingOnEveryPlatform() throws IOException {
        Path root = dir.resolve("course");
        Path project = Path.of("").toAbsolutePath();
        FileTrees.copy(project.resolve("assignments"), root.resolve("assignments"));
        Path a = root.resolve("assignments/02-box/assignment.json");
        ObjectNode n = (ObjectNode) JSON.readTree(a.toFile());
        n.put("points", n.get("points").asInt() + 1);
        Files.writeString(a, n.toString());
        Path sub = Files.createDirectories(dir.resolve("submission"));
        Files.writeString(sub.resolve("Sphere.java"), "package raylab.surface;\n");
        Path out = dir.resolve("out");
        Path pl = dir.resolve("pl/results.json");
        ByteArrayOutputStream console = new ByteArrayOutputStream();
        int status = GradeCommand.run(Grader.Options.defaults(root).withMilestones(List.of("sphere")), 7L, sub, out,
                s -> { }, true, new PrintStream(console, true, StandardCharsets.UTF_8), report -> {
                    try {
                        Files.createDirectories(pl.getParent());
                        Reports.write(pl, PrairieLearn.results(report, false));
                    } catch (IOException e) {
                        throw new java.io.UncheckedIOException(e);
                    }
                });
        assertEquals(1, status, "the grader could not run: exit 1");
        JsonNode gs = JSON.readTree(out.resolve("results.json").toFile());
        assertFalse(gs.has("score"), gs.toString());
        assertEquals(GradeReport.FAILED_FOR_STUDENTS, gs.get("output").asText());
        assertNoSecret(gradescopeShown(gs), "Gradescope");
        assertFalse(gradescopeShown(gs).contains("assignment.json"), "no instructor path: " + gs);
        JsonNode p = JSON.readTree(pl.toFile());
        assertFalse(p.get("gradable").asBoolean(), p.toString());
        assertFalse(p.toString().contains("assignment.json"), "no instructor path: " + p);
        String html = Files.readString(out.resolve("report.html"));
        assertTrue(html.contains("02-box/assignment.json: points is"), "the instructors' report has the cause: " + html);
    }
}
