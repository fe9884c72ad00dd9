package raylab.course;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * The JDK as every raylab tool uses it: javac in this JVM ({@link #javac}, the one place raylab
 * compiles), the {@code java} launcher for child JVMs ({@link #javaExecutable}), and the build
 * and work folders they fill ({@link #deleteTree}); for release checks, {@code check} and grading.
 */
public final class JavaBuild {
    /**
     * A compile error, as every raylab tool reads javac's: the file (null when javac names none),
     * its 1-based line and column (0: unknown), javac's message's first line, and its whole text
     * (the terminal's feedback shows all of it, {@code raylab.cli.CompileErrors}).
     */
    public record Problem(Path file, long line, long column, String message, String text) {
        /** From javac's whole {@code text}: the message is its first line. */
        public Problem(Path file, long line, long column, String text) {
            this(file, line, column, text.split("\n")[0], text);
        }

        /** The errors among javac's diagnostics, in javac's order. */
        public static List<Problem> of(List<Diagnostic<? extends JavaFileObject>> diagnostics) {
            List<Problem> out = new ArrayList<>();
            for (Diagnostic<? extends JavaFileObject> d : diagnostics) {
                if (d.getKind() == Diagnostic.Kind.ERROR) {
                    Path file = d.getSource() == null ? null : Path.of(d.getSource().toUri());
                    out.add(new Problem(file, d.getLineNumber(), d.getColumnNumber(), hint(d.getMessage(Locale.ROOT))));
                }
            }
            return out;
        }

        /** What javac says of a byte order mark, which some Windows editors put at a file's start. */
        static final String BOM = "illegal character: '\\ufeff'";

        /** javac's message, with what to do about it where javac's words do not say. */
        static String hint(String message) {
            return message.startsWith(BOM) ? BOM + " (the file starts with a byte order mark, which javac does not"
                    + " accept: save it as UTF-8 without BOM)" + message.substring(BOM.length()) : message;
        }

        @Override
        public String toString() {
            return (file == null ? "" : file + ":" + line + ": ") + message;
        }
    }

    /** The outcome of a compile: success, or javac's errors (every raylab compile, incremental or not). */
    public record Result(boolean success, List<Problem> errors) {
    }

    private JavaBuild() {
    }

    /**
     * Ends a child JVM and every process it started (forcibly), and waits up to 5 s for it to be
     * gone, so that what it left can be read.
     */
    public static void stop(Process p) {
        p.descendants().forEach(ProcessHandle::destroyForcibly);
        p.destroyForcibly();
        try {
            p.waitFor(5, java.util.concurrent.TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The class path this JVM runs with, as paths. */
    public static List<Path> ownClassPath() {
        String cp = System.getProperty("java.class.path", "");
        List<Path> out = new ArrayList<>();
        for (String s : cp.split(File.pathSeparator)) {
            if (!s.isBlank()) {
                out.add(Path.of(s));
            }
        }
        return out;
    }

    /**
     * Compiles {@code sources} against {@code classPath} into {@code outDir} (created if needed),
     * as Java 17.
     */
    public static Result compile(List<Path> sources, List<Path> classPath, Path outDir) throws IOException {
        if (sources.isEmpty()) {
            Files.createDirectories(outDir);
            return new Result(true, List.of());
        }
        List<Problem> errors = Problem.of(javac(sources, classPath, outDir, List.of("-implicit:none")));
        return new Result(errors.isEmpty(), errors);
    }

    /**
     * javac's option for {@code a + b} on strings as {@code StringBuilder} calls, as the JDK
     * builds its own {@code java.base}, instead of an {@code invokedynamic} call site that each
     * JVM links the first time it runs it. A grading's child JVMs live a few seconds and run
     * hundreds of such sites once: linked, they cost about 4 % of a grading's CPU (docs/testing.md,
     * S8). The course's Maven build compiles raylab's classes with it (pom.xml, profile
     * {@code course}; a starter's build keeps javac's default); the grader compiles its stand-ins
     * and the starter's stubs with it. Not its tests: a hidden test's message would become
     * constants of its pieces, and {@code HiddenText} withholds any visible text that holds one.
     * A student's code is compiled as javac compiles it by default, in {@code check} and in the
     * grader alike.
     */
    public static final String INLINE_CONCAT = "-XDstringConcat=inline";

    /**
     * The one place raylab runs javac on files: in this JVM, as Java 17 ({@code --release 17}),
     * UTF-8, no warnings, no annotation processing, then {@code options} (such as {@code -g},
     * {@code -parameters}, {@code -implicit:none}, {@code -sourcepath}), into {@code outDir}
     * (created if needed) against {@code classPath}.
     *
     * @return javac's diagnostics; the sources compiled when none of them is an
     *         {@link Diagnostic.Kind#ERROR} (javac reports every failure as one)
     */
    public static List<Diagnostic<? extends JavaFileObject>> javac(List<Path> sources, List<Path> classPath,
            Path outDir, List<String> options) throws IOException {
        Files.createDirectories(outDir);
        JavaCompiler javac = compiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, Locale.ROOT,
                StandardCharsets.UTF_8)) {
            List<String> all = new ArrayList<>(List.of("--release", "17", "-encoding", "UTF-8", "-nowarn",
                    "-proc:none"));
            all.addAll(options);
            all.addAll(List.of("-d", outDir.toString(), "-classpath", pathOf(classPath)));
            boolean ok = javac.getTask(new StringWriter(), files, diagnostics, all, null,
                    files.getJavaFileObjectsFromPaths(sources)).call();
            List<Diagnostic<? extends JavaFileObject>> out = new ArrayList<>(diagnostics.getDiagnostics());
            if (!ok && out.stream().noneMatch(d -> d.getKind() == Diagnostic.Kind.ERROR)) {
                throw new IOException("javac failed without naming an error");
            }
            return out;
        }
    }

    /** The system Java compiler; a JRE has none, which is bad input (a one-line IOException). */
    public static JavaCompiler compiler() throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new IOException("no Java compiler in this runtime: run raylab with a JDK, not a JRE");
        }
        return javac;
    }

    /** Paths joined with the platform's path separator, as {@code -classpath} takes them. */
    public static String pathOf(List<Path> paths) {
        return paths.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator));
    }

    /**
     * Deletes a file or a folder with everything in it, if it exists (a link is deleted, never
     * followed): for the build, work and staging folders the tools make.
     */
    public static void deleteTree(Path p) throws IOException {
        if (p == null || !Files.exists(p, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (Stream<Path> s = Files.walk(p)) {
            for (Path q : (Iterable<Path>) s.sorted(Comparator.reverseOrder())::iterator) {
                Files.deleteIfExists(q);
            }
        }
    }

    /**
     * As {@link #deleteTree}, but best effort: what cannot be deleted is left and the rest is
     * still deleted (clean-up after a grading, where a child may have left files it owns).
     */
    public static void deleteTreeQuietly(Path p) {
        if (p == null || !Files.exists(p, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (Stream<Path> s = Files.walk(p)) {
            for (Path q : (Iterable<Path>) s.sorted(Comparator.reverseOrder())::iterator) {
                try {
                    Files.deleteIfExists(q);
                } catch (IOException ignored) {
                    // best effort
                }
            }
        } catch (IOException | java.io.UncheckedIOException ignored) {
            // best effort
        }
    }

    /**
     * The JIT and collector of every short-lived child JVM raylab starts (a test JVM of
     * {@code check} or of a grading, a trusted render, a student process, the grader itself):
     * C1 only and one collector thread. Their runs are seconds long, so C2's compiler threads cost
     * more CPU than its faster code saves (a whole grading with the trusted JVMs on C2 took twice
     * their CPU; docs/testing.md, "S3"). The one place these are chosen; {@code raylab.grade.JvmOptions}
     * adds the heap sizes of a grading's processes.
     */
    public static final List<String> QUICK_JVM = List.of("-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC");

    /** The {@code java} launcher of the JDK this JVM runs on ({@code java.home/bin/java}), for child JVMs. */
    public static String javaExecutable() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }

    /** Every .java file under a directory, sorted (empty if the directory does not exist). */
    public static List<Path> sourcesUnder(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (var s = Files.walk(dir)) {
            return s.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
    }
}
