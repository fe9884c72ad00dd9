package raylab.grade;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.course.Assignment;
import raylab.course.JavaBuild;
import raylab.scene.SceneException;
import raylab.scene.SceneLoader;

/**
 * Fuzzes the grading path of a graded scene with valid scenes of every form the scene format
 * allows ({@link SceneFormatVariantsTest}'s generator, seeded from the fuzzer's input) and a
 * variant spec for each: {@link GradedScenes#forGrading} (draw, check, render the reference) must
 * return, and a variant must load. Never an internal error. Saved inputs:
 * src/test/resources/raylab/grade/SceneVariantsFuzzTestInputs/validScene.
 */
class SceneVariantsFuzzTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static Path dir;

    @BeforeAll
    static void setUp() throws IOException {
        dir = Files.createTempDirectory("raylab-variants-fuzz");
        Files.createDirectories(dir.resolve("scenes/meshes"));
        Files.writeString(dir.resolve("scenes/meshes/quad.obj"), SceneFormatVariantsTest.QUAD, StandardCharsets.US_ASCII);
    }

    @AfterAll
    static void cleanUp() {
        JavaBuild.deleteTreeQuietly(dir);
    }

    @FuzzTest(maxDuration = "60s")
    void validScene(FuzzedDataProvider in) throws IOException {
        long seed = in.consumeLong();
        long gradingSeed = in.consumeLong() & ((1L << 53) - 1);
        Random r = new Random(seed);
        ObjectNode scene = SceneFormatVariantsTest.scene(r);
        ObjectNode spec = SceneFormatVariantsTest.spec(r, scene);
        Path file = dir.resolve("scenes/fuzz.json");
        Files.writeString(file, scene.toString());
        Assignment a = new Assignment("fuzz", 1, "Fuzz", 1, List.of(),
                List.of(new Assignment.StudentFile("src/main/java/raylab/surface/Sphere.java", List.of("Sphere.intersect"))),
                new Assignment.Tests("fuzz", List.of(), List.of(), 0, 0, null),
                List.of(new Assignment.GradedScene("scenes/fuzz.json", "scenes/reference/fuzz.png", 1, 0.002, spec)),
                List.of(), false, Path.of("assignments/01-fuzz"));
        GradedScenes.Graded g;
        try {
            g = GradedScenes.forGrading(dir, a, 0, gradingSeed, true);
        } catch (IOException | RuntimeException e) {
            throw new AssertionError("scene seed " + seed + ", grading seed " + gradingSeed + ": " + e + "; scene "
                    + scene + " variant " + spec, e);
        }
        if (g.varied()) {
            try {
                SceneLoader.parse(g.json(), file);
            } catch (SceneException e) {
                throw new AssertionError("scene seed " + seed + ": the variant does not load: " + e.getMessage(), e);
            }
        }
    }
}
