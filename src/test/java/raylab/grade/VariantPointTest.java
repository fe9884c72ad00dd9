package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.course.Assignment;
import raylab.course.Assignments;

/**
 * Every bundled graded scene's variants keep the scene's point ({@link VariantCheck}) on the
 * first draw, over many seeds; and the check is real: variants that lose the point are caught.
 */
class VariantPointTest {
    static final ObjectMapper JSON = new ObjectMapper();
    /** Seeds per scene; each is printed in its test's name and failure message. */
    static final int SEEDS = Integer.getInteger("raylab.variantSeeds", 12);
    static Path root;
    static Assignments all;

    @BeforeAll
    static void load() throws IOException {
        root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        all = Assignments.load(root);
    }

    @Test
    void everyGradedSceneWithPointsHasAValidVariantSpec() throws IOException {
        GradedScenes.validate(root, all.all());
        for (Assignment a : all.all()) {
            for (Assignment.GradedScene sc : a.scenes()) {
                if (sc.points() > 0) {
                    assertNotNull(sc.variant(), a.folder() + ": " + sc.scene() + " carries points but has no \"variant\"");
                }
            }
        }
    }

    @TestFactory
    Stream<DynamicTest> firstDrawKeepsThePoint() {
        List<DynamicTest> out = new ArrayList<>();
        SplittableRandom seeds = new SplittableRandom(20261202L);
        for (Assignment a : all.all()) {
            for (int i = 0; i < a.scenes().size(); i++) {
                int index = i;
                for (int k = 0; k < SEEDS; k++) {
                    long seed = seeds.nextLong() & ((1L << 53) - 1);
                    String scene = a.scenes().get(i).scene();
                    out.add(DynamicTest.dynamicTest(scene + " seed " + seed, () -> {
                        GradedScenes.Graded g = GradedScenes.forGrading(root, a, index, seed, false);
                        assertTrue(g.varied(), scene + ": grading seed " + seed + ": expected a variant, got: " + g.note());
                        String why = g.attempt() == 0 ? "" : String.join("; ", firstProblems(a, index, seed));
                        assertEquals(0, g.attempt(), () -> scene + ": grading seed " + seed
                                + ": expected the first draw to keep the point, it took draw " + (g.attempt() + 1)
                                + "; first draw's problems: " + why);
                    }));
                }
            }
        }
        return out.stream();
    }

    private static List<String> firstProblems(Assignment a, int index, long seed) throws Exception {
        Path file = root.resolve(a.scenes().get(index).scene());
        JsonNode pub = JSON.readTree(file.toFile());
        VariantSpec spec = GradedScenes.spec(a, index, pub);
        ObjectNode v = SceneVariants.variant(pub, spec, SceneVariants.seedFor(seed, GradedScenes.name(a.scenes().get(index))));
        List<String> lights = new ArrayList<>();
        pub.path("lights").forEach(l -> lights.add(l.path("name").asText()));
        return VariantCheck.problems(VariantCheck.analyze(pub, file), VariantCheck.analyze(v, file), spec.coverage(), lights);
    }
}
