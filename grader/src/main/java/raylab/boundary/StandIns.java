package raylab.boundary;

import java.io.IOException;
import java.io.StringWriter;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.stream.Collectors;

import javax.lang.model.element.Modifier;
import javax.tools.Diagnostic;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;

import com.sun.source.tree.ClassTree;
import com.sun.source.tree.CompilationUnitTree;
import com.sun.source.tree.MethodTree;
import com.sun.source.tree.Tree;
import com.sun.source.tree.VariableTree;
import com.sun.source.util.JavacTask;
import com.sun.source.util.SourcePositions;
import com.sun.source.util.Trees;

import raylab.course.JavaBuild;

/**
 * Stand-in classes for the grader's process: the public (starter) source of a student class with
 * the body of each graded method replaced by a call into the student process
 * ({@link Remote#call}). Everything else of the class (fields, constructor, bounding box) is the
 * starter's own code, so the grader's tests and renderer use the class as they would the
 * student's, and only the graded methods run in the student's process.
 */
public final class StandIns {
    private StandIns() {
    }

    /**
     * The stand-in source of {@code fqcn} from its public source: the bodies of the methods
     * named in {@code methods} (all overloads) forward to the student process.
     */
    public static String forwarding(String source, String fqcn, Set<String> methods) throws IOException {
        String simple = fqcn.substring(fqcn.lastIndexOf('.') + 1);
        JavaCompiler javac = JavaBuild.compiler();
        JavaFileObject file = new SimpleJavaFileObject(URI.create("string:///" + fqcn.replace('.', '/') + ".java"),
                JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                return source;
            }
        };
        JavacTask task = (JavacTask) javac.getTask(new StringWriter(), null, null, List.of("-proc:none"), null,
                List.of(file));
        CompilationUnitTree unit = task.parse().iterator().next();
        SourcePositions pos = Trees.instance(task).getSourcePositions();
        record Splice(long start, long end, String text) {
        }
        List<Splice> splices = new ArrayList<>();
        Set<String> found = new java.util.HashSet<>();
        for (Tree t : unit.getTypeDecls()) {
            if (!(t instanceof ClassTree c) || !c.getSimpleName().contentEquals(simple)) {
                continue;
            }
            for (Tree m : c.getMembers()) {
                if (m instanceof MethodTree mt && methods.contains(mt.getName().toString()) && mt.getBody() != null) {
                    long start = pos.getStartPosition(unit, mt.getBody());
                    long end = pos.getEndPosition(unit, mt.getBody());
                    splices.add(new Splice(start, end, body(fqcn, mt)));
                    found.add(mt.getName().toString());
                }
            }
        }
        for (String m : methods) {
            if (!found.contains(m)) {
                throw new IOException("no method " + simple + "." + m + " with a body in the public source of " + fqcn);
            }
        }
        splices.sort(Comparator.comparingLong(Splice::start).reversed());
        StringBuilder b = new StringBuilder(source);
        for (Splice s : splices) {
            b.replace((int) s.start(), (int) s.end(), s.text());
        }
        return b.toString();
    }

    private static String body(String fqcn, MethodTree m) {
        boolean isStatic = m.getModifiers().getFlags().contains(Modifier.STATIC);
        String args = m.getParameters().stream().map(VariableTree::getName).map(Object::toString)
                .collect(Collectors.joining(", "));
        String call = "raylab.boundary.Remote.call(" + (isStatic ? "null" : "this") + ", \"" + fqcn + "\", \""
                + m.getName() + "\", new Object[] {" + args + "})";
        String ret = m.getReturnType() == null ? "void" : m.getReturnType().toString();
        if (ret.equals("void")) {
            return "{ " + call + "; }";
        }
        String boxed = switch (ret) {
            case "boolean" -> "Boolean";
            case "double" -> "Double";
            case "int" -> "Integer";
            case "long" -> "Long";
            case "float" -> "Float";
            default -> ret;
        };
        return "{ return (" + boxed + ") " + call + "; }";
    }

    /**
     * Compiles sources given as text (relative path such as {@code raylab/surface/Sphere.java} →
     * source) against {@code classPath} into {@code out}, as Java 17 with {@code -parameters}.
     */
    public static void compile(Map<String, String> sources, List<Path> classPath, Path out) throws IOException {
        Files.createDirectories(out);
        if (sources.isEmpty()) {
            return;
        }
        Path src = Files.createTempDirectory("standin-src");
        try {
            List<Path> files = new ArrayList<>();
            for (var e : sources.entrySet()) {
                Path f = src.resolve(e.getKey());
                Files.createDirectories(f.getParent());
                Files.writeString(f, e.getValue(), StandardCharsets.UTF_8);
                files.add(f);
            }
            List<Diagnostic<? extends JavaFileObject>> errors = JavaBuild.javac(files, classPath, out,
                    List.of("-implicit:none", "-parameters", JavaBuild.INLINE_CONCAT)).stream()
                    .filter(d -> d.getKind() == Diagnostic.Kind.ERROR).toList();
            if (!errors.isEmpty()) {
                StringBuilder msg = new StringBuilder("the grader's stand-in classes do not compile:");
                for (Diagnostic<? extends JavaFileObject> d : errors) {
                    msg.append("\n  ").append(d.getSource() == null ? "" : src.relativize(Path.of(d.getSource().toUri())))
                            .append(":").append(d.getLineNumber()).append(": ").append(d.getMessage(Locale.ROOT));
                }
                throw new IOException(msg.toString());
            }
        } finally {
            JavaBuild.deleteTreeQuietly(src);
        }
    }
}
