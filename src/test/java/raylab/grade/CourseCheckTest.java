package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.cli.Main;
import raylab.course.FileTrees;
import raylab.grade.platform.PrairieLearn;

/**
 * The course checks itself (issue 36, item 2): the instructor's usual mistakes each make
 * {@code bundle} (all three platforms) and {@code self-check} (what Gradescope's setup.sh runs)
 * refuse with one clear line and a non-zero exit, and the same course graded anyway gives a failed
 * grading on every platform (never a score). Each case works on a copy of the course.
 */
class CourseCheckTest {
    static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    /** A copy of what a bundle holds: assignments, scenes, grader tests, test helpers, visible tests, sources. */
    private Path course(String name) throws IOException {
        Path project = Path.of("").toAbsolutePath();
        Path root = dir.resolve(name);
        for (String f : List.of("assignments", "scenes", "grader/tests", "src/test/java", "src/main/java", "src/tools/java")) {
            FileTrees.copy(project.resolve(f), root.resolve(f));
        }
        return root;
    }

    private record Run(int status, String err) {
    }

    private static Run raylab(String... args) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), args);
        return new Run(status, err.toString(StandardCharsets.UTF_8));
    }

    /** The lines that name a problem: each one line, each naming what to fix. */
    private static List<String> problemLines(String err) {
        return err.lines().filter(l -> l.startsWith("raylab: ")).toList();
    }

    @Test
    void pointsThatDoNotAddUpStopEveryBundleAndTheSelfCheck() throws Exception {
        Path root = course("points");
        Path a = root.resolve("assignments/02-box/assignment.json");
        ObjectNode n = (ObjectNode) JSON.readTree(a.toFile());
        n.put("points", n.get("points").asInt() + 1);
        Files.writeString(a, n.toString());
        Path jar = Files.writeString(dir.resolve("raylab.jar"), "not used: the check comes first");
        for (String target : List.of("gradescope", "prairielearn", "classroom50")) {
            Path out = dir.resolve("out-" + target + (target.equals("gradescope") ? ".zip" : ""));
            Run r = raylab("bundle", target, "--out", out.toString(), "--root", root.toString(), "--jar", jar.toString());
            assertEquals(1, r.status(), target + ": " + r.err());
            List<String> lines = problemLines(r.err());
            assertEquals(1, lines.size(), target + ": one clear line: " + r.err());
            assertTrue(lines.get(0).contains("02-box/assignment.json: points is"), lines.get(0));
            assertFalse(Files.exists(out), target + ": nothing written");
        }
        Run r = raylab("self-check", "--root", root.toString(), "--quiet");
        assertEquals(1, r.status(), r.err());
        assertEquals(1, problemLines(r.err()).size(), r.err());
        assertTrue(r.err().contains("raylab: course problem: ") && r.err().contains("points is"), r.err());
    }

    @Test
    void aHiddenTestThatDoesNotCompileStopsTheSelfCheckAndFailsTheGrading() throws Exception {
        Path root = course("compile");
        Path hidden = root.resolve("grader/tests/raylab/surface/SphereHiddenTest.java");
        String text = Files.readString(hidden);
        Files.writeString(hidden, text.substring(0, text.lastIndexOf('}')) + "    int broken = undefinedName;\n}\n");
        Run r = raylab("self-check", "--root", root.toString(), "--cache", dir.resolve("cache-compile").toString(),
                "--milestone", "sphere", "--quiet");
        assertEquals(1, r.status(), r.err());
        List<String> lines = problemLines(r.err());
        assertEquals(1, lines.size(), "one clear line: " + r.err());
        assertTrue(lines.get(0).contains("do not compile") && lines.get(0).contains("SphereHiddenTest.java"), lines.get(0));
        assertGradingFails(root, dir.resolve("cache-compile"), "SphereHiddenTest.java");
        // Only what it must: a grading of box alone (PrairieLearn's per-milestone question) is not touched.
        Path sub = Files.createDirectories(dir.resolve("sub-box"));
        Files.copy(Path.of("src/main/java/raylab/surface/Box.java"), sub.resolve("Box.java"));
        Grader.Options o = Grader.Options.defaults(root).withMilestones(List.of("box"));
        o = new Grader.Options(root, o.milestones(), o.limits(), o.sceneLimit(), o.sceneHeapMb(),
                dir.resolve("cache-compile"), o.sandboxUser(), o.parallel(), o.sandboxMode());
        Path out = dir.resolve("graded-box");
        int status = GradeCommand.run(o, 5L, sub, out, s -> { }, true,
                new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8), null);
        assertEquals(0, status, "box is graded");
        JsonNode box = JSON.readTree(out.resolve("results.json").toFile());
        double max = 0;
        for (JsonNode t : box.get("tests")) {
            max += t.get("max_score").asDouble();
        }
        assertEquals(max, box.get("score").asDouble(), 1e-6, "the reference box scores full marks: " + box.get("output"));
    }

    @Test
    void aHiddenTestThatFailsOnTheReferenceStopsTheSelfCheckAndFailsTheGrading() throws Exception {
        Path root = course("failing");
        Path hidden = root.resolve("grader/tests/raylab/surface/SphereHiddenTest.java");
        String text = Files.readString(hidden);
        Files.writeString(hidden, text.substring(0, text.lastIndexOf('}'))
                + "    @Test\n    @DisplayName(\"WRONG-EXPECTATION the answer is 43\")\n"
                + "    void wrongExpectation() {\n        org.junit.jupiter.api.Assertions.assertEquals(43, 42, \"the answer\");\n"
                + "    }\n}\n");
        Run r = raylab("self-check", "--root", root.toString(), "--cache", dir.resolve("cache-failing").toString(),
                "--milestone", "sphere", "--quiet");
        assertEquals(1, r.status(), r.err());
        List<String> lines = problemLines(r.err());
        assertEquals(1, lines.size(), "one clear line: " + r.err());
        assertTrue(lines.get(0).contains("wrongExpectation") && lines.get(0).contains("fails on the reference solution"),
                lines.get(0));
        assertGradingFails(root, dir.resolve("cache-failing"), "wrongExpectation");
    }

    @Test
    void aGradedSceneWhoseVariantsLoseItsPointStopsTheSelfCheck() throws Exception {
        Path root = course("variant");
        Path a = root.resolve("assignments/01-sphere/assignment.json");
        ObjectNode n = (ObjectNode) JSON.readTree(a.toFile());
        ObjectNode v = (ObjectNode) n.get("scenes").get(1).get("variant");
        v.putObject("camera").put("yaw", 45).put("pitch", 30).put("distance", 0.5).put("fov", 15);
        v.put("coverage", 1.1);
        Files.writeString(a, n.toString());
        Run r = raylab("self-check", "--root", root.toString(), "--cache", dir.resolve("cache-variant").toString(),
                "--milestone", "sphere", "--quiet");
        assertEquals(1, r.status(), r.err());
        List<String> lines = problemLines(r.err());
        assertEquals(1, lines.size(), "one clear line: " + r.err());
        assertTrue(lines.get(0).contains("scenes/spheres.json: graded as published: no variant of 8 kept its point")
                && lines.get(0).contains("narrow its"), lines.get(0));
    }

    /** Graded anyway: exit 1, Gradescope's and PrairieLearn's files say the grading failed, the cause only for staff. */
    private void assertGradingFails(Path root, Path cache, String cause) throws IOException {
        Path sub = Files.createDirectories(dir.resolve("sub-" + cache.getFileName()));
        Files.copy(Path.of("src/main/java/raylab/surface/Sphere.java"), sub.resolve("Sphere.java"));
        Path out = dir.resolve("graded-" + cache.getFileName());
        Path pl = out.resolve("pl.json");
        Grader.Options o = Grader.Options.defaults(root).withMilestones(List.of("sphere"));
        o = new Grader.Options(root, o.milestones(), o.limits(), o.sceneLimit(), o.sceneHeapMb(), cache, o.sandboxUser(),
                o.parallel(), o.sandboxMode());
        int status = GradeCommand.run(o, 5L, sub, out, s -> { }, true,
                new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8), report -> {
                    try {
                        Reports.write(pl, PrairieLearn.results(report, false));
                    } catch (IOException e) {
                        throw new java.io.UncheckedIOException(e);
                    }
                });
        assertEquals(1, status, "a grading the course cannot decide: exit 1");
        JsonNode gs = JSON.readTree(out.resolve("results.json").toFile());
        assertFalse(gs.has("score"), gs.toString());
        assertEquals(GradeReport.FAILED_FOR_STUDENTS, gs.get("output").asText());
        assertFalse(gs.toString().contains(cause), "no hidden name for students: " + gs);
        JsonNode p = JSON.readTree(pl.toFile());
        assertFalse(p.get("gradable").asBoolean(), p.toString());
        assertFalse(p.toString().contains(cause), "no hidden name for students: " + p);
        assertTrue(Files.readString(out.resolve("report.html")).contains(cause), "the instructors' report has the cause");
    }
}
