package raylab.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.Optional;

import raylab.course.NotImplemented;

/**
 * An exception thrown by the student's code, named as theirs: "your code threw
 * NullPointerException in Sphere.intersect (Sphere.java:37) while tracing pixel (3, 4) of
 * scenes/sphere.json", with the frames that lie in student files only. An exception with no
 * frame in a student file is the framework's own fault ("internal error"). Shared by the commands
 * ({@code render}, {@code trace}, {@code check}) and usable by the grader.
 */
public final class StudentFault {
    /** The student files when no assignment.json can be read (the seven of the course). */
    static final List<String> DEFAULT_FILES = raylab.course.Watchdog.DEFAULT_FILES;

    /** At most this many student frames are listed. */
    static final int FRAMES = raylab.course.Watchdog.FRAMES;

    private StudentFault() {
    }

    /**
     * Stuck student code ({@link raylab.course.Watchdog}): says {@code sentence} ("your code has
     * run for 2 s in ... an endless loop? while rendering ...") as a one-line error and, run from
     * the command line, ends the JVM with exit status 1 ({@code Main.FAILED}): the stuck thread
     * cannot be stopped otherwise. Run in-process (a test calling {@link Main#run}), the JVM is not
     * ended: the line is said and the command goes on waiting.
     */
    static void stuck(java.io.PrintWriter err, String sentence) {
        if (Main.standalone) {
            raylab.course.Watchdog.endJvm(err, "raylab: " + sentence, Main.FAILED);
        }
        err.println("raylab: " + sentence);
        err.flush();
    }

    /** The student files of the project at {@code root}, '/'-separated relative paths. */
    public static List<String> studentFiles(Path root) {
        return raylab.course.Watchdog.studentFiles(root);
    }

    /** The source path of a frame's class: src/main/java/raylab/surface/Sphere.java for raylab.surface.Sphere$1. */
    static String sourceOf(StackTraceElement e) {
        return raylab.course.Watchdog.sourceOf(e);
    }

    /** The frames of {@code t} (or, if it has none, of its causes) that lie in student files, innermost first. */
    public static List<StackTraceElement> studentFrames(Throwable t, Collection<String> studentFiles) {
        for (Throwable c = t; c != null; c = c.getCause() == c ? null : c.getCause()) {
            List<StackTraceElement> out = new ArrayList<>();
            for (StackTraceElement e : c.getStackTrace()) {
                if (studentFiles.contains(sourceOf(e))) {
                    out.add(e);
                }
            }
            if (!out.isEmpty()) {
                return out;
            }
        }
        return List.of();
    }

    /** Whether {@code t} is the student's: thrown in a student file, and not a stub's NotImplemented. */
    public static boolean isStudents(Throwable t, Collection<String> studentFiles) {
        return !(t instanceof NotImplemented) && !studentFrames(t, studentFiles).isEmpty();
    }

    /**
     * "your code threw NullPointerException in Sphere.intersect (Sphere.java:37) CONTEXT: message
     * [at ... < ...]", or empty when {@code t} is not the student's. {@code context} (for example
     * "while tracing pixel (3, 4) of scenes/sphere.json") may be empty.
     */
    public static Optional<String> describe(Throwable t, Collection<String> studentFiles, String context) {
        if (!isStudents(t, studentFiles)) {
            return Optional.empty();
        }
        Throwable thrown = t;
        while (thrown.getCause() != null && thrown.getCause() != thrown && thrown.getStackTrace().length > 0
                && studentFrames(thrown, studentFiles).isEmpty()) {
            thrown = thrown.getCause();
        }
        List<StackTraceElement> frames = studentFrames(thrown, studentFiles);
        StackTraceElement top = frames.get(0);
        StringBuilder b = new StringBuilder("your code threw ").append(thrown.getClass().getSimpleName())
                .append(" in ").append(place(top));
        if (context != null && !context.isBlank()) {
            b.append(' ').append(context.strip());
        }
        String message = thrown.getMessage();
        if (message != null && !message.isBlank()) {
            b.append(": ").append(Errors.oneLine(message));
        }
        if (thrown instanceof StackOverflowError) {
            b.append(" (endless recursion?)");
        }
        return Optional.of(b.append(calledFrom(frames)).toString());
    }

    static String calledFrom(List<StackTraceElement> frames) {
        return raylab.course.Watchdog.calledFrom(frames);
    }

    /** Sphere.intersect (Sphere.java:37) */
    static String place(StackTraceElement e) {
        return raylab.course.Watchdog.place(e);
    }
}
