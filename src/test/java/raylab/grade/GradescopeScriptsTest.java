package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Gradescope's scripts of {@code bundle gradescope}, run with bash (issue 36, items 1, 2 and 7):
 * setup.sh picks a JDK 17 or newer even when an older {@code javac} comes first on the PATH (the
 * JDK 8 and 11 base images), never swallows a failed step, and run_autograder turns a failed
 * grading into Gradescope's own "The autograder failed to execute correctly" (no results.json,
 * no score) with the cause in the instructors' output.
 */
class GradescopeScriptsTest {
    @TempDir
    Path dir;

    /** Runs a script with bash; returns its exit status and puts its output in {@code log}. */
    private int bash(String script, Path ag, Path log, String... env) throws Exception {
        Path file = dir.resolve("script-" + System.nanoTime() + ".sh");
        Files.writeString(file, script, StandardCharsets.UTF_8);
        ProcessBuilder pb = new ProcessBuilder("bash", file.toString()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        pb.environment().put("AUTOGRADER_ROOT", ag.toString());
        for (int i = 0; i < env.length; i += 2) {
            pb.environment().put(env[i], env[i + 1]);
        }
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the script finished");
        return p.exitValue();
    }

    /** A fake JDK whose java and javac say they are version {@code spec} ("1.8", "11"). */
    private Path fakeJdk(String name, String spec) throws IOException {
        Path bin = Files.createDirectories(dir.resolve(name).resolve("bin"));
        for (String tool : new String[] {"java", "javac"}) {
            Path t = bin.resolve(tool);
            Files.writeString(t, "#!/bin/sh\necho '    java.specification.version = " + spec + "' >&2\n");
            t.toFile().setExecutable(true);
        }
        return bin;
    }

    @Test
    void setupUsesAJdk17EvenWhenAnOlderJavacComesFirst() throws Exception {
        Path jdk17 = Path.of("/usr/lib/jvm");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isDirectory(jdk17), "needs a JDK under /usr/lib/jvm");
        for (String old : new String[] {"1.8", "11"}) {
            Path ag = Files.createDirectories(dir.resolve("ag-" + old).resolve("source")).getParent();
            Path bin = fakeJdk("jdk-" + old, old);
            Path log = dir.resolve("setup-" + old + ".log");
            int status = bash(BundleCommand.SETUP, ag, log, "PATH", bin + ":" + System.getenv("PATH"),
                    "RAYLAB_SETUP_JDK_ONLY", "1");
            String out = Files.readString(log);
            assertEquals(0, status, "setup.sh with java " + old + " first on the PATH: " + out);
            String chosen = Files.readString(ag.resolve("source/java-path")).strip();
            assertFalse(chosen.startsWith(bin.toString()), "the JDK " + old + " on the PATH is not used: " + chosen);
            Process v = new ProcessBuilder(chosen, "-XshowSettings:properties", "-version").redirectErrorStream(true).start();
            String props = new String(v.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            v.waitFor();
            String spec = props.lines().filter(l -> l.strip().startsWith("java.specification.version")).findFirst()
                    .orElse("").replaceAll(".*= *", "").strip();
            assertTrue(Integer.parseInt(spec) >= 17, "the chosen java is 17 or newer: " + chosen + " is " + spec);
        }
    }

    @Test
    void setupSwallowsNoFailure() {
        assertFalse(BundleCommand.SETUP.contains("|| true"), "setup.sh ignores no failed step:\n" + BundleCommand.SETUP);
        assertTrue(BundleCommand.SETUP.contains("set -euo pipefail"), BundleCommand.SETUP);
        assertTrue(BundleCommand.SETUP.contains("raylab.jar self-check"), "setup.sh checks the course");
    }

    @Test
    void aFailedGradingLeavesGradescopeNoResultsAndTheCauseInTheOutput() throws Exception {
        for (int exit : new int[] {1, 2}) {
            Path ag = dir.resolve("run-" + exit);
            Path source = Files.createDirectories(ag.resolve("source"));
            Path fake = source.resolve("fake-java");
            // The grader as it fails: writes its results.json (no score), prints the cause, exits non-zero.
            Files.writeString(fake, "#!/bin/sh\nmkdir -p \"$AUTOGRADER_ROOT/results\"\n"
                    + "echo '{\"output\": \"The autograder failed\", \"tests\": []}' > \"$AUTOGRADER_ROOT/results/results.json\"\n"
                    + "echo 'raylab: grading failed: CAUSE-FOR-STAFF' >&2\nexit " + exit + "\n");
            fake.toFile().setExecutable(true);
            Files.writeString(source.resolve("java-path"), fake + "\n");
            Path log = dir.resolve("run-" + exit + ".log");
            int status = bash(BundleCommand.RUN, ag, log);
            String out = Files.readString(log);
            assertEquals(1, status, "run_autograder fails: " + out);
            assertFalse(Files.exists(ag.resolve("results/results.json")),
                    "no results.json: Gradescope says the autograder failed and records no score");
            assertTrue(out.contains("CAUSE-FOR-STAFF"), "the cause is in the instructors' output: " + out);
            assertTrue(out.contains("the grading failed (exit status " + exit + ")"), out);
        }
        // Graded: results.json stays, exit 0.
        Path ag = dir.resolve("run-ok");
        Path source = Files.createDirectories(ag.resolve("source"));
        Path fake = source.resolve("fake-java");
        Files.writeString(fake, "#!/bin/sh\nmkdir -p \"$AUTOGRADER_ROOT/results\"\n"
                + "echo '{\"score\": 3, \"tests\": []}' > \"$AUTOGRADER_ROOT/results/results.json\"\nexit 0\n");
        fake.toFile().setExecutable(true);
        Files.writeString(source.resolve("java-path"), fake + "\n");
        assertEquals(0, bash(BundleCommand.RUN, ag, dir.resolve("ok.log")));
        assertTrue(Files.readString(ag.resolve("results/results.json")).contains("\"score\": 3"));
    }
}
