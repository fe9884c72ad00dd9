package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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

import raylab.course.JavaBuild;
import raylab.course.SolutionRegions;

/**
 * Batched renders ({@link Speculation}) give the pixels of a render one call at a time, bit for
 * bit, whatever the student's code does: the reference, and Sphere.intersect variants whose
 * answers differ from the reference's (so predictions fail and pixels are traced again), one of
 * them throwing at some pixels (the same first pixel and message must be reported). The same for
 * Shadows.isShadowed, whose questions to the scene come back with their calls and are answered in
 * the next frame ({@link StudentProcess#multi}): shadow rays the lecture's way, code that catches
 * everything around the question, asks two or twenty questions one after the other, or throws.
 * Each render (deterministic) and each compile is made once per class run and shared by the tests
 * that compare with it: the reference one call at a time, and the sphere variants' batched renders.
 */
class BatchedRenderTest {
    private static Path dir;
    private static Path standIns;
    private static Path references;
    private static String reference;
    private static Path shadowStandIns;
    private static Path shadowReferences;
    private static String shadowReference;

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
            // Misses whenever the record's test count (a group's, one more per surface it tries)
            // leaves 1 modulo 3: the count must reach the student's code as a call at a time gives it.
            case "readsTheTestCount" -> reference.replace("double a = ray.d.dot(ray.d);",
                    "if (outRecord.tests % 3 == 1) { return false; }\n        double a = ray.d.dot(ray.d);");
            default -> throw new IllegalArgumentException(name);
        };
    }

    /** Shadows.isShadowed's body in place of the reference's solution region. */
    private static String shadowVariant(String name) {
        String body = switch (name) {
            case "reference" -> null;
            // The lecture's way: a fixed offset along the normal, blockers before the light.
            case "lecture" -> "Vec3 origin = x.plus(n.times(1e-4));\n"
                    + "return scene.intersectsAny(new Ray(origin, light.position.minus(origin), 0, 1), scratch);";
            // Catches everything around the question (also what the grader throws through it).
            case "catchesEverything" -> "Vec3 origin = x.plus(n.times(1e-4));\n"
                    + "try { return scene.intersectsAny(new Ray(origin, light.position.minus(origin), 0, 1), scratch); }\n"
                    + "catch (Throwable t) { return false; }";
            // Two questions one after the other, the second depending on the first's answer.
            case "asksTwice" -> "Vec3 origin = x.plus(n.times(1e-4));\n"
                    + "Ray r = new Ray(origin, light.position.minus(origin), 0, 0.5);\n"
                    + "if (scene.intersectsAny(r, scratch)) { return true; }\n"
                    + "return scene.intersectsAny(new Ray(r.evaluate(0.5), light.position.minus(r.evaluate(0.5)),"
                    + " 0, 1), scratch);";
            // Twenty questions in a row, more than one frame carries back: the last go one at a time.
            case "asksTwenty" -> "Vec3 origin = x.plus(n.times(1e-4));\n"
                    + "Vec3 d = light.position.minus(origin);\n"
                    + "for (int i = 0; i < 20; i++) {\n"
                    + "  if (scene.intersectsAny(new Ray(origin.plus(d.times(i / 20.0)), d, 0, 1.0 / 20), scratch)) {"
                    + " return true; }\n}\nreturn false;";
            // Throws for points right of some line (the render must name the first such pixel).
            case "throwsOnTheRight" -> "if (x.x > 0.7) { throw new IllegalStateException(\"right of the line\"); }\n"
                    + "Vec3 origin = x.plus(n.times(1e-4));\n"
                    + "return scene.intersectsAny(new Ray(origin, light.position.minus(origin), 0, 1), scratch);";
            default -> throw new IllegalArgumentException(name);
        };
        if (body == null) {
            return shadowReference;
        }
        int from = shadowReference.indexOf("// BEGIN SOLUTION shadows");
        int to = shadowReference.indexOf("// END SOLUTION", from);
        assertTrue(from > 0 && to > from, "the reference Shadows.java has its solution region");
        return shadowReference.substring(0, from) + body + "\n" + shadowReference.substring(to + "// END SOLUTION".length());
    }

    @BeforeAll
    static void standIns(@org.junit.jupiter.api.io.TempDir Path tmp) throws Exception {
        dir = tmp;
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        reference = Files.readString(root.resolve("src/main/java/raylab/surface/Sphere.java"));
        standIns = dir.resolve("standins");
        references = dir.resolve("ref");
        prepare(reference, "Sphere.java", "raylab/surface/Sphere", "intersect", raylab.surface.Sphere.class,
                standIns, references);
        shadowReference = Files.readString(root.resolve("src/main/java/raylab/shading/Shadows.java"));
        shadowStandIns = dir.resolve("shadow-standins");
        shadowReferences = dir.resolve("shadow-ref");
        prepare(shadowReference, "Shadows.java", "raylab/shading/Shadows", "isShadowed",
                raylab.shading.Shadows.class, shadowStandIns, shadowReferences);
    }

    /** Compiles the stand-in of a student class and copies its reference class alone (the predictor). */
    private static void prepare(String source, String file, String path, String method, Class<?> ref, Path standInDir,
            Path referenceDir) throws Exception {
        String starter = SolutionRegions.toStudent(file, source, Set.of());
        StandIns.compile(Map.of(path + ".java", StandIns.forwarding(starter, path.replace('/', '.'), Set.of(method))),
                StudentProcessTest.classDirs(), standInDir);
        Path cls = Path.of(ref.getProtectionDomain().getCodeSource().getLocation().toURI()).resolve(path + ".class");
        Files.createDirectories(referenceDir.resolve(path).getParent());
        Files.copy(cls, referenceDir.resolve(path + ".class"));
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"reference", "lecture", "catchesEverything", "asksTwice", "asksTwenty", "throwsOnTheRight"})
    void shadowQuestionsAnsweredLaterGiveThePixelsOfOneCallAtATime(String student) throws Exception {
        Path studentClasses = dir.resolve("shadows-" + student);
        compile(Map.of("raylab/shading/Shadows.java", shadowVariant(student)), studentClasses);
        Milestone m = new Milestone("raylab.shading.Shadows", shadowStandIns, shadowReferences, "scenes/shadows.json");
        Render batched = render(m, "shadows-" + student, studentClasses, true);
        Render single = render(m, "shadows-" + student, studentClasses, false);
        assertSameAsOneCallAtATime(student, batched, single);
        if (!student.equals("throwsOnTheRight")) {
            // The sky's pixels call no stand-in: the reference image's trace gives them, unsent.
            java.util.regex.Matcher only = java.util.regex.Pattern.compile("framework-only pixels (\\d+)")
                    .matcher(batched.log());
            assertTrue(only.find() && Long.parseLong(only.group(1)) > 0, () -> "pixels no stand-in was called for: "
                    + batched.log());
            assertTrue(batched.log().contains("questions sent back"), () -> "the batched render's counts: "
                    + batched.log());
            assertTrue(!batched.log().contains("questions sent back 0,"), () -> "questions came back with their calls: "
                    + batched.log());
            // Twenty questions one after the other outlast the frames that carry questions back:
            // the rest are asked one at a time. The others ask almost none that way (only in the
            // few pixels a batched render traces one call at a time).
            java.util.regex.Matcher c = java.util.regex.Pattern
                    .compile("live callbacks (\\d+), questions sent back (\\d+)").matcher(batched.log());
            assertTrue(c.find(), () -> "the batched render's counts: " + batched.log());
            long live = Long.parseLong(c.group(1));
            long later = Long.parseLong(c.group(2));
            if (student.equals("asksTwenty")) {
                assertTrue(live > 0, () -> "questions asked one at a time: " + batched.log());
            } else {
                assertTrue(live * 100 < later, () -> "questions asked one at a time, under 1%: " + batched.log());
            }
        }
    }

    /** A milestone's served class, its stand-in and reference classes, and the scene rendered. */
    private record Milestone(String served, Path standIns, Path references, String scene) {
    }

    private static Milestone sphere() {
        return new Milestone("raylab.surface.Sphere", standIns, references, "scenes/spheres.json");
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"reference", "ignoresClosest", "plainQuadratic", "throwsOnTheRight", "readsTheTestCount"})
    void batchedPixelsAreThePixelsOfOneCallAtATime(String student) throws Exception {
        Path studentClasses = dir.resolve("student-" + student);
        compile(Map.of("raylab/surface/Sphere.java", variant(student)), studentClasses);
        Render batched = render(sphere(), student, studentClasses, true);
        Render single = render(sphere(), student, studentClasses, false);
        assertSameAsOneCallAtATime(student, batched, single);
        if (student.equals("readsTheTestCount")) {
            Path referenceClasses = dir.resolve("student-reference");
            compile(Map.of("raylab/surface/Sphere.java", variant("reference")), referenceClasses);
            Render plain = render(sphere(), "reference", referenceClasses, false);
            assertFalse(java.util.Arrays.equals(plain.raw(), single.raw()),
                    "the test count changes the image (else this variant tests nothing)");
        }
    }

    /** The same error line, and without one the same pixels bit for bit; throwsOnTheRight names its pixel. */
    private static void assertSameAsOneCallAtATime(String student, Render batched, Render single) {
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
        compile(Map.of("raylab/surface/Sphere.java", variant(student)), studentClasses);
        Render batched = render(sphere(), student, studentClasses, true);
        Path referenceClasses = dir.resolve("student-reference");
        compile(Map.of("raylab/surface/Sphere.java", variant("reference")), referenceClasses);
        Render single = render(sphere(), "reference", referenceClasses, false);
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

    private record Render(byte[] raw, String error, byte[] png, byte[] reference, String log) {
    }

    /** The student classes compiled so far (each folder compiled once). */
    private static final CompiledOnce COMPILED = new CompiledOnce();
    /** The renders made so far, by what they render (each made once: several tests compare with the same one). */
    private static final Map<List<Object>, Render> RENDERS = new java.util.HashMap<>();

    /** The student's classes from {@code sources} into {@code out}, compiled once per class run. */
    private static void compile(Map<String, String> sources, Path out) throws Exception {
        COMPILED.compile(sources, out);
    }

    /**
     * The render of {@code m} with the student's classes, batched or one call at a time: made once
     * per class run (a render is deterministic; the tests that compare with the same render share it).
     */
    private static synchronized Render render(Milestone m, String student, Path studentClasses, boolean batched)
            throws Exception {
        List<Object> key = List.of(m, student, studentClasses, batched);
        Render r = RENDERS.get(key);
        if (r == null) {
            r = renderNow(m, student, studentClasses, batched);
            RENDERS.put(key, r);
        }
        return r;
    }

    private static Render renderNow(Milestone m, String student, Path studentClasses, boolean batched) throws Exception {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        Path out = dir.resolve(student + (batched ? "-batched" : "-single"));
        Files.createDirectories(out);
        List<Path> studentPath = new ArrayList<>();
        studentPath.add(studentClasses);
        studentPath.addAll(StudentProcessTest.classDirs());
        Path config = out.resolve("student.properties");
        Remote.writeConfig(config, new StudentProcess.Config(StudentJvm.javaCommand(studentPath, 128,
                List.of(m.served())), null, Set.of(m.served()), 60_000, 1));
        List<String> cp = new ArrayList<>();
        cp.add(m.standIns().toString());
        cp.add(System.getProperty("java.class.path"));
        Path png = out.resolve("render.png");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-Draylab.boundary=" + config, "-Draylab.boundary.raw=true", "-Djava.awt.headless=true"));
        if (batched) {
            cmd.add("-Draylab.boundary.references=" + m.references());
        }
        // The scene at a quarter of its size: one call at a time is slow.
        Path scene = out.resolve(Path.of(m.scene()).getFileName());
        String json = Files.readString(root.resolve(m.scene()));
        assertTrue(json.contains("\"width\": 400, \"height\": 300"), "the scene's size as expected");
        Files.writeString(scene, json.replace("\"width\": 400, \"height\": 300", "\"width\": 100, \"height\": 75"));
        cmd.addAll(List.of("-cp", String.join(File.pathSeparator, cp), "raylab.boundary.TrustedRender",
                scene.toString(), png.toString(), m.scene()));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(out.resolve("log.txt").toFile());
        pb.environment().put("RAYLAB_GRADE_TIMES", "1"); // the counts of the batched render
        Process p = pb.start();
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "the render finished");
        Path err = Path.of(png + ".err");
        Path raw = Path.of(png + ".raw");
        Path ref = Path.of(png + ".reference.png");
        return new Render(Files.isRegularFile(raw) ? Files.readAllBytes(raw) : null,
                Files.isRegularFile(err) ? Files.readString(err, StandardCharsets.UTF_8) : "",
                Files.isRegularFile(png) ? Files.readAllBytes(png) : null,
                Files.isRegularFile(ref) ? Files.readAllBytes(ref) : null,
                Files.readString(out.resolve("log.txt"), StandardCharsets.UTF_8));
    }
}
