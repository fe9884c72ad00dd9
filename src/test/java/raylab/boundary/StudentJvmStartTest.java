package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Whose fault a student process that does not start is (real child JVMs, as in
 * {@link StudentProcessTest}). Before its first HELLO no code of the student's has run, so a
 * process that never starts is the grading's failure ({@link GradingFailure}: the milestone reads
 * "the autograder failed", no point is decided), not a wrong answer of the student's; a restart
 * after the student's code ran that does not start stays the student's.
 */
class StudentJvmStartTest {
    @TempDir
    Path dir;

    /** The student process's command behind {@code sh -c script}, which runs it with {@code exec "$@"}. */
    private static StudentProcess.Config behind(String script, List<String> javaOptions, long budgetMillis) {
        List<String> cmd = new ArrayList<>(List.of("/bin/sh", "-c", script, "wrapper"));
        List<String> java = new ArrayList<>(StudentJvm.javaCommand(StudentProcessTest.classDirs(), 128,
                List.of("raylab.remote.Echo")));
        // The options go right after the java launcher (the channel wrapper's three words come first).
        int launcher = java.indexOf(raylab.course.JavaBuild.javaExecutable());
        java.addAll(launcher + 1, javaOptions);
        cmd.addAll(java);
        return new StudentProcess.Config(cmd, null, StudentProcessTest.SERVED, budgetMillis, 2);
    }

    @Test
    void aProcessThatNeverStartsIsTheGradingsFailureNotTheStudents() {
        // The course's mistake: a JVM option this JVM does not know (RAYLAB_STUDENT_JVM_OPTS, a launcher).
        try (StudentProcess p = new StudentProcess(behind("exec \"$@\"", List.of("-XX:+NoSuchOptionOfRaylab"), 5_000))) {
            GradingFailure first = assertThrows(GradingFailure.class, () -> p.call("raylab.remote.Echo", "echo", null, 1.0));
            assertTrue(first.getMessage().contains("Unrecognized VM option 'NoSuchOptionOfRaylab'"), first.getMessage());
            assertTrue(first.getMessage().contains("not the student's code"), first.getMessage());
            assertEquals(0, p.starts(), "a start that failed before any student code ran is not the student's restart");
            // Every later call fails so too, never as the student's restarts used up (StudentTimeout).
            for (int i = 0; i < 4; i++) {
                GradingFailure again = assertThrows(GradingFailure.class,
                        () -> p.call("raylab.remote.Echo", "echo", null, 2.0), "call " + (i + 2));
                assertEquals(first.getMessage(), again.getMessage());
            }
            assertEquals(0, p.starts());
        }
    }

    @Test
    void aProcessThatFailsOnceToStartIsTriedOnceMore() throws Exception {
        Path once = dir.resolve("failed-once");
        String script = "if [ ! -e '" + once + "' ]; then : > '" + once + "'; echo 'a fork failed' >&2; exit 1; fi; exec \"$@\"";
        try (StudentProcess p = new StudentProcess(behind(script, List.of(), 5_000))) {
            assertEquals(1.0, p.call("raylab.remote.Echo", "echo", null, 1.0), "the second try answers");
            assertTrue(Files.exists(once), "the first try ran and failed");
            assertEquals(1, p.starts(), "the failed try is not counted");
        }
    }

    @Test
    void aRestartThatDoesNotStartAfterTheStudentsCodeRanIsTheStudents() throws Exception {
        // The first JVM starts; every later one ends before its HELLO (as when the student's code
        // left its run folder too full to copy back in).
        Path started = dir.resolve("started");
        String script = "if [ -e '" + started + "' ]; then echo 'run folder full' >&2; exit 1; fi; : > '" + started
                + "'; exec \"$@\"";
        try (StudentProcess p = new StudentProcess(behind(script, List.of(), 500))) {
            assertEquals(1.0, p.call("raylab.remote.Echo", "echo", null, 1.0));
            assertThrows(StudentTimeout.class, () -> p.call("raylab.remote.Echo", "hang", null, "x"));
            StudentException e = assertThrows(StudentException.class, () -> p.call("raylab.remote.Echo", "echo", null, 2.0));
            assertEquals("your code threw Error: the student process did not start: run folder full", e.getMessage());
            assertEquals(2, p.starts(), "the restart is counted against the student");
        }
    }
}
