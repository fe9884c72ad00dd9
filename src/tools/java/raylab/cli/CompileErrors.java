package raylab.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import raylab.course.JavaBuild;

/**
 * javac's errors as a student reads them on the terminal: the first few as
 * {@code file:line:col: message}, the source line and a caret under the column, then one line
 * saying how many more there are. Used by the launcher's incremental build ({@code check},
 * {@code render}, {@code trace}) and reusable by the grader's feedback.
 */
public final class CompileErrors {
    /** How many errors are shown in full. */
    public static final int SHOWN = 3;

    private CompileErrors() {
    }

    /**
     * The errors as terminal lines: the first {@code shown} in full (file relative to
     * {@code root}), then "... and N more errors".
     */
    public static List<String> format(List<JavaBuild.Problem> errors, Path root, int shown) {
        List<String> lines = new ArrayList<>();
        for (int i = 0; i < Math.min(shown, errors.size()); i++) {
            JavaBuild.Problem e = errors.get(i);
            String[] message = e.text().strip().split("\n");
            String where = e.file() == null ? "" : relative(root, e.file()) + ":" + (e.line() > 0 ? e.line() + ":" : "")
                    + (e.column() > 0 ? e.column() + ":" : "") + " ";
            lines.add(where + "error: " + message[0].strip());
            String source = sourceLine(e.file(), e.line());
            if (source != null) {
                lines.add(source);
                if (e.column() > 0) {
                    lines.add(caret(source, (int) e.column()));
                }
            }
            for (int k = 1; k < message.length; k++) {
                lines.add("  " + message[k].strip());
            }
        }
        int more = errors.size() - Math.min(shown, errors.size());
        if (more > 0) {
            lines.add("... and " + more + " more error" + (more == 1 ? "" : "s") + " (fix the first one first:"
                    + " one mistake often causes several)");
        }
        return lines;
    }

    /** The same as one text block, ending in a line break. */
    public static String text(List<JavaBuild.Problem> errors, Path root) {
        StringBuilder b = new StringBuilder();
        format(errors, root, SHOWN).forEach(l -> b.append(l).append('\n'));
        return b.toString();
    }

    /** Spaces (tabs kept where the source has them) up to the column, then ^. */
    static String caret(String source, int column) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < column - 1; i++) {
            b.append(i < source.length() && source.charAt(i) == '\t' ? '\t' : ' ');
        }
        return b.append('^').toString();
    }

    private static String sourceLine(Path file, long line) {
        if (file == null || line < 1) {
            return null;
        }
        try {
            List<String> all = Files.readAllLines(file, StandardCharsets.UTF_8);
            return line <= all.size() ? all.get((int) line - 1).stripTrailing() : null;
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    static String relative(Path root, Path file) {
        Path a = root.toAbsolutePath().normalize();
        Path f = file.toAbsolutePath().normalize();
        return (f.startsWith(a) ? a.relativize(f) : f).toString().replace('\\', '/');
    }
}
