package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raylab.course.release.AddSceneTest.run;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;
import raylab.course.SolutionRegions;

/**
 * {@code raylab assignment add-test}: an instructor adds a hidden sphere test in a copy of the
 * project. The first run writes a skeleton in grader/tests/raylab/surface with the tag and the
 * helpers; the checks refuse it until it is written, refuse a test that does not compile, lacks
 * the tag or misses the named bug; then it is graded with a weight and extra points, and
 * {@code raylab grade} scores it as the plan says.
 */
class AddTestTest {
    @TempDir
    Path dir;

    private static final String CLASS = "SphereFarHiddenTest";
    private static final String REL = "grader/tests/raylab/surface/" + CLASS + ".java";

    /** A written hidden test: rays from far away hit the near side at t = the distance to it. */
    private static final String WRITTEN = """
            package raylab.surface;

            import java.util.SplittableRandom;

            import org.junit.jupiter.api.DisplayName;
            import org.junit.jupiter.api.Tag;
            import org.junit.jupiter.api.Test;

            import raylab.hidden.Calls;
            import raylab.hidden.Hidden;
            import raylab.math.Vec3;
            import raylab.ray.IntersectionRecord;
            import raylab.ray.Ray;

            /** Hidden test of Sphere.intersect: a ray from outside enters through the near side. */
            @Tag("sphere")
            class SphereFarHiddenTest {
                @Test
                @DisplayName("a ray from far away hits the near side, not the far one")
                void nearSideFirst() {
                    long seed = 0x5eedL;
                    SplittableRandom r = Hidden.rng(seed);
                    for (int i = 0; i < 50; i++) {
                        Vec3 c = Hidden.point(r, 5);
                        double radius = Hidden.uniform(r, 0.5, 3);
                        Vec3 n = Hidden.unit(r);
                        double dist = Hidden.uniform(r, 1, 100);
                        Vec3 hit = c.plus(n.times(radius));
                        Ray ray = new Ray(hit.plus(n.times(dist)), n.times(-1));
                        Sphere s = new Sphere(c, radius, Hidden.M, "far #" + i);
                        IntersectionRecord rec = new IntersectionRecord();
                        boolean returned = Calls.intersect(s, rec, ray);
                        Hidden.assertHit("from far away #" + i + " (seed " + seed + ")", s, ray, rec, returned, dist, hit,
                                n, "the nearer root comes first");
                    }
                }

                @Test
                @DisplayName("a ray that passes beside the sphere misses it")
                void besideMisses() {
                    Sphere s = new Sphere(new Vec3(0, 0, 0), 1, Hidden.M, "unit");
                    IntersectionRecord rec = new IntersectionRecord();
                    org.junit.jupiter.api.Assertions.assertEquals(false, Calls.intersect(s, rec,
                            new Ray(new Vec3(0, 1.5, 5), new Vec3(0, 0, -1))), "expected a miss, got a hit");
                }
            }
            """;

    @Test
    void skeletonThenChecksThenWeightedPointsThatTheGraderGives() throws IOException {
        Path root = Path.of("").toAbsolutePath();
        Path copy = AddSceneTest.copy(root, dir.resolve("course"));
        Path json = copy.resolve("assignments/01-sphere/assignment.json");
        byte[] before = Files.readAllBytes(json);
        Assignment sphere = Assignments.load(copy).byId("sphere").orElseThrow();
        String c = "--root=" + copy;

        String out = run(0, "assignment", "add-test", "sphere", CLASS, c);
        Path test = copy.resolve(REL);
        String skeleton = Files.readString(test);
        assertTrue(out.contains("wrote the skeleton " + REL), out);
        assertTrue(skeleton.contains("package raylab.surface;") && skeleton.contains("@Tag(\"sphere\")")
                && skeleton.contains("import raylab.hidden.Calls;") && skeleton.contains("Hidden.rng(seed)")
                && skeleton.contains("class " + CLASS + " {"), skeleton);
        assertArrayEquals(before, Files.readAllBytes(json), "the skeleton is not graded yet");

        // The unwritten skeleton fails on the reference: refused.
        out = run(1, "assignment", "add-test", "sphere", CLASS, c);
        assertTrue(out.contains("the test fails on the reference solution") && out.contains("write this hidden test"), out);
        // A test that does not compile, one without the tag: refused.
        Files.writeString(test, WRITTEN.replace("Hidden.unit(r);", "Hidden.unit(r)"));
        out = run(1, "assignment", "add-test", "sphere", CLASS, c);
        assertTrue(out.contains("the test does not compile: " + REL + ":"), out);
        Files.writeString(test, WRITTEN.replace("@Tag(\"sphere\")", "@Tag(\"box\")"));
        out = run(1, "assignment", "add-test", "sphere", CLASS, c);
        assertTrue(out.contains("has no test the grader would run: its class needs @Tag(\"sphere\")"), out);

        // The written test against a "bug" it cannot catch (a copy of the reference), a folder and another
        // milestone's file (refused), then a bug it catches: the far root first.
        Files.writeString(test, WRITTEN);
        String reference = Files.readString(root.resolve("src/main/java/raylab/surface/Sphere.java"));
        Path same = Files.createDirectories(dir.resolve("same")).resolve("Sphere.java");
        Files.writeString(same, reference);
        out = run(1, "assignment", "add-test", "sphere", CLASS, "--buggy", same.toString(), c);
        assertTrue(out.contains("the test passes on " + same + " too: it does not catch that bug"), out);
        Path farFirst = Files.createDirectories(dir.resolve("far-first")).resolve("Sphere.java");
        assertTrue(reference.contains("double t = t0;"));
        Files.writeString(farFirst, reference.replace("double t = t0;", "double t = t1;"));
        out = run(2, "assignment", "add-test", "sphere", CLASS, "--buggy", dir.resolve("same").toString(), c);
        assertTrue(out.contains(dir.resolve("same") + ": no such file"), out);
        Path box = Files.createDirectories(dir.resolve("box")).resolve("Box.java");
        Files.writeString(box, Files.readString(root.resolve("src/main/java/raylab/surface/Box.java")));
        out = run(2, "assignment", "add-test", "sphere", CLASS, "--buggy", box.toString(), c);
        assertTrue(out.contains(box + ": not a student file of milestone sphere (its files: Sphere.java)"), out);
        assertArrayEquals(before, Files.readAllBytes(json), "nothing was graded by a refused run");

        out = run(0, "assignment", "add-test", "sphere", CLASS, "--buggy", farFirst.toString(), "--points", "2",
                "--weight", "3", c);
        System.out.println(out);
        assertTrue(out.contains("2 test method(s) pass on the reference solution; on Sphere.java 1 fail: "
                + "\"a ray from far away hits the near side, not the far one\""), out);
        Assignment after = Assignments.load(copy).byId("sphere").orElseThrow();
        assertTrue(after.tests().hidden().contains(REL), after.tests().hidden().toString());
        assertEquals(sphere.tests().hiddenPoints() + 2, after.tests().hiddenPoints());
        assertEquals(sphere.points() + 2, after.points());
        assertEquals(3.0, after.tests().hiddenWeights().get(CLASS));

        // The split: the old hidden methods weigh 1, the new ones 3 each.
        GradingPlan.Plan plan = GradingPlan.of(copy, after);
        List<GradingPlan.Item> hiddenTests = plan.hidden().stream().filter(i -> i.kind() == GradingPlan.Kind.TEST).toList();
        long total = hiddenTests.stream().mapToLong(GradingPlan.Item::cents).sum();
        assertEquals(100L * after.tests().hiddenPoints(), total, "hiddenPoints split exactly");
        int oldMethods = hiddenTests.size() - 2;
        double exactNew = 100.0 * after.tests().hiddenPoints() * 3 / (oldMethods + 6);
        double exactOld = 100.0 * after.tests().hiddenPoints() / (oldMethods + 6);
        for (GradingPlan.Item i : hiddenTests) {
            double exact = i.key().startsWith("raylab.surface." + CLASS + "#") ? exactNew : exactOld;
            assertTrue(Math.abs(i.cents() - exact) < 1, i.key() + ": expected about " + exact + " cents, got " + i.cents());
        }
        String handout = Files.readString(copy.resolve("assignments/01-sphere/README.md"));
        assertTrue(handout.contains("| **total** | **" + after.points() + "** |"), handout);

        // raylab grade after the due date scores the new test with its weighted points, on the reference.
        Path sub = Files.createDirectories(dir.resolve("submission"));
        Files.writeString(sub.resolve("Sphere.java"), SolutionRegions.toStudent("Sphere.java", reference, Set.of("sphere")));
        Path results = dir.resolve("results");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), "grade", sub.toString(), "--out", results.toString(),
                "--root", copy.toString(), "--quiet", "--milestone", "sphere", "--after-due-date", "--test-timeout", "5",
                "--cache", root.resolve("target/grader-cache").toString(), "--milestone-timeout", "60",
                "--scene-timeout", "30", "--heap", "256", "--sandbox-user", "");
        assertEquals(0, status, () -> err.toString(StandardCharsets.UTF_8));
        JsonNode r = new ObjectMapper().readTree(results.resolve("results.json").toFile());
        int found = 0;
        for (JsonNode t : r.get("tests")) {
            for (GradingPlan.Item i : hiddenTests) {
                if (i.key().startsWith("raylab.surface." + CLASS + "#") && t.get("name").asText().equals("sphere: " + i.name() + " (hidden test)")) {
                    found++;
                    assertEquals(i.points(), t.get("max_score").asDouble(), 1e-9, t.toString());
                    assertEquals(i.points(), t.get("score").asDouble(), 1e-9, "the reference passes: " + t);
                }
            }
        }
        assertEquals(2, found, "both new hidden tests are graded: " + r.get("tests"));
        assertEquals(after.points(), r.get("score").asDouble(), 1e-9, "the reference earns every point");
    }
}
