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

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;

/**
 * Every method the lecture or a handout names or allows earns full marks, through
 * {@code raylab grade} (visible and hidden tests, data cases and scenes): the corpus in
 * src/test/resources/submissions/lecture/, one folder per method, each written plainly from the
 * lecture and the handout. Each is graded in the one milestone its file belongs to (the others
 * are the reference), so a run takes one milestone's grading. A zero-point note (the slide's
 * shade() order traces shadow rays the plan could skip) is printed, and takes nothing.
 */
@ExtendWith(SharedGraderCache.class)
class LectureMethodsTest {
    static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path dir;

    /**
     * Grades the reference overlaid with a resource submission ({@code lecture/NAME}, or a folder
     * by absolute path) in the given milestones alone.
     */
    static JsonNode grade(Path dir, String overlay, String... milestones) throws IOException {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        Path sub = GraderTest.submission(dir, overlay);
        Path out = dir.resolve("out");
        Files.createDirectories(out);
        List<String> args = new ArrayList<>(List.of("grade", sub.toString(), "--out", out.toString(), "--root",
                root.toString(), "--quiet", "--test-timeout", "60", "--milestone-timeout", "600", "--scene-timeout", "300",
                "--heap", "256", "--sandbox-user", ""));
        for (String m : milestones) {
            args.add("--milestone");
            args.add(m);
        }
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), args.toArray(String[]::new));
        assertEquals(0, status, () -> "grade should succeed: " + err.toString(StandardCharsets.UTF_8) + why(out));
        JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
        GraderTest.checkSchema(r);
        return r;
    }

    /** The reason results.json gives when the grader could not run. */
    static String why(Path out) {
        try {
            return JSON.readTree(out.resolve("results.json").toFile()).path("output").asText();
        } catch (IOException e) {
            return "(no results.json)";
        }
    }

    @ParameterizedTest(name = "{0} ({1})")
    @CsvSource({
        "lecture/sphere-algebraic, sphere",
        "lecture/sphere-geometric, sphere",
        "lecture/box-slabs-infinities, box",
        "lecture/box-six-faces, box",
        "lecture/triangle-plane-edges, triangle",
        "lecture/triangle-barycentric-cramer, triangle",
        "lecture/shading-lecture-order, lambert",
        "lecture/shadows-offset-origin, shadows",
        "lecture/shadows-tmin, shadows",
    })
    void scoresFullMarks(String overlay, String milestone) throws IOException {
        JsonNode r = grade(dir, overlay, milestone);
        double score = 0;
        double max = 0;
        StringBuilder lost = new StringBuilder();
        StringBuilder notes = new StringBuilder();
        int graded = 0;
        for (JsonNode t : r.get("tests")) {
            if (!t.get("tags").get(0).asText().equals(milestone)) {
                continue;
            }
            graded++;
            score += t.get("score").asDouble();
            max += t.get("max_score").asDouble();
            if (t.get("score").asDouble() < t.get("max_score").asDouble()) {
                lost.append("\n  ").append(t.get("name").asText()).append(": ").append(t.get("output").asText());
            }
            if (t.get("output").asText().contains("Note (no points taken)")) {
                notes.append("\n  ").append(t.get("name").asText());
            }
        }
        System.out.printf("%s in %s: %.2f / %.2f%s%n", overlay, milestone, score, max,
                notes.length() == 0 ? "" : ", notes (no points taken) on:" + notes);
        assertTrue(graded > 0, "milestone " + milestone + " was graded");
        assertEquals(max, score, 1e-9, overlay + " is a method the lecture allows: it must score full marks in "
                + milestone + "; lost:" + lost);
    }
}
