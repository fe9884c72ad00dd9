package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.FileTrees;
import raylab.course.JavaBuild;

/**
 * The launcher's quick build: a changed student file is compiled alone into target/incremental;
 * a changed framework file asks for the full build; a compile error reaches the terminal as
 * file:line:col: message, the source line and a caret.
 */
class IncrementalTest {
    static final String SPHERE = "src/main/java/raylab/surface/Sphere.java";
    static final String VEC3 = "src/main/java/raylab/math/Vec3.java";

    /** A project folder with the real assignments, Sphere.java and Vec3.java, built at t = 1000 s. */
    static Path project(Path dir) throws IOException {
        FileTrees.copy(Path.of("assignments"), dir.resolve("assignments"));
        for (String f : List.of(SPHERE, VEC3)) {
            Files.createDirectories(dir.resolve(f).getParent());
            Files.copy(Path.of(f), dir.resolve(f));
            Files.setLastModifiedTime(dir.resolve(f), FileTime.fromMillis(500_000));
        }
        Files.createDirectories(dir.resolve("target"));
        Files.writeString(dir.resolve("target/raylab.jar"), "");
        Files.setLastModifiedTime(dir.resolve("target/raylab.jar"), FileTime.fromMillis(1_000_000));
        return dir;
    }

    @Test
    void aChangedStudentFileIsCompiledAloneAndOnlyOnce(@TempDir Path dir) throws IOException {
        Path root = project(dir);
        Incremental inc = Incremental.of(root);
        assertTrue(inc.plan().upToDate(), "nothing changed since the build: " + inc.plan());
        Files.setLastModifiedTime(root.resolve(SPHERE), FileTime.fromMillis(2_000_000));
        assertEquals(List.of(root.resolve(SPHERE)), inc.plan().compile(), "to compile");
        assertEquals(List.of(), inc.plan().needFullBuild(), "full build needed for");
        JavaBuild.Result r = inc.update(JavaBuild.ownClassPath());
        assertTrue(r.success(), "compile errors: " + r.errors());
        assertTrue(Files.isRegularFile(root.resolve("target/incremental/raylab/surface/Sphere.class")));
        assertTrue(inc.plan().upToDate(), "compiled once, then up to date: " + inc.plan());
        // Put back at an older time (cp -p, an editor's undo): compiled again.
        Files.setLastModifiedTime(root.resolve(SPHERE), FileTime.fromMillis(1_500_000));
        assertEquals(List.of(root.resolve(SPHERE)), inc.plan().compile(), "to compile after a change of time");
    }

    @Test
    void aChangedFrameworkFileAsksForTheFullBuild(@TempDir Path dir) throws IOException {
        Path root = project(dir);
        Files.setLastModifiedTime(root.resolve(VEC3), FileTime.fromMillis(2_000_000));
        Incremental inc = Incremental.of(root);
        assertEquals(List.of(root.resolve(VEC3)), inc.plan().needFullBuild(), "full build needed for");
        assertNull(inc.update(JavaBuild.ownClassPath()), "update must refuse and ask for the full build");
        assertEquals(Incremental.FULL_BUILD, Launch.prepare(root), "Launch's exit status");
    }

    @Test
    void aCompileErrorIsShownWithFileLineColumnSourceAndCaret(@TempDir Path dir) throws IOException {
        Path root = project(dir);
        Path sphere = root.resolve(SPHERE);
        List<String> lines = Files.readAllLines(sphere, StandardCharsets.UTF_8);
        int k = lines.indexOf(lines.stream().filter(l -> l.contains("double a = ray.d.dot(ray.d);")).findFirst()
                .orElseThrow());
        lines.set(k, lines.get(k).replace("ray.d.dot(ray.d)", "ray.d.dott(ray.d)"));
        lines.add(k + 1, "        int unused = \"text\";");
        Files.write(sphere, lines, StandardCharsets.UTF_8);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream saved = System.err;
        int status;
        try {
            System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
            status = Launch.prepare(root);
        } finally {
            System.setErr(saved);
        }
        String text = err.toString(StandardCharsets.UTF_8);
        assertEquals(1, status, "exit status; stderr:\n" + text);
        String[] out = text.split("\n");
        assertEquals(SPHERE + ":" + (k + 1) + ":" + (lines.get(k).indexOf(".dott") + 1) + ": error: cannot find symbol",
                out[0], "first line; stderr:\n" + text);
        int src = firstIndex(out, lines.get(k));
        assertEquals(1, src, "the source line follows the first line; stderr:\n" + text);
        assertEquals(" ".repeat(lines.get(k).indexOf(".dott")) + "^", out[src + 1], "the caret; stderr:\n" + text);
        assertTrue(text.contains(SPHERE + ":" + (k + 2) + ":"), "the second error's place; stderr:\n" + text);
        assertTrue(out[out.length - 1].startsWith("raylab: your code does not compile (2 errors)"),
                "last line; stderr:\n" + text);
        assertFalse(Files.exists(root.resolve("target/incremental/raylab/surface/Sphere.class")),
                "no class file from a failed compile");
    }

    /**
     * A byte order mark at the file's start (some Windows editors write one) fails javac with
     * "illegal character: '\\ufeff'": the message says what that is and what to do, here as in
     * the grader's report, which read the same {@link JavaBuild.Problem}.
     */
    @Test
    void aByteOrderMarkIsNamed(@TempDir Path dir) throws IOException {
        Path root = project(dir);
        Path sphere = root.resolve(SPHERE);
        Files.writeString(sphere, "\ufeff" + Files.readString(sphere, StandardCharsets.UTF_8), StandardCharsets.UTF_8);
        Files.setLastModifiedTime(sphere, FileTime.fromMillis(2_000_000));
        JavaBuild.Result r = Incremental.of(root).update(JavaBuild.ownClassPath());
        assertFalse(r.success(), "javac does not accept a byte order mark");
        assertEquals("illegal character: '\\ufeff' (the file starts with a byte order mark, which javac does not accept:"
                + " save it as UTF-8 without BOM)", r.errors().get(0).message(), r.errors().toString());
    }

    @Test
    void moreErrorsThanShownAreCounted() {
        List<JavaBuild.Problem> errors = List.of(new JavaBuild.Problem(null, 1, 1, "a"),
                new JavaBuild.Problem(null, 2, 1, "b"), new JavaBuild.Problem(null, 3, 1, "c"),
                new JavaBuild.Problem(null, 4, 1, "d"), new JavaBuild.Problem(null, 5, 1, "e"));
        List<String> lines = CompileErrors.format(errors, Path.of(""), 3);
        assertEquals(List.of("error: a", "error: b", "error: c",
                "... and 2 more errors (fix the first one first: one mistake often causes several)"), lines);
    }

    private static int firstIndex(String[] lines, String wanted) {
        for (int i = 0; i < lines.length; i++) {
            if (lines[i].equals(wanted)) {
                return i;
            }
        }
        return -1;
    }
}
