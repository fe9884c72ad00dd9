package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;
import java.util.List;
import java.util.Set;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;
import raylab.course.SolutionRegions;
import raylab.render.PngFiles;

/**
 * What students see on Gradescope: results.json's top-level output is HTML that shows a wrong
 * scene's render, reference and heatmap (decoded here from their data URIs), the metric and
 * tolerance, the failed visible tests' full messages with hints, ignored files as one line (not
 * listed), and scores in cents that add up to each milestone's points.
 */
class GradescopeOutputTest {
    @TempDir
    Path dir;

    @Test
    void oneWrongSceneShowsItsThreeImagesAndNoIgnoredList() throws IOException {
        Path root = Path.of("").toAbsolutePath();
        Assignments all = Assignments.load(root);
        Assignment box = all.byId("box").orElseThrow();
        // The reference Box with one realistic bug (a swapped slab is never reordered).
        Path sub = Files.createDirectories(dir.resolve("sub"));
        Path src = root.resolve(box.files().get(0).path());
        Files.writeString(sub.resolve("Box.java"), SolutionRegions.toStudent("Box.java", Files.readString(src), Set.of("box")));
        Files.copy(root.resolve("src/test/resources/submissions/bugs1/Box.java"), sub.resolve("Box.java"),
                java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Files.writeString(sub.resolve("notes-to-self.txt"), "not graded");
        Files.writeString(sub.resolve("Scratch.java"), "class Scratch {}");
        Path out = dir.resolve("out");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), "grade", sub.toString(), "--out", out.toString(),
                "--root", root.toString(), "--quiet", "--milestone", "box", "--test-timeout", "5",
                "--milestone-timeout", "60", "--scene-timeout", "30", "--heap", "256",
                // Not a sandbox test: without the shared user, another grading on this machine cannot stop ours.
                "--sandbox-user", "");
        assertEquals(0, status, () -> err.toString(StandardCharsets.UTF_8));
        JsonNode r = new ObjectMapper().readTree(out.resolve("results.json").toFile());
        assertEquals("html", r.get("output_format").asText());
        String html = r.get("output").asText();
        assertTrue(html.length() <= HtmlReport.STUDENT_BUDGET, "within the budget: " + html.length());
        System.out.println("results.json output: " + html.length() + " characters of HTML, results.json "
                + Files.size(out.resolve("results.json")) + " bytes");

        // The scene that differs: its block holds three images that decode, as large as the scene.
        int at = html.indexOf("DIFFERS</b> scenes/boxes.json");
        assertTrue(at >= 0, "the wrong scene is named: " + html);
        int end = html.indexOf("</div>\n", html.indexOf("Heatmap:", at));
        List<String> uris = HtmlReport.dataUris(html.substring(at, end));
        BufferedImage reference = PngFiles.read(root.resolve("scenes/reference/boxes.png"));
        assertEquals(4, uris.size(), "render, reference, heatmap and the legend: " + uris.size());
        for (String uri : uris.subList(0, 3)) {
            BufferedImage img = ImageIO.read(new ByteArrayInputStream(Base64.getDecoder().decode(
                    uri.substring("data:image/png;base64,".length()))));
            assertNotNull(img, "decodes");
            assertEquals(reference.getWidth(), img.getWidth(), "full size: the page is within the budget");
        }
        assertTrue(html.indexOf("your render") < html.indexOf("reference\"") && html.contains("difference (heatmap)"));
        assertTrue(html.substring(at, end).contains("allowed: 0.200%"), "the tolerance is shown");
        assertTrue(html.contains("black where the pixels are equal"), "the heatmap has a legend");

        // Ignored files: one line, no list.
        assertFalse(html.contains("notes-to-self.txt") || html.contains("Scratch"), "no list of ignored files");
        assertTrue(html.contains("2 submitted files were not graded"), html);
        assertTrue(Files.readString(out.resolve("report.html")).contains("notes-to-self.txt"),
                "the instructors' report lists them");

        // Failed visible tests: full message with its hint, under the handout's name.
        assertTrue(html.contains("HINT:"), "hints are shown");

        // Scores: cents, and the milestone adds up to its points exactly.
        long cents = 0;
        long maxCents = 0;
        for (JsonNode t : r.get("tests")) {
            double s = t.get("max_score").asDouble();
            assertEquals(Math.round(s * 100) / 100.0, s, 0, "max_score in cents: " + t);
            maxCents += Math.round(s * 100);
            cents += Math.round(t.get("score").asDouble() * 100);
        }
        assertEquals(100L * box.points(), maxCents, "the box's tests add up to its points");
        assertEquals(cents / 100.0, r.get("score").asDouble(), 1e-9);
        // The page students see at once shows the visible points only, never the total.
        long visibleCents = 0;
        long visibleMaxCents = 0;
        for (JsonNode t : r.get("tests")) {
            if (t.get("visibility").asText().equals("visible")) {
                visibleCents += Math.round(t.get("score").asDouble() * 100);
                visibleMaxCents += Math.round(t.get("max_score").asDouble() * 100);
            }
        }
        assertTrue(visibleMaxCents < maxCents, "the box milestone has hidden tests");
        assertTrue(html.contains("Visible results " + GradingPlan.points(visibleCents) + " / "
                + GradingPlan.points(visibleMaxCents)), "visible score shown: " + html.substring(0, 400));
        assertFalse(html.contains("Score ") || html.contains(" / 15"), "no total with hidden points: " + html.substring(0, 400));
    }
}
