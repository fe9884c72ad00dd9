package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.course.SolutionRegions;

/**
 * Batched renders ({@link Speculation}) give the pixels of a render one call at a time, bit for
 * bit, whatever the student's code does: the reference, and Sphere.intersect variants whose
 * answers differ from the reference's (so predictions fail and pixels are traced again), one of
 * them throwing at some pixels (the same first pixel and message must be reported).
 */
class BatchedRenderTest {
    private static Path dir;
    private static Path standIns;
    private static Path references;
    private static String reference;

    /** The student's Sphere.intersect, as a change of the reference source. */
    private static String variant(String name) {
        return switch (name) {
            case "reference" -> reference;
            // Ignores the closest hit so far: a later sphere overrides a nearer one.
            case "ignoresClosest" -> reference.replace("|| t >= outRecord.t", "");
            // The lecture's plain quadratic formula: the same hits, t differing in the last bits.
            case "plainQuadratic" -> reference.replace("double t0 = q == 0 ? 0 : c / q;",
                    "double t0 = (b - Math.sqrt(b * b - a * c)) / a;");
            // Throws for rays going right of some line (the render must name the first such pixel).
            case "throwsOnTheRight" -> reference.replace("double a = ray.d.dot(ray.d);",
                    "double a = ray.d.dot(ray.d);\n        if (ray.d.x > 0.21 * Math.sqrt(a)) {"
                            + " throw new IllegalStateException(\"right of the line\"); }");
            default -> throw new IllegalArgumentException(name);
        };
    }

    @BeforeAll
    static void standIns(@org.junit.jupiter.api.io.TempDir Path tmp) throws Exception {
        dir = tmp;
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        reference = Files.readString(root.resolve("src/main/java/raylab/surface/Sphere.java"));
        String starter = SolutionRegions.toStudent("Sphere.java", reference, Set.of());
        standIns = dir.resolve("standins");
        StandIns.compile(Map.of("raylab/surface/Sphere.java",
                StandIns.forwarding(starter, "raylab.surface.Sphere", Set.of("intersect"))),
                StudentProcessTest.classDirs(), standIns);
        // The predictor: the reference Sphere class alone.
        references = dir.resolve("ref");
        Path cls = Path.of(raylab.surface.Sphere.class.getProtectionDomain().getCodeSource().getLocation().toURI())
                .resolve("raylab/surface/Sphere.class");
        Files.createDirectories(references.resolve("raylab/surface"));
        Files.copy(cls, references.resolve("raylab/surface/Sphere.class"));
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"reference", "ignoresClosest", "plainQuadratic", "throwsOnTheRight"})
    void batchedPixelsAreThePixelsOfOneCallAtATime(String student) throws Exception {
        Path studentClasses = dir.resolve("student-" + student);
        StandIns.compile(Map.of("raylab/surface/Sphere.java", variant(student)), StudentProcessTest.classDirs(),
                studentClasses);
        Render batched = render(student, studentClasses, true);
        Render single = render(student, studentClasses, false);
        assertEquals(single.error(), batched.error(), "the error line of the render");
        if (student.equals("throwsOnTheRight")) {
            assertTrue(single.error().contains("while tracing pixel ("), () -> "names the pixel: " + single.error());
            assertTrue(single.error().contains("right of the line"), () -> "the student's message: " + single.error());
        } else {
            assertEquals("", single.error(), "no error");
            assertArrayEquals(single.raw(), batched.raw(),
                    "every channel of every pixel, bit for bit, batched and one call at a time");
        }
    }

    /**
     * The first round of each band traces with predictions only, so the batched render also gives
     * the reference solution's image, whatever the student answers (the grader compares with it).
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"reference", "ignoresClosest", "plainQuadratic"})
    void theFirstRoundsGiveTheReferenceImageWhateverTheStudentAnswers(String student) throws Exception {
        Path studentClasses = dir.resolve("student-" + student);
        StandIns.compile(Map.of("raylab/surface/Sphere.java", variant(student)), StudentProcessTest.classDirs(),
                studentClasses);
        Render batched = render(student, studentClasses, true);
        Path referenceClasses = dir.resolve("student-reference");
        StandIns.compile(Map.of("raylab/surface/Sphere.java", variant("reference")), StudentProcessTest.classDirs(),
                referenceClasses);
        Render single = render("reference", referenceClasses, false);
        assertEquals("", batched.error(), "no error");
        assertTrue(batched.reference() != null, "the batched render of " + student + " leaves the reference image");
        int[] want = pixels(single.png());
        int[] got = pixels(batched.reference());
        assertEquals(want.length, got.length, "pixels");
        for (int i = 0; i < want.length; i++) {
            final int k = i;
            assertEquals(want[i], got[i], () -> "pixel " + k + ": the reference's colour, rendered one call at a time"
                    + " (expected) and from the first rounds of " + student + "'s batched render (actual)");
        }
    }

    private static int[] pixels(byte[] png) throws java.io.IOException {
        java.awt.image.BufferedImage im = javax.imageio.ImageIO.read(new java.io.ByteArrayInputStream(png));
        return im.getRGB(0, 0, im.getWidth(), im.getHeight(), null, 0, im.getWidth());
    }

    private record Render(byte[] raw, String error, byte[] png, byte[] reference) {
    }

    private static Render render(String student, Path studentClasses, boolean batched) throws Exception {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        Path out = dir.resolve(student + (batched ? "-batched" : "-single"));
        Files.createDirectories(out);
        List<Path> studentPath = new ArrayList<>();
        studentPath.add(studentClasses);
        studentPath.addAll(StudentProcessTest.classDirs());
        Path config = out.resolve("student.properties");
        Remote.writeConfig(config, new StudentProcess.Config(StudentProcess.javaCommand(studentPath, 128,
                List.of("raylab.surface.Sphere")), null, Set.of("raylab.surface.Sphere"), 60_000, 1));
        List<String> cp = new ArrayList<>();
        cp.add(standIns.toString());
        cp.add(System.getProperty("java.class.path"));
        Path png = out.resolve("render.png");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Draylab.boundary=" + config, "-Draylab.boundary.raw=true", "-Djava.awt.headless=true"));
        if (batched) {
            cmd.add("-Draylab.boundary.references=" + references);
        }
        // scenes/spheres.json at a quarter of its size: one call at a time is slow.
        Path scene = out.resolve("spheres.json");
        String json = Files.readString(root.resolve("scenes/spheres.json"));
        assertTrue(json.contains("\"width\": 400, \"height\": 300"), "the scene's size as expected");
        Files.writeString(scene, json.replace("\"width\": 400, \"height\": 300", "\"width\": 100, \"height\": 75"));
        cmd.addAll(List.of("-cp", String.join(File.pathSeparator, cp), "raylab.boundary.TrustedRender",
                scene.toString(), png.toString(), "scenes/spheres.json"));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(out.resolve("log.txt").toFile())
                .start();
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "the render finished");
        Path err = Path.of(png + ".err");
        Path raw = Path.of(png + ".raw");
        Path ref = Path.of(png + ".reference.png");
        return new Render(Files.isRegularFile(raw) ? Files.readAllBytes(raw) : null,
                Files.isRegularFile(err) ? Files.readString(err, StandardCharsets.UTF_8) : "",
                Files.isRegularFile(png) ? Files.readAllBytes(png) : null,
                Files.isRegularFile(ref) ? Files.readAllBytes(ref) : null);
    }
}
