package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.cli.Main;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.FileTrees;

/** Variants are deterministic, vary with the seed, move only what their spec allows, and bad specs are one-line errors. */
class SceneVariantsTest {
    static final ObjectMapper JSON = new ObjectMapper();
    static Path root;
    static Assignments all;

    @TempDir
    Path dir;

    @BeforeAll
    static void load() throws IOException {
        root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        all = Assignments.load(root);
    }

    /** Every bundled graded scene with a spec: (milestone, index). */
    static Stream<Arguments> scenes() throws IOException {
        List<Arguments> out = new ArrayList<>();
        for (Assignment a : Assignments.load(Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath()
                .normalize()).all()) {
            for (int i = 0; i < a.scenes().size(); i++) {
                if (a.scenes().get(i).variant() != null) {
                    out.add(Arguments.of(a.scenes().get(i).scene(), a, i));
                }
            }
        }
        return out.stream();
    }

    private static JsonNode published(Assignment a, int i) throws IOException {
        return JSON.readTree(root.resolve(a.scenes().get(i).scene()).toFile());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void sameSeedSameJsonOtherSeedsDiffer(String scene, Assignment a, int i) throws IOException {
        JsonNode pub = published(a, i);
        String before = pub.toString();
        VariantSpec spec = GradedScenes.spec(a, i, pub);
        Set<String> seen = new HashSet<>();
        for (long seed = 1; seed <= 20; seed++) {
            String one = SceneVariants.variant(pub, spec, seed).toString();
            String two = SceneVariants.variant(published(a, i), GradedScenes.spec(a, i, published(a, i)), seed).toString();
            assertEquals(one, two, scene + ", seed " + seed + ": the same seed must give the same JSON");
            assertNotEquals(before, one, scene + ", seed " + seed + ": a variant must differ from the published scene");
            seen.add(one);
        }
        if (spec.pan() > 0) {
            // (2·pan + 1)² − 1 whole-pixel pans: 20 draws may repeat one, rarely more.
            assertTrue(seen.size() >= 17, scene + ": 20 seeds gave only " + seen.size() + " different pans");
        } else {
            assertEquals(20, seen.size(), scene + ": 20 seeds must give 20 different variants");
        }
        assertEquals(before, pub.toString(), scene + ": the published JSON must not change");
    }

    @Test
    void seedForIsFixedAcrossMachinesAndDependsOnGradingSeedAndName() {
        // Values of the documented algorithm (FNV-1a 64 of the name, SplitMix64 finalizer), computed independently.
        assertEquals(-8449880682918180140L, SceneVariants.seedFor(42, "shadows"));
        assertEquals(8494681247349236930L, SceneVariants.seedFor(42, "showcase"));
        assertEquals(-8795874983921357161L, SceneVariants.seedFor(43, "shadows"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void movesOnlyWhatTheSpecAllows(String scene, Assignment a, int i) throws IOException {
        JsonNode pub = published(a, i);
        VariantSpec spec = GradedScenes.spec(a, i, pub);
        for (long seed = 1; seed <= 50; seed++) {
            JsonNode v = SceneVariants.variant(pub, spec, seed);
            String where = scene + ", seed " + seed + ": ";
            assertEquals(pub.get("image"), v.get("image"), where + "image size");
            assertEquals(pub.get("materials"), v.get("materials"), where + "materials");
            JsonNode pc = pub.get("camera");
            JsonNode vc = v.get("camera");
            if (pc.get("type").asText().equals("perspective")) {
                assertEquals(pc.get("lookAt"), vc.get("lookAt"), where + "the look-at point stays");
                double r0 = dist(pc.get("eye"), pc.get("lookAt"));
                double r1 = dist(vc.get("eye"), vc.get("lookAt"));
                assertTrue(Math.abs(r1 / r0 - 1) <= spec.distance() + 1e-6, where + "eye distance " + r1 + " from " + r0
                        + " beyond the bound " + spec.distance());
                assertTrue(Math.abs(vc.path("fov").asDouble(60) - pc.path("fov").asDouble(60)) <= spec.fov() + 1e-6,
                        where + "fov " + vc.get("fov") + " from " + pc.get("fov"));
            } else {
                double pixel = pc.get("viewHeight").asDouble() / pub.get("image").get("height").asInt();
                for (int k = 0; k < 3; k++) {
                    double moved = (vc.get("eye").get(k).asDouble() - pc.get("eye").get(k).asDouble()) / pixel;
                    assertEquals(Math.rint(moved), moved, 0.0, where + "the orthographic eye moves by whole pixels, axis " + k);
                    assertTrue(Math.abs(moved) <= spec.pan(), where + "pan " + moved + " beyond " + spec.pan());
                }
            }
            for (int l = 0; l < pub.path("lights").size(); l++) {
                for (int k = 0; k < 3; k++) {
                    double d = v.get("lights").get(l).get("position").get(k).asDouble()
                            - pub.get("lights").get(l).get("position").get(k).asDouble();
                    assertTrue(Math.abs(d) <= spec.lightMove()[k] + 1e-6, where + "light " + l + " axis " + k + " moved " + d);
                }
            }
            Set<String> placed = new HashSet<>();
            spec.groups().forEach(g -> placed.addAll(g.objects()));
            for (int s = 0; s < pub.get("surfaces").size(); s++) {
                JsonNode ps = pub.get("surfaces").get(s);
                JsonNode vs = v.get("surfaces").get(s);
                if (!placed.contains(ps.path("name").asText())) {
                    assertEquals(ps, vs, where + "\"" + ps.path("name").asText() + "\" is not placed and must not move");
                } else {
                    double[] bound = spec.groups().stream().filter(g -> g.objects().contains(ps.get("name").asText()))
                            .findFirst().orElseThrow().move();
                    for (int k = 0; k < 3; k++) {
                        double d = anchor(vs, k) - anchor(ps, k);
                        assertTrue(Math.abs(d) <= bound[k] + 1e-6, where + ps.get("name") + " axis " + k + " moved " + d);
                        if (bound[k] == 0) {
                            assertEquals(anchor(ps, k), anchor(vs, k), 0.0, where + ps.get("name") + " must keep axis " + k
                                    + " (bound 0: what stands on the floor stays on it)");
                        }
                    }
                }
            }
        }
    }

    /** A point that moves with the surface: centre, min corner, first vertex or translation. */
    private static double anchor(JsonNode s, int k) {
        return switch (s.get("type").asText()) {
            case "sphere" -> s.get("center").get(k).asDouble();
            case "box" -> s.get("min").get(k).asDouble();
            case "triangle" -> s.get("vertices").get(0).get(k).asDouble();
            default -> s.has("translate") ? s.get("translate").get(k).asDouble() : 0;
        };
    }

    private static double dist(JsonNode a, JsonNode b) {
        double s = 0;
        for (int k = 0; k < 3; k++) {
            double d = a.get(k).asDouble() - b.get(k).asDouble();
            s += d * d;
        }
        return Math.sqrt(s);
    }

    static Stream<Arguments> badSpecs() {
        return Stream.of(
                Arguments.of("scenes/shadows.json", "{\"camera\": {\"yaw\": 90}}",
                        "v.camera.yaw: must be a number from 0 to 45, got 90"),
                Arguments.of("scenes/shadows.json", "{\"camera\": {\"pan\": 2}}",
                        "v.camera.pan: only an orthographic camera pans by whole pixels; this scene's camera is perspective (use yaw, pitch, distance, fov)"),
                Arguments.of("scenes/boxes-front.json", "{\"camera\": {\"yaw\": 5}}",
                        "v.camera.yaw: only a perspective camera orbits; this scene's camera is orthographic (use pan)"),
                Arguments.of("scenes/boxes-front.json", "{\"camera\": {\"pan\": 1.5}}",
                        "v.camera.pan: must be a whole number of pixels from 0 to 32, got 1.5"),
                Arguments.of("scenes/shadows.json", "{\"lights\": {\"move\": [1, -1, 1]}}",
                        "v.lights.move[1]: must be a number >= 0 (a bound: the move is drawn within ±it), got -1"),
                Arguments.of("scenes/shadows.json", "{\"lights\": {\"move\": [1, 1]}}",
                        "v.lights.move: must be [dx, dy, dz], three numbers >= 0, got [1,1]"),
                Arguments.of("scenes/sphere.json", "{\"lights\": {\"move\": [1, 1, 1]}}",
                        "v.lights: the scene has no lights to vary"),
                Arguments.of("scenes/shadows.json", "{\"placement\": [{\"objects\": [\"clay ball\", \"lamp\"], \"move\": [1, 0, 1]}]}",
                        "v.placement[0].objects[1]: the scene has no surface named \"lamp\""),
                Arguments.of("scenes/shadows.json", "{\"placement\": [{\"objects\": [\"floor\"], \"move\": [1, 0, 1]}, {\"objects\": [\"floor\"], \"move\": [1, 0, 1]}]}",
                        "v.placement[1].objects[0]: \"floor\" is already placed by another group"),
                Arguments.of("scenes/shadows.json", "{\"placement\": [{\"objects\": [\"floor\"]}]}",
                        "v.placement[0]: missing \"move\": [dx, dy, dz]"),
                Arguments.of("scenes/shadows.json", "{\"camera\": {\"yaw\": 5}, \"jitter\": 1}",
                        "v.jitter: unknown field (allowed: camera, coverage, lights, placement)"),
                Arguments.of("scenes/shadows.json", "{\"coverage\": 1}",
                        "v.coverage: must be a number from 1.1 to 10, got 1"),
                Arguments.of("scenes/shadows.json", "{}",
                        "v: varies nothing: give camera, lights or placement"),
                Arguments.of("scenes/shadows.json", "[]", "v: must be an object, got array"));
    }

    @ParameterizedTest(name = "{1}")
    @MethodSource("badSpecs")
    void badSpecsAreOneLineErrorsWithTheirJsonPath(String scene, String spec, String expected) throws IOException {
        JsonNode pub = JSON.readTree(root.resolve(scene).toFile());
        VariantSpec.Invalid e = assertThrows(VariantSpec.Invalid.class, () -> VariantSpec.parse(JSON.readTree(spec), "v", pub));
        assertEquals(expected, e.getMessage());
    }

    /** A copy of the project's assignments and scenes, enough for raylab variant --root. */
    private Path project() throws IOException {
        Path p = dir.resolve("project");
        for (String d : List.of("assignments", "scenes")) {
            FileTrees.copy(root.resolve(d), p.resolve(d));
        }
        return p;
    }

    private record Run(int status, String out, String err) {
    }

    private static Run run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new PrintWriter(out, true, StandardCharsets.UTF_8), new PrintWriter(err, true, StandardCharsets.UTF_8), args);
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    @Test
    void variantCommandPrintsTheGradingsJsonAndRendersItsReference() throws IOException {
        Run r = run("variant", "scenes/shadows.json", "--seed", "7", "--root", root.toString());
        assertEquals(0, r.status(), r.err());
        Assignment shadows = all.byId("shadows").orElseThrow();
        GradedScenes.Graded g = GradedScenes.forGrading(root, shadows, 0, 7, false);
        assertEquals(g.json(), r.out(), "the printed JSON is the variant a grading with seed 7 scores");
        assertTrue(r.err().contains("grading seed 7: variant seed " + g.seed()), r.err());
        Path png = dir.resolve("v.png");
        Run o = run("variant", root.resolve("scenes/shadows.json").toString(), "--seed", "7", "--root", root.toString(),
                "-o", png.toString());
        assertEquals(0, o.status(), o.err());
        assertEquals("", o.out(), "with -o and without --json nothing is printed on standard output");
        assertTrue(java.util.Arrays.equals(GradedScenes.renderReference(g.json(), root.resolve("scenes/shadows.json")),
                Files.readAllBytes(png)), "-o writes the variant's reference");
        assertFalse(java.util.Arrays.equals(Files.readAllBytes(root.resolve("scenes/reference/shadows.png")),
                Files.readAllBytes(png)), "the variant's reference is not the published one");
    }

    @Test
    void aBadSpecStopsVariantAndGradeWithOneLineNamingFileAndPath() throws IOException {
        Path p = project();
        Path f = p.resolve("assignments/05-shadows/assignment.json");
        ObjectNode a = (ObjectNode) JSON.readTree(f.toFile());
        ((ObjectNode) a.get("scenes").get(2).get("variant").get("lights")).putArray("move").add(0.3).add(-0.15).add(0.3);
        Files.writeString(f, a.toPrettyString());
        Run r = run("variant", "scenes/shadows.json", "--seed", "1", "--root", p.toString());
        assertEquals(2, r.status());
        assertEquals("raylab: assignments/05-shadows/assignment.json: scenes[2].variant.lights.move[1]: must be a number >= 0"
                + " (a bound: the move is drawn within ±it), got -0.15\n", r.err());
        Path out = dir.resolve("out");
        Run g = run("grade", Files.createDirectories(dir.resolve("empty")).toString(), "--root", p.toString(), "--out", out.toString(), "--quiet",
                "--cache", dir.resolve("cache").toString());
        assertEquals(1, g.status(), "a bad spec: the grader could not grade");
        // The student reads that the grading failed (no score, no instructor path); the instructors' report has the cause.
        JsonNode results = JSON.readTree(out.resolve("results.json").toFile());
        assertFalse(results.has("score"), results.toString());
        assertEquals(GradeReport.FAILED_FOR_STUDENTS, results.get("output").asText());
        assertTrue(Files.readString(out.resolve("report.html")).contains("scenes[2].variant.lights.move[1]"),
                "the instructors' report names the bad spec");
    }
}
