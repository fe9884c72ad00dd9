package raylab.course;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

/**
 * Where each module's sources live in the instructor's tree (docs/architecture.md). The module
 * lines are the release line: the starter holds the lab as source ({@link #LAB}) and the tools
 * ({@link #TOOLS}) as a jar; the other roots are the instructor's. One Maven build compiles them
 * all onto one class path; which may use which is checked by {@code ModuleLinesTest}.
 */
public final class SourceRoots {
    /** The lab: the ray tracer the student reads and edits. */
    public static final String LAB = "src/main/java";
    /** The lab's resources (a surface type's services file, for one). */
    public static final String LAB_RESOURCES = "src/main/resources";
    /** The tools: what students run but never read (cli, check, the test JVM, the student process, inspect). */
    public static final String TOOLS = "src/tools/java";

    private SourceRoots() {
    }

    /** Every main source root and resource folder a change to which needs a full build. */
    public static List<String> all() {
        return List.of("src/main", "src/tools", "src/mesh-engine", "grader/src/main", "src/authoring");
    }

    /** Whether {@code root} is the instructor's tree (it has the tools as source), not a starter. */
    public static boolean isCourseTree(Path root) {
        return Files.isDirectory(root.resolve(TOOLS));
    }

    /**
     * The classes whose source is below {@code root/sourceRoot}, by the name of their file
     * (raylab/cli/Main.java: "raylab.cli.Main"); empty when the folder is missing.
     */
    public static Set<String> classesUnder(Path root, String sourceRoot) throws IOException {
        Path dir = root.resolve(sourceRoot);
        Set<String> out = new TreeSet<>();
        if (!Files.isDirectory(dir)) {
            return out;
        }
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                String rel = dir.relativize(p).toString().replace('\\', '/');
                if (rel.endsWith(".java") && !rel.endsWith("package-info.java") && Files.isRegularFile(p)) {
                    out.add(rel.substring(0, rel.length() - 5).replace('/', '.'));
                }
            }
        }
        return out;
    }

    /**
     * Whether a class file's path in a jar or class folder (raylab/cli/Main$1.class) was compiled
     * from the source of one of {@code classes} (a nested class by its outer class's file).
     */
    public static boolean compiledFrom(String classFile, Set<String> classes) {
        if (!classFile.endsWith(".class")) {
            return false;
        }
        String name = classFile.substring(0, classFile.length() - 6).replace('/', '.');
        int nested = name.indexOf('$');
        return classes.contains(nested < 0 ? name : name.substring(0, nested));
    }
}
