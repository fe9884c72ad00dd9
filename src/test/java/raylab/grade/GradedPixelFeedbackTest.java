package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The graded feedback of issue 40, through {@code raylab grade --seed N} on graded variants: for a
 * scene that differs, the trusted render process traces the worst pixels both ways, the scene's
 * message names the most common first difference (the planted mistake), and the students' HTML
 * (Gradescope's output) and report.html show the worst pixels' ray trees as static HTML, no script.
 */
@ExtendWith(SharedGraderCache.class)
class GradedPixelFeedbackTest {
    @TempDir
    Path dir;

    /** Grades one planted mistake, checks the scene's feedback names it, and gives the results. */
    private JsonNode planted(String overlay, String milestone, String sceneFile, String method, String phrase)
            throws IOException {
        long seed = 4040;
        Path out = dir.resolve("out-" + milestone);
        GradedVariantsTest.load();
        JsonNode r = GradedVariantsTest.grade(GraderTest.submission(dir, overlay), seed, out, milestone);
        JsonNode t = GradedVariantsTest.scene(r, sceneFile);
        String where = "seed " + seed + ", " + overlay + ", variant of " + sceneFile;
        assertEquals(0, t.get("score").asDouble(), 1e-9, where + ": the scene differs: " + t);
        assertEquals("failed", t.get("status").asText(), where + ": the scene differs: " + t);
        String msg = t.get("output").asText();
        System.out.println(where + ": " + msg);
        assertTrue(msg.contains("the most common first difference") && msg.contains(method) && msg.contains(phrase),
                where + ": expected the message to name " + method + " and '" + phrase + "', was: " + msg);
        String students = r.get("output").asText();
        String report = Files.readString(out.resolve("report.html"));
        for (String html : List.of(students, report)) {
            assertTrue(html.contains("Why pixels differ") && html.contains("(first difference)"),
                    where + ": the worst pixels' trees are shown");
            int section = html.indexOf("class=\"raylab-pixels\"");
            String part = html.substring(section, html.indexOf("</div></div>", section));
            assertFalse(part.contains("<script") || part.contains("onclick") || part.contains("<style"),
                    where + ": static HTML with inline styles only: " + part);
        }
        return r;
    }

    @Test
    void wrongRootNamedInTheFeedbackOfTheSphereVariants() throws IOException {
        planted("inspect/sphere-farther-root", "sphere", "spheres.json", "Sphere.intersect", "farther root");
    }

    @Test
    void acneNamedInTheFeedbackOfTheShadowVariants() throws IOException {
        planted("bugs2", "shadows", "shadows.json", "Shadows.isShadowed", "shadow acne");
    }

    @Test
    void unnormalisedHalfVectorNamedInTheFeedbackOfTheHighlightVariants() throws IOException {
        planted("bugs1", "phong", "highlights.json", "BlinnPhong.specular", "unit vector");
    }

    /**
     * The only lambert scene with points, diffuse.json, has no ambient light, so a shade() without
     * ka·Ia matches it; diffuse-ambient.json (0 points, feedback only) shows the ambient term and
     * its feedback names it, while the milestone's points and the submission's score are unchanged.
     */
    @Test
    void missingAmbientNamedInTheFeedbackOfTheAmbientSceneWhichEarnsNothing() throws IOException {
        JsonNode r = planted("inspect/shading-no-ambient", "lambert", "diffuse-ambient.json", "Shading.shade",
                "leaves out the ambient term");
        JsonNode ambient = GradedVariantsTest.scene(r, "diffuse-ambient.json");
        assertEquals(0, ambient.get("max_score").asDouble(), 1e-9, "feedback only, no points: " + ambient);
        JsonNode diffuse = GradedVariantsTest.scene(r, "diffuse.json");
        assertEquals(2, diffuse.get("score").asDouble(), 1e-9,
                "diffuse.json has no ambient light: the same shade() matches it: " + diffuse);
        double max = 0;
        for (JsonNode t : r.get("tests")) {
            max += t.get("max_score").asDouble();
        }
        assertEquals(10, max, 1e-9, "the lambert milestone's points (assignment.json) are unchanged");
    }

    @Test
    void inwardNormalNamedInTheFeedbackOfTheTriangleVariants() throws IOException {
        planted("mistakes/triangle-normal-toward-ray", "triangle", "triangles.json", "Triangle.intersect",
                "points into the surface");
    }
}
