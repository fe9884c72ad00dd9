package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Stopping {@code raylab render} at any moment leaves no file behind. A child JVM renders the
 * showcase with a slowed-down PNG write (a test hook that pauses after every 4 KiB), the test waits
 * until the hidden temporary file exists (or the plan is printed, for a stop while rendering), then
 * sends the signal and looks at the folder. KILL cannot be caught: it leaves at most the hidden
 * temporary file, never a visible or partial image, and the next write to the same target
 * removes it.
 */
class InterruptTest {
    @TempDir
    Path dir;

    Path out;
    Path tmpdir;

    private Process render(Path target) throws IOException {
        out = dir.resolve("stdout.txt");
        tmpdir = Files.createDirectories(dir.resolve("javatmp"));
        Files.createDirectories(target.getParent());
        return ChildJvm.start(List.of("-Draylab.test.slowPngWriteMillis=100", "-Djava.io.tmpdir=" + tmpdir),
                Map.of(), out, dir.resolve("stderr.txt"), "render", "scenes/showcase.json", "-o", target.toString(),
                "--threads", "2");
    }

    /** Waits (up to two minutes, as a guard against a hang) until the condition holds. */
    private static void await(Process p, String what, Predicate<Void> condition) throws InterruptedException {
        for (int i = 0; i < 12_000; i++) {
            if (condition.test(null)) {
                return;
            }
            if (!p.isAlive()) {
                throw new AssertionError("the render ended (exit " + p.exitValue() + ") before " + what);
            }
            Thread.sleep(10);
        }
        p.destroyForcibly();
        throw new AssertionError("never saw " + what);
    }

    private static List<String> listing(Path d) {
        try (Stream<Path> s = Files.list(d)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        } catch (IOException e) {
            return List.of("(unreadable: " + e + ")");
        }
    }

    private static boolean temporaryBeingWritten(Path folder) {
        try (Stream<Path> s = Files.list(folder)) {
            return s.anyMatch(p -> p.getFileName().toString().startsWith(".showcase.png.")
                    && p.toFile().length() > 0);
        } catch (IOException e) {
            return false;
        }
    }

    private void signalDuringTheWrite(String signal, int expectedExit) throws Exception {
        Path images = dir.resolve("images");
        Path target = images.resolve("showcase.png");
        Process p = render(target);
        await(p, "the temporary file being written", v -> temporaryBeingWritten(images));
        send(p, signal);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "stopped");
        assertEquals(expectedExit, p.exitValue(), "exit status after " + signal);
        assertEquals(List.of(), listing(images), "nothing left beside the output after " + signal);
        assertEquals(List.of(), listing(tmpdir), "no ImageIO cache file left in java.io.tmpdir");
    }

    private static void send(Process p, String signal) throws Exception {
        if (signal.equals("TERM")) {
            p.destroy(); // SIGTERM on Unix
        } else {
            Process kill = new ProcessBuilder("kill", "-" + signal, Long.toString(p.pid())).inheritIO().start();
            assertEquals(0, kill.waitFor(), "kill -" + signal);
        }
    }

    private static boolean unix() {
        return !System.getProperty("os.name").toLowerCase().contains("win");
    }

    @Test
    void termDuringTheWriteLeavesNothing() throws Exception {
        assumeTrue(unix());
        signalDuringTheWrite("TERM", 143);
    }

    /**
     * Whether this process ignores SIGINT (a job started in the background by a shell without job
     * control): the child JVM inherits that, and the JVM then leaves INT ignored, by design.
     */
    private static boolean interruptIgnored() {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/self/status"))) {
                if (line.startsWith("SigIgn:")) {
                    return (Long.parseUnsignedLong(line.substring(7).trim(), 16) & (1L << (2 - 1))) != 0;
                }
            }
        } catch (IOException | RuntimeException e) {
            // no /proc: assume not
        }
        return false;
    }

    @Test
    void interruptDuringTheWriteLeavesNothing() throws Exception {
        assumeTrue(unix());
        assumeTrue(!interruptIgnored(), "SIGINT is ignored by this test run (a background job): the child would ignore it too");
        signalDuringTheWrite("INT", 130);
    }

    @Test
    void termWhileRenderingLeavesNothing() throws Exception {
        assumeTrue(unix());
        Path images = dir.resolve("images");
        Process p = render(images.resolve("showcase.png"));
        await(p, "the plan", v -> {
            try {
                return Files.readString(out).contains("plan:");
            } catch (IOException e) {
                return false;
            }
        });
        p.destroy();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "stopped");
        assertEquals(List.of(), listing(images));
    }

    @Test
    void killDuringTheWriteLeavesNoVisibleFileAndTheNextRenderCleansUp() throws Exception {
        assumeTrue(unix());
        Path images = dir.resolve("images");
        Path target = images.resolve("showcase.png");
        Process p = render(target);
        await(p, "the temporary file being written", v -> temporaryBeingWritten(images));
        p.destroyForcibly(); // SIGKILL: no shutdown hook runs
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "killed");
        List<String> left = listing(images);
        assertFalse(left.contains("showcase.png"), "no partial image under the target's name: " + left);
        assertEquals(1, left.size(), "KILL cannot be caught: the hidden temporary file stays: " + left);
        for (String name : left) {
            assertTrue(name.matches("\\.showcase\\.png\\." + p.pid() + "\\.[0-9a-z]+\\.tmp"),
                    "only the hidden temporary file of the killed process may remain: " + left);
        }
        assertEquals(0, BadInputCliTest.run("render", "scenes/sphere.json", "-o", target.toString(), "-q").status());
        assertEquals(List.of("showcase.png"), listing(images), "the next render removed the stale temporary file");
    }
}
