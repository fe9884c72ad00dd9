package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.SolutionRegions;
import raylab.course.TestLauncher;

/**
 * Attacks on the grader (src/test/resources/submissions/attacks/Sphere.java: loading the
 * reference solution, forging the report protocol, printing hidden test data, opening sockets,
 * leaving files in /tmp and detached processes, writing the grader's files and a forged
 * results.json after the grader's last write) graded in each sandbox mode, and a grader that
 * itself overflows its stack or runs out of memory. Each attack must fail closed; what a mode
 * does not isolate (see grader/README.md) is not asserted for that mode, and says so.
 */
class GraderAttackTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static Path root;
    static Assignments assignments;

    @TempDir
    Path dir;

    @BeforeAll
    static void load() throws IOException {
        root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        assignments = Assignments.load(root);
    }

    /** What one attack run left behind. */
    record Run(JsonNode results, String prairielearn, int connections, String tag, Path out, Path cache, int status) {
    }

    /** Grades the attack submission (milestone sphere) in the given mode, with the given sandbox user ("" for none). */
    private Run attack(String mode, String user) throws Exception {
        long tag = 31_000 + new SplittableRandom(System.nanoTime()).nextInt(9_000);
        Path cache = root.resolve("target/grader-cache");
        Path out = Files.createDirectories(dir.resolve("out-" + mode));
        Path sub = Files.createDirectories(dir.resolve("sub-" + mode));
        for (Assignment a : assignments.all()) {
            for (Assignment.StudentFile f : a.files()) {
                Path src = root.resolve(f.path());
                Files.writeString(sub.resolve(src.getFileName()), SolutionRegions.toStudent(src.getFileName().toString(),
                        Files.readString(src), Set.of(a.id())));
            }
        }
        AtomicInteger connections = new AtomicInteger();
        try (ServerSocket server = new ServerSocket(0, 50, InetAddress.getLoopbackAddress())) {
            Thread accept = new Thread(() -> {
                while (!server.isClosed()) {
                    try (Socket s = server.accept()) {
                        connections.incrementAndGet();
                    } catch (IOException e) {
                        return;
                    }
                }
            });
            accept.setDaemon(true);
            accept.start();
            String attack = Files.readString(root.resolve("src/test/resources/submissions/attacks/Sphere.java"))
                    .replace("@CACHE@", cache.toString()).replace("@OUT@", out.toString())
                    .replace("@PORT@", Integer.toString(server.getLocalPort())).replace("@TAG@", Long.toString(tag));
            Files.writeString(sub.resolve("Sphere.java"), attack);
            // In a sandbox the attack's renders cannot finish (each intersect prints every ray seen so
            // far): a short scene limit keeps the wait for their time-out short. The renders are not
            // what these tests check.
            String[] base = {"grade", sub.toString(), "--out", out.toString(), "--root", root.toString(), "--quiet",
                "--test-timeout", "5", "--milestone-timeout", "60", "--scene-timeout", "5", "--heap", "256",
                "--milestone", "sphere", "--sandbox", mode, "--sandbox-user", user,
                "--prairielearn", out.resolveSibling(out.getFileName() + "-pl.json").toString()};
            String[] args = base;
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                    new PrintWriter(err, true, StandardCharsets.UTF_8), args);
            // A detached forger would write results.json 4 s after its JVM started: wait past that.
            Thread.sleep(4_500);
            assertTrue(Files.isRegularFile(out.resolve("results.json")), () -> "no results.json: " + err);
            JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
            return new Run(r, Files.readString(out.resolveSibling(out.getFileName() + "-pl.json")), connections.get(), Long.toString(tag), out,
                    cache, status);
        }
    }

    /** Nothing of the hidden classes in what the student sees at once. */
    private static void assertHiddenStaysHidden(Run run) throws IOException {
        for (JsonNode t : run.results().get("tests")) {
            if (t.get("visibility").asText().equals("visible")) {
                String shown = t.get("output").asText();
                assertFalse(shown.contains("Hidden") || shown.contains("SphereCasesTest"), "hidden data shown: " + shown);
            }
        }
        // PrairieLearn shows its results.json at once: before the due date nothing of a hidden test.
        for (JsonNode t : JSON.readTree(run.prairielearn()).get("tests")) {
            String m = t.get("message").asText() + t.get("output").asText();
            assertFalse(m.contains("Hidden") || m.contains("SphereCasesTest") || m.contains("rays seen"),
                    "PrairieLearn results show hidden details: " + m);
        }
    }

    /** What every mode guarantees. */
    private static void assertFailClosed(Run run) throws IOException {
        assertEquals(0, run.status(), "graded");
        GraderTest.checkSchema(run.results());
        assertFalse(run.results().toString().contains("forged " + run.tag()), "no results.json written after the grader's");
        assertHiddenStaysHidden(run);
        double score = 0;
        double max = 0;
        for (JsonNode t : run.results().get("tests")) {
            score += t.get("score").asDouble();
            max += t.get("max_score").asDouble();
        }
        // A sphere that never hits passes only the miss tests: far below half the points.
        assertTrue(score < max / 2, "no forged or borrowed points: " + score + " of " + max);
        assertTrue(ProcessHandle.allProcesses().noneMatch(p -> p.info().commandLine().orElse("")
                .contains("sleep " + run.tag())), "the detached process was killed");
        assertTrue(Files.isRegularFile(root.resolve("grader/tests/raylab/hidden/Hidden.java")), "grader sources intact");
    }

    /** What the namespace and user modes add: the grader's files are out of reach. */
    private static void assertGraderFilesOutOfReach(Run run) {
        assertFalse(Files.exists(run.cache().resolve("canary-" + run.tag() + ".txt")), "no file written into the cache");
    }

    /** What the namespace mode adds: no network, a private /tmp. */
    private static void assertIsolated(Run run) throws IOException {
        assertEquals(0, run.connections(), "no connection to the host's loopback");
        assertFalse(Files.exists(Path.of("/tmp/raylab-attack-" + run.tag() + ".txt")), "nothing left in /tmp");
    }

    /** The instructors' report.html (the student's results.json leaves the sandbox line out). */
    private static String instructorsReport(Run run) throws IOException {
        return Files.readString(run.out().resolve("report.html"));
    }

    private static boolean namespaces() {
        return Sandbox.namespacesWork(Sandbox.isRoot());
    }

    @Test
    void namespaceSandboxWithTheSandboxUser() throws Exception {
        assumeTrue(namespaces(), "unshare cannot create namespaces here");
        Run run = attack("namespace", GraderTest.sandboxUser());
        assertTrue(instructorsReport(run).contains("sandbox: namespaces"), "the instructors' report names the sandbox mode");
        assertFailClosed(run);
        assertGraderFilesOutOfReach(run);
        assertIsolated(run);
    }

    @Test
    void namespaceSandboxWithoutTheSandboxUser() throws Exception {
        assumeTrue(namespaces(), "unshare cannot create namespaces here");
        Run run = attack("namespace", "");
        assertFailClosed(run);
        assertGraderFilesOutOfReach(run);
        assertIsolated(run);
    }

    @Test
    void sandboxUserWithoutNamespaces() throws Exception {
        assumeTrue(Sandbox.isRoot() && Files.readString(Path.of("/etc/passwd")).contains("\n" + GraderTest.sandboxUser() + ":"),
                "needs root and the user " + GraderTest.sandboxUser() + " (.ci/run creates it)");
        Run run = attack("user", GraderTest.sandboxUser());
        assertTrue(instructorsReport(run).contains("sandbox: user"), "the instructors' report names the sandbox mode");
        assertFailClosed(run);
        assertGraderFilesOutOfReach(run);
        // Not isolated in this mode (README): the network and the shared /tmp.
        Files.deleteIfExists(Path.of("/tmp/raylab-attack-" + run.tag() + ".txt"));
    }

    @Test
    void noSandboxAtAll() throws Exception {
        Run run = attack("none", "");
        assertTrue(instructorsReport(run).contains("sandbox: none"), "the instructors' report names the sandbox mode");
        // Not isolated in this mode (README): network, /tmp, the grader's files; the reference
        // classes in the cache are readable, so the score is not asserted here. What the
        // submission copied out of the hidden classes is withheld from visible outputs.
        assertEquals(0, run.status());
        GraderTest.checkSchema(run.results());
        assertHiddenStaysHidden(run);
        assertTrue(run.results().toString().contains("withheld: it contains text of the hidden tests"),
                "the attack did print hidden text, and it was withheld");
        assertFalse(run.results().toString().contains("forged " + run.tag()), "no results.json written after the grader's");
        assertTrue(ProcessHandle.allProcesses().noneMatch(p -> p.info().commandLine().orElse("")
                .contains("sleep " + run.tag())), "the detached process was killed");
        // The attack did run (this mode does not stop these): the test would see them elsewhere.
        assertTrue(Files.deleteIfExists(Path.of("/tmp/raylab-attack-" + run.tag() + ".txt")), "the attack ran");
        assertTrue(Files.deleteIfExists(run.cache().resolve("canary-" + run.tag() + ".txt")), "the attack ran");
        assertTrue(run.connections() > 0, "the attack reached the network");
    }

    /** Endless recursion inside the grader itself (its log callback) still gives a results.json. */
    @Test
    void aStackOverflowInsideTheGraderStillWritesResults() throws IOException {
        Path out = dir.resolve("out-so");
        int status = GradeCommand.run(options(), Files.createDirectories(dir.resolve("empty")), out,
                s -> recurse(0), true, new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
        assertEquals(1, status);
        JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
        GraderTest.checkSchema(r);
        assertEquals(0, r.get("score").asDouble());
        assertTrue(r.get("output").asText().contains("StackOverflowError"), r.get("output").asText());
    }

    /** Running out of memory inside the grader still gives a results.json naming it. */
    @Test
    void anOutOfMemoryErrorInsideTheGraderStillWritesResults() throws IOException {
        Path out = dir.resolve("out-oom");
        int status = GradeCommand.run(options(), Files.createDirectories(dir.resolve("empty2")), out, s -> {
            long[] hog = new long[Integer.MAX_VALUE - 8];
            hog[0] = 1;
        }, true, new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
        assertEquals(1, status);
        JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
        GraderTest.checkSchema(r);
        assertTrue(r.get("output").asText().contains("OutOfMemoryError"), r.get("output").asText());
    }

    @Test
    void aMissingSubmissionIsExitTwoWithAResultsFile() throws IOException {
        Path out = dir.resolve("out-missing");
        int status = GradeCommand.run(options(), dir.resolve("no-such-folder"), out, s -> { }, true,
                new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
        assertEquals(2, status);
        JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
        assertEquals(0, r.get("score").asDouble());
        assertTrue(r.get("output").asText().contains("no such file or directory"), r.get("output").asText());
    }

    private static Grader.Options options() {
        return Grader.Options.defaults(root).withMilestones(List.of("lambert"))
                .withLimits(new TestLauncher.Limits(256, Duration.ofSeconds(30), 5, 4096), Duration.ofSeconds(30));
    }

    private static int recurse(int n) {
        return recurse(n + 1) + 1;
    }
}
