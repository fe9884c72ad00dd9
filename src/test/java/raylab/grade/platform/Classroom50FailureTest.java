package raylab.grade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.grade.GradeReport;

/**
 * Classroom 50's way to say that a grading failed (issue 36, item 1): its runner turns a non-zero
 * exit of autograder.py into an error result with no score (foundation50/classroom50,
 * cli/gh-teacher/autograders_tests: "autograder_nonzero_exit_synthesizes_error", "status=error").
 * The bundle's autograder.py exits 1 with a message for the student when {@code ./raylab check}
 * fails or writes no valid result.json, and exits 0 when it grades (whatever the score).
 */
class Classroom50FailureTest {
    @TempDir
    Path dir;

    private record Run(int status, String output) {
    }

    private Run autograder(String raylabScript) throws Exception {
        Path checkout = Files.createDirectories(dir.resolve("checkout-" + System.nanoTime()));
        Files.writeString(checkout.resolve("raylab"), raylabScript);
        Path py = checkout.resolve("autograder.py");
        Files.writeString(py, Classroom50Bundle.AUTOGRADER.replace("@MILESTONES@", "[\"sphere\", \"box\"]"));
        ProcessBuilder pb = new ProcessBuilder("python3", py.toString()).directory(checkout.toFile()).redirectErrorStream(true);
        pb.environment().put("RAYLAB_MILESTONE", "box");
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "autograder.py finished");
        return new Run(p.exitValue(), out);
    }

    @Test
    void aCheckThatCannotRunIsAnErrorResultWithNoScore() throws Exception {
        String[] broken = {
            "echo 'raylab: internal error' >&2; exit 2\n", // the course's side broke
            "exit 0\n", // no result.json
            "for a in \"$@\"; do last=\"$a\"; done; echo 'not json {' > \"$last\"; exit 1\n", // a broken result.json
        };
        for (String script : broken) {
            Run r = autograder(script);
            assertEquals(1, r.status(), "a failed grading exits non-zero (Classroom 50: status=error): " + r.output());
            assertTrue(r.output().contains("the autograder failed") && r.output().contains("no points were decided"),
                    r.output());
            assertTrue(r.output().contains("not of your code"), r.output());
        }
        assertTrue(GradeReport.FAILED_FOR_STUDENTS.contains("no points were decided"));
    }

    @Test
    void aGradedCheckExitsZeroWhateverTheScore() throws Exception {
        Run r = autograder("for a in \"$@\"; do last=\"$a\"; done\n"
                + "echo '{\"score\": 12, \"max-score\": 100}' > \"$last\"; exit 1\n");
        assertEquals(0, r.status(), r.output());
        assertTrue(r.output().contains("raylab: 12 / 100"), r.output());
    }
}
