package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignments;

/**
 * Realistic single bugs cost real points, through {@code raylab grade}: at least 1 point of their
 * milestone each, and the scene that shows the bug fails too. bugs3: the lecture's slabs without
 * a case for d = 0 (0/0 = NaN for a ray in a face's plane), a fixed shadow epsilon of 0.01, the
 * Phong power taken before the clamp, a sphere that is correct only when a test is on the call
 * stack. bugs4: a box that ignores tMax. (That every correct alternative keeps full marks with the
 * same tests and scenes is {@link GraderTest}'s part.)
 */
@ExtendWith(SharedGraderCache.class)
class RealisticBugsTest {
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

    /** The reference student files, flat, overlaid with the files of a resource submission. */
    private Path submission(String overlay) throws IOException {
        return GraderTest.submission(dir, overlay);
    }

    private JsonNode grade(Path sub, String... milestones) throws IOException {
        Path out = dir.resolve("out");
        Files.createDirectories(out);
        List<String> args = new ArrayList<>(List.of("grade", sub.toString(), "--out", out.toString(), "--root",
                root.toString(), "--quiet", "--test-timeout", "30", "--milestone-timeout", "300", "--scene-timeout", "120",
                "--heap", "256", "--seed", "17", // the graded scenes' variants of one fixed seed
                // Scores only: without the sandbox user, no other grading on the machine (whose
                // end-of-grading kill targets that user) can end these test JVMs early.
                "--sandbox-user", ""));
        for (String m : milestones) {
            args.add("--milestone");
            args.add(m);
        }
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), args.toArray(String[]::new));
        assertEquals(0, status, () -> "grade should succeed: " + err.toString(StandardCharsets.UTF_8));
        JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
        GraderTest.checkSchema(r);
        return r;
    }

    /** Asserts that milestone id lost at least {@code atLeast} points, and prints what it lost. */
    private static double assertLost(JsonNode r, String id, double atLeast) {
        Map<String, double[]> m = GraderTest.perMilestone(r);
        double lost = m.get(id)[1] - m.get(id)[0];
        StringBuilder failed = new StringBuilder();
        for (JsonNode t : r.get("tests")) {
            if (t.get("tags").get(0).asText().equals(id) && t.get("score").asDouble() < t.get("max_score").asDouble()) {
                failed.append("\n  ").append(t.get("name").asText()).append(": −")
                        .append(t.get("max_score").asDouble() - t.get("score").asDouble());
            }
        }
        System.out.printf("%s loses %.2f of %.2f points:%s%n", id, lost, m.get(id)[1], failed);
        assertTrue(lost >= atLeast - 1e-9, id + " should lose at least " + atLeast + " points, lost " + lost + failed);
        return lost;
    }

    /** Asserts that the named scene of milestone id scored 0. */
    private static void assertSceneFails(JsonNode r, String id, String sceneFile) {
        for (JsonNode t : r.get("tests")) {
            if (t.get("tags").get(0).asText().equals(id) && t.get("name").asText().endsWith("/" + sceneFile)) {
                assertEquals(0, t.get("score").asDouble(), 1e-9, "the render shows the bug: " + t);
                return;
            }
        }
        throw new AssertionError("no graded scene " + sceneFile + " in milestone " + id);
    }

    @Test
    void naiveSlabsCloseShadowEpsilonLateClampAndAStackInspectingSphereLosePoints() throws IOException {
        JsonNode r = grade(submission("bugs3"), "sphere", "box", "shadows", "phong");
        // The lecture's slabs as written: rays in a face's plane (orthographic views) miss.
        assertLost(r, "box", 3);
        assertSceneFails(r, "box", "boxes-front.json");
        // A fixed offset of 0.01 skips blockers close to the point: small scenes lose their shadows.
        assertLost(r, "shadows", 1.5);
        assertSceneFails(r, "shadows", "shadows-small.json");
        // max(0, (n·h)^p): wrong for an even or fractional p when n·h < 0 (no render shows it).
        assertLost(r, "phong", 1);
        // Correct only when a test is on the stack: every test, data case and render calls intersect
        // from a worker thread without a test on its stack, so it keeps only what its other answer
        // earns (here: misses, the flat-coloured silhouette of sphere.json, the touching ray).
        Map<String, double[]> m = GraderTest.perMilestone(r);
        assertLost(r, "sphere", 0.6 * m.get("sphere")[1]);
        assertSceneFails(r, "sphere", "spheres.json");
        assertSceneFails(r, "sphere", "spheres-dome.json");
    }

    @Test
    void aBoxIgnoringTMaxLosesPoints() throws IOException {
        JsonNode r = grade(submission("bugs4"), "box");
        // Shadow rays end at the light: a box beyond the lamp must not darken the room. Only
        // shadow rays have a finite tMax, and the box milestone's scenes must render before the
        // shadows milestone is written, so tests and a data case show it, not a box scene.
        assertLost(r, "box", 1.5);
    }
}
