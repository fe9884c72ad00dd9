package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.stream.LongStream;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import picocli.CommandLine;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.scene.SceneException;
import raylab.scene.SceneLoader;

/**
 * The scene format and the grader agree: every scene that docs/scene-format.md and the loader
 * accept can be varied, checked and rendered for grading. A seeded generator writes valid scenes
 * in every form the format allows (a colour as three numbers or one, a camera by {@code lookAt} or
 * {@code viewDirection}, both camera types, every optional key present or left out, integers
 * written {@code 8.0}, every material and surface type, a mesh with and without scale and
 * translate, lights with and without name and shadows) with a variant spec that moves the camera,
 * the lights and named surfaces; for each, {@link GradedScenes#forGrading} (the grading's path:
 * draw, check, render the reference) and {@code raylab variant} (JSON and {@code -o}) must
 * succeed. The seed of a failing case is in the test's name and message.
 */
class SceneFormatVariantsTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final long BASE_SEED = 0x36a5L;
    private static final int CASES = 40;

    @TempDir
    static Path tmp;

    private static final java.util.concurrent.atomic.AtomicInteger varied = new java.util.concurrent.atomic.AtomicInteger();

    /** The case: {@code "intensity": 1} crashed {@code SceneVariants.vec}. */
    @Test
    void oneNumberIntensityIsVariedAndKeepsItsForm() throws Exception {
        ObjectNode scene = (ObjectNode) JSON.readTree("""
                {"image": {"width": 16, "height": 12},
                 "camera": {"type": "perspective", "eye": [0, 0, 5], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
                 "materials": {"m": {"type": "lambertian", "kd": 0.8}},
                 "surfaces": [{"type": "sphere", "name": "ball", "center": [0, 0, 0], "radius": 1, "material": "m"}],
                 "lights": [{"type": "point", "position": [3, 3, 3], "intensity": 1}]}""");
        VariantSpec spec = VariantSpec.parse(JSON.readTree("{\"lights\": {\"move\": [0.5, 0.5, 0.5], \"intensity\": 0.2}}"),
                "variant", scene);
        ObjectNode v = SceneVariants.variant(scene, spec, 7);
        JsonNode i = v.get("lights").get(0).get("intensity");
        assertTrue(i.isNumber(), "a one-number intensity stays one number; got " + i);
        assertTrue(i.asDouble() >= 0.8 && i.asDouble() <= 1.2 && i.asDouble() != 1,
                "intensity 1 scaled by 1 ± 0.2 (not 1 exactly for seed 7); got " + i);
        assertLoads(v, Path.of("scenes/one.json"), "seed 7");
    }

    @TestFactory
    Stream<DynamicTest> everyFormOfTheFormatIsVariedAndGraded() {
        return LongStream.range(0, CASES).mapToObj(k -> {
            long seed = BASE_SEED + k;
            return DynamicTest.dynamicTest("scene seed " + seed, () -> check(seed));
        });
    }

    /** Most cases must really be varied, or the factory above would test little. */
    @org.junit.jupiter.api.AfterAll
    static void mostWereVaried() {
        assertTrue(varied.get() >= CASES / 2, "cases varied (not graded as published): expected at least "
                + CASES / 2 + " of " + CASES + ", got " + varied.get());
    }

    private void check(long seed) throws Exception {
        Path root = Files.createDirectories(tmp.resolve("case-" + seed));
        Random r = new Random(seed);
        ObjectNode scene = scene(r);
        ObjectNode variant = spec(r, scene);
        Files.createDirectories(root.resolve("scenes/meshes"));
        Files.writeString(root.resolve("scenes/meshes/quad.obj"), QUAD, StandardCharsets.US_ASCII);
        Path file = root.resolve("scenes/fuzz.json");
        Files.writeString(file, JSON.writerWithDefaultPrettyPrinter().writeValueAsString(scene));
        String what = "scene seed " + seed + ": " + scene + " variant " + variant;
        try {
            SceneLoader.load(file);
        } catch (SceneException e) {
            fail("the generator made a scene the loader refuses (a bug of this test), " + what + ": " + e.getMessage());
        }
        Files.createDirectories(root.resolve("scenes/reference"));
        Files.write(root.resolve("scenes/reference/fuzz.png"), GradedScenes.renderReference(Files.readString(file), file));
        Files.createDirectories(root.resolve("assignments/01-fuzz"));
        ObjectNode a = JSON.createObjectNode().put("id", "fuzz").put("order", 1).put("title", "Fuzz").put("points", 1);
        a.putArray("files").addObject().put("path", "src/main/java/raylab/surface/Sphere.java")
                .putArray("methods").add("Sphere.intersect");
        a.putObject("tests").put("tag", "fuzz").put("visiblePoints", 0).put("hiddenPoints", 0).putArray("visible");
        a.putArray("scenes").addObject().put("scene", "scenes/fuzz.json").put("reference", "scenes/reference/fuzz.png")
                .put("points", 1).put("tolerance", 0.002).set("variant", variant);
        Files.writeString(root.resolve("assignments/01-fuzz/assignment.json"), a.toString());
        Assignment m = Assignments.load(root).all().get(0);

        long gradingSeed = r.nextLong() & ((1L << 53) - 1);
        GradedScenes.Graded g;
        try {
            g = GradedScenes.forGrading(root, m, 0, gradingSeed, true);
        } catch (IOException | RuntimeException e) {
            throw new AssertionError("grading seed " + gradingSeed + ", " + what + ": " + e + " at "
                    + List.of(e.getStackTrace()).subList(0, Math.min(4, e.getStackTrace().length)), e);
        }
        if (g.varied()) {
            varied.incrementAndGet();
            assertLoads((ObjectNode) JSON.readTree(g.json()), file, what);
            assertEquals(scene.get("image").get("width").asInt(),
                    ImageIO.read(new ByteArrayInputStream(g.reference())).getWidth(), "reference width, " + what);
            assertSameForm(scene, JSON.readTree(g.json()), what);
        } else {
            assertTrue(g.note().contains("graded as published"), "not varied means a note saying so, " + what + ": " + g.note());
        }

        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = new CommandLine(new VariantCommand());
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(err));
        int code = cl.execute("--root", root.toString(), root.resolve("scenes/fuzz.json").toString(),
                "--seed", Long.toString(gradingSeed), "--json", "-o", root.resolve("v.png").toString());
        assertEquals(0, code, "raylab variant exit status, " + what + "; stderr: " + err);
        assertTrue(Files.size(root.resolve("v.png")) > 0, "raylab variant -o wrote the image, " + what);
        assertEquals(g.json().strip(), out.toString().strip(), "raylab variant prints the JSON grading scores, " + what);
    }

    private static void assertLoads(ObjectNode v, Path file, String what) {
        try {
            SceneLoader.parse(v.toString(), file);
        } catch (SceneException e) {
            fail("the variant does not load, " + what + ": " + e.getMessage() + "; variant " + v);
        }
    }

    /** The variant keeps the published keys: lookAt or viewDirection, one number or three. */
    private static void assertSameForm(JsonNode published, JsonNode v, String what) {
        assertEquals(published.get("camera").has("lookAt"), v.get("camera").has("lookAt"), "camera keys, " + what);
        for (int i = 0; i < published.path("lights").size(); i++) {
            assertEquals(published.get("lights").get(i).get("intensity").isNumber(),
                    v.get("lights").get(i).get("intensity").isNumber(), "light " + i + " intensity form, " + what);
        }
    }

    // ---- the generator: valid scenes in every form of docs/scene-format.md ----

    /** The mesh the generated scenes may use, at scenes/meshes/quad.obj. */
    static final String QUAD = "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n";

    static ObjectNode scene(Random r) {
        ObjectNode s = JSON.createObjectNode();
        if (r.nextBoolean()) {
            s.put("$schema", "../scene.schema.json");
        }
        ObjectNode image = s.putObject("image");
        int w = 8 + r.nextInt(17);
        int h = 6 + r.nextInt(13);
        if (r.nextBoolean()) {
            image.put("width", (double) w).put("height", (double) h); // 8.0 is an integer too
        } else {
            image.put("width", w).put("height", h);
        }
        switch (r.nextInt(4)) {
            case 0 -> image.put("samplesPerPixel", 4).put("sampler", "stratified");
            case 1 -> image.put("samplesPerPixel", 2).put("sampler", "random");
            case 2 -> image.put("samplesPerPixel", 1);
            default -> { }
        }
        boolean perspective = r.nextBoolean();
        ObjectNode cam = s.putObject("camera").put("type", perspective ? "perspective" : "orthographic");
        double[] eye = {r.nextGaussian(), 1 + r.nextDouble(), 5 + r.nextDouble()};
        vector(cam, "eye", eye);
        if (r.nextBoolean()) {
            vector(cam, "lookAt", new double[] {0, 0, 0});
        } else {
            vector(cam, "viewDirection", new double[] {-eye[0], -eye[1], -eye[2]});
        }
        vector(cam, "up", new double[] {0, 1, 0});
        if (perspective) {
            cam.put("fov", 30 + r.nextInt(40));
        } else {
            cam.put("viewHeight", 3 + r.nextDouble() * 3);
        }
        if (r.nextBoolean()) {
            colour(s, "background", r);
        }
        if (r.nextBoolean()) {
            colour(s, "ambient", r);
        }
        if (r.nextBoolean()) {
            ObjectNode e = s.putObject("effects");
            for (String k : List.of("shadows", "specular", "ambient", "acceleration")) {
                if (r.nextBoolean()) {
                    e.put(k, r.nextBoolean());
                }
            }
        }
        ObjectNode mats = s.putObject("materials");
        ObjectNode lam = mats.putObject("lam").put("type", "lambertian");
        colour(lam, "kd", r);
        if (r.nextBoolean()) {
            colour(lam, "ka", r);
        }
        ObjectNode bp = mats.putObject("shiny").put("type", "blinnPhong");
        colour(bp, "kd", r);
        colour(bp, "ks", r);
        bp.put("p", r.nextBoolean() ? 32 : 0);
        if (r.nextBoolean()) {
            colour(bp, "ka", r);
        }
        colour(mats.putObject("flat").put("type", "flat"), "color", r);
        mats.putObject("normals").put("type", "normals");
        List<String> names = List.of("lam", "shiny", "flat", "normals");
        ArrayNode surfaces = s.putArray("surfaces");
        ObjectNode ball = surfaces.addObject().put("type", "sphere").put("name", "ball");
        vector(ball, "center", new double[] {0, 0, 0});
        ball.put("radius", 1).put("material", names.get(r.nextInt(4)));
        ObjectNode floor = surfaces.addObject().put("type", "box");
        if (r.nextBoolean()) {
            floor.put("name", "floor");
        }
        vector(floor, "min", new double[] {-3, -1.5, -3});
        vector(floor, "max", new double[] {3, -1, 3});
        floor.put("material", names.get(r.nextInt(4)));
        ObjectNode tri = surfaces.addObject().put("type", "triangle").put("name", "tri");
        ArrayNode vs = tri.putArray("vertices");
        for (double[] v : new double[][] {{-2, 0, -1}, {-1, 0, -1}, {-2, 1, -1}}) {
            ArrayNode a = vs.addArray();
            for (double c : v) {
                a.add(c);
            }
        }
        tri.put("material", names.get(r.nextInt(4)));
        if (r.nextBoolean()) {
            ObjectNode mesh = surfaces.addObject().put("type", "mesh").put("name", "quad")
                    .put("file", "meshes/quad.obj").put("material", names.get(r.nextInt(4)));
            if (r.nextBoolean()) {
                mesh.put("scale", 0.5);
            }
            if (r.nextBoolean()) {
                vector(mesh, "translate", new double[] {1.5, 0.5, -0.5});
            }
        }
        if (r.nextInt(4) > 0) {
            ArrayNode lights = s.putArray("lights");
            int n = 1 + r.nextInt(2);
            for (int i = 0; i < n; i++) {
                ObjectNode l = lights.addObject().put("type", "point");
                if (r.nextBoolean()) {
                    l.put("name", "lamp " + i);
                }
                vector(l, "position", new double[] {3 - 6 * i, 4, 3});
                if (r.nextBoolean()) {
                    l.put("intensity", r.nextBoolean() ? 1 : 0.7); // one number, an int or not
                } else {
                    colour(l, "intensity", r);
                }
                if (r.nextBoolean()) {
                    l.put("shadows", r.nextBoolean());
                }
            }
        }
        return s;
    }

    /** A spec valid for the scene: its camera type's moves, lights when it has some, named surfaces. */
    static ObjectNode spec(Random r, ObjectNode scene) {
        ObjectNode v = JSON.createObjectNode();
        ObjectNode cam = v.putObject("camera");
        if (scene.get("camera").get("type").asText().equals("perspective")) {
            cam.put("yaw", 10).put("pitch", 5).put("distance", 0.1).put("fov", 2);
        } else {
            cam.put("pan", 1 + r.nextInt(2));
        }
        if (scene.has("lights") && r.nextBoolean()) {
            ObjectNode l = v.putObject("lights");
            ArrayNode move = l.putArray("move");
            move.add(0.3).add(r.nextBoolean() ? 0 : 0.2).add(0.3);
            if (r.nextBoolean()) {
                l.put("intensity", 0.1);
            }
        }
        if (r.nextBoolean()) {
            ArrayNode p = v.putArray("placement");
            ObjectNode g = p.addObject();
            g.putArray("objects").add("ball");
            g.putArray("move").add(0.1).add(0).add(0.1);
            if (scene.get("surfaces").size() > 3) {
                ObjectNode g2 = p.addObject();
                g2.putArray("objects").add("quad").add("tri");
                g2.putArray("move").add(0.1).add(0.1).add(0);
            }
        }
        return v;
    }

    private static void vector(ObjectNode o, String key, double[] v) {
        ArrayNode a = o.putArray(key);
        for (double c : v) {
            a.add(c);
        }
    }

    private static void colour(ObjectNode o, String key, Random r) {
        if (r.nextBoolean()) {
            o.put(key, Math.round(r.nextDouble() * 100) / 100.0);
        } else {
            ArrayNode a = o.putArray(key);
            for (int i = 0; i < 3; i++) {
                a.add(Math.round(r.nextDouble() * 100) / 100.0);
            }
        }
    }
}
