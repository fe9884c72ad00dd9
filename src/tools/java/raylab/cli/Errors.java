package raylab.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;

import picocli.CommandLine;
import picocli.CommandLine.IExecutionExceptionHandler;
import picocli.CommandLine.ParseResult;
import raylab.course.NotImplemented;
import raylab.scene.Display;
import raylab.scene.SceneException;

/**
 * Turns every failure into one line on standard error and an exit status: no stack traces
 * (set RAYLAB_DEBUG=1 to see them).
 */
final class Errors implements IExecutionExceptionHandler {
    @Override
    public int handleExecutionException(Exception ex, CommandLine cl, ParseResult parse) {
        PrintWriter err = cl.getErr();
        if (System.getenv("RAYLAB_DEBUG") != null) {
            ex.printStackTrace(err);
        }
        Throwable t = ex;
        while (t.getCause() != null && !(t instanceof SceneException) && !(t instanceof NotImplemented)
                && !(t instanceof UserError)) {
            t = t.getCause();
        }
        if (t instanceof SceneException || t instanceof UserError) {
            err.println("raylab: " + oneLine(t.getMessage()));
            return ((t instanceof UserError u) ? u.status : Main.BAD_INPUT);
        }
        if (t instanceof NotImplemented) {
            err.println("raylab: " + oneLine(t.getMessage()));
            return Main.NOT_IMPLEMENTED;
        }
        if (t instanceof IOException || t instanceof UncheckedIOException) {
            err.println("raylab: " + oneLine(t.getMessage()));
            return Main.FAILED;
        }
        java.util.Optional<String> students = StudentFault.describe(t,
                StudentFault.studentFiles(java.nio.file.Path.of("").toAbsolutePath()), "");
        if (students.isPresent()) {
            err.println("raylab: " + students.get());
            return Main.FAILED;
        }
        err.println("raylab: internal error: " + t.getClass().getSimpleName() + ": " + oneLine(t.getMessage())
                + frames(t) + " (RAYLAB_DEBUG=1 shows the stack trace)");
        return Main.FAILED;
    }

    /**
     * The raylab frames of the stack, innermost first (at most 6), so that an exception thrown
     * by a student's method can be shown at its line in the student's file.
     */
    static String frames(Throwable t) {
        StringBuilder b = new StringBuilder();
        int n = 0;
        for (StackTraceElement e : t.getStackTrace()) {
            if (e.getClassName().startsWith("raylab.") && e.getFileName() != null && n < 6) {
                b.append(n++ == 0 ? " [at " : " < ").append(e.getClassName()).append('.').append(e.getMethodName())
                        .append('(').append(e.getFileName()).append(':').append(e.getLineNumber()).append(')');
            }
        }
        return n == 0 ? "" : b.append(']').toString();
    }

    /** A message as one line: line breaks and other control characters escaped, never cut. */
    static String oneLine(String s) {
        if (s == null) {
            return "(no message)";
        }
        return Display.escape(s.strip());
    }
}
