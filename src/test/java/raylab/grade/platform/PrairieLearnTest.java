package raylab.grade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Random;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.grade.GradeReport;
import raylab.grade.GradeReport.Kind;

/**
 * PrairieLearn's results.json from hand-made reports: the schema written from PrairieLearn's
 * documentation, the score as a fraction, hidden tests left out before the due date, gradable
 * false on a compile error, and the 1 MB limit with images shrunk to fit.
 */
class PrairieLearnTest {
    static final ObjectMapper JSON = new ObjectMapper();

    static JsonNode valid(String text) throws Exception {
        JsonNode n = JSON.readTree(text);
        List<String> errors = JsonSchema.load("/schemas/prairielearn-results.schema.json").validate(n);
        assertTrue(errors.isEmpty(), () -> "results.json does not follow PrairieLearn's schema: " + errors);
        return n;
    }

    static GradeReport.Test test(String m, String name, Kind kind, double max, boolean passed, String visibility,
            GradeReport.Images images) {
        return new GradeReport.Test(m, name, kind, max, passed ? max : 0, passed, passed ? "" : "expected t = 2, got 3",
                "", visibility, 5, "f", images);
    }

    static GradeReport report(List<String> notes, GradeReport.Test... tests) {
        return new GradeReport(List.of(new GradeReport.Milestone("box", "Ray-box intersection", notes, List.of(tests))),
                List.of("src/main/java/raylab/surface/Box.java <- Box.java"), List.of(), List.of(), 1.0);
    }

    @Test
    void theHiddenTestsCountAtEveryGradingAndAreShownAsATotalBeforeTheDueDate() throws Exception {
        GradeReport r = report(List.of("the hidden tests' run did not finish (see the hidden tests)"),
                test("box", "hitsFromOutside", Kind.VISIBLE, 2, true, "visible", null),
                test("box", "missesBehind", Kind.VISIBLE, 3, false, "visible", null),
                test("box", "BoxHiddenTest.secretEdge", Kind.HIDDEN, 5, false, "after_due_date", null),
                test("box", "BoxHiddenTest.secretCorner", Kind.HIDDEN, 4, true, "after_due_date", null));
        JsonNode before = valid(PrairieLearn.results(r, false));
        assertEquals(6.0 / 14, before.get("score").asDouble(), 1e-12, "2 visible + 4 hidden of all 14 points");
        assertEquals(3, before.get("tests").size(), "the hidden tests as one row before the due date: " + before);
        JsonNode total = before.get("tests").get(2);
        assertEquals("box: " + PrairieLearn.HIDDEN_ROW, total.get("name").asText());
        assertEquals(4.0, total.get("points").asDouble());
        assertEquals(9.0, total.get("max_points").asDouble());
        assertEquals("", total.get("message").asText());
        assertFalse(before.toString().contains("secretEdge") || before.toString().contains("secretCorner")
                || before.toString().contains("BoxHiddenTest"), "no name of a hidden test: " + before);
        assertFalse(before.get("message").asText().contains("did not finish"), "nor of the hidden run: " + before);
        assertTrue(before.get("gradable").asBoolean());
        assertEquals("expected t = 2, got 3", before.get("tests").get(1).get("message").asText());
        assertEquals(0.0, before.get("tests").get(1).get("points").asDouble());
        assertEquals(3.0, before.get("tests").get(1).get("max_points").asDouble());

        JsonNode after = valid(PrairieLearn.results(r, true));
        assertEquals(6.0 / 14, after.get("score").asDouble(), 1e-12, "the same grade, 6 of all 14 points");
        assertEquals(4, after.get("tests").size());
        assertEquals("box: BoxHiddenTest.secretEdge", after.get("tests").get(2).get("name").asText());
        assertTrue(after.get("message").asText().contains("did not finish"), after.get("message").asText());
    }

    @Test
    void aCompileErrorIsNotGradable() throws Exception {
        GradeReport r = report(List.of("your code does not compile, so this milestone scores 0:\nBox.java:12: ';' expected"),
                test("box", "hitsFromOutside", Kind.VISIBLE, 2, false, "visible", null));
        JsonNode n = valid(PrairieLearn.results(r, false));
        assertFalse(n.get("gradable").asBoolean(), "a compile error does not cost an attempt: " + n);
        assertTrue(n.get("message").asText().contains("Box.java:12"), n.get("message").asText());
    }

    @Test
    void resultsStayUnderOneMegabyteWithImagesShrunkToFit() throws Exception {
        long seed = 20261202L;
        Random rnd = new Random(seed);
        List<GradeReport.Test> tests = new ArrayList<>();
        // Ten scenes of noise (PNG cannot compress it): about 2.9 MB each at full size.
        for (int i = 0; i < 10; i++) {
            byte[] png = noise(1200, 800, rnd);
            tests.add(test("box", "scene s" + i + ".json", Kind.SCENE, 1, false, "visible",
                    new GradeReport.Images(png, png, png, "mean error 3.1% (tolerance 0.2%)")));
        }
        GradeReport r = report(List.of(), tests.toArray(new GradeReport.Test[0]));
        String text = PrairieLearn.results(r, false);
        int bytes = text.getBytes(StandardCharsets.UTF_8).length;
        assertTrue(bytes <= PrairieLearn.LIMIT_BYTES, "results.json is " + bytes + " bytes, over 1 MB (seed " + seed + ")");
        JsonNode n = valid(text);
        JsonNode images = n.get("tests").get(0).get("images");
        assertEquals(3, images.size(), "render, reference and difference still attached at " + bytes + " bytes");
        assertEquals(List.of("your render", "reference", "difference"),
                List.of(images.get(0).get("label").asText(), images.get(1).get("label").asText(), images.get(2).get("label").asText()));
        String url = images.get(0).get("url").asText();
        BufferedImage shown = ImageIO.read(new ByteArrayInputStream(Base64.getDecoder().decode(url.substring(url.indexOf(',') + 1))));
        assertTrue(shown.getWidth() < 1200 && shown.getWidth() >= 120, "shrunk, not dropped: width " + shown.getWidth());
        assertEquals(shown.getWidth() * 2 / 3, shown.getHeight(), 1, "aspect ratio kept");

        // A small report keeps its images as rendered.
        byte[] small = noise(40, 30, new Random(seed));
        JsonNode one = valid(PrairieLearn.results(report(List.of(), test("box", "scene a.json", Kind.SCENE, 1, true, "visible",
                new GradeReport.Images(small, small, small, "mean error 0.1%"))), false));
        assertEquals("data:image/png;base64," + Base64.getEncoder().encodeToString(small),
                one.get("tests").get(0).get("images").get(0).get("url").asText());
        assertEquals("mean error 0.1%", one.get("tests").get(0).get("message").asText());
    }

    static byte[] noise(int w, int h, Random rnd) throws Exception {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                img.setRGB(x, y, rnd.nextInt(1 << 24));
            }
        }
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        ImageIO.write(img, "png", b);
        return b.toByteArray();
    }

    @Test
    void theSchemaCheckerRejectsWhatPrairieLearnWouldNot() throws Exception {
        JsonSchema pl = JsonSchema.load("/schemas/prairielearn-results.schema.json");
        JsonNode bad = JSON.readTree("{\"gradable\": true, \"score\": 1.5, \"message\": \"\", \"output\": \"\","
                + " \"tests\": [{\"name\": \"t\", \"points\": \"1\", \"max_points\": 1,"
                + " \"images\": [{\"label\": \"x\", \"url\": \"http://example.com/a.png\"}]}], \"extra\": 1}");
        List<String> errors = pl.validate(bad);
        assertEquals(List.of("$.score: 1.5 above the maximum 1", "$.tests[0].points: expected [number], got string \"1\"",
                "$.tests[0].images[0].url: \"http://example.com/a.png\" does not match ^data:image/(png|jpeg|gif);base64,[A-Za-z0-9+/=]+$",
                "$: unexpected field \"extra\""), errors);
        JsonSchema c50 = JsonSchema.load("/schemas/classroom50-result.schema.json");
        JsonNode wrong = JSON.readTree("{\"schema\": \"classroom50/result/v2\", \"classroom\": \"c\", \"assignment\": \"a\","
                + " \"submission\": \"s\", \"commit\": \"u\", \"release\": \"u\", \"review\": \"u\","
                + " \"datetime\": \"2026-12-02T04:00:00Z\", \"score\": 1.5, \"tests\": [{\"test-name\": \"t\", \"passed\": true,"
                + " \"score\": 1, \"max-score\": 1, \"kept\": \"verbatim\"}]}");
        assertEquals(List.of("$: missing \"max-score\"", "$.schema: expected \"classroom50/result/v1\", got \"classroom50/result/v2\"",
                "$.score: expected [integer], got number 1.5"), c50.validate(wrong));
    }
}
