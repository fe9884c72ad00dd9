package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.junit.jupiter.api.Test;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.grade.GradeReport.Kind;

/**
 * What Gradescope shows a student before the due date reveals nothing of the hidden tests.
 * Gradescope's autograder specification (results.json, "Controlling test case visibility"): the
 * top-level {@code output} is always shown; each test is shown by its own {@code visibility}
 * ({@code visible} at once; {@code after_due_date}, {@code after_published}, {@code hidden}
 * later or never); standard output by {@code stdout_visibility}; and "if test cases are hidden,
 * students will not be able to see their total score" (the top-level {@code score}). This test
 * reads every one of those fields of a results.json whose hidden tests lost points.
 */
class BeforeDueDateTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static final Set<String> VISIBILITIES = Set.of("visible", "hidden", "after_due_date", "after_published");

    /** Two milestones; the hidden tests fail with messages and notes that must stay hidden. */
    static GradeReport report() {
        List<GradeReport.Test> sphere = new ArrayList<>();
        sphere.add(new GradeReport.Test("sphere", "a ray from outside hits the near side", Kind.VISIBLE, 1.37, 1.37, true,
                "", "", "visible", 3, "SphereTest.java", null));
        sphere.add(new GradeReport.Test("sphere", "a ray that misses", Kind.VISIBLE, 1.37, 0, false,
                "no hit expected\nHINT: the discriminant", "", "visible", 3, "SphereTest.java", null));
        sphere.add(new GradeReport.Test("sphere", "HIDDEN-NAME-1 grazing rays", Kind.HIDDEN, 2.19, 0, false,
                "HIDDEN-MESSAGE-1 expected t = 3", "", "after_due_date", 3, "SphereHiddenTest.java", null)
                .withNote("HIDDEN-NOTE-1"));
        sphere.add(new GradeReport.Test("sphere", "data case: HIDDEN-CASE-1", Kind.CASE, 0.83, 0, false,
                "HIDDEN-MESSAGE-2", "", "after_due_date", 3, "cases/hidden.json", null));
        sphere.add(new GradeReport.Test("sphere", "scenes/sphere.json", Kind.SCENE, 2, 2, true, "", "", "visible", 3,
                "scenes/sphere.json", null));
        List<GradeReport.Test> lambert = new ArrayList<>();
        lambert.add(new GradeReport.Test("lambert", "a light behind the surface adds nothing", Kind.VISIBLE, 0.67, 0.67,
                true, "", "", "visible", 3, "ShadingTest.java", null)
                .withNote("your loop traced 1 shadow ray the plan could skip"));
        lambert.add(new GradeReport.Test("lambert", "HIDDEN-NAME-2 random lights", Kind.HIDDEN, 1.11, 0, false,
                "HIDDEN-MESSAGE-3", "", "hidden", 3, "ShadingHiddenTest.java", null));
        return new GradeReport(List.of(
                new GradeReport.Milestone("sphere", "Ray-sphere intersection", List.of(), sphere),
                new GradeReport.Milestone("lambert", "Lambertian shading", List.of(), lambert)),
                List.of("Sphere.java"), List.of(), List.of(), 4.2);
    }

    @Test
    void nothingShownBeforeTheDueDateRevealsAHiddenScoreTotalOrMessage() throws IOException {
        GradeReport r = report();
        JsonNode root = JSON.readTree(Reports.gradescope(r));
        // Text that only the hidden results hold: their names, messages and notes, the total and
        // each milestone's score with hidden points, and the hidden points earned or lost.
        List<String> secrets = new ArrayList<>(List.of("HIDDEN-NAME-1", "HIDDEN-NAME-2", "HIDDEN-MESSAGE-1",
                "HIDDEN-MESSAGE-2", "HIDDEN-MESSAGE-3", "HIDDEN-NOTE-1", "HIDDEN-CASE-1"));
        secrets.add(HtmlReport.fmt(r.score()) + " / " + HtmlReport.fmt(r.maxScore()));
        for (GradeReport.Milestone m : r.milestones()) {
            secrets.add(HtmlReport.fmt(m.score()) + " / " + HtmlReport.fmt(m.maxScore()));
        }
        // Always shown: every top-level field but score (handled below) and tests (by their visibility).
        List<String> shown = new ArrayList<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = root.fields(); it.hasNext();) {
            Map.Entry<String, JsonNode> e = it.next();
            if (!e.getKey().equals("tests") && !e.getKey().equals("score")) {
                shown.add(e.getKey() + "=" + (e.getValue().isTextual() ? e.getValue().asText() : e.getValue().toString()));
            }
        }
        assertEquals("hidden", root.path("stdout_visibility").asText(), "the grader's standard output is never shown");
        assertTrue(VISIBILITIES.contains(root.path("visibility").asText("visible")), root.toString());
        boolean anyHidden = false;
        double visibleScore = 0;
        for (JsonNode t : root.get("tests")) {
            String v = t.path("visibility").asText("");
            assertTrue(VISIBILITIES.contains(v), "every test names its visibility (no default applies): " + t);
            if (v.equals("visible")) {
                shown.add(t.toString()); // every field of the entry: name, number, score, max_score, status, output, tags
                visibleScore += t.get("score").asDouble();
            } else {
                anyHidden = true;
            }
        }
        // The top-level score is the full grade; Gradescope hides it while a test is hidden.
        assertTrue(anyHidden || Math.abs(root.get("score").asDouble() - visibleScore) < 1e-9,
                "the total is shown only when no test is hidden, or it holds visible points only");
        assertEquals(r.score(), root.get("score").asDouble(), 1e-9, "the grade itself counts every test");
        String all = String.join("\n", shown);
        for (String s : secrets) {
            assertFalse(all.contains(s), () -> "shown before the due date: '" + s + "' in\n" + all);
        }
        String output = root.get("output").asText();
        assertTrue(output.contains(HtmlReport.HIDDEN_AFTER_DUE), output);
        double visibleMax = 1.37 + 1.37 + 2 + 0.67;
        assertTrue(output.contains("Visible results " + HtmlReport.fmt(visibleScore) + " / " + HtmlReport.fmt(visibleMax)),
                output);
        // The visible note is shown with its test, and takes nothing.
        assertTrue(all.contains("Note (no points taken): your loop traced 1 shadow ray the plan could skip"), all);
    }

    @Test
    void afterTheDueDateHiddenEntriesHoldTheirMessagesAndNotes() throws IOException {
        JsonNode root = JSON.readTree(Reports.gradescope(report()));
        String hidden = "";
        for (JsonNode t : root.get("tests")) {
            if (!t.get("visibility").asText().equals("visible")) {
                hidden += t + "\n";
            }
        }
        for (String s : List.of("HIDDEN-MESSAGE-1", "HIDDEN-MESSAGE-2", "HIDDEN-MESSAGE-3", "HIDDEN-NOTE-1")) {
            assertTrue(hidden.contains(s), s + " in the hidden entries: " + hidden);
        }
    }
}
