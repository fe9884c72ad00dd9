package raylab.grade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/** Checks a platform's output against its schema (src/test/resources/schemas) and the sums the schema cannot state. */
public final class PlatformSchemas {
    private static final ObjectMapper JSON = new ObjectMapper();

    private PlatformSchemas() {
    }

    /** PrairieLearn's results.json: the schema, and the score is the share of the points listed. */
    public static JsonNode prairieLearn(String text) throws IOException {
        JsonNode n = JSON.readTree(text);
        List<String> errors = JsonSchema.load("/schemas/prairielearn-results.schema.json").validate(n);
        assertTrue(errors.isEmpty(), () -> "not PrairieLearn's results.json: " + errors);
        double points = 0;
        double max = 0;
        for (JsonNode t : n.get("tests")) {
            points += t.get("points").asDouble();
            max += t.get("max_points").asDouble();
        }
        if (max > 0) {
            assertEquals(points / max, n.get("score").asDouble(), 1e-6, "score is the share of the tests' points");
        }
        return n;
    }

    /** Classroom 50's result.json: the schema, and score / max-score are the sums of the tests'. */
    public static JsonNode classroom50(String text) throws IOException {
        JsonNode n = JSON.readTree(text);
        List<String> errors = JsonSchema.load("/schemas/classroom50-result.schema.json").validate(n);
        assertTrue(errors.isEmpty(), () -> "not Classroom 50's result.json: " + errors);
        long score = 0;
        long max = 0;
        for (JsonNode t : n.get("tests")) {
            score += t.get("score").asLong();
            max += t.get("max-score").asLong();
        }
        assertEquals(score, n.get("score").asLong(), "score is the sum of the tests' scores");
        assertEquals(max, n.get("max-score").asLong(), "max-score is the sum of the tests' max-scores");
        return n;
    }
}
