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
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;

/**
 * The grader behind the process boundary, sphere milestone:
 * the reference scores every point, and a probing submission's student process reaches no
 * reference class of another milestone, no second Sphere, no hidden test, no grader class and
 * no reference image (it says what it found in every failing test's message).
 */
@ExtendWith(SharedGraderCache.class)
class BoundaryGradeTest {
    @TempDir
    Path dir;

    private JsonNode grade(Path sub) throws IOException {
        Path out = dir.resolve("out-" + sub.getFileName());
        Files.createDirectories(out);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), "grade", sub.toString(), "--out", out.toString(),
                "--root", Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize().toString(), "--quiet", "--milestone", "sphere", "--test-timeout", "20",
                "--milestone-timeout", "200", "--scene-timeout", "200", "--heap", "256", "--sandbox-user",
                GraderTest.sandboxUser());
        assertEquals(0, status, () -> "grade should succeed: " + err.toString(StandardCharsets.UTF_8));
        return new ObjectMapper().readTree(out.resolve("results.json").toFile());
    }

    @Test
    void theReferenceScoresEveryPointAcrossTheBoundary() throws IOException {
        JsonNode r = grade(GraderTest.submission(dir, "reference"));
        List<String> lost = new ArrayList<>();
        double max = 0;
        for (JsonNode t : r.get("tests")) {
            max += t.get("max_score").asDouble();
            if (t.get("score").asDouble() < t.get("max_score").asDouble()) {
                lost.add(t.get("name").asText() + ": " + t.get("output").asText());
            }
        }
        assertEquals(List.of(), lost, "tests the reference lost behind the boundary");
        assertEquals(20.0, max, 1e-9, "the sphere milestone's points");
    }

    /**
     * What the student's code prints never reaches the test JVM's signed channel to the grader:
     * the reference with a debugging print that ends in no newline ({@code System.out.print("t? ")}
     * at every call) scores every point. Before, the student process of a milestone's first
     * tests wrote its output to the channel itself, the text ran into the next report line, and
     * every report after it was lost: the grading failed (or, before that, scored 0).
     */
    @Test
    void aPrintWithoutANewlineCostsNothing() throws IOException {
        Path sub = GraderTest.submission(dir, "reference");
        Path sphere = sub.resolve("Sphere.java");
        String text = Files.readString(sphere);
        String signature = "public boolean intersect(IntersectionRecord outRecord, Ray ray) {";
        assertTrue(text.contains(signature), text);
        Files.writeString(sphere, text.replace(signature, signature + " System.out.print(\"t? \");"));
        JsonNode r = grade(sub);
        assertFalse(r.has("extra_data"), "no part failed: " + r.get("extra_data"));
        assertEquals(20.0, r.get("score").asDouble(), 1e-9, () -> "every point: " + r.get("tests"));
    }

    @Test
    void theStudentProcessReachesNoSecret() throws IOException {
        JsonNode r = grade(GraderTest.submission(dir, "boundary-probe"));
        int probes = 0;
        for (JsonNode t : r.get("tests")) {
            String out = t.get("output").asText();
            assertFalse(out.contains("PROBE FOUND"), () -> t.get("name").asText() + ": " + out);
            if (out.contains("PROBE found nothing")) {
                probes++;
            }
            assertEquals(0.0, t.get("score").asDouble(), () -> "a point for a submission that implements nothing: "
                    + t.get("name").asText());
        }
        assertTrue(probes > 0, () -> "the probe reported in some visible message: " + r.get("tests"));
        for (JsonNode t : r.get("tests")) {
            if (t.get("name").asText().endsWith("scenes/sphere.json")) {
                String out = t.get("output").asText();
                assertTrue(out.contains("your code threw IllegalStateException in Sphere.intersect (Sphere.java:")
                        && out.contains("while tracing pixel (") && out.contains("of scenes/sphere.json"),
                        () -> "the render's failure names the student's frame and the pixel: " + out);
            }
        }
    }
}
