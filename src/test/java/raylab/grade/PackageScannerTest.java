package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.LongStream;
import java.util.stream.Stream;

import javax.tools.JavaCompiler;
import javax.tools.SimpleJavaFileObject;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import com.sun.source.tree.CompilationUnitTree;
import com.sun.source.util.JavacTask;

import raylab.course.Assignments;
import raylab.course.PackageScanner;
import raylab.course.Submission;

/**
 * The package line of a student file is found by a linear scan: huge comments, thousands of
 * comment or blank lines, Unicode escapes and files at the size limit are read in linear time
 * and agree with javac's own parser (the compiler tree API) on seeded random prefixes.
 */
class PackageScannerTest {
    private static final String BODY = "\nimport raylab.math.Vec3;\npublic final class Sphere {}\n";

    @TempDir
    Path dir;

    /** javac's answer: the package name of the parsed compilation unit. */
    static String javac(String source) throws IOException {
        JavaCompiler c = ToolProvider.getSystemJavaCompiler();
        SimpleJavaFileObject file = new SimpleJavaFileObject(URI.create("string:///Sphere.java"),
                javax.tools.JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignore) {
                return source;
            }
        };
        JavacTask task = (JavacTask) c.getTask(new java.io.StringWriter(), null, d -> { }, List.of("-proc:none"), null,
                List.of(file));
        for (CompilationUnitTree u : task.parse()) {
            return u.getPackageName() == null ? "" : u.getPackageName().toString();
        }
        return "";
    }

    @Test
    void aHundredKilobyteCommentBeforeThePackageLine() throws IOException {
        String src = "/*" + "x".repeat(100 * 1024) + "*/\npackage raylab.surface;" + BODY;
        assertEquals("raylab.surface", PackageScanner.packageOf(src));
        assertEquals("raylab.surface", javac(src));
        assertAccepted(src);
    }

    @Test
    void twoThousandLineCommentsAndThreeThousandBlankLines() throws IOException {
        String lines = "// a comment line\n".repeat(2000);
        String blanks = "\n".repeat(3000);
        for (String src : List.of(lines + "package raylab.surface;" + BODY, blanks + "package raylab.surface;" + BODY,
                "\r\n".repeat(3000) + "// x\r\n".repeat(2000) + "package raylab.surface;" + BODY)) {
            assertEquals("raylab.surface", PackageScanner.packageOf(src));
            assertEquals(javac(src), PackageScanner.packageOf(src));
            assertAccepted(src);
        }
    }

    @Test
    void unicodeEscapesAreTranslatedAsTheCompilerDoes() throws IOException {
        String[] sources = {
            "\\u0070ackage raylab\\u002esurface;" + BODY,
            "\\uuu002f\\u002f comment\\u000apackage raylab.surface;" + BODY,
            "// not a line end: \\\\u000a package wrong;\npackage raylab.surface;" + BODY,
            "\\u002f* hidden */ package raylab.surface;" + BODY,
        };
        for (String src : sources) {
            assertEquals(javac(src), PackageScanner.packageOf(src), src);
            assertEquals("raylab.surface", PackageScanner.packageOf(src), src);
        }
        // An escaped star-slash ends the comment, as in javac.
        String closed = "/* \\u002a/ package first; */ package raylab.surface;" + BODY;
        assertEquals("first", PackageScanner.packageOf(closed));
        assertEquals(javac(closed), PackageScanner.packageOf(closed));
        assertEquals("", PackageScanner.packageOf("packagex raylab.surface;"));
        assertEquals("", PackageScanner.packageOf("/* never closed package raylab.surface;"));
        assertEquals("raylab.surface", PackageScanner.packageOf("package /* c */ raylab . // x\n surface ;"));
    }

    static LongStream seeds() {
        return LongStream.range(0, 60).map(i -> 0x9E3779B97F4A7C15L * (i + 1));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void randomPrefixesAgreeWithJavac(long seed) throws IOException {
        SplittableRandom r = new SplittableRandom(seed);
        StringBuilder b = new StringBuilder();
        String[] pieces = {" ", "\t", "\n", "\r\n", "// c\n", "/* c */", "/** doc\n * more */", "/* // */", "// /* \n",
            "\\u0020", "\\u000a", "/*** */", "/* \\u002a/ */", "\f"};
        int n = r.nextInt(40);
        for (int i = 0; i < n; i++) {
            b.append(pieces[r.nextInt(pieces.length)]);
        }
        String pkg = r.nextBoolean() ? "raylab.surface" : "raylab . material";
        String src = b + "package " + pkg + ";" + BODY;
        assertEquals(javac(src), PackageScanner.packageOf(src), () -> "seed " + seed + ": " + src);
    }

    @Test
    void aFileAtTheSizeLimitIsReadAndOneByteMoreIsRefused() throws IOException {
        String head = "package raylab.surface;" + BODY;
        String comment = "/*" + "y".repeat((int) Submission.MAX_FILE - head.length() - 5) + "*/\n";
        String atLimit = comment + head;
        assertEquals(Submission.MAX_FILE, atLimit.getBytes(StandardCharsets.UTF_8).length);
        assertAccepted(atLimit);
        Path sub = Files.createDirectories(dir.resolve("big"));
        Files.writeString(sub.resolve("Sphere.java"), atLimit + " ");
        Submission s = Submission.read(sub, Assignments.load(root()).all());
        assertTrue(s.files().isEmpty(), "over the limit: refused");
        assertTrue(s.ignored().stream().anyMatch(x -> x.contains("larger than")), s.ignored().toString());
    }

    static Path root() {
        return Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
    }

    private void assertAccepted(String src) throws IOException {
        Path sub = Files.createDirectories(dir.resolve("s" + System.nanoTime()));
        Files.writeString(sub.resolve("Sphere.java"), src);
        Submission s = Submission.read(sub, Assignments.load(root()).all());
        assertEquals(src, s.files().get("src/main/java/raylab/surface/Sphere.java"), () -> s.ignored().toString());
        try (Stream<Path> x = Files.list(sub)) {
            assertEquals(1, x.count());
        }
    }
}
