package raylab.course;

import java.util.ArrayList;
import java.util.List;

/**
 * Zero-point notes: what a test reports about a correct result that cost more than the render
 * plan needs (for example shadow rays toward lights behind the surface). A test prints a line
 * starting with {@link #PREFIX}; the grader and {@code check} take these lines out of the test's
 * output and show them beside its result, which they never change.
 */
public final class Notes {
    /** The start of a note line in a test's output. */
    public static final String PREFIX = "raylab note: ";

    private Notes() {
    }

    /** The notes in a test's output, one per line, in order, without repeats (empty if none). */
    public static String of(String output) {
        if (output == null || output.isEmpty()) {
            return "";
        }
        List<String> notes = new ArrayList<>();
        for (String line : output.split("\\R")) {
            if (line.startsWith(PREFIX)) {
                String n = line.substring(PREFIX.length()).strip();
                if (!n.isEmpty() && !notes.contains(n)) {
                    notes.add(n);
                }
            }
        }
        return String.join("\n", notes);
    }

    /** The notes {@code notes} (one per line) followed by the new ones of {@code output}, without repeats. */
    public static String add(String notes, String output) {
        List<String> all = new ArrayList<>(notes == null || notes.isEmpty() ? List.of() : List.of(notes.split("\n")));
        for (String n : of(output).split("\n")) {
            if (!n.isEmpty() && !all.contains(n)) {
                all.add(n);
            }
        }
        return String.join("\n", all);
    }

    /** The output without its note lines. */
    public static String strip(String output) {
        if (output == null || !output.contains(PREFIX)) {
            return output == null ? "" : output;
        }
        StringBuilder b = new StringBuilder();
        for (String line : output.split("\\R", -1)) {
            if (!line.startsWith(PREFIX)) {
                b.append(line).append('\n');
            }
        }
        return b.toString().strip();
    }
}
