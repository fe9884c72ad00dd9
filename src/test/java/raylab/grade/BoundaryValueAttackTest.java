package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;
import raylab.course.SolutionRegions;

/**
 * Issue 35's attacks on values and trust at the process boundary, graded in every sandbox mode
 * the machine has (src/test/resources/submissions/forgers/): a forged Lambertian scene (an
 * unfinished Lambertian whose Shading empties the server's list of answers "used" by
 * reflection), forged shadows (verdicts read from the scratch record each call brings, the
 * reference's shadow-ray origin printed from it), a sphere that is correct only while a thread
 * of its JVM runs a test framework (tests versus renders), and a box and a triangle that claim
 * any hit a record comes in with. Each attacked milestone must score at most what its honest
 * twin scores (the same files with the attack switched off, {@code @ARMED@} false), and the
 * milestones with the reference solution beside them full marks. Each grading takes only the
 * attacked milestones and phong (the reference beside them).
 */
class BoundaryValueAttackTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final List<String> ATTACKED = List.of("Sphere.java", "Box.java", "Triangle.java", "Lambertian.java",
            "Shading.java", "Shadows.java");
    private static final List<String> MILESTONES = List.of("sphere", "box", "triangle", "lambert", "shadows", "phong");
    private static Path root;
    private static Assignments assignments;
    private static Map<String, Double> honest;
    private static Map<String, Double> max;
    /** The four gradings, queued at once and run two at a time (docs/testing.md); each test asks for its own and the honest twin. */
    private static ConcurrentGradings<Graded> gradings;

    @BeforeAll
    static void load() throws Exception {
        root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        assignments = Assignments.load(root);
        gradings = new ConcurrentGradings<>("forger-grading", Integer.getInteger("raylab.test.attack.concurrent", 2));
        if (ConcurrentGradings.oneTestSelected()) {
            return; // -Dtest=BoundaryValueAttackTest#one: each test grades what it needs
        }
        // The shared cache built once here, not by the first two gradings at the same time.
        SharedGraderCache.whole(root);
        gradings.start(HONEST, BoundaryValueAttackTest::honestTwin);
        if (namespaces()) {
            gradings.start("namespace", () -> grade(true, "namespace", GraderTest.sandboxUser()));
        }
        if (sandboxUserExists()) {
            gradings.start("user", () -> grade(true, "user", GraderTest.sandboxUser()));
        }
        gradings.start("none", () -> grade(true, "none", ""));
    }

    @AfterAll
    static void close() throws InterruptedException {
        gradings.close();
    }

    private static final String HONEST = "honest twin";

    private static boolean namespaces() {
        return Sandbox.namespacesWork(Sandbox.isRoot());
    }

    private static boolean sandboxUserExists() throws IOException {
        return Sandbox.isRoot() && Files.readString(Path.of("/etc/passwd")).contains("\n" + GraderTest.sandboxUser() + ":");
    }

    private record Graded(Map<String, Double> score, Map<String, Double> max, String text) {
    }

    private static Graded grade(boolean armed, String mode, String user) throws Exception {
        Path work = Files.createTempDirectory("raylab-forgers");
        try {
            Path cache = root.resolve(mode.equals("none") ? "target/grader-cache-none" : "target/grader-cache");
            if (mode.equals("none")) {
                SharedGraderCache.seed(cache); // a copy of the shared build, not a build of its own
            }
            Path out = Files.createDirectories(work.resolve("out"));
            Path sub = Files.createDirectories(work.resolve("sub"));
            Set<String> all = new TreeSet<>(assignments.ids());
            for (Assignment a : assignments.all()) {
                for (Assignment.StudentFile f : a.files()) {
                    Path src = root.resolve(f.path());
                    String name = src.getFileName().toString();
                    String text = ATTACKED.contains(name)
                            ? Files.readString(root.resolve("src/test/resources/submissions/forgers/" + name))
                                    .replace("@ARMED@", Boolean.toString(armed))
                            : SolutionRegions.toStudent(name, Files.readString(src), all);
                    Files.writeString(sub.resolve(name), text);
                }
            }
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            List<String> args = new java.util.ArrayList<>(List.of("grade", sub.toString(), "--out", out.toString(),
                    "--root", root.toString(), "--quiet", "--test-timeout", "10", "--milestone-timeout", "120",
                    "--scene-timeout", "30", "--heap", "256", "--sandbox", mode, "--sandbox-user", user, "--cache",
                    cache.toString(), "--seed", "35"));
            for (String m : MILESTONES) {
                args.add("--milestone");
                args.add(m);
            }
            int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                    new PrintWriter(err, true, StandardCharsets.UTF_8), args.toArray(String[]::new));
            assertEquals(0, status, () -> "graded: " + err);
            JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
            Map<String, Double> score = new TreeMap<>();
            Map<String, Double> most = new TreeMap<>();
            for (JsonNode t : r.get("tests")) {
                String m = t.get("tags").get(0).asText();
                score.merge(m, t.get("score").asDouble(), Double::sum);
                most.merge(m, t.get("max_score").asDouble(), Double::sum);
            }
            System.out.println("[forgers] " + mode + " " + (armed ? "armed" : "honest twin") + ": " + score + " of "
                    + most);
            return new Graded(score, most, r.toString());
        } finally {
            JavaBuild.deleteTreeQuietly(work);
        }
    }

    /** The honest twins' grading (honest code scores the same in every mode). */
    private static Graded honestTwin() throws Exception {
        return grade(false, namespaces() ? "namespace" : "none", namespaces() ? GraderTest.sandboxUser() : "");
    }

    /** The honest twins' scores (graded once). */
    private static synchronized Map<String, Double> honest() throws Exception {
        if (honest == null) {
            Graded g = gradings.get(HONEST, BoundaryValueAttackTest::honestTwin);
            honest = g.score();
            max = g.max();
        }
        return honest;
    }

    private static void assertNoPointFromTheAttacks(Graded armed) throws Exception {
        Map<String, Double> twin = honest();
        for (String m : MILESTONES) {
            double got = armed.score().getOrDefault(m, 0.0);
            if (m.equals("phong")) {
                assertEquals(max.get(m), got, 1e-9, "phong (the reference beside the attacks): full marks expected");
                continue;
            }
            assertTrue(got <= twin.getOrDefault(m, 0.0) + 1e-9, m + ": no point from the attack: armed " + got
                    + ", its honest twin " + twin.get(m) + " (of " + max.get(m) + ")");
        }
        // The forged Lambertian scene: an unfinished Lambertian renders nothing like the reference.
        assertTrue(armed.score().getOrDefault("lambert", 0.0) <= twin.getOrDefault("lambert", 0.0) + 1e-9,
                "lambert: no point from the forged diffuse");
    }

    @Test
    void inTheNamespaceSandbox() throws Exception {
        assumeTrue(namespaces(), "unshare cannot create namespaces here");
        assertNoPointFromTheAttacks(gradings.get("namespace", () -> grade(true, "namespace", GraderTest.sandboxUser())));
    }

    @Test
    void withTheSandboxUserWithoutNamespaces() throws Exception {
        assumeTrue(sandboxUserExists(), "needs root and the user " + GraderTest.sandboxUser() + " (.ci/run creates it)");
        assertNoPointFromTheAttacks(gradings.get("user", () -> grade(true, "user", GraderTest.sandboxUser())));
    }

    @Test
    void withoutASandbox() throws Exception {
        assertNoPointFromTheAttacks(gradings.get("none", () -> grade(true, "none", "")));
    }
}
