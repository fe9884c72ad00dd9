package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;

/**
 * Through {@code raylab grade --seed N}: the graded scenes are variants (their references, rendered
 * in the grader, are the ones in the report, not the published ones); the reference solution
 * scores every variant; a buggy submission loses the same scenes on variants as on the published
 * scenes (RealisticBugsTest, with its own seed, is the published-scene side of the same bugs).
 */
@ExtendWith(SharedGraderCache.class)
class GradedVariantsTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static Path root;
    static Assignments all;

    @TempDir
    Path dir;

    @BeforeAll
    static void load() throws IOException {
        root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        all = Assignments.load(root);
    }

    static JsonNode grade(Path sub, long seed, Path out, String... milestones) throws IOException {
        Files.createDirectories(out);
        List<String> args = new ArrayList<>(List.of("grade", sub.toString(), "--out", out.toString(), "--root",
                root.toString(), "--quiet", "--test-timeout", "30", "--milestone-timeout", "300", "--scene-timeout", "120",
                "--heap", "256", "--sandbox-user", "", "--seed", Long.toString(seed)));
        for (String m : milestones) {
            args.add("--milestone");
            args.add(m);
        }
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), args.toArray(String[]::new));
        assertEquals(0, status, () -> "grade should succeed: " + err.toString(StandardCharsets.UTF_8));
        return JSON.readTree(out.resolve("results.json").toFile());
    }

    static JsonNode scene(JsonNode r, String sceneFile) {
        for (JsonNode t : r.get("tests")) {
            if (t.get("name").asText().endsWith("/" + sceneFile)) {
                return t;
            }
        }
        throw new AssertionError("no graded scene " + sceneFile + " in " + r.get("tests"));
    }

    @Test
    void theReferenceScoresEveryVariantAndTheReportShowsTheVariantsReferences() throws IOException {
        long seed = 20261202;
        Path out = dir.resolve("out-ref");
        JsonNode r = grade(GraderTest.submission(dir, "reference"), seed, out, "box", "shadows");
        String html = Files.readString(out.resolve("report.html"));
        assertTrue(html.contains("scene variants: seed " + seed), "the instructors' report names the seed");
        assertFalse(r.get("output").asText().contains("scene variants: seed"),
                "the students' page does not (an instructor note): " + r.get("output").asText());
        for (String id : List.of("box", "shadows")) {
            Assignment a = all.byId(id).orElseThrow();
            for (int i = 0; i < a.scenes().size(); i++) {
                Assignment.GradedScene sc = a.scenes().get(i);
                JsonNode t = scene(r, Path.of(sc.scene()).getFileName().toString());
                assertEquals(t.get("max_score").asDouble(), t.get("score").asDouble(), 1e-9,
                        "seed " + seed + ": the reference scores the variant of " + sc.scene() + ": " + t);
                GradedScenes.Graded g = GradedScenes.forGrading(root, a, i, seed, true);
                assertTrue(g.varied(), sc.scene() + " is varied");
                assertTrue(html.contains(Base64.getEncoder().encodeToString(g.reference())),
                        "seed " + seed + ": the report shows the variant's reference of " + sc.scene());
                assertFalse(html.contains(Base64.getEncoder().encodeToString(Files.readAllBytes(root.resolve(sc.reference())))),
                        "seed " + seed + ": the published reference of " + sc.scene() + " is not what was compared");
            }
        }
    }

    @Test
    void realisticBugsLoseTheirScenesOnVariantsToo() throws IOException {
        long seed = 1234567;
        JsonNode r = grade(GraderTest.submission(dir, "bugs3"), seed, dir.resolve("out-bugs"), "sphere", "box", "shadows");
        // As on the published scenes (RealisticBugsTest): the lecture's slabs miss rays in face
        // planes, a fixed offset of 0.01 loses the small scene's shadows, the stack-inspecting
        // sphere loses the scenes with overlapping spheres.
        for (String f : List.of("boxes-front.json", "shadows-small.json", "spheres.json", "spheres-dome.json")) {
            JsonNode t = scene(r, f);
            assertEquals(0, t.get("score").asDouble(), 1e-9, "seed " + seed + ": the variant of " + f + " shows the bug: " + t);
        }
        // and what the bugs do not touch still scores on its variant
        for (String f : List.of("boxes.json", "shadows.json", "boxes-lamp.json")) {
            JsonNode t = scene(r, f);
            assertEquals(t.get("max_score").asDouble(), t.get("score").asDouble(), 1e-9,
                    "seed " + seed + ": the variant of " + f + " does not show these bugs: " + t);
        }
    }
}
