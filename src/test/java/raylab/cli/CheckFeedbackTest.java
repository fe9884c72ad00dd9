package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.FileTrees;
import raylab.course.GradingPlan;
import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.MilestoneCheck;

/**
 * {@code raylab check sphere} on a Sphere whose far root is never tried (a realistic bug from
 * the grader's test submissions) speaks like the autograder: the failing test under its handout
 * name with its full message and hint, the next step the earliest failure in handout order, and a
 * points table whose total equals the visible part of the autograder's score for the same file.
 */
class CheckFeedbackTest {
    @TempDir
    Path dir;

    /** The parts of the project check reads, copied (renders and build output go into the copy). */
    static Path copyLayout(Path root, Path to) throws IOException {
        for (String d : List.of("assignments", "scenes", "src/test/java", "grader/tests/raylab/cases")) {
            FileTrees.copy(root.resolve(d), to.resolve(d));
        }
        return to;
    }

    @Test
    void farRootNeverTried() throws IOException {
        Path root = Path.of("").toAbsolutePath();
        Path copy = copyLayout(root, dir.resolve("project"));
        Assignment sphere = Assignments.load(copy).byId("sphere").orElseThrow();
        Path buggy = root.resolve("src/test/resources/submissions/bugs2/Sphere.java");
        assertTrue(Files.readString(buggy).contains("BUG: the far root is never tried"), "the planted bug");
        Path overlay = dir.resolve("student-classes");
        JavaBuild.Result compiled = MilestoneBuild.compileOverlay(Map.of("raylab/surface/Sphere.java",
                Files.readString(buggy)), dir.resolve("student-src"), JavaBuild.ownClassPath(), overlay);
        assertTrue(compiled.success(), compiled.errors().toString());

        List<MilestoneCheck.Outcome> outcomes = MilestoneCheck.run(copy, List.of(sphere), 2, s -> { }, List.of(overlay));
        MilestoneCheck.Outcome o = outcomes.get(0);
        StringWriter text = new StringWriter();
        PrintWriter w = new PrintWriter(text);
        CheckCommand.printDetails(w, o);
        CheckCommand.printTable(w, outcomes);
        w.flush();
        String out = text.toString();
        System.out.println(out);

        // Named as the handout names it, with the full message and its hint.
        String handout = Files.readString(root.resolve("assignments/01-sphere/README.md"));
        assertTrue(handout.contains("\"a ray starting inside …\""), "the handout cites the test");
        assertTrue(out.contains("FAIL \"a ray starting inside hits the far side (the farther root), normal outward\""), out);
        assertTrue(out.contains("HINT: the ray starts inside (at r(tMin)): where it enters is behind its start"), out);
        assertTrue(out.contains("expected: hit at t=1.5"), "the whole message, not only its first line: " + out);
        // The next step: the earliest failing test in the order of the test file (= the handout's order).
        GradingPlan.Plan plan = GradingPlan.of(copy, sphere);
        String firstFailing = o.rows().stream().filter(r -> !r.passed()).findFirst().orElseThrow().item().name();
        assertTrue(o.nextStep().startsWith("fix \"" + firstFailing + "\""), o.nextStep());
        // Sphere: 6 points of hidden tests and 1 of hidden data cases.
        assertEquals("hidden tests and data cases: 7 points, graded after submission", plan.hiddenLine());
        assertTrue(out.contains("  " + plan.hiddenLine()), out);
        assertTrue(out.contains("data case \"ray passing beside the sphere misses\""), "visible data cases run: " + out);

        // The same file through the autograder: the visible part of its score equals check's total.
        Path sub = Files.createDirectories(dir.resolve("submission"));
        Files.copy(buggy, sub.resolve("Sphere.java"));
        Path results = dir.resolve("results");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), "grade", sub.toString(), "--out", results.toString(),
                "--root", root.toString(), "--quiet", "--milestone", "sphere", "--test-timeout", "5",
                "--milestone-timeout", "60", "--scene-timeout", "30", "--heap", "256",
                // Not a sandbox test: without the shared user, another grading on this machine cannot stop ours.
                "--sandbox-user", "");
        assertEquals(0, status, () -> err.toString(StandardCharsets.UTF_8));
        JsonNode r = new ObjectMapper().readTree(results.resolve("results.json").toFile());
        long visibleEarned = 0;
        long visibleMax = 0;
        for (JsonNode t : r.get("tests")) {
            if (t.get("visibility").asText().equals("visible")) {
                visibleEarned += Math.round(t.get("score").asDouble() * 100);
                visibleMax += Math.round(t.get("max_score").asDouble() * 100);
            }
        }
        assertEquals(plan.visibleCents(), visibleMax, "the same points are visible");
        assertEquals(visibleEarned, o.earnedCents(), "check's points equal the visible part of the autograder's score");
        assertTrue(visibleEarned < visibleMax, "the bug costs points");
        assertTrue(out.contains("visible total: " + GradingPlan.points(visibleEarned) + " / "
                + GradingPlan.points(visibleMax) + " points"), out);
        // The grader names the test as the handout does, too.
        boolean named = false;
        for (JsonNode t : r.get("tests")) {
            named |= t.get("name").asText().equals("sphere: a ray starting inside hits the far side (the farther root),"
                    + " normal outward") && t.get("status").asText().equals("failed")
                    && t.get("output").asText().contains("HINT: the ray starts inside");
        }
        assertTrue(named, "the grader's entry for the test: " + r.get("tests"));
    }
}
