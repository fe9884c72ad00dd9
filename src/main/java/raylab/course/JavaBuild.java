package raylab.course;

import java.io.File;
import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/** Compiles Java sources in-process with javax.tools, for release checks, {@code check} and grading. */
public final class JavaBuild {
    /** A compile error: the file, its line, and javac's message. */
    public record Problem(Path file, long line, String message) {
        @Override
        public String toString() {
            return (file == null ? "" : file + ":" + line + ": ") + message;
        }
    }

    /** The outcome: success, or the errors. */
    public record Result(boolean success, List<Problem> errors) {
    }

    private JavaBuild() {
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
        Files.createDirectories(outDir);
        if (sources.isEmpty()) {
            return new Result(true, List.of());
        }
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new IOException("no Java compiler in this runtime: run raylab with a JDK, not a JRE");
        }
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, Locale.ROOT,
                StandardCharsets.UTF_8)) {
            List<String> options = List.of("--release", "17", "-encoding", "UTF-8", "-nowarn", "-proc:none",
                    "-implicit:none", "-d", outDir.toString(), "-classpath",
                    classPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator)));
            Iterable<? extends JavaFileObject> units = files.getJavaFileObjectsFromPaths(sources);
            StringWriter noise = new StringWriter();
            boolean ok = javac.getTask(noise, files, diagnostics, options, null, units).call();
            List<Problem> errors = new ArrayList<>();
            for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
                if (d.getKind() == Diagnostic.Kind.ERROR) {
                    Path file = d.getSource() == null ? null : Path.of(d.getSource().toUri());
                    errors.add(new Problem(file, d.getLineNumber(), d.getMessage(Locale.ROOT).split("\n")[0]));
                }
            }
            return new Result(ok && errors.isEmpty(), errors);
        }
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
