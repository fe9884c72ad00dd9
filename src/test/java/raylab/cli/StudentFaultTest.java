package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.JavaBuild;

/**
 * An exception thrown by the student's code is reported as the student's, with the pixel and
 * the scene and the student-file frames only; "internal error" is kept for the framework.
 */
class StudentFaultTest {
    static final String SPHERE = "src/main/java/raylab/surface/Sphere.java";
    @TempDir
    static Path dir;
    static Path classes;
    static int line;

    /** Sphere.java that throws a NullPointerException for every ray going down (d.y < 0). */
    @BeforeAll
    static void compileFaultySphere() throws IOException {
        List<String> lines = new ArrayList<>(Files.readAllLines(Path.of(SPHERE), StandardCharsets.UTF_8));
        int k = lines.indexOf("    public boolean intersect(IntersectionRecord outRecord, Ray ray) {");
        assertTrue(k > 0, "intersect's first line not found in " + SPHERE);
        lines.add(k + 1, "        if (ray.d.y < 0) { Object nothing = null; nothing.hashCode(); }");
        line = k + 2;
        Path src = dir.resolve("src/raylab/surface/Sphere.java");
        Files.createDirectories(src.getParent());
        Files.write(src, lines, StandardCharsets.UTF_8);
        classes = dir.resolve("classes");
        JavaBuild.Result r = JavaBuild.compile(List.of(src), JavaBuild.ownClassPath(), classes);
        assertTrue(r.success(), "the faulty sphere must compile: " + r.errors());
    }

    static String[] run(String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-cp", classes + File.pathSeparator + System.getProperty("java.class.path"), "raylab.cli.Main"));
        cmd.addAll(List.of(args));
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile());
        pb.environment().remove("RAYLAB_DEBUG");
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "raylab did not finish");
        return new String[] {Integer.toString(p.exitValue()), Files.readString(out), Files.readString(err)};
    }

    @Test
    void renderNamesTheStudentsExceptionPixelAndScene() throws Exception {
        String[] r = run("render", "scenes/sphere.json", "-o", dir.resolve("x.png").toString(), "--quiet");
        String err = r[2].strip();
        assertEquals("1", r[0], "exit status; stderr: " + err);
        String expected = "raylab: your code threw NullPointerException in Sphere.intersect (Sphere.java:" + line
                + ") while tracing pixel (0, 120) of scenes/sphere.json: ";
        assertTrue(err.startsWith(expected), "expected the line to start with\n" + expected + "\nactual:\n" + err);
        assertTrue(err.endsWith("; ./raylab trace scenes/sphere.json --pixel 0 120 shows that ray"), "actual: " + err);
        assertFalse(err.contains("internal error"), "not the framework's fault: " + err);
        assertFalse(err.contains("Group") || err.contains("Bvh") || err.contains("Renderer"),
                "student-file frames only: " + err);
        assertEquals(1, err.lines().count(), "one line: " + err);
        assertFalse(Files.exists(dir.resolve("x.png")), "no image written");
    }

    @Test
    void traceNamesTheStudentsExceptionAndPixel() throws Exception {
        String[] r = run("trace", "scenes/sphere.json", "--pixel", "160", "200");
        String err = r[2].strip();
        assertEquals("1", r[0], "exit status; stderr: " + err);
        String expected = "raylab: your code threw NullPointerException in Sphere.intersect (Sphere.java:" + line
                + ") while tracing pixel (160, 200) of scenes/sphere.json";
        assertTrue(err.startsWith(expected), "expected the line to start with\n" + expected + "\nactual:\n" + err);
    }

    @Test
    void aFrameworkFaultIsAnInternalError() {
        RuntimeException e = new IllegalStateException("broken");
        e.setStackTrace(new StackTraceElement[] {new StackTraceElement("raylab.render.Renderer", "trace",
                "Renderer.java", 10)});
        assertFalse(StudentFault.describe(e, StudentFault.DEFAULT_FILES, "").isPresent(),
                "a fault with no student frame is not the student's");
        e.setStackTrace(new StackTraceElement[] {new StackTraceElement("raylab.surface.Box", "intersect", "Box.java", 50),
            new StackTraceElement("raylab.surface.Group", "intersect", "Group.java", 30),
            new StackTraceElement("raylab.surface.Box", "slab", "Box.java", 70)});
        assertEquals("your code threw IllegalStateException in Box.intersect (Box.java:50) while testing: broken"
                + " [called from Box.slab (Box.java:70)]",
                StudentFault.describe(e, StudentFault.DEFAULT_FILES, "while testing").orElseThrow());
        assertFalse(StudentFault.isStudents(new raylab.course.NotImplemented("sphere", "Sphere.intersect"),
                StudentFault.DEFAULT_FILES), "a stub's NotImplemented is not an exception of the student's");
    }
}
