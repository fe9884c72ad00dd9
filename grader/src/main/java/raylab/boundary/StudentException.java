package raylab.boundary;

import java.util.List;

/**
 * An exception the student's code threw in the student process, as the grader tells it: the
 * exception's class and message and the student's own stack frames.
 */
public class StudentException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final String className;
    private final String studentMessage;
    private final List<String> frames;

    public StudentException(String className, String studentMessage, List<String> frames, String context) {
        super(describe(className, studentMessage, frames, context));
        this.className = className;
        this.studentMessage = studentMessage;
        this.frames = List.copyOf(frames);
    }

    /** "your code threw NullPointerException in Sphere.intersect (Sphere.java:37): message". */
    static String describe(String className, String message, List<String> frames, String context) {
        String simple = className.substring(className.lastIndexOf('.') + 1);
        StringBuilder b = new StringBuilder("your code threw ").append(simple);
        if (!frames.isEmpty()) {
            b.append(" in ").append(frames.get(0));
        }
        if (context != null && !context.isEmpty()) {
            b.append(" ").append(context);
        }
        if (message != null && !message.isEmpty()) {
            b.append(": ").append(message);
        }
        return b.toString();
    }

    /** The student exception's class name, such as {@code java.lang.NullPointerException}. */
    public String className() {
        return className;
    }

    public String studentMessage() {
        return studentMessage;
    }

    /** The student's stack frames, innermost first ("Sphere.intersect (Sphere.java:37)"). */
    public List<String> frames() {
        return frames;
    }

    /** The same exception with more context ("while tracing pixel (3, 4) of scenes/sphere.json"). */
    public StudentException in(String context) {
        return new StudentException(className, studentMessage, frames, context);
    }
}
