package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.api.extension.ExtendWith;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.SolutionRegions;

/**
 * A constant earns nothing: every graded method replaced by a constant answer, graded through
 * {@code raylab grade} in every milestone at once, scores 0 in every milestone. Each test that a
 * constant passes (always miss, always hit, one colour) is scored together with a case the same
 * constant fails (for example {@code Check.miss} also asks for a control hit).
 *
 * <p>The stubs are made from the starter: each {@code throw new NotImplemented(...)} of a graded
 * method becomes {@code return CONSTANT;} (a boolean for {@code intersect} and
 * {@code isShadowed}, a colour for {@code diffuse}, {@code specular} and {@code shade}).
 */
@ExtendWith(SharedGraderCache.class)
class ConstantStubsTest {
    static final ObjectMapper JSON = new ObjectMapper();
    private static final Pattern STUB = Pattern.compile("throw new NotImplemented\\(\"[\\w-]+\", \"(\\w+)\\.(\\w+)\"\\);");

    /** One kind of constant: what every boolean and every colour method returns. */
    enum Kind {
        ALWAYS_MISS("false", "raylab.math.Color.BLACK"),
        ALWAYS_HIT("true", "raylab.math.Color.WHITE"),
        ONE_COLOUR("false", "new raylab.math.Color(0.25, 0.5, 0.75)");

        final String bool;
        final String colour;

        Kind(String bool, String colour) {
            this.bool = bool;
            this.colour = colour;
        }
    }

    @TempDir
    Path dir;

    @ParameterizedTest
    @EnumSource(Kind.class)
    void everyGradedMethodAsAConstantScoresZeroInEveryMilestone(Kind kind) throws IOException {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        Path sub = Files.createDirectories(dir.resolve("stub-" + kind));
        int stubs = 0;
        for (Assignment a : Assignments.load(root).all()) {
            for (Assignment.StudentFile f : a.files()) {
                Path src = root.resolve(f.path());
                String text = SolutionRegions.toStudent(src.getFileName().toString(), Files.readString(src), Set.of());
                Matcher m = STUB.matcher(text);
                StringBuilder b = new StringBuilder();
                while (m.find()) {
                    String method = m.group(2);
                    String constant = method.equals("intersect") || method.equals("isShadowed") ? kind.bool : kind.colour;
                    m.appendReplacement(b, Matcher.quoteReplacement("return " + constant + ";"));
                    stubs++;
                }
                m.appendTail(b);
                Files.writeString(sub.resolve(src.getFileName()), b.toString());
            }
        }
        assertEquals(7, stubs, "a constant for each graded method (3 intersect, diffuse, shade, isShadowed, specular)");

        Path out = Files.createDirectories(dir.resolve("out"));
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8),
                "grade", sub.toString(), "--out", out.toString(), "--root", root.toString(), "--quiet",
                "--test-timeout", "30", "--milestone-timeout", "300", "--scene-timeout", "120",
                "--heap", "256", "--seed", "17", "--sandbox-user", "");
        assertEquals(0, status, () -> "grade should succeed: " + err.toString(StandardCharsets.UTF_8));
        JsonNode r = JSON.readTree(out.resolve("results.json").toFile());
        GraderTest.checkSchema(r);

        Map<String, StringBuilder> earned = new TreeMap<>();
        for (JsonNode t : r.get("tests")) {
            if (t.get("score").asDouble() > 0) {
                earned.computeIfAbsent(t.get("tags").get(0).asText(), k -> new StringBuilder())
                        .append("\n  ").append(t.get("name").asText()).append(": ").append(t.get("score").asDouble())
                        .append(" of ").append(t.get("max_score").asDouble());
            }
        }
        Map<String, double[]> per = GraderTest.perMilestone(r);
        assertEquals(6, per.size(), "every milestone graded: " + per.keySet());
        StringBuilder why = new StringBuilder();
        earned.forEach((id, tests) -> why.append("\n").append(id).append(": ").append(per.get(id)[0]).append(" of ")
                .append(per.get(id)[1]).append(tests));
        System.out.println(kind + " earned:" + (why.length() == 0 ? " nothing" : why));
        assertTrue(earned.isEmpty(), "expected: 0 points in every milestone for " + kind + " stubs; got:" + why);
    }
}
