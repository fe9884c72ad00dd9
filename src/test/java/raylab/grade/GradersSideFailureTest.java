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

    private record Run(int status, String log) {
    }

    /** {@code raylab grade-all} of the sphere milestone in a process of its own, with this environment. */
    private Run gradeAll(Path subs, Path out, Map<String, String> env) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JvmOptions.GRADER);
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "raylab.cli.Main", "grade-all", subs.toString(),
                "--out", out.toString(), "--root", SharedGraderCache.root().toString(), "--milestone", "sphere",
                "--cache", dir.resolve("cache").toString(), "--jobs", "1"));
        Path log = dir.resolve("grade-all-" + System.nanoTime() + ".log");
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(SharedGraderCache.root().toFile()).redirectErrorStream(true)
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
