package raylab.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the grading plan reads from the project's own test sources: every graded test method,
 * visible or hidden, has a name for students, as the handouts and results.json show it.
 */
class GradingPlanTest {
    private static final Path ROOT = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();

    @Test
    void everyGradedTestMethodHasADisplayName() throws IOException {
        List<String> unnamed = new ArrayList<>();
        int tests = 0;
        int hidden = 0;
        for (Assignment a : Assignments.load(ROOT).all()) {
            GradingPlan.Plan plan = GradingPlan.of(ROOT, a);
            List<GradingPlan.Item> items = new ArrayList<>(plan.visible());
            items.addAll(plan.hidden());
            for (GradingPlan.Item item : items) {
                if (item.kind() != GradingPlan.Kind.TEST) {
                    continue;
                }
                tests++;
                hidden += plan.hidden().contains(item) ? 1 : 0;
                String method = item.key().substring(item.key().indexOf('#') + 1);
                // Without @DisplayName the plan falls back to the method's name.
                if (item.name().equals(method) || item.name().isBlank()) {
                    unnamed.add(a.id() + ": " + item.key());
                }
            }
        }
        // The full repository has the hidden tests: a count of 0 would mean they were not read.
        assertTrue(hidden > 0, "no hidden test was read from " + ROOT + " (" + tests + " tests in all)");
        assertEquals(List.of(), unnamed, "test methods without @DisplayName (" + unnamed.size() + " of " + tests + ")");
    }

    @Test
    void aDisplayNameWithQuotesAndUnicodeIsReadAsWritten(@TempDir Path dir) throws IOException {
        Path src = dir.resolve("ExampleTest.java");
        Files.writeString(src, String.join("\n",
                "class ExampleTest {",
                "    @Test",
                "    @DisplayName(\"n·h < 0: no \\\"highlight\\\", whatever p\")",
                "    void named() {",
                "    }",
                "",
                "    @Test",
                "    void unnamed() {",
                "    }",
                "}"), StandardCharsets.UTF_8);
        List<GradingPlan.TestMethod> found = GradingPlan.testMethods(src, "ExampleTest");
        assertEquals(List.of(new GradingPlan.TestMethod("ExampleTest", "named", "n·h < 0: no \"highlight\", whatever p"),
                new GradingPlan.TestMethod("ExampleTest", "unnamed", "unnamed")), found);
        assertFalse(found.get(0).displayName().contains("\\"), "escapes are undone: " + found.get(0));
    }

    @Test
    void weightedSharesAddUpExactlyAndEqualWeightsAreTheEqualSplit() {
        // 700 cents over weights 1,1,1,3,3: exact shares 77.8 (x3) and 233.3 (x2); floors 77,77,77,233,233 = 697,
        // the 3 cents left one each to the first three.
        assertEquals(List.of(78L, 78L, 78L, 233L, 233L), boxed(GradingPlan.share(700, new double[] {1, 1, 1, 3, 3})));
        for (int n = 1; n <= 9; n++) {
            double[] ones = new double[n];
            java.util.Arrays.fill(ones, 1);
            assertEquals(boxed(GradingPlan.share(800, n)), boxed(GradingPlan.share(800, ones)), n + " equal weights");
        }
        assertEquals(List.of(), boxed(GradingPlan.share(800, new double[0])));
    }

    @Test
    void aWeightForAClassThatIsNotHiddenIsRefused(@TempDir Path dir) throws IOException {
        Path folder = Files.createDirectories(dir.resolve("assignments/01-a"));
        Files.writeString(folder.resolve("assignment.json"), "{\"id\": \"a\", \"order\": 1, \"title\": \"A\", \"points\": 2,"
                + " \"files\": [], \"tests\": {\"tag\": \"a\", \"visible\": [], \"hidden\": [\"grader/tests/x/AHiddenTest.java\"],"
                + " \"visiblePoints\": 0, \"hiddenPoints\": 2, \"hiddenWeights\": {\"BHiddenTest\": 2}}}");
        IOException e = org.junit.jupiter.api.Assertions.assertThrows(IOException.class, () -> Assignments.load(dir));
        assertEquals("assignments/01-a/assignment.json: tests.hiddenWeights names \"BHiddenTest\", which is not a class of"
                + " tests.hidden (write Class or Class.method, simple names)", e.getMessage());
        Files.writeString(folder.resolve("assignment.json"), Files.readString(folder.resolve("assignment.json"))
                .replace("\"BHiddenTest\": 2", "\"AHiddenTest.m\": 0"));
        e = org.junit.jupiter.api.Assertions.assertThrows(IOException.class, () -> Assignments.load(dir));
        assertEquals("assignments/01-a/assignment.json: tests.hiddenWeights.AHiddenTest.m must be a number > 0, got 0.0",
                e.getMessage());
    }

    @Test
    void twoMilestonesThatListOneFileAreRefusedWithTheRecipe(@TempDir Path dir) throws IOException {
        for (String id : List.of("ambient", "lambert")) {
            Path folder = Files.createDirectories(dir.resolve("assignments/0" + (id.equals("ambient") ? 1 : 2) + "-" + id));
            Files.writeString(folder.resolve("assignment.json"), "{\"id\": \"" + id + "\", \"order\": "
                    + (id.equals("ambient") ? 1 : 2) + ", \"title\": \"T\", \"points\": 0, \"files\": [{\"path\":"
                    + " \"src/main/java/raylab/shading/Shading.java\", \"methods\": [\"Shading.shade\"]}],"
                    + " \"tests\": {\"tag\": \"" + id + "\", \"visible\": [], \"visiblePoints\": 0, \"hiddenPoints\": 0}}");
        }
        IOException e = org.junit.jupiter.api.Assertions.assertThrows(IOException.class, () -> Assignments.load(dir));
        assertEquals("assignments/02-lambert/assignment.json: src/main/java/raylab/shading/Shading.java is a file of"
                + " milestone ambient already; a file belongs to one milestone: put the methods of lambert in a file of"
                + " their own (docs/instructors.md, \"Splitting a topic over milestones\")", e.getMessage());
    }

    private static List<Long> boxed(long[] a) {
        List<Long> out = new ArrayList<>();
        for (long v : a) {
            out.add(v);
        }
        return out;
    }
}
