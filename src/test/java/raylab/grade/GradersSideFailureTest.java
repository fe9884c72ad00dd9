package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Never a silent wrong grade, on the path a class takes: the grader's own test JVMs cannot start
 * (here a JVM option the JDK does not know, as a course's mistake in {@code RAYLAB_TRUSTED_JVM_OPTS}
 * or a broken image would do), so every part of the reference's grading fails on the grader's side.
 * That grading decided nothing: {@code raylab grade-all} says "grading failed" in the gradebook
 * and exits 1, the student's results.json has no score (Gradescope's run_autograder then uploads
 * none: "The autograder failed"), the staff's log names the JVM's own words, and the next run of
 * the same command, with the course fixed, grades the student again: full marks. Before, the same
 * grading exited 0 with a score of 0.
 */
class GradersSideFailureTest {
    static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    @Test
    void aGradingWhoseTrustedJvmsCannotStartIsGradedAgainNotScored() throws Exception {
        Path subs = Files.createDirectories(dir.resolve("submissions"));
        Path ref = GraderTest.submission(dir, "reference");
        Files.createDirectories(subs.resolve("ada"));
        Files.copy(ref.resolve("Sphere.java"), subs.resolve("ada/Sphere.java"));
        SharedGraderCache.seed(dir.resolve("cache"));
        Path out = dir.resolve("graded");

        Run broken = gradeAll(subs, out, Map.of("RAYLAB_TRUSTED_JVM_OPTS", "-XX:+RaylabNoSuchOption"));
        assertEquals(1, broken.status, "not every submission graded: " + broken.log);
        assertEquals("ada,,,grading failed", row(out), "the gradebook: no points, no total, the status");
        JsonNode results = JSON.readTree(out.resolve("ada/results.json").toFile());
        assertFalse(results.has("score"), "no score was decided: " + results);
        assertEquals(GradeReport.FAILED_FOR_STUDENTS, results.get("output").asText());
        assertTrue(results.path("extra_data").path(GradingStatus.FAILED_TESTS).size() > 0, results.toString());
        String gradeLog = Files.readString(out.resolve("ada/grade.log"));
        assertTrue(gradeLog.contains("grading failed: sphere: the grading of")
                && gradeLog.contains("Unrecognized VM option 'RaylabNoSuchOption'"),
                "the staff's log names the parts and the JVM's words: " + gradeLog);
        assertTrue(broken.log.contains("ada: NOT GRADED: the grading failed on the grader's side"), broken.log);

        Run fixed = gradeAll(subs, out, Map.of());
        assertEquals(0, fixed.status, "graded again: " + fixed.log);
        assertTrue(fixed.log.contains("0 already graded, 1 to grade"), "the failed grading is not taken as done: "
                + fixed.log);
        int max = raylab.course.Assignments.load(SharedGraderCache.root()).byId("sphere").orElseThrow().points();
        assertEquals("ada," + max + "," + max + ",graded", row(out), "the reference's full marks");
    }

    /**
     * A milestone of scenes only (here the sphere milestone without its tests and data cases, as an
     * instructor's new topic may start) is rendered in a render JVM of its own
     * ({@code SceneGrading.renderAlone}): the reference's full marks. When that JVM cannot start,
     * every scene is the grading's failure, and the staff's message names the JVM's exit status and
     * its own first line. Before, it said "ended early" and nothing of why.
     */
    @Test
    void aMilestoneOfScenesOnlyIsRenderedInAJvmOfItsOwnAndItsFailureSaysWhy() throws Exception {
        Path course = dir.resolve("course");
        for (String d : List.of("assignments", "scenes", "grader", "src/main/java", "src/main/resources", "src/tools/java",
                "src/test/java")) {
            if (Files.exists(SharedGraderCache.root().resolve(d))) {
                raylab.course.FileTrees.copy(SharedGraderCache.root().resolve(d), course.resolve(d));
            }
        }
        Path json = course.resolve("assignments/01-sphere/assignment.json");
        com.fasterxml.jackson.databind.node.ObjectNode a = (com.fasterxml.jackson.databind.node.ObjectNode) JSON.readTree(
                json.toFile());
        a.remove("cases");
        a.set("tests", JSON.readTree("{\"tag\": \"sphere\", \"visible\": [], \"visiblePoints\": 0, \"hiddenPoints\": 0}"));
        int points = 0;
        for (JsonNode sc : a.get("scenes")) {
            points += sc.get("points").asInt();
        }
        a.put("points", points);
        Files.writeString(json, a.toPrettyString());
        Path sub = Files.createDirectories(dir.resolve("scenes-only"));
        Files.copy(GraderTest.submission(dir, "reference").resolve("Sphere.java"), sub.resolve("Sphere.java"));
        int scenes = a.get("scenes").size();

        Run good = grade(course, sub, dir.resolve("good"), Map.of());
        assertEquals(0, good.status, good.log);
        JsonNode r = JSON.readTree(dir.resolve("good/results.json").toFile());
        assertEquals(points, r.get("score").asDouble(), 1e-9, "the reference's full marks: " + r);
        assertEquals(scenes, r.get("tests").size(), "the scenes and nothing else: " + r);

        Run broken = grade(course, sub, dir.resolve("broken"), Map.of("RAYLAB_RENDER_JVM_OPTS", "-XX:+RaylabNoSuchOption"));
        assertEquals(1, broken.status, "the grading failed: " + broken.log);
        JsonNode b = JSON.readTree(dir.resolve("broken/results.json").toFile());
        assertFalse(b.has("score"), "no score was decided: " + b);
        assertEquals(scenes, b.path("extra_data").path(GradingStatus.FAILED_TESTS).size(), b.toString());
        assertTrue(broken.log.contains("the grader's JVM that renders the scenes ended early, before this scene was"
                + " rendered, and it runs no code of the student's: exit status 1; it said: Unrecognized VM option"
                + " 'RaylabNoSuchOption'"), "the staff's message names the exit status and the JVM's words: " + broken.log);
    }

    /** {@code raylab grade} of the sphere milestone of {@code course} in a process of its own, with this environment. */
    private Run grade(Path course, Path sub, Path out, Map<String, String> env) throws IOException, InterruptedException {
        return run(course, env, "grade", sub.toString(), "--out", out.toString(), "--root", course.toString(), "--quiet",
                "--milestone", "sphere", "--cache", dir.resolve("course-cache").toString());
    }

    private record Run(int status, String log) {
    }

    /** {@code raylab grade-all} of the sphere milestone in a process of its own, with this environment. */
    private Run gradeAll(Path subs, Path out, Map<String, String> env) throws IOException, InterruptedException {
        return run(SharedGraderCache.root(), env, "grade-all", subs.toString(), "--out", out.toString(), "--root",
                SharedGraderCache.root().toString(), "--milestone", "sphere", "--cache", dir.resolve("cache").toString(),
                "--jobs", "1");
    }

    /** {@code raylab ARGS} in a process of its own in {@code workDir}, with this environment. */
    private Run run(Path workDir, Map<String, String> env, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JvmOptions.GRADER);
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "raylab.cli.Main"));
        cmd.addAll(List.of(args));
        Path log = dir.resolve(args[0] + "-" + System.nanoTime() + ".log");
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(workDir.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        pb.environment().putAll(env);
        Process p = pb.start();
        if (!p.waitFor(10, TimeUnit.MINUTES)) {
            p.destroyForcibly();
        }
        return new Run(p.exitValue(), Files.readString(log));
    }

    /** The gradebook's row of the one student. */
    private static String row(Path out) throws IOException {
        List<String> lines = Files.readAllLines(out.resolve("gradebook.csv"));
        assertEquals(List.of("student,sphere,total,status"), lines.subList(0, 1), "the header: " + lines);
        assertEquals(2, lines.size(), "one student: " + lines);
        return lines.get(1);
    }
}
