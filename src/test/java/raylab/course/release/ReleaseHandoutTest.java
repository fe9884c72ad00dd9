package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;

/**
 * One source for points: a handout's title total and grading table come from assignment.json at
 * release, so changing a milestone's points there changes the starter's handout with no other
 * edit; visible data cases ship in the starter (hidden ones do not) with the case checker.
 */
class ReleaseHandoutTest {
    @TempDir
    Path dir;

    @Test
    void changingPointsInAssignmentJsonChangesTheHandoutAtTheNextRelease() throws IOException {
        Path copy = copyProject();
        Path json = copy.resolve("assignments/02-box/assignment.json");
        // Add 3 to the visible points (and so to the total), whatever they are today.
        int[] raised = raiseVisiblePoints(json, 3);
        int newTotal = raised[0];
        int newVisible = raised[1];
        String handoutBefore = Files.readString(copy.resolve("assignments/02-box/README.md"));

        Release.Tree tree = Release.build(copy);
        String handout = new String(tree.files().get("assignments/02-box/README.md"), StandardCharsets.UTF_8);
        assertTrue(handout.lines().findFirst().orElse("").endsWith("(" + newTotal + " points)"), handout.lines().findFirst().orElse(""));
        int tests = GradingPlan.testMethods(copy.resolve("src/test/java/raylab/surface/BoxTest.java"),
                "raylab.surface.BoxTest").size();
        assertTrue(handout.contains("| visible tests (`BoxTest`, tag `box`): " + tests
                + " tests, the points shared equally | " + newVisible + " |"), handout);
        assertTrue(handout.contains("| **total** | **" + newTotal + "** |"), handout);
        assertEquals(handoutBefore, Files.readString(copy.resolve("assignments/02-box/README.md")),
                "no edit of the handout itself was needed");
        // Everything but the table is the instructor's text.
        assertTrue(handout.contains("## Classic blunders") || handout.contains("## The math"), "the handout's prose stays");

        // Visible data cases ship (and only they), with the checker; the totals still add up in the starter.
        String cases = new String(tree.files().get("assignments/01-sphere/cases/basic.json"), StandardCharsets.UTF_8);
        JsonNode shipped = new ObjectMapper().readTree(cases);
        List<GradingPlan.CaseInfo> all = GradingPlan.cases(copy, Assignments.load(copy).byId("sphere").orElseThrow());
        long visible = all.stream().filter(c -> c.visibility().equals("visible")).count();
        assertTrue(visible >= 1 && visible < all.size(), "sphere has visible and hidden cases");
        assertEquals(visible, shipped.size());
        for (JsonNode c : shipped) {
            assertEquals("visible", c.get("visibility").asText());
        }
        assertTrue(tree.files().containsKey(Release.CASE_CHECK_STARTER), "the case checker ships");
        assertFalse(tree.files().containsKey("assignments/02-box/cases/basic.json"), "a file of hidden cases does not ship");

        Path starter = dir.resolve("starter");
        for (var e : tree.files().entrySet()) {
            Path t = starter.resolve(e.getKey());
            Files.createDirectories(t.getParent());
            Files.write(t, e.getValue());
        }
        Assignments s = Assignments.load(starter);
        for (Assignment a : Assignments.load(copy).all()) {
            Assignment b = s.byId(a.id()).orElseThrow();
            assertEquals(a.points(), b.points());
            GradingPlan.Plan inStarter = GradingPlan.of(starter, b);
            GradingPlan.Plan inTree = GradingPlan.of(copy, a);
            // (A data case's generated method is numbered among the cases of its tree, so keys may differ.)
            assertEquals(inTree.visible().stream().map(i -> i.kind() + " " + i.name() + " " + i.cents() + " " + i.tolerance())
                    .toList(), inStarter.visible().stream().map(i -> i.kind() + " " + i.name() + " " + i.cents() + " "
                            + i.tolerance()).toList(), "students can run what the grader calls visible: " + a.id());
            assertEquals(inTree.hiddenCents(), inStarter.hiddenCents(), a.id());
        }
    }

    @Test
    void releaseRegeneratesTheInstructorsHandoutsWithTheStartersAndSaysWhich() throws IOException {
        Path copy = copyProject();
        int newTotal = raiseVisiblePoints(copy.resolve("assignments/04-lambert/assignment.json"), 2)[0];
        Path untouched = copy.resolve("assignments/02-box/README.md");
        long boxModified = Files.getLastModifiedTime(untouched).toMillis();
        String boxBefore = Files.readString(untouched);

        Path starter = dir.resolve("starter");
        String out = AddSceneTest.run(0, "release", "--out", starter.toString(), "--no-verify", "--root", copy.toString());
        assertTrue(out.contains("updated the instructor's handout assignments/04-lambert/README.md"), out);
        assertFalse(out.contains("assignments/02-box/README.md"), "only the handout that changed: " + out);
        String instructor = Files.readString(copy.resolve("assignments/04-lambert/README.md"));
        assertTrue(instructor.lines().findFirst().orElse("").endsWith("(" + newTotal + " points)"), instructor);
        assertTrue(instructor.contains("| **total** | **" + newTotal + "** |"), instructor);
        assertEquals(Files.readString(starter.resolve("assignments/04-lambert/README.md")), instructor,
                "the instructor's handout is the starter's");
        assertEquals(boxBefore, Files.readString(untouched));
        assertEquals(boxModified, Files.getLastModifiedTime(untouched).toMillis(), "a handout that agrees is not rewritten");
    }

    private Path copyProject() throws IOException {
        Path root = Path.of("").toAbsolutePath();
        Path copy = dir.resolve("course");
        for (String f : Release.projectFiles(root)) {
            Path t = copy.resolve(f);
            Files.createDirectories(t.getParent());
            Files.copy(root.resolve(f), t);
        }
        return copy;
    }

    /** Adds {@code by} to a milestone's visiblePoints and total; the new {total, visiblePoints}. */
    private static int[] raiseVisiblePoints(Path json, int by) throws IOException {
        String text = Files.readString(json);
        java.util.regex.Matcher total = java.util.regex.Pattern.compile("\"points\": (\\d+),").matcher(text);
        java.util.regex.Matcher visible = java.util.regex.Pattern.compile("\"visiblePoints\": (\\d+),").matcher(text);
        assertTrue(total.find() && visible.find(), text);
        int newTotal = Integer.parseInt(total.group(1)) + by;
        int newVisible = Integer.parseInt(visible.group(1)) + by;
        Files.writeString(json, text.replaceFirst("\"points\": \\d+,", "\"points\": " + newTotal + ",")
                .replaceFirst("\"visiblePoints\": \\d+,", "\"visiblePoints\": " + newVisible + ","));
        return new int[] {newTotal, newVisible};
    }
}
