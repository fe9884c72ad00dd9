package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.FileTrees;
import raylab.course.JavaBuild;
import raylab.course.SolutionRegions;

/**
 * A plane milestone built from test resources only, as an instructor builds it: into a copy of
 * the course go {@code src/main/java/raylab/surface/Plane.java} (solution markers),
 * {@code PlaneType.java}, {@code src/main/resources/META-INF/services/raylab.scene.SurfaceType}
 * (all from {@code src/test/resources/extension/plane/}), {@code assignments/07-plane/} (two data
 * cases) and {@code scenes/plane.json}, graded with {@code add-scene --variant}; no framework file
 * is edited. The instructor's build is raylab's classes with the two new ones (compiled here).
 * Then {@code release} cuts the student stub, and {@code grade} grades a correct and a buggy
 * plane through the process boundary, the scene on its variant, the data cases included.
 */
class PlaneMilestoneTest {
    @TempDir
    Path dir;

    private static final String ASSIGNMENT = """
            {
              "id": "plane",
              "order": 7,
              "title": "Planes",
              "points": 2,
              "requires": [],
              "files": [{"path": "src/main/java/raylab/surface/Plane.java", "methods": ["Plane.intersect"]}],
              "tests": {"tag": "plane", "visible": [], "visiblePoints": 0, "hiddenPoints": 0},
              "scenes": [],
              "cases": ["cases/plane.json"]
            }
            """;

    private static final String SCENE = """
            {
              "image": {"width": 64, "height": 48},
              "camera": {"type": "perspective", "eye": [0, 1, 6], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fov": 50},
              "background": [0.1, 0.1, 0.3],
              "materials": {"red": {"type": "flat", "color": [0.9, 0.2, 0.1]}},
              "surfaces": [
                {"type": "plane", "name": "floor", "point": [0, -1, 0], "normal": [0, 1, 0], "material": "red"}
              ]
            }
            """;

    record Ran(int status, String out) {
    }

    @Test
    void aPlaneMilestoneFromTestResourcesIsReleasedAndGraded() throws Exception {
        Path here = Path.of("").toAbsolutePath();
        Path ext = here.resolve("src/test/resources/extension/plane");
        Path course = AddSceneTest.copy(here, dir.resolve("course"));
        // The instructor's new files, and nothing else changed.
        List<String> added = List.of("src/main/java/raylab/surface/Plane.java", "src/main/java/raylab/surface/PlaneType.java",
                "src/main/resources/META-INF/services/raylab.scene.SurfaceType");
        for (String f : added) {
            Files.createDirectories(course.resolve(f).getParent());
            Files.copy(ext.resolve(f), course.resolve(f));
        }
        Files.createDirectories(course.resolve("assignments/07-plane/cases"));
        Files.writeString(course.resolve("assignments/07-plane/assignment.json"), ASSIGNMENT);
        Files.copy(ext.resolve("assignments/07-plane/cases/plane.json"), course.resolve("assignments/07-plane/cases/plane.json"));
        Files.writeString(course.resolve("assignments/07-plane/README.md"), "# Milestone 7 — Planes (2 points)\n\n## Grading\n");
        Files.writeString(dir.resolve("plane.json"), SCENE);

        // The instructor's build: raylab's classes plus the two new ones and the registration.
        Path code = dir.resolve("code");
        Path ownCode = null;
        List<String> rest = new ArrayList<>();
        for (Path p : JavaBuild.ownClassPath()) {
            if (Files.isDirectory(p) && Files.exists(p.resolve("raylab/cli/Main.class"))) {
                ownCode = p;
            } else {
                rest.add(p.toAbsolutePath().toString());
            }
        }
        assertTrue(ownCode != null, "raylab's classes are a folder on the test class path");
        FileTrees.copy(ownCode, code);
        JavaBuild.Result r = JavaBuild.compile(List.of(course.resolve(added.get(0)), course.resolve(added.get(1))),
                JavaBuild.ownClassPath(), code);
        assertTrue(r.success(), () -> "the plane compiles: " + r.errors());
        Files.createDirectories(code.resolve("META-INF/services"));
        Files.copy(course.resolve(added.get(2)), code.resolve("META-INF/services/raylab.scene.SurfaceType"));
        String cp = code + File.pathSeparator + String.join(File.pathSeparator, rest);

        Ran s = raylab(cp, course, "assignment", "add-scene", "plane", dir.resolve("plane.json").toString(), "--points", "2",
                "--variant", "{\"camera\": {\"yaw\": 10, \"pitch\": 4, \"distance\": 0.05}, \"placement\": [{\"objects\": "
                        + "[\"floor\"], \"move\": [0, 0.15, 0]}]}", "--root", course.toString());
        assertEquals(0, s.status(), s.out());
        assertTrue(s.out().contains("updated assignments/07-plane/assignment.json (2 -> 4 points)"), s.out());

        Ran rel = raylab(cp, course, "release", "--out", dir.resolve("starter").toString(), "--no-verify", "--root",
                course.toString());
        assertEquals(0, rel.status(), rel.out());
        String stub = Files.readString(dir.resolve("starter/src/main/java/raylab/surface/Plane.java"));
        assertTrue(stub.contains("throw new NotImplemented(\"plane\", \"Plane.intersect\");") && !stub.contains("dn == 0"),
                "the student stub, cut from the solution markers: " + stub);
        assertTrue(Files.exists(dir.resolve("starter/src/main/java/raylab/surface/PlaneType.java"))
                && Files.exists(dir.resolve("starter/" + added.get(2))), "the scene entry ships with the starter");
        assertEquals(Files.readString(course.resolve(added.get(2))), Files.readString(dir.resolve("starter/" + added.get(2))),
                "the services file keeps its provider, whose source the starter ships");
        for (String instructorOnly : List.of("raylab.cli.OptionalCommand", "raylab.surface.PackedEngine",
                "raylab.course.BoundaryHooks")) {
            // The instructor's modules register these (StarterNamesNoInstructorClassTest); the starter has no list.
            try (var files = Files.walk(dir.resolve("starter"))) {
                assertEquals(List.of(), files.filter(p -> p.endsWith(Path.of("META-INF/services", instructorOnly)))
                        .toList(), "the starter lists no provider for " + instructorOnly);
            }
        }

        // The scene schema knows the plane, in the starter and in the instructor's tree.
        assertTrue(rel.out().contains("updated scenes/scene.schema.json with the surface types plane"), rel.out());
        JsonNode schema = new ObjectMapper().readTree(dir.resolve("starter/scenes/scene.schema.json").toFile());
        assertEquals("[\"type\",\"point\",\"normal\",\"material\"]", schema.at("/$defs/plane/required").toString());
        assertEquals("plane", schema.at("/$defs/plane/properties/type/const").asText());
        assertEquals("[\"sphere\",\"box\",\"triangle\",\"mesh\",\"plane\"]",
                schema.at("/$defs/surface/properties/type/enum").toString());
        assertEquals(schema, new ObjectMapper().readTree(course.resolve("scenes/scene.schema.json").toFile()));

        String reference = Files.readString(course.resolve(added.get(0)));
        Map<String, JsonNode> correct = grade(cp, course, "correct",
                SolutionRegions.toStudent("Plane.java", reference, Set.of("plane")));
        assertEquals(2, correct.get("plane: scenes/plane.json").get("score").asDouble(), 1e-9, correct.toString());
        assertEquals(1, correct.get("plane: data case: a ray straight down hits the floor at t = 4").get("score").asDouble(),
                1e-9, correct.toString());
        assertEquals(1, correct.get("plane: data case: a ray parallel to the floor misses").get("score").asDouble(), 1e-9);

        assertTrue(reference.contains("point.minus(ray.p)"));
        String buggy = SolutionRegions.toStudent("Plane.java", reference.replace("point.minus(ray.p)", "ray.p.minus(point)"),
                Set.of("plane"));
        Map<String, JsonNode> wrong = grade(cp, course, "buggy", buggy);
        assertEquals(0, wrong.get("plane: scenes/plane.json").get("score").asDouble(), 1e-9, wrong.toString());
        assertEquals(0, wrong.get("plane: data case: a ray straight down hits the floor at t = 4").get("score").asDouble(), 1e-9);
        assertEquals(1, wrong.get("plane: data case: a ray parallel to the floor misses").get("score").asDouble(), 1e-9);
    }

    /** Grades a submission of one Plane.java; its tests by name. */
    private Map<String, JsonNode> grade(String cp, Path course, String name, String plane) throws Exception {
        Path sub = Files.createDirectories(dir.resolve(name));
        Files.writeString(sub.resolve("Plane.java"), plane);
        Path results = dir.resolve(name + "-results");
        Ran g = raylab(cp, course, "grade", sub.toString(), "--out", results.toString(), "--root", course.toString(), "--quiet",
                "--milestone", "plane", "--test-timeout", "10", "--cache",
                Path.of("target/grader-cache").toAbsolutePath().toString(), "--milestone-timeout", "120",
                "--scene-timeout", "60", "--heap", "256", "--sandbox-user", "");
        assertEquals(0, g.status(), g.out());
        JsonNode r = new ObjectMapper().readTree(results.resolve("results.json").toFile());
        assertFalse(r.path("output").asText().contains("graded as published"), "the scene is graded on a variant: " + r);
        assertTrue(Files.readString(results.resolve("report.html")).contains("scene variants: seed"),
                "the instructors' report names the variants' seed");
        assertFalse(r.path("output").asText().contains("scene variants: seed"), "the seed is an instructor's note: " + r);
        Map<String, JsonNode> out = new LinkedHashMap<>();
        for (JsonNode t : r.get("tests")) {
            out.put(t.get("name").asText(), t);
        }
        return out;
    }

    private static Ran raylab(String cp, Path workDir, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-cp", cp, "raylab.cli.Main"));
        cmd.addAll(List.of(args));
        Path out = Files.createTempFile(workDir.getParent(), "raylab", ".out");
        Process p = new ProcessBuilder(cmd).directory(workDir.toFile()).redirectErrorStream(true).redirectOutput(out.toFile())
                .start();
        assertTrue(p.waitFor(600, TimeUnit.SECONDS), "raylab " + String.join(" ", args) + " ended");
        return new Ran(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8));
    }
}
