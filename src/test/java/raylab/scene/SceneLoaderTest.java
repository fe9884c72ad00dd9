package raylab.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.camera.OrthographicCamera;
import raylab.camera.PerspectiveCamera;
import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.FlatColor;
import raylab.material.Lambertian;
import raylab.material.NormalColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.surface.Box;
import raylab.surface.Mesh;
import raylab.surface.Sphere;
import raylab.surface.Triangle;

/** Valid scenes load with the values they state and the documented defaults. */
class SceneLoaderTest {
    private static final double EPS = 1e-12;
    private static final String CAMERA =
            "\"camera\": {\"type\": \"perspective\", \"eye\": [0, 1, 5], \"lookAt\": [0, 0, 0],"
            + " \"up\": [0, 1, 0], \"fov\": 90}";

    private static Scene parse(String json) throws SceneException {
        return SceneLoader.parse(json, Path.of("test.json"));
    }

    private static String minimal(String extra) {
        return "{\"image\": {\"width\": 4, \"height\": 2}, " + CAMERA + ", \"surfaces\": []"
                + (extra.isEmpty() ? "" : ", " + extra) + "}";
    }

    private static void assertVec(Vec3 expected, Vec3 actual, String what) {
        assertTrue(Math.abs(expected.x - actual.x) <= EPS && Math.abs(expected.y - actual.y) <= EPS
                && Math.abs(expected.z - actual.z) <= EPS,
                () -> what + ": expected " + expected + ", got " + actual);
    }

    @Test
    void minimalSceneGetsTheDocumentedDefaults() throws SceneException {
        Scene s = parse(minimal(""));
        assertEquals(4, s.width);
        assertEquals(2, s.height);
        assertEquals(1, s.samplesPerPixel);
        assertEquals(Sampler.STRATIFIED, s.sampler);
        assertEquals(Color.BLACK, s.background);
        assertEquals(Color.BLACK, s.ambient);
        assertEquals(Effects.AUTO, s.effects);
        assertTrue(s.surfaces.isEmpty());
        assertTrue(s.lights.isEmpty());
        assertEquals(Path.of("test.json"), s.source);
    }

    @Test
    void perspectiveCameraFrameAndCentreRay() throws SceneException {
        Scene s = parse(minimal(""));
        assertInstanceOf(PerspectiveCamera.class, s.camera);
        // view direction lookAt − eye = (0, −1, −5); w = −view/‖view‖ = (0, 1, 5)/√26
        double r = Math.sqrt(26);
        assertVec(new Vec3(0, 1 / r, 5 / r), s.camera.w, "w");
        assertVec(new Vec3(0, 1, 5), s.camera.eye, "eye");
        // u = up × w / ‖up × w‖ = (5, 0, 0)/5 = (1, 0, 0)
        assertVec(new Vec3(1, 0, 0), s.camera.u, "u");
        // The ray through the image centre (2, 1) goes along −w from the eye.
        Ray ray = s.camera.generateRay(2, 1);
        assertVec(new Vec3(0, 1, 5), ray.p, "centre ray origin");
        assertVec(new Vec3(0, -1 / r, -5 / r), ray.d.normalize(), "centre ray direction");
    }

    @Test
    void viewDirectionGivesTheSameFrameAsTheEquivalentLookAt() throws SceneException {
        Scene a = parse(minimal(""));
        Scene b = parse(minimal("").replace("\"lookAt\": [0, 0, 0]", "\"viewDirection\": [0, -2, -10]"));
        assertVec(a.camera.u, b.camera.u, "u");
        assertVec(a.camera.v, b.camera.v, "v");
        assertVec(a.camera.w, b.camera.w, "w");
    }

    @Test
    void orthographicCameraRaysAreParallelAndSpanViewHeight() throws SceneException {
        Scene s = parse("{\"image\": {\"width\": 4, \"height\": 2}, \"camera\": {\"type\":"
                + " \"orthographic\", \"eye\": [1, 2, 3], \"viewDirection\": [0, 0, -1], \"up\":"
                + " [0, 1, 0], \"viewHeight\": 6}, \"surfaces\": []}");
        assertInstanceOf(OrthographicCamera.class, s.camera);
        // Top edge centre (x = 2, y = 0): eye + (viewHeight/2)·v = (1, 5, 3), direction (0, 0, −1).
        Ray top = s.camera.generateRay(2, 0);
        assertVec(new Vec3(1, 5, 3), top.p, "top centre ray origin");
        assertVec(new Vec3(0, 0, -1), top.d.normalize(), "top centre ray direction");
        // Left edge centre (x = 0, y = 1): half width = 3·4/2 = 6 → (1 − 6, 2, 3).
        assertVec(new Vec3(-5, 2, 3), s.camera.generateRay(0, 1).p, "left centre ray origin");
    }

    @Test
    void imageSettingsEffectsBackgroundAndAmbient() throws SceneException {
        Scene s = parse("{\"$schema\": \"scene.schema.json\", \"image\": {\"width\": 320.0,"
                + " \"height\": 240, \"samplesPerPixel\": 16, \"sampler\": \"random\"}, " + CAMERA
                + ", \"surfaces\": [], \"background\": [0.1, 0.2, 0.3], \"ambient\": 0.25,"
                + " \"effects\": {\"shadows\": false, \"acceleration\": true}}");
        assertEquals(320, s.width);
        assertEquals(240, s.height);
        assertEquals(16, s.samplesPerPixel);
        assertEquals(Sampler.RANDOM, s.sampler);
        assertEquals(new Color(0.1, 0.2, 0.3), s.background);
        assertEquals(new Color(0.25, 0.25, 0.25), s.ambient);
        assertEquals(new Effects(false, null, null, true), s.effects);
    }

    @Test
    void materialsSurfacesAndLightsWithDefaults() throws SceneException {
        Scene s = parse(minimal("").replace("\"surfaces\": []", """
                "materials": {
                  "red": {"type": "lambertian", "kd": [0.8, 0.1, 0.1]},
                  "shiny": {"type": "blinnPhong", "kd": 0.5, "ks": [0.6, 0.6, 0.6], "p": 64, "ka": 0.1},
                  "white": {"type": "flat", "color": 1},
                  "debug": {"type": "normals"}
                },
                "surfaces": [
                  {"type": "sphere", "name": "ball", "center": [1, 2, 3], "radius": 0.5, "material": "red"},
                  {"type": "box", "min": [-1, -2, -3], "max": [1, 2, 3], "material": "shiny"},
                  {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "material": "white"},
                  {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"},
                  {"type": "box", "min": [0, 0, 0], "max": [0, 1, 1], "material": "debug"}
                ],
                "lights": [
                  {"type": "point", "name": "key", "position": [5, 5, 5], "intensity": [1, 0.5, 0.25]},
                  {"type": "point", "position": [0, 9, 0], "intensity": 2, "shadows": false}
                ]"""));
        assertEquals(5, s.surfaces.size());

        Sphere ball = assertInstanceOf(Sphere.class, s.surfaces.get(0));
        assertEquals("ball", ball.name());
        assertEquals(new Vec3(1, 2, 3), ball.center);
        assertEquals(0.5, ball.radius);
        Lambertian red = assertInstanceOf(Lambertian.class, ball.material());
        assertEquals("red", red.name());
        assertEquals(new Color(0.8, 0.1, 0.1), red.kd);
        assertEquals(red.kd, red.ka, "ka defaults to kd");

        Box box = assertInstanceOf(Box.class, s.surfaces.get(1));
        assertEquals("box #1", box.name());
        assertEquals(new Vec3(-1, -2, -3), box.min);
        assertEquals(new Vec3(1, 2, 3), box.max);
        BlinnPhong shiny = assertInstanceOf(BlinnPhong.class, box.material());
        assertEquals(new Color(0.5, 0.5, 0.5), shiny.kd);
        assertEquals(new Color(0.6, 0.6, 0.6), shiny.ks);
        assertEquals(64, shiny.p);
        assertEquals(new Color(0.1, 0.1, 0.1), shiny.ka);

        Triangle tri = assertInstanceOf(Triangle.class, s.surfaces.get(2));
        assertEquals("triangle #2", tri.name());
        assertEquals(new Vec3(1, 0, 0), tri.b);
        assertEquals(Color.WHITE, assertInstanceOf(FlatColor.class, tri.material()).color);

        assertEquals("sphere #3", s.surfaces.get(3).name());
        assertSame(red, s.surfaces.get(3).material(), "one material object per name");
        assertInstanceOf(NormalColor.class, s.surfaces.get(4).material());

        PointLight key = s.lights.get(0);
        assertEquals("key", key.name);
        assertEquals(new Vec3(5, 5, 5), key.position);
        assertEquals(new Color(1, 0.5, 0.25), key.intensity);
        assertTrue(key.castsShadows, "shadows default to true");
        PointLight second = s.lights.get(1);
        assertEquals("light #1", second.name);
        assertEquals(new Color(2, 2, 2), second.intensity);
        assertFalse(second.castsShadows);
    }

    @Test
    void meshIsScaledTranslatedAndFoundRelativeToTheSceneFile(@TempDir Path tmp) throws Exception {
        Path meshes = Files.createDirectories(tmp.resolve("meshes"));
        // A unit square as one quad (forms i/t/n and negative indices): two fan triangles.
        Files.writeString(meshes.resolve("quad.obj"), "# quad\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\n"
                + "v 0 1 0\r\nvt 0 0\r\nvn 0 0 1\r\nf 1/1/1 2//1 -2/1 -1\r\n");
        Path sceneDir = Files.createDirectories(tmp.resolve("scenes"));
        Path file = sceneDir.resolve("s.json");
        Files.writeString(file, minimal("").replace("\"surfaces\": []",
                "\"materials\": {\"m\": {\"type\": \"normals\"}}, \"surfaces\": ["
                + "{\"type\": \"mesh\", \"name\": \"quad\", \"file\": \"../meshes/quad.obj\","
                + " \"material\": \"m\", \"scale\": 2, \"translate\": [10, 0, -1]},"
                + "{\"type\": \"mesh\", \"file\": \"../meshes/quad.obj\", \"material\": \"m\"}]"));
        Scene s = SceneLoader.load(file);
        Mesh quad = assertInstanceOf(Mesh.class, s.surfaces.get(0));
        assertEquals("quad", quad.name());
        assertEquals(2, quad.primitiveCount());
        List<Triangle> t = quad.triangles();
        // v·2 + (10, 0, −1)
        assertEquals(new Vec3(10, 0, -1), t.get(0).a);
        assertEquals(new Vec3(12, 0, -1), t.get(0).b);
        assertEquals(new Vec3(12, 2, -1), t.get(0).c);
        assertEquals(new Vec3(10, 0, -1), t.get(1).a);
        assertEquals(new Vec3(12, 2, -1), t.get(1).b);
        assertEquals(new Vec3(10, 2, -1), t.get(1).c);
        assertEquals("quad triangle #0", t.get(0).name());
        assertEquals("quad triangle #1", t.get(1).name());
        assertEquals("m", t.get(1).material().name());

        Mesh plain = assertInstanceOf(Mesh.class, s.surfaces.get(1));
        assertEquals("mesh #1", plain.name());
        assertEquals(new Vec3(1, 1, 0), plain.triangles().get(0).c);
        assertEquals("mesh #1 triangle #1", plain.triangles().get(1).name());
    }

    @Test
    void byteOrderMarkIsAccepted(@TempDir Path tmp) throws Exception {
        Path file = tmp.resolve("bom.json");
        byte[] body = minimal("").getBytes(StandardCharsets.UTF_8);
        byte[] bytes = new byte[body.length + 3];
        bytes[0] = (byte) 0xEF;
        bytes[1] = (byte) 0xBB;
        bytes[2] = (byte) 0xBF;
        System.arraycopy(body, 0, bytes, 3, body.length);
        Files.write(file, bytes);
        assertEquals(4, SceneLoader.load(file).width);
    }

    @Test
    void lineAndColumnCountCrLfLineEndings() {
        String json = "{\r\n  \"image\": {\"width\": 4, \"height\": 2},\r\n  \"camera\": 7,\r\n"
                + "  \"surfaces\": []\r\n}";
        SceneException e = assertThrows(SceneException.class, () -> parse(json));
        assertEquals("test.json:3:13: $.camera: expected an object {...}, got the number 7",
                e.getMessage());
    }

    @Test
    void materialNamesThatAreNotIdentifiersAreQuotedInPaths() {
        String json = minimal("").replace("\"surfaces\": []",
                "\"materials\": {\"my red\": {\"type\": \"lambertian\", \"kd\": [1, 1]}}, \"surfaces\": []");
        SceneException e = assertThrows(SceneException.class, () -> parse(json));
        assertTrue(e.getMessage().contains(": $.materials[\"my red\"].kd: expected 3 numbers [r, g, b], got 2"),
                e.getMessage());
    }

    @Test
    void fileProblemsAreOneLineWithTheFileAsGiven(@TempDir Path tmp) {
        Path missing = tmp.resolve("nope.json");
        assertEquals(missing + ": no such file",
                assertThrows(SceneException.class, () -> SceneLoader.load(missing)).getMessage());
        assertEquals(tmp + ": is a directory, not a scene file",
                assertThrows(SceneException.class, () -> SceneLoader.load(tmp)).getMessage());
    }

    @Test
    void degenerateTriangleAndFlatBoxAreAllowed() throws SceneException {
        Scene s = parse(minimal("").replace("\"surfaces\": []",
                "\"materials\": {\"m\": {\"type\": \"normals\"}}, \"surfaces\": ["
                + "{\"type\": \"triangle\", \"vertices\": [[0, 0, 0], [1, 1, 1], [2, 2, 2]], \"material\": \"m\"},"
                + "{\"type\": \"box\", \"min\": [0, 0, 0], \"max\": [0, 0, 0], \"material\": \"m\"}]"));
        assertEquals(2, s.surfaces.size());
    }

    @Test
    void suggestionsCatchTyposButNotUnrelatedWords() {
        List<String> keys = SceneLoader.ACCEPTED_KEYS.get("sphere");
        assertEquals("radius", SceneLoader.suggest("radus", keys));
        assertEquals("center", SceneLoader.suggest("centre", keys));
        assertEquals("material", SceneLoader.suggest("Material", keys));
        assertNull(SceneLoader.suggest("color", keys));
        assertEquals("blinnPhong", SceneLoader.suggest("phong", SceneLoader.MATERIAL_TYPES.keySet()));
        assertEquals(3, SceneLoader.editDistance("kitten", "sitting"));
        assertEquals(0, SceneLoader.editDistance("", ""));
        assertEquals(4, SceneLoader.editDistance("", "abcd"));
    }

    @Test
    void everyExampleSceneUnderScenesLoads() throws IOException, SceneException {
        Path scenes = Path.of("scenes");
        if (!Files.isDirectory(scenes)) {
            return;
        }
        try (var files = Files.walk(scenes)) {
            for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".json")
                    && !p.getFileName().toString().equals("scene.schema.json"))::iterator) {
                SceneLoader.load(f);
            }
        }
    }
}
