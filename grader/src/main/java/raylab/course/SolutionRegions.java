package raylab.course;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The reference solution marked in place in a source file, and the stub that replaces it:
 * <pre>
 *     // BEGIN SOLUTION sphere
 *     ...reference code...
 *     // STUB
 *     // throw new NotImplemented("sphere", "Sphere.intersect");
 *     // END SOLUTION
 * </pre>
 * {@link #toStudent} drops the reference code and uncomments the stub lines; a region without a
 * {@code // STUB} part disappears entirely. Malformed markers are an error that names the line.
 */
public final class SolutionRegions {
    private static final Pattern BEGIN = Pattern.compile("^\\s*// BEGIN SOLUTION ([a-z][a-z0-9-]*)\\s*$");
    private static final Pattern STUB = Pattern.compile("^\\s*// STUB\\s*$");
    private static final Pattern END = Pattern.compile("^\\s*// END SOLUTION\\s*$");
    private static final Pattern ANY_MARKER = Pattern.compile("(BEGIN|END) SOLUTION|^\\s*// STUB\\s*$");
    private static final Pattern STUB_LINE = Pattern.compile("^(\\s*)// ?(.*)$");

    /** One marked region: its milestone and its line numbers (1-based, inclusive). */
    public record Region(String milestone, int beginLine, int stubLine, int endLine,
            List<String> solution, List<String> stub) {
    }

    private SolutionRegions() {
    }

    /** The regions of a file's text, in order; throws IllegalArgumentException if malformed. */
    public static List<Region> parse(String fileName, String text) {
        String[] lines = text.split("\n", -1);
        List<Region> out = new ArrayList<>();
        int i = 0;
        while (i < lines.length) {
            Matcher b = BEGIN.matcher(lines[i]);
            if (!b.matches()) {
                if (ANY_MARKER.matcher(lines[i]).find()) {
                    throw new IllegalArgumentException(fileName + ":" + (i + 1)
                            + ": marker outside a solution region or malformed: " + lines[i].trim());
                }
                i++;
                continue;
            }
            String id = b.group(1);
            int begin = i;
            int stub = -1;
            List<String> solution = new ArrayList<>();
            List<String> stubLines = new ArrayList<>();
            i++;
            while (true) {
                if (i >= lines.length) {
                    throw new IllegalArgumentException(fileName + ":" + (begin + 1)
                            + ": BEGIN SOLUTION " + id + " has no END SOLUTION");
                }
                String line = lines[i];
                if (END.matcher(line).matches()) {
                    break;
                }
                if (STUB.matcher(line).matches()) {
                    if (stub >= 0) {
                        throw new IllegalArgumentException(fileName + ":" + (i + 1) + ": second // STUB in one region");
                    }
                    stub = i;
                } else if (BEGIN.matcher(line).matches() || line.contains("BEGIN SOLUTION")
                        || line.contains("END SOLUTION")) {
                    throw new IllegalArgumentException(fileName + ":" + (i + 1)
                            + ": solution regions cannot nest (region opened at line " + (begin + 1) + ")");
                } else if (stub >= 0) {
                    Matcher m = STUB_LINE.matcher(line);
                    if (!m.matches() && !line.isBlank()) {
                        throw new IllegalArgumentException(fileName + ":" + (i + 1)
                                + ": stub lines must be comments (// ...)");
                    }
                    stubLines.add(line);
                } else {
                    solution.add(line);
                }
                i++;
            }
            out.add(new Region(id, begin + 1, stub < 0 ? -1 : stub + 1, i + 1, solution, stubLines));
            i++;
        }
        return out;
    }

    /** Whether the text has any solution region. */
    public static boolean hasRegions(String text) {
        return text.contains("BEGIN SOLUTION");
    }

    /**
     * The student's version: every region replaced by its uncommented stub, except regions of the
     * milestones in {@code keep}, which stay as reference code without their markers.
     */
    public static String toStudent(String fileName, String text, java.util.Set<String> keep) {
        List<Region> regions = parse(fileName, text);
        String[] lines = text.split("\n", -1);
        StringBuilder sb = new StringBuilder(text.length());
        int next = 0;
        for (Region r : regions) {
            for (int k = next; k < r.beginLine() - 1; k++) {
                sb.append(lines[k]).append('\n');
            }
            if (keep.contains(r.milestone())) {
                for (String s : r.solution()) {
                    sb.append(s).append('\n');
                }
            } else {
                for (String s : r.stub()) {
                    Matcher m = STUB_LINE.matcher(s);
                    sb.append(m.matches() ? m.group(1) + m.group(2) : s).append('\n');
                }
            }
            next = r.endLine();
            // A region removed entirely between two blank lines would leave two in a row.
            boolean removed = !keep.contains(r.milestone()) && r.stub().isEmpty();
            if (removed && next < lines.length && lines[next].isBlank()
                    && (sb.length() < 2 || sb.charAt(sb.length() - 2) == '\n')) {
                next++;
            }
        }
        for (int k = next; k < lines.length; k++) {
            sb.append(lines[k]);
            if (k < lines.length - 1) {
                sb.append('\n');
            }
        }
        return sb.toString();
    }
}
