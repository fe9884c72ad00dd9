package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static raylab.course.release.AddSceneTest.copy;
import static raylab.course.release.AddSceneTest.run;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.SplittableRandom;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.grade.GradedScenes;

/**
 * {@code raylab assignment add-scene} gives every scene a variant checked on the spot with the
 * grader's check, refuses a scene that would be graded as published, and takes the milestone's
 * tolerance by default; the variant it writes keeps the point in the grader's own draw
 * ({@link GradedScenes#forGrading}) on grading seeds it was not checked on.
 */
class AddSceneVariantTest {
    @TempDir
    static Path dir;
    static Path course;

    /** Two matte spheres on a floor under one light: a shadows scene. */
    private static final String LIT = """
            {
              "image": {"width": 64, "height": 48},
              "camera": {"type": "perspective", "eye": [0, 2, 8], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
              "background": [0.1, 0.1, 0.12],
              "ambient": [0.1, 0.1, 0.1],
              "materials": {"clay": {"type": "lambertian", "kd": [0.8, 0.6, 0.5]}},
              "surfaces": [
                {"type": "box", "name": "floor", "min": [-6, -1.2, -6], "max": [6, -1, 6], "material": "clay"},
                {"type": "sphere", "name": "ball", "center": [-1, 0, 0], "radius": 1, "material": "clay"},
                {"type": "sphere", "name": "small", "center": [1.5, -0.5, 0.5], "radius": 0.5, "material": "clay"}
              ],
              "lights": [{"type": "point", "name": "key", "position": [2, 5, 3], "intensity": [1, 1, 1]}]
            }
            """;

    private static final String UNLIT = """
            {
              "image": {"width": 64, "height": 48},
              "camera": {"type": "perspective", "eye": [0, 0, 6], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
              "materials": {"n": {"type": "normals"}},
              "surfaces": [{"type": "sphere", "name": "one", "center": [0, 0, 0], "radius": 1.2, "material": "n"}]
            }
            """;

    @BeforeEach
    void course() throws IOException {
        if (course == null) {
            course = copy(Path.of("").toAbsolutePath(), dir.resolve("course"));
        }
    }

    private static Path scene(String name, String text) throws IOException {
        return AddSceneTest.write(dir.resolve(name), text);
    }

    private static byte[] json(String folder) throws IOException {
        return Files.readAllBytes(course.resolve("assignments").resolve(folder).resolve("assignment.json"));
    }

    @Test
    void aLitSceneGetsTheMilestonesToleranceAndADefaultVariantThatTheGraderKeeps() throws IOException {
        String out = run(0, "assignment", "add-scene", "shadows", scene("lit.json", LIT).toString(), "--points", "2",
                "--root", course.toString());
        Assignment shadows = Assignments.load(course).byId("shadows").orElseThrow();
        int index = shadows.scenes().size() - 1;
        Assignment.GradedScene added = shadows.scenes().get(index);
        assertEquals("scenes/lit.json", added.scene());
        assertEquals(0.003, added.tolerance(), 0, "the tolerance of shadows' other scenes, not 0.002");
        // Camera and lights, the lights' moves a tenth (a twentieth up) of the camera's distance
        // sqrt(68) = 8.25 to its look-at point, possibly narrowed: what was written is what was checked.
        String v = added.variant().toString();
        assertTrue(v.equals("{\"camera\":{\"yaw\":15,\"pitch\":6,\"distance\":0.1},\"lights\":{\"move\":[0.82,0.41,0.82],"
                + "\"intensity\":0.15}}") || out.contains("(the default narrowed"), "expected the default variant, got " + v
                + "\n" + out);
        assertTrue(out.contains("variant " + v) && out.contains("keeps the point on each of 8 grading seeds"), out);
        // The grader's own draw keeps the point at once on seeds add-scene did not check.
        SplittableRandom seeds = new SplittableRandom(77);
        for (int k = 0; k < 4; k++) {
            long seed = seeds.nextLong() & ((1L << 53) - 1);
            GradedScenes.Graded g = GradedScenes.forGrading(course, shadows, index, seed, false);
            assertTrue(g.varied() && g.attempt() == 0, "grading seed " + seed + ": expected the first draw to keep the"
                    + " point, got attempt " + g.attempt() + " " + g.note());
        }
    }

    @Test
    void aGivenVariantIsWrittenAsGivenAndTheSphereMilestoneKeeps0point002() throws IOException {
        String spec = "{\"camera\":{\"yaw\":10,\"pitch\":4}}";
        run(0, "assignment", "add-scene", "sphere", scene("given.json", UNLIT).toString(), "--points", "1", "--variant", spec,
                "--root", course.toString());
        Assignment sphere = Assignments.load(course).byId("sphere").orElseThrow();
        Assignment.GradedScene added = sphere.scenes().get(sphere.scenes().size() - 1);
        assertEquals(spec, added.variant().toString());
        assertEquals(0.002, added.tolerance(), 0, "sphere's scenes all have 0.002");
    }

    @Test
    void refusalsChangeNothing() throws IOException {
        byte[] before = json("01-sphere");
        Path s = scene("refused.json", UNLIT);
        String none = run(2, "assignment", "add-scene", "sphere", s.toString(), "--points", "1", "--variant", "none",
                "--root", course.toString());
        assertTrue(none.contains("WARNING: refused.json would be graded as published") && none.contains("Nothing was changed"),
                none);
        String lost = run(1, "assignment", "add-scene", "sphere", s.toString(), "--points", "1", "--variant",
                "{\"placement\": [{\"objects\": [\"one\"], \"move\": [40, 0, 0]}]}", "--root", course.toString());
        assertTrue(lost.contains("the --variant loses the scene's point on 8 of 8 grading seeds")
                && lost.contains("\"one\" is out of view"), lost);
        String bound = run(2, "assignment", "add-scene", "sphere", s.toString(), "--points", "1", "--variant",
                "{\"camera\": {\"yaw\": 90}}", "--root", course.toString());
        assertTrue(bound.contains("--variant: variant.camera.yaw"), bound);
        String notJson = run(2, "assignment", "add-scene", "sphere", s.toString(), "--points", "1", "--variant", "{camera",
                "--root", course.toString());
        assertTrue(notJson.contains("--variant: not valid JSON"), notJson);
        Path fixed = scene("fixed.json", UNLIT.replace("\"lookAt\": [0, 0, 0]", "\"viewDirection\": [0, 0, -1]"));
        String nothing = run(1, "assignment", "add-scene", "sphere", fixed.toString(), "--points", "1", "--root",
                course.toString());
        assertTrue(nothing.contains("WARNING: the default variant has nothing to move in fixed.json (no lights, and a"
                + " camera without lookAt), so it would be graded as published"), nothing);
        // (A yaw of a viewDirection camera is no refusal any more: SceneVariants turns such cameras too,
        // SceneFormatVariantsTest.)
        assertArrayEquals(before, json("01-sphere"), "assignment.json untouched");
        assertFalse(Files.exists(course.resolve("scenes/refused.json")), "the scene was not copied");
        assertFalse(Files.exists(course.resolve("scenes/reference/refused.png")), "no reference was written");
    }
}
