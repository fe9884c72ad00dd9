package raylab.course;

import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Says what went wrong in a render in the student's terms, for {@code raylab check} and the
 * grader: an exception thrown by the student's code is shown as that exception at its line in
 * the student's file (not as an internal error of raylab), and running out of memory is called
 * that.
 */
public final class Explain {
    /** A stack frame as {@code raylab render} prints it: raylab.surface.Sphere.intersect(Sphere.java:42). */
    private static final Pattern FRAME = Pattern.compile("([A-Za-z_$][\\w$]*(?:\\.[A-Za-z_$][\\w$]*)*)\\.([\\w$<>]+)\\(([\\w$]+\\.java):(\\d+)\\)");
    private static final Pattern INTERNAL = Pattern.compile("^(?:raylab: )?internal error: ([\\w.$]+): (.*?)(?: \\[at .*)?(?: \\(RAYLAB_DEBUG=1 shows the stack trace\\))?$");

    private Explain() {
    }

    /**
     * The error line of a failed render (as {@code raylab render} printed it), in the student's
     * terms: "your code threw IllegalStateException: boom at src/main/java/raylab/surface/Sphere.java:42
     * (in Sphere.intersect)" when a frame lies in one of {@code studentFiles}; otherwise the line.
     */
    public static String renderFailure(String line, List<String> studentFiles) {
        if (line == null) {
            return "";
        }
        String l = line.strip().replaceFirst("^raylab: ", "");
        Matcher m = INTERNAL.matcher(l);
        if (!m.matches()) {
            return l;
        }
        String type = m.group(1);
        String message = m.group(2);
        if (type.endsWith("OutOfMemoryError")) {
            return "the render ran out of memory (" + message + "): look for something that grows with every ray,"
                    + " such as a list or an array allocated per hit and kept";
        }
        if (type.endsWith("StackOverflowError")) {
            message = "endless recursion?";
        }
        Matcher f = FRAME.matcher(l);
        while (f.find()) {
            String cls = f.group(1);
            String outer = cls.contains("$") ? cls.substring(0, cls.indexOf('$')) : cls;
            String path = "src/main/java/" + outer.replace('.', '/') + ".java";
            if (studentFiles.contains(path)) {
                String simple = outer.substring(outer.lastIndexOf('.') + 1);
                return "your code threw " + type + (message.isBlank() || message.equals("(no message)") ? "" : ": " + message)
                        + " at " + path + ":" + f.group(4) + " (in " + simple + "." + f.group(2) + ")";
            }
        }
        return "the render failed: " + type + ": " + message;
    }
}
