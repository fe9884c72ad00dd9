package raylab.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.JavaBuild;

/**
 * A surface type added the way an instructor adds one, from test resources only
 * ({@code src/test/resources/extension/plane/}: {@code Plane.java} with solution markers,
 * {@code PlaneType.java}, its {@code META-INF/services} line): compiled beside raylab, without
 * any framework file edited, the scene format knows {@code "plane"} (its keys checked, its
 * errors with file:line:col), {@code raylab render} draws it, and a graded scene's variant moves
 * it ({@code raylab variant}). Without the registration on the class path the type is unknown.
 * Each run is a child JVM whose class path is the extension's classes and raylab's.
 */
class SurfaceExtensionTest {
    @TempDir
    static Path dir;
    static Path classes;
    static Path root;

    private static final String SCENE = """
            {
              "image": {"width": 32, "height": 24},
              "camera": {"type": "perspective", "eye": [0, 1, 6], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fov": 50},
              "background": [0, 0, 1],
              "materials": {"red": {"type": "flat", "color": [1, 0, 0]}, "n": {"type": "normals"}},
              "surfaces": [
                {"type": "plane", "name": "floor", "point": [0, -1, 0], "normal": [0, 1, 0], "material": "red"},
                {"type": "sphere", "name": "ball", "center": [0, 0, 0], "radius": 0.8, "material": "n"}
              ]
            }
            """;

    private static final String ASSIGNMENT = """
            {
              "id": "plane",
              "order": 7,
              "title": "Planes",
              "points": 4,
              "files": [{"path": "src/main/java/raylab/surface/Plane.java", "methods": ["Plane.intersect"]}],
              "tests": {"tag": "plane", "visible": [], "visiblePoints": 0, "hiddenPoints": 0},
              "scenes": [
                {"scene": "scenes/plane.json", "reference": "scenes/reference/plane.png", "points": 2, "tolerance": 0.003,
                 "variant": {"camera": {"yaw": 10, "pitch": 4, "distance": 0.05},
                             "placement": [{"objects": ["floor"], "move": [0, 0.2, 0]}]}}
              ],
              "cases": ["cases/plane.json"]
            }
            """;

    /** Runs the milestone's data cases as the grader's case test does (DataCases, CaseCheck). */
    private static final String PROBE = """
            public class CaseProbe {
                public static void main(String[] args) throws Exception {
                    java.nio.file.Path root = java.nio.file.Path.of(args[0]);
                    raylab.course.Assignment a = raylab.course.Assignments.load(root).byId("plane").orElseThrow();
                    try {
                        for (raylab.grade.DataCases.Case c : raylab.grade.DataCases.load(root, a)) {
                            try {
                                raylab.cases.CaseCheck.check(c.json());
                                System.out.println("passed: " + c.name());
                            } catch (AssertionError e) {
                                System.out.println("failed: " + c.name() + ": " + e.getMessage().split("\\n")[0]);
                            }
                        }
                    } catch (java.io.IOException e) {
                        System.out.println("refused: " + e.getMessage());
                    }
                }
            }
            """;

    @BeforeAll
    static void compileTheExtension() throws IOException {
        Path ext = Path.of("src/test/resources/extension/plane").toAbsolutePath();
        classes = dir.resolve("classes");
        JavaBuild.Result r = JavaBuild.compile(JavaBuild.sourcesUnder(ext.resolve("src/main/java")),
                JavaBuild.ownClassPath(), classes);
        assertTrue(r.success(), "the extension compiles: " + r.errors());
        Path services = classes.resolve("META-INF/services/raylab.scene.SurfaceType");
        Files.createDirectories(services.getParent());
        Files.copy(ext.resolve("src/main/resources/META-INF/services/raylab.scene.SurfaceType"), services);
        root = dir.resolve("course");
        Files.createDirectories(root.resolve("scenes"));
        Files.createDirectories(root.resolve("assignments/07-plane"));
        Files.writeString(root.resolve("scenes/plane.json"), SCENE);
        Files.writeString(root.resolve("assignments/07-plane/assignment.json"), ASSIGNMENT);
        Files.createDirectories(root.resolve("assignments/07-plane/cases"));
        Files.copy(ext.resolve("assignments/07-plane/cases/plane.json"), root.resolve("assignments/07-plane/cases/plane.json"));
        // The probe, and a buggy plane (t with the wrong sign) compiled apart, put first on a class path.
        Path probe = Files.createDirectories(dir.resolve("probe-src")).resolve("CaseProbe.java");
        Files.writeString(probe, PROBE);
        List<Path> cp = new ArrayList<>(List.of(classes));
        cp.addAll(JavaBuild.ownClassPath());
        JavaBuild.Result pr = JavaBuild.compile(List.of(probe, Path.of("grader/tests/raylab/cases/CaseCheck.java").toAbsolutePath()), cp, classes);
        assertTrue(pr.success(), () -> "the probe compiles: " + pr.errors());
        Path planeSrc = ext.resolve("src/main/java/raylab/surface/Plane.java");
        String reference = Files.readString(planeSrc);
        assertTrue(reference.contains("point.minus(ray.p)"));
        Path buggySrc = Files.createDirectories(dir.resolve("buggy-src/raylab/surface")).resolve("Plane.java");
        Files.writeString(buggySrc, reference.replace("point.minus(ray.p)", "ray.p.minus(point)"));
        assertTrue(JavaBuild.compile(List.of(buggySrc), cp, dir.resolve("buggy")).success(), "the buggy plane compiles");
    }

    record Ran(int status, String out, String err) {
    }

    private static Ran raylab(boolean withExtension, String... args) throws IOException, InterruptedException {
        return java(withExtension ? classes + File.pathSeparator : "", "raylab.cli.Main", args);
    }

    private static Ran java(String before, String main, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-cp", before + System.getProperty("java.class.path"), main));
        cmd.addAll(List.of(args));
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        Process p = new ProcessBuilder(cmd).directory(root.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile()).start();
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "raylab " + String.join(" ", args) + " ended");
        return new Ran(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8), Files.readString(err, StandardCharsets.UTF_8));
    }

    @Test
    void renderDrawsThePlaneAndItsKeysAreChecked() throws Exception {
        Ran r = raylab(true, "render", "scenes/plane.json", "-o", dir.resolve("plane.png").toString(), "--quiet");
        assertEquals(0, r.status(), r.out() + r.err());
        BufferedImage img = ImageIO.read(dir.resolve("plane.png").toFile());
        assertEquals(0xff0000, img.getRGB(16, 23) & 0xffffff, "the floor plane (flat red) at the bottom centre");
        assertEquals(0x0000ff, img.getRGB(16, 0) & 0xffffff, "the background (blue) at the top centre");

        Files.writeString(dir.resolve("bad.json"), SCENE.replace("\"normal\": [0, 1, 0]", "\"normal\": [0, 0, 0]"));
        r = raylab(true, "render", dir.resolve("bad.json").toString(), "-o", dir.resolve("bad.png").toString());
        assertEquals(2, r.status(), r.out() + r.err());
        assertTrue(r.err().contains("bad.json:7:") && r.err().contains("a plane's normal must not be [0, 0, 0]"), r.err());
        Files.writeString(dir.resolve("typo.json"), SCENE.replace("\"point\": [0, -1, 0]", "\"pont\": [0, -1, 0]"));
        r = raylab(true, "render", dir.resolve("typo.json").toString(), "-o", dir.resolve("typo.png").toString());
        assertEquals(2, r.status(), r.out() + r.err());
        assertTrue(r.err().contains("unknown key \"pont\" in a plane (did you mean \"point\"?)"), r.err());
    }

    @Test
    void aVariantMovesThePlane() throws Exception {
        Ran r = raylab(true, "variant", "scenes/plane.json", "--seed", "7", "--root", root.toString());
        assertEquals(0, r.status(), r.out() + r.err());
        JsonNode v = new ObjectMapper().readTree(r.out().substring(r.out().indexOf('{')));
        JsonNode floor = v.get("surfaces").get(0);
        assertEquals("plane", floor.get("type").asText());
        double y = floor.get("point").get(1).asDouble();
        assertTrue(y != -1 && Math.abs(y + 1) <= 0.2, "expected the floor moved within ±0.2 in y, got y = " + y + ": " + r.out());
        assertEquals(0, floor.get("point").get(0).asDouble(), 0, "no move in x (bound 0)");
    }

    @Test
    void withoutItsRegistrationThePlaneIsUnknown() throws Exception {
        Ran r = raylab(false, "render", "scenes/plane.json", "-o", dir.resolve("none.png").toString());
        assertEquals(2, r.status(), r.out() + r.err());
        assertTrue(r.err().contains("unknown surface type \"plane\""), r.err());
        assertNotEquals(true, Files.exists(dir.resolve("none.png")), "no image written");
    }

    @Test
    void dataCasesOfThePlaneRunAndCatchABuggyPlane() throws Exception {
        Ran r = java(classes + File.pathSeparator, "CaseProbe", root.toString());
        assertEquals(0, r.status(), r.out() + r.err());
        assertEquals(List.of("passed: a ray straight down hits the floor at t = 4", "passed: a ray parallel to the floor misses"),
                r.out().lines().toList(), r.err());
        r = java(dir.resolve("buggy") + File.pathSeparator + classes + File.pathSeparator, "CaseProbe", root.toString());
        assertEquals(0, r.status(), r.out() + r.err());
        List<String> lines = r.out().lines().toList();
        assertEquals(2, lines.size(), r.out() + r.err());
        assertTrue(lines.get(0).startsWith("failed: a ray straight down hits the floor at t = 4: "), lines.get(0));
        assertEquals("passed: a ray parallel to the floor misses", lines.get(1));

        Path cases = root.resolve("assignments/07-plane/cases/plane.json");
        String cases0 = Files.readString(cases);
        String noNormal = cases0.replace(", \"normal\": [0, 1, 0]},\n   \"ray\": {\"p\": [0, 0, 0]",
                "},\n   \"ray\": {\"p\": [0, 0, 0]");
        assertNotEquals(cases0, noNormal, "the second case lost its normal");
        Files.writeString(cases, noNormal);
        try {
            r = java(classes + File.pathSeparator, "CaseProbe", root.toString());
        } finally {
            Files.writeString(cases, cases0);
        }
        assertTrue(r.out().startsWith("refused: ") && r.out().contains("case 'a ray parallel to the floor misses': \"surface\": missing required key \"normal\" in a plane"),
                r.out() + r.err());
    }

    @Test
    void traceSaysWhatThePlaneTypeKnowsAboutAMiss() throws Exception {
        // An orthographic view along -z: every eye ray is parallel to the wall x = 5.
        Files.writeString(dir.resolve("wall.json"), """
                {
                  "image": {"width": 8, "height": 8},
                  "camera": {"type": "orthographic", "eye": [0, 0, 5], "viewDirection": [0, 0, -1], "up": [0, 1, 0],
                             "viewHeight": 4},
                  "materials": {"n": {"type": "normals"}},
                  "surfaces": [{"type": "plane", "name": "wall", "point": [5, 0, 0], "normal": [1, 0, 0], "material": "n"}]
                }
                """);
        Ran r = raylab(true, "trace", dir.resolve("wall.json").toString(), "--pixel", "4", "4");
        assertEquals(0, r.status(), r.out() + r.err());
        assertTrue(r.out().contains("\"wall\": ") && r.out().contains("; the ray is parallel to the plane (n·d = 0)"),
                r.out());
    }
}
