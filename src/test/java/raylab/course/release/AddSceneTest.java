package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.FileTrees;
import raylab.course.GradingPlan;
import raylab.course.SolutionRegions;
import raylab.render.ImageCompare;
import raylab.render.PngFiles;

/**
 * An instructor adds a scene and a data case to milestone sphere in a copy of the project, each
 * in one command; the handout's table, the total and the reference follow, and {@code raylab
 * grade} grades both (with the reference solution: full marks, out of the new total). A command
 * that fails changes nothing.
 */
class AddSceneTest {
    @TempDir
    Path dir;

    private static final String SCENE = """
            {
              "image": {"width": 64, "height": 48},
              "camera": {"type": "perspective", "eye": [0, 0, 6], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
              "background": [0.1, 0.1, 0.12],
              "materials": {"n": {"type": "normals"}},
              "surfaces": [
                {"type": "sphere", "name": "left", "center": [-1.2, 0, 0], "radius": 1, "material": "n"},
                {"type": "sphere", "name": "right", "center": [1.2, 0, -1], "radius": 1.3, "material": "n"}
              ]
            }
            """;

    private static final String CASE = """
            {"name": "ray from far away hits the near side", "surface": {"type": "sphere", "center": [0, 0, 0],
             "radius": 2}, "ray": {"p": [0, 0, 10], "d": [0, 0, -1]}, "expect": {"hit": true, "t": 8}}
            """;

    static Path copy(Path root, Path to) throws IOException {
        for (String d : List.of("assignments", "scenes", "grader", "src/main/java", "src/main/resources", "src/tools/java",
                "src/test/java")) {
            if (Files.exists(root.resolve(d))) { // the lab has no resources of its own (docs/architecture.md)
                FileTrees.copy(root.resolve(d), to.resolve(d));
            }
        }
        return to;
    }

    static String run(int expected, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(new PrintWriter(out), new PrintWriter(err), args);
        assertEquals(expected, status, () -> "raylab " + String.join(" ", args) + "\n" + out + err);
        return out + err.toString();
    }

    @Test
    void addSceneAndCaseEndToEndAndGradePicksThemUp() throws IOException {
        Path root = Path.of("").toAbsolutePath();
        Path copy = copy(root, dir.resolve("course"));
        Path scene = dir.resolve("twospheres.json");
        Files.writeString(scene, SCENE);
        Path json = copy.resolve("assignments/01-sphere/assignment.json");
        Path readme = copy.resolve("assignments/01-sphere/README.md");
        byte[] jsonBefore = Files.readAllBytes(json);

        // Failures change nothing: an unknown milestone, a malformed scene.
        String bad = run(2, "assignment", "add-scene", "spheres", scene.toString(), "--points", "3", "--root", copy.toString());
        assertTrue(bad.strip().startsWith("raylab: unknown milestone 'spheres'"), bad);
        Path broken = dir.resolve("broken.json");
        Files.writeString(broken, "{\"image\": ");
        run(2, "assignment", "add-scene", "sphere", broken.toString(), "--points", "3", "--root", copy.toString());
        assertArrayEquals(jsonBefore, Files.readAllBytes(json), "assignment.json untouched");

        String out = run(0, "assignment", "add-scene", "sphere", scene.toString(), "--points", "3", "--tolerance", "0.003",
                "--root", copy.toString());
        System.out.println(out);
        Assignment sphere = Assignments.load(copy).byId("sphere").orElseThrow();
        assertEquals(23, sphere.points());
        Assignment.GradedScene added = sphere.scenes().get(sphere.scenes().size() - 1);
        assertEquals(List.of("scenes/twospheres.json", "scenes/reference/twospheres.png", 3, 0.003),
                List.of(added.scene(), added.reference(), added.points(), added.tolerance()), sphere.scenes().toString());
        // The default variant for a scene without lights: the camera only, checked on the spot.
        assertEquals("{\"camera\":{\"yaw\":15,\"pitch\":6,\"distance\":0.1}}", added.variant().toString());
        assertTrue(out.contains("the first draw keeps the point on each of 8 grading seeds"), out);
        // The reference is the reference solution's render.
        Path fresh = dir.resolve("fresh.png");
        run(0, "render", scene.toString(), "-o", fresh.toString(), "--quiet");
        assertTrue(ImageCompare.compare(PngFiles.read(fresh), PngFiles.read(copy.resolve("scenes/reference/twospheres.png")))
                .matches(0));
        String handout = Files.readString(readme);
        assertTrue(handout.contains("| `scenes/twospheres.json` matches its reference (tolerance 0.3 %) | 3 |"), handout);
        assertTrue(handout.contains("(23 points)") && handout.contains("| **total** | **23** |"), handout);
        assertTrue(out.contains("DIFFERS 0/3         scenes/twospheres.json (tolerance 0.3 %)"), "shows what students see: " + out);

        out = run(0, "assignment", "add-case", "sphere", write(dir.resolve("case.json"), CASE).toString(), "--points", "1",
                "--visible", "--root", copy.toString());
        sphere = Assignments.load(copy).byId("sphere").orElseThrow();
        assertEquals(24, sphere.points());
        assertTrue(Files.readString(readme).contains("| data case \"ray from far away hits the near side\" | 1 |"));
        assertEquals(GradingPlan.of(copy, sphere).visibleCents() + GradingPlan.of(copy, sphere).hiddenCents(), 2400);

        // raylab grade on the reference solution: both new items graded and passed, out of 24.
        Path sub = Files.createDirectories(dir.resolve("submission"));
        Path src = root.resolve("src/main/java/raylab/surface/Sphere.java");
        Files.writeString(sub.resolve("Sphere.java"), SolutionRegions.toStudent("Sphere.java", Files.readString(src),
                Set.of("sphere")));
        Path results = dir.resolve("results");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(new ByteArrayOutputStream(), true),
                new PrintWriter(err, true, StandardCharsets.UTF_8), "grade", sub.toString(), "--out", results.toString(),
                "--root", copy.toString(), "--quiet", "--milestone", "sphere", "--test-timeout", "5",
                // A cache the sandbox user can read (the temporary folder is private to this user).
                "--cache", root.resolve("target/grader-cache").toString(),
                "--milestone-timeout", "60", "--scene-timeout", "30", "--heap", "256",
                // Not a sandbox test: without the shared user, another grading on this machine cannot stop ours.
                "--sandbox-user", "");
        assertEquals(0, status, () -> err.toString(StandardCharsets.UTF_8));
        JsonNode r = new ObjectMapper().readTree(results.resolve("results.json").toFile());
        double max = 0;
        boolean sceneGraded = false;
        boolean caseGraded = false;
        for (JsonNode t : r.get("tests")) {
            max += t.get("max_score").asDouble();
            sceneGraded |= t.get("name").asText().equals("sphere: scenes/twospheres.json") && t.get("score").asDouble() == 3;
            caseGraded |= t.get("name").asText().equals("sphere: data case: ray from far away hits the near side")
                    && t.get("score").asDouble() == 1 && t.get("visibility").asText().equals("visible");
        }
        assertTrue(sceneGraded && caseGraded, r.get("tests").toString());
        assertEquals(24, max, 1e-9);
        assertEquals(24, r.get("score").asDouble(), 1e-9, "the reference earns every point");
    }

    static Path write(Path p, String text) throws IOException {
        Files.writeString(p, text);
        return p;
    }
}
