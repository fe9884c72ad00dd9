package raylab.grade;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

/**
 * The {@code META-INF/services} files of a cut of the build (the student starter, the grader's
 * framework jars): each may list only providers the cut has, since {@link java.util.ServiceLoader}
 * stops with a {@code ServiceConfigurationError} on a listed class it cannot find. The format is
 * {@code ServiceLoader}'s: one class name a line, {@code #} to the end of a line a comment.
 */
public final class ServiceFiles {
    /** Where services files live in a jar or class folder. */
    public static final String FOLDER = "META-INF/services/";
    /** Where they live in the project's sources. */
    public static final String SOURCE_FOLDER = "src/main/resources/" + FOLDER;

    private ServiceFiles() {
    }

    /** The provider class names a services file lists, in order. */
    public static List<String> providers(String text) {
        List<String> out = new ArrayList<>();
        for (String line : text.split("\n", -1)) {
            String name = provider(line);
            if (!name.isEmpty()) {
                out.add(name);
            }
        }
        return out;
    }

    /**
     * The services file with only the providers {@code present} accepts (other lines kept), or
     * null when no provider is left.
     */
    public static String keep(String text, Predicate<String> present) {
        StringBuilder out = new StringBuilder();
        boolean any = false;
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String name = provider(lines[i]);
            if (!name.isEmpty() && !present.test(name)) {
                continue;
            }
            any |= !name.isEmpty();
            out.append(lines[i]);
            if (i < lines.length - 1) {
                out.append('\n');
            }
        }
        return any ? out.toString() : null;
    }

    /** The path of a class's file in a jar or class folder: {@code raylab/surface/Mesh$Engine.class}. */
    public static String classFile(String className) {
        return className.replace('.', '/') + ".class";
    }

    /** The source file that defines a class (its outermost class's): {@code raylab/surface/Mesh.java}. */
    public static String sourceFile(String className) {
        int nested = className.indexOf('$');
        return (nested < 0 ? className : className.substring(0, nested)).replace('.', '/') + ".java";
    }

    private static String provider(String line) {
        int comment = line.indexOf('#');
        return (comment < 0 ? line : line.substring(0, comment)).strip();
    }
}
