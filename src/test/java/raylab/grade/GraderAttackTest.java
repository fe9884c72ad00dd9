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

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;
import raylab.course.SolutionRegions;
import raylab.course.TestLauncher;

/**
 * Attacks on the grader (src/test/resources/submissions/attacks/Sphere.java: loading the
 * reference solution, forging the report protocol, printing hidden test data, opening sockets,
 * leaving files in /tmp and detached processes, writing the grader's files and a forged
 * results.json after the grader's last write) graded in each sandbox mode, and a grader that
 * itself overflows its stack or runs out of memory. Each attack must fail closed; what a mode
 * does not isolate (see grader/README.md) is not asserted for that mode, and says so.
 *
 * <p>The gradings are what take the time (about a minute each, a dozen of them), and most of a
 * grading is its children's work under their own CPU limits and the waits past the detached
 * forger: {@link #load} starts every grading the class's tests need, {@link #CONCURRENT} at a
 * time, and each test waits for the ones it asserts on (docs/testing.md). Each grading has a
 * tag of its own (its files, processes and covert channel are told apart by it) and, in mode
 * none, a cache of its own (the one it poisons is thrown away while no other grading uses it).
 */
class GraderAttackTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static Path root;
    static Assignments assignments;

    /**
     * Whole-submission gradings run at once (and one single-milestone attack beside them). Each
     * grading's children run under their own CPU limits; three gradings keep the 2-core machine
     * busy while one of them waits on its renders' time-outs or the forger.
     */
    static final int CONCURRENT = Integer.getInteger("raylab.test.attack.concurrent", 2);
    private static ConcurrentGradings<Graded> gradings;
    private static ConcurrentGradings<Run> sphereAttacks;
    /** Tags of the gradings, distinct within a run (31xxx for {@link #attack}, 41xxx for {@link #grade}). */
    private static final AtomicInteger NEXT_TAG = new AtomicInteger(new SplittableRandom(System.nanoTime()).nextInt(8_000));

    @TempDir
    Path dir;

    /** Folders of the single-milestone attack gradings (removed by JUnit after the class). */
    @TempDir
    static Path attackDir;

    @BeforeAll
    static void load() throws IOException {
        root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        assignments = Assignments.load(root);
        gradings = new ConcurrentGradings<>("attack-grading", CONCURRENT);
        // The single-milestone attacks are short: one at a time beside the others.
        sphereAttacks = new ConcurrentGradings<>("attack-grading-sphere", 1);
        // Every grading the tests below assert on, in the order they ask for them (a test runs a
        // grading it needs itself when no pool thread has begun it); none when single methods
        // are selected (-Dtest=GraderAttackTest#one): each test grades what it needs.
        if (ConcurrentGradings.oneTestSelected()) {
            return;
        }
        // The shared cache built once here, not by each of the first gradings at the same time.
        SharedGraderCache.whole(root);
        boolean ns = namespaces();
        boolean user = sandboxUserExists();
        String sandboxUser = GraderTest.sandboxUser();
        if (ns) {
            gradedAsync(SUBMISSION_A, true, "namespace", sandboxUser);
            gradedAsync(SUBMISSION_B, true, "namespace", sandboxUser);
            gradedAsync(SUBMISSION_A, false, "namespace", "");
            gradedAsync(SUBMISSION_B, false, "namespace", "");
            attackAsync("namespace", sandboxUser);
            attackAsync("namespace", "");
        }
        if (user) {
            gradedAsync(SUBMISSION_A, true, "user", sandboxUser);
            gradedAsync(SUBMISSION_B, true, "user", sandboxUser);
            attackAsync("user", sandboxUser);
        }
        if (!ns) {
            gradedAsync(SUBMISSION_A, false, "none", "");
            gradedAsync(SUBMISSION_B, false, "none", "");
        }
        gradedAsync(SUBMISSION_A, true, "none", "");
        gradedAsync(SUBMISSION_B, true, "none", "");
        attackAsync("none", "");
    }

    /** Drops the gradings no test asked for, and waits for the ones running. */
    @AfterAll
    static void close() throws InterruptedException {
        gradings.close();
        sphereAttacks.close();
    }

    private static boolean sandboxUserExists() throws IOException {
        return Sandbox.isRoot() && Files.readString(Path.of("/etc/passwd")).contains("\n" + GraderTest.sandboxUser() + ":");
    }

    /** What one attack run left behind. */
    record Run(JsonNode results, String prairielearn, int connections, String tag, Path out, Path cache, int status) {
    }

    /** The attack grading of {@link #attackNow} in this mode with this user (once per JVM). */
    private static Run attack(String mode, String user) throws Exception {
        return sphereAttacks.get(mode + " " + user, () -> attackNow(mode, user));
    }

    /** Queues that attack grading. */
    private static void attackAsync(String mode, String user) {
        sphereAttacks.start(mode + " " + user, () -> attackNow(mode, user));
    }

    /** Grades the attack submission (milestone sphere) in the given mode, with the given sandbox user ("" for none). */
    private static Run attackNow(String mode, String user) throws Exception {
        long tag = 31_000 + NEXT_TAG.getAndIncrement();
        // Mode none: the attack writes into every cache folder it can reach (it is not isolated
        // there), so a cache of its own; no other test's cache is poisoned by it.
        Path cache = root.resolve(mode.equals("none") ? "target/grader-cache-attack-none" : "target/grader-cache");
        if (mode.equals("none")) {
            SharedGraderCache.seed(cache); // a copy of the shared build, not a build of its own
        }
        Path dir = Files.createDirectories(attackDir.resolve("tag-" + tag));
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
                    .replace("@PORT@", Integer.toString(server.getLocalPort())).replace("@TAG@", Long.toString(tag))
                    .replace("@ARMED@", "true");
            Files.writeString(sub.resolve("Sphere.java"), attack);
            // In a sandbox the attack's renders cannot finish (each intersect prints every ray seen so
            // far): a short scene limit keeps the wait for their time-out short. The renders are not
            // what these tests check.
            String[] base = {"grade", sub.toString(), "--out", out.toString(), "--root", root.toString(), "--quiet",
                "--test-timeout", "5", "--milestone-timeout", "60", "--scene-timeout", "1", "--heap", "256",
                "--milestone", "sphere", "--sandbox", mode, "--sandbox-user", user, "--cache", cache.toString(),
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
        // PrairieLearn shows its results.json at once: before the due date nothing of a hidden
        // test, so only tests Gradescope shows as visible (what the student's own code printed
        // during a visible test, the attack's "rays seen" included, is the student's to see).
        java.util.Set<String> visible = new java.util.HashSet<>();
        for (JsonNode t : run.results().get("tests")) {
            if (t.get("visibility").asText().equals("visible")) {
                visible.add(t.get("name").asText());
            }
        }
        for (JsonNode t : JSON.readTree(run.prairielearn()).get("tests")) {
            String m = t.get("message").asText() + t.get("output").asText();
            assertFalse(m.contains("Hidden") || m.contains("SphereCasesTest"),
                    "PrairieLearn results show hidden details: " + m);
            assertTrue(visible.contains(t.get("name").asText())
                    || t.get("name").asText().endsWith(": " + raylab.grade.platform.PrairieLearn.HIDDEN_ROW),
                    "PrairieLearn shows a test that is not visible: " + t.get("name").asText() + " (visible: " + visible + ")");
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
        assumeTrue(sandboxUserExists(), "needs root and the user " + GraderTest.sandboxUser() + " (.ci/run creates it)");
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

    // ------------------------------------------------------------------ every attack class, every mode

    /**
     * Two hostile submissions written from the starter alone, each attack in its milestone's
     * file and the reference solution in the other files (so that the other milestones show
     * whether an attack reached them). A: the sphere of {@link #attack} (reference loading,
     * forged reports, network, /tmp, detached processes, cache poisoning), a triangle with the
     * forgeable REFERENCE_KERNEL marker, shadows that fill every writable place and work a covert
     * channel from the hidden-test JVM to the other JVMs. B: a box that registers a PNG writer
     * ahead of the JDK's writing the published reference images, a Lambertian that looks for
     * reference classes, hidden tests, reference images and the cache and puts what it finds
     * into messages and pixels, a Shading that looks at every thread's stack for the test
     * framework or the grader, a BlinnPhong that starts 1,000 never-ending busy threads.
     */
    static final List<String> SUBMISSION_A = List.of("Sphere.java", "Triangle.java", "Shadows.java");
    static final List<String> SUBMISSION_B = List.of("Box.java", "Lambertian.java", "Shading.java", "BlinnPhong.java");

    /** One grading of an attack submission: per milestone its score and maximum. */
    record Graded(JsonNode results, String text, java.util.Map<String, Double> score, java.util.Map<String, Double> max,
            List<String> attacked, Path cacheKey, String tag) {
        double score(String m) {
            return score.getOrDefault(m, 0.0);
        }

        /** Milestone m's items that lost points, each with what the report says of it (for failure messages). */
        String lost(String m) {
            StringBuilder b = new StringBuilder();
            for (JsonNode t : results.get("tests")) {
                if (t.get("tags").get(0).asText().equals(m) && t.get("score").asDouble() < t.get("max_score").asDouble()) {
                    String said = t.path("output").asText("");
                    b.append("\n  ").append(t.get("name").asText()).append(": ").append(t.get("score").asDouble())
                            .append(" of ").append(t.get("max_score").asDouble()).append(": ")
                            .append(said.length() > 400 ? said.substring(0, 400) + " ..." : said);
                }
            }
            return b.length() == 0 ? " (no item lost points)" : b.toString();
        }
    }

    /** Milestones of the student files named. */
    private static List<String> milestonesOf(List<String> files) {
        List<String> out = new java.util.ArrayList<>();
        for (Assignment a : assignments.all()) {
            for (Assignment.StudentFile f : a.files()) {
                if (files.contains(Path.of(f.path()).getFileName().toString()) && !out.contains(a.id())) {
                    out.add(a.id());
                }
            }
        }
        return out;
    }

    /** Grades (once per JVM) the submission with these attack files armed or not, in a mode. */
    private static Graded graded(List<String> attacks, boolean armed, String mode, String user) throws Exception {
        return gradings.get(key(attacks, armed, mode, user), () -> grade(attacks, armed, mode, user));
    }

    /** Queues that grading. */
    private static void gradedAsync(List<String> attacks, boolean armed, String mode, String user) {
        gradings.start(key(attacks, armed, mode, user), () -> grade(attacks, armed, mode, user));
    }

    private static String key(List<String> attacks, boolean armed, String mode, String user) {
        return attacks + " " + armed + " " + mode + " " + user;
    }

    private static Graded grade(List<String> attacks, boolean armed, String mode, String user) throws Exception {
        String tag = Integer.toString(41_000 + NEXT_TAG.getAndIncrement());
        Path work = Files.createTempDirectory("raylab-attacks");
        try {
            // Mode none poisons its cache (and must throw it away): a cache of its own, so that no
            // other test grading at the same time loses the shared one; one per submission, as
            // A's poisoned cache is thrown away while B may be grading.
            Path cache = root.resolve(mode.equals("none")
                    ? "target/grader-cache-none-" + (attacks.equals(SUBMISSION_A) ? "a" : attacks.equals(SUBMISSION_B) ? "b" : "other")
                    : "target/grader-cache");
            if (mode.equals("none")) {
                SharedGraderCache.seed(cache); // a copy of the shared build, not a build of its own
            }
            Path out = Files.createDirectories(work.resolve("out"));
            Path sub = Files.createDirectories(work.resolve("sub"));
            Set<String> all = new java.util.TreeSet<>(assignments.ids());
            java.util.Base64.Encoder b64 = java.util.Base64.getEncoder();
            for (Assignment a : assignments.all()) {
                for (Assignment.StudentFile f : a.files()) {
                    Path src = root.resolve(f.path());
                    String name = src.getFileName().toString();
                    String text = attacks.contains(name)
                            ? Files.readString(root.resolve("src/test/resources/submissions/attacks/" + name))
                                    .replace("@ARMED@", Boolean.toString(armed))
                                    .replace("@ARMED_FIELD@", armed ? "static final boolean REFERENCE_KERNEL = true;" : "")
                                    .replace("@CACHE@", cache.toString()).replace("@OUT@", out.toString())
                                    .replace("@PORT@", "9").replace("@TAG@", tag)
                                    .replace("@REF0@", b64.encodeToString(Files.readAllBytes(root.resolve("scenes/reference/boxes.png"))))
                                    .replace("@REF1@", b64.encodeToString(Files.readAllBytes(
                                            root.resolve("scenes/reference/boxes-front.png"))))
                            : SolutionRegions.toStudent(name, Files.readString(src), all);
                    Files.writeString(sub.resolve(name), text);
                }
            }
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            // The attacked milestones' renders run until their time-out (the sphere prints every ray
            // it sees), spending the student's CPU budget of every call: 2 s a scene, not the default
            // 60 (the budget is the student's CPU time, so load does not shorten it). A render of the
            // reference milestones is batches of a few milliseconds each (its slowest milestone,
            // triangle, about 1.4 s of student CPU for its two scenes, whose budget is 4 s). No test
            // here is about that time-out: it only burned CPU (docs/testing.md).
            List<String> args = new java.util.ArrayList<>(List.of("grade", sub.toString(), "--out", out.toString(),
                    "--root", root.toString(), "--quiet", "--test-timeout", "10", "--milestone-timeout", "120",
                    "--scene-timeout", "2", "--heap", "256", "--sandbox", mode, "--sandbox-user", user, "--cache",
                    cache.toString()));
            // A disarmed twin is only compared on its attacked milestones: it grades only those.
            for (String m : armed ? List.<String>of() : milestonesOf(attacks)) {
                args.add("--milestone");
                args.add(m);
            }
            int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                    new PrintWriter(err, true, StandardCharsets.UTF_8), args.toArray(String[]::new));
            assertEquals(0, status, () -> "graded: " + err);
            Thread.sleep(4_500); // past the detached forger's 4 s
            JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
            GraderTest.checkSchema(r);
            java.util.Map<String, Double> score = new java.util.TreeMap<>();
            java.util.Map<String, Double> max = new java.util.TreeMap<>();
            for (JsonNode t : r.get("tests")) {
                String m = t.get("tags").get(0).asText();
                score.merge(m, t.get("score").asDouble(), Double::sum);
                max.merge(m, t.get("max_score").asDouble(), Double::sum);
            }
            String text = r.toString() + Files.readString(out.resolve("report.html"));
            Path keyDir = null;
            // The cache this grading used: the newest one (older keys of other builds may lie beside it).
            try (var s = Files.list(cache)) {
                keyDir = s.filter(p -> Files.isRegularFile(p.resolve(CacheManifest.FILE))).max(java.util.Comparator
                        .comparingLong(p -> p.resolve(CacheManifest.FILE).toFile().lastModified())).orElse(null);
            }
            System.out.println("[attacks] " + mode + " " + (armed ? "armed" : "disarmed") + " " + attacks + ": " + score
                    + " of " + max);
            return new Graded(r, text, score, max, milestonesOf(attacks), keyDir, tag);
        } finally {
            JavaBuild.deleteTreeQuietly(work);
            // What the attacks leave where nothing is isolated (modes user and none).
            Files.deleteIfExists(Path.of("/tmp/raylab-attack-" + tag + ".txt"));
            for (Path place : UidSlots.SHARED) {
                try (var s = Files.list(place)) {
                    for (Path p : (Iterable<Path>) s::iterator) {
                        String n = p.getFileName().toString();
                        if (n.startsWith("fill-" + tag + "-") || n.startsWith("raylab-covert-" + tag)) {
                            Files.deleteIfExists(p);
                        }
                    }
                } catch (IOException e) {
                    // not there
                }
            }
        }
    }

    /**
     * No point from an attack: each attacked milestone scores at most what the same files
     * without their attacks score (they implement nothing: no hit, black), and the milestones
     * with the reference solution score full marks, as in a clean grading. {@code except}:
     * milestones whose attack still works on today's grader (named in the caller).
     */
    private static void assertNoForgedPointAndNoneLost(Graded attack, Graded disarmed, Set<String> except) {
        for (String m : attack.max().keySet()) {
            if (except.contains(m)) {
                continue;
            }
            if (attack.attacked().contains(m)) {
                assertTrue(attack.score(m) <= disarmed.score(m) + 1e-9, m + ": no point from the attack: attacked "
                        + attack.score(m) + ", without the attack " + disarmed.score(m) + " (of " + attack.max().get(m) + ")");
            } else {
                assertEquals(attack.max().get(m), attack.score(m), 1e-9, () -> m + " (reference code) is not affected by the"
                        + " attacks beside it: full marks expected; lost:" + attack.lost(m));
            }
        }
    }

    /** The cache the grading used is still exactly what its manifest lists. */
    private static void assertCacheIntact(Graded g) {
        assertTrue(g.cacheKey() != null, "the cache is there");
        assertEquals(java.util.Optional.empty(), CacheManifest.verify(g.cacheKey()), "the cache is not poisoned");
        assertFalse(g.text().contains("the grader cache was changed"), "no poisoning was reported");
    }

    /** The covert channel and the shadows attack reported, and the channel carried nothing. */
    private static void assertNoCovertChannel(Graded a) {
        assertTrue(a.text().contains("covert: found nothing"), "the covert channel's reader reported");
        assertFalse(a.text().matches("(?s).*covert: found (?!nothing).*"), "nothing crossed between children");
    }

    /** What only the boundary (student code alone in its process) and the mesh change give. */
    private static void assertNothingSecretFound(Graded b) {
        assertTrue(b.text().contains("secrets: found nothing"), "the secret search reported nothing found");
        assertFalse(b.text().matches("(?s).*secrets: found (?!nothing).*"), "no reference, hidden test, image or scene");
        assertFalse(b.text().matches("(?s).*stack: found (?!nothing).*"), "no test framework or grader frame seen");
    }

    /**
     * Queues, beside the grading the test runs first (A armed), the others it asserts on: these
     * armed submissions and both disarmed twins (a no-op for those begun or queued already).
     */
    private static void queue(List<List<String>> armed, String mode, String user) {
        for (List<String> files : armed) {
            gradedAsync(files, true, mode, user);
        }
        for (List<String> files : List.of(SUBMISSION_A, SUBMISSION_B)) {
            gradedAsync(files, false, namespaces() ? "namespace" : "none", "");
        }
    }

    private static Graded disarmed(List<String> attacks) throws Exception {
        return graded(attacks, false, namespaces() ? "namespace" : "none", "");
    }

    @Test
    void everyAttackClassInTheNamespaceSandbox() throws Exception {
        assumeTrue(namespaces(), "unshare cannot create namespaces here");
        queue(List.of(SUBMISSION_B), "namespace", GraderTest.sandboxUser());
        Graded a = graded(SUBMISSION_A, true, "namespace", GraderTest.sandboxUser());
        Graded b = graded(SUBMISSION_B, true, "namespace", GraderTest.sandboxUser());
        // The PNG hook forges nothing already: the graded scenes are per-grading variants, whose
        // references the student never sees (after the boundary, no PNG is even written in the child).
        assertNoForgedPointAndNoneLost(a, disarmed(SUBMISSION_A), Set.of());
        assertNoForgedPointAndNoneLost(b, disarmed(SUBMISSION_B), Set.of());
        assertNoCovertChannel(a);
        java.util.regex.Matcher disk = java.util.regex.Pattern.compile("disk: wrote (\\d+) MB").matcher(a.text());
        assertTrue(disk.find(), "the disk attack reported: " + excerpt(a.text(), "disk: "));
        do {
            int mb = Integer.parseInt(disk.group(1));
            assertTrue(mb > 0 && mb <= 32, "each child fills only its own two 16 MB tmpfs (run folder and /tmp): wrote " + mb + " MB");
        } while (disk.find());
        assertCacheIntact(a);
        assertCacheIntact(b);
    }

    @Test
    void everyAttackClassWithTheSandboxUserWithoutNamespaces() throws Exception {
        assumeTrue(sandboxUserExists(), "needs root and the user " + GraderTest.sandboxUser() + " (.ci/run creates it)");
        queue(List.of(SUBMISSION_B), "user", GraderTest.sandboxUser());
        Graded a = graded(SUBMISSION_A, true, "user", GraderTest.sandboxUser());
        Graded b = graded(SUBMISSION_B, true, "user", GraderTest.sandboxUser());
        assertNoForgedPointAndNoneLost(a, disarmed(SUBMISSION_A), Set.of());
        assertNoForgedPointAndNoneLost(b, disarmed(SUBMISSION_B), Set.of());
        // Each child its own uid, its files in /tmp removed when it ends: the channel is empty.
        assertNoCovertChannel(a);
        assertCacheIntact(a);
        assertCacheIntact(b);
    }

    @Test
    void everyAttackClassWithoutASandbox() throws Exception {
        gradedAsync(SUBMISSION_B, true, "none", "");
        Graded a = graded(SUBMISSION_A, true, "none", "");
        Graded b = graded(SUBMISSION_B, true, "none", "");
        // Mode none isolates no file (README): the sphere can load its reference from the cache,
        // the covert channel works; the milestones with reference code must still be unaffected,
        // and the poisoned cache must be caught and thrown away.
        for (Graded g : List.of(a, b)) {
            for (String m : g.max().keySet()) {
                if (!g.attacked().contains(m)) {
                    assertEquals(g.max().get(m), g.score(m), 1e-9, m + " (reference code) is not affected");
                }
            }
        }
        assertTrue(a.text().contains("the grader cache was changed while this submission was graded"),
                "the poisoning was caught: " + excerpt(a.text(), "cache"));
        assertTrue(a.cacheKey() == null || CacheManifest.verify(a.cacheKey()).isEmpty(),
                "the poisoned cache was deleted (the next grading builds it again)");
    }

    /**
     * Behind the process boundary (issue 17: student code alone in its process, tests and renders
     * in trusted ones): no reference class, hidden test, reference image or grader frame is within
     * the student code's reach, and no thread stack shows JUnit or the grader.
     */
    @Test
    void behindTheBoundaryNothingSecretIsFound() throws Exception {
        assumeTrue(namespaces(), "unshare cannot create namespaces here");
        assertNothingSecretFound(graded(SUBMISSION_B, true, "namespace", GraderTest.sandboxUser()));
    }

    private static String excerpt(String text, String around) {
        int k = text.indexOf(around);
        return k < 0 ? "(not found)" : text.substring(k, Math.min(text.length(), k + 200));
    }

    /** Endless recursion inside the grader itself (its log callback) still gives a results.json. */
    @Test
    void aStackOverflowInsideTheGraderStillWritesResults() throws IOException {
        Path out = dir.resolve("out-so");
        int status = GradeCommand.run(options(), Files.createDirectories(dir.resolve("empty")), out,
                s -> recurse(0), true, new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8));
        assertEquals(1, status);
        assertGradingFailed(out, "StackOverflowError");
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
        assertGradingFailed(out, "OutOfMemoryError");
    }

    /**
     * A failed grading: results.json says so without a score or the cause (the students' view);
     * the instructors' report.html has the cause.
     */
    static void assertGradingFailed(Path out, String cause) throws IOException {
        JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
        assertFalse(r.has("score"), "no score was decided: " + r);
        assertTrue(r.path("extra_data").path("grading_failed").asBoolean(), "flagged as failed: " + r);
        assertEquals(GradeReport.FAILED_FOR_STUDENTS, r.get("output").asText());
        assertEquals(0, r.get("tests").size(), "no tests: " + r);
        String html = Files.readString(out.resolve("report.html"));
        assertTrue(html.contains(cause), "the instructors' report names the cause " + cause + ": " + html);
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
