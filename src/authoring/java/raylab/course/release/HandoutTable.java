package raylab.course.release;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;

/**
 * The points in a handout, generated from {@code assignment.json} (through {@link GradingPlan},
 * as check and the grader count them): the total in the title line
 * {@code # Milestone N — Title (20 points)} and the table of the {@code ## Grading} section.
 * {@code raylab release} writes the starter's handouts with it and rewrites the instructor's
 * ({@link #refresh}), and {@code raylab assignment add-scene|add-case|add-test} rewrite the
 * instructor's.
 */
public final class HandoutTable {
    private static final Pattern TITLE = Pattern.compile("(?m)^(# .*\\()(\\d+(?:\\.\\d+)?)( points\\)\\s*)$");

    private HandoutTable() {
    }

    /**
     * Rewrites every milestone handout of the instructor's tree whose title total or grading
     * table is not what {@code assignment.json} says (each to a temporary name, then moved).
     *
     * @return the handouts rewritten, relative to {@code root} ('/'-separated)
     */
    public static List<String> refresh(Path root) throws IOException {
        List<String> out = new ArrayList<>();
        for (Assignment a : Assignments.load(root).all()) {
            Path readme = root.resolve(a.folder()).resolve("README.md");
            if (!Files.isRegularFile(readme)) {
                continue;
            }
            String text = Files.readString(readme, StandardCharsets.UTF_8);
            String updated = update(text, GradingPlan.of(root, a));
            if (!updated.equals(text)) {
                Path tmp = Files.createTempFile(readme.getParent(), ".README.md", ".tmp");
                try {
                    Files.writeString(tmp, updated, StandardCharsets.UTF_8);
                    try {
                        Files.setPosixFilePermissions(tmp, PosixFilePermissions.fromString("rw-r--r--"));
                    } catch (UnsupportedOperationException e) {
                        // not a POSIX file system
                    }
                    Files.move(tmp, readme, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
                } finally {
                    Files.deleteIfExists(tmp);
                }
                out.add(root.relativize(readme).toString().replace('\\', '/'));
            }
        }
        return out;
    }

    /** The handout with its title total and grading table made from the plan. */
    public static String update(String readme, GradingPlan.Plan plan) {
        Assignment a = plan.assignment();
        String text = readme;
        Matcher t = TITLE.matcher(text);
        if (t.find()) {
            text = text.substring(0, t.start()) + t.group(1) + a.points() + t.group(3) + text.substring(t.end());
        }
        String table = table(plan);
        List<String> lines = new ArrayList<>(List.of(text.split("\n", -1)));
        int heading = -1;
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).strip().equals("## Grading")) {
                heading = i;
                break;
            }
        }
        if (heading < 0) {
            String end = text.endsWith("\n") ? "" : "\n";
            return text + end + "\n## Grading\n\n" + table + "\n";
        }
        int start = -1;
        int i = heading + 1;
        for (; i < lines.size(); i++) {
            String l = lines.get(i).strip();
            if (l.startsWith("#")) {
                break; // the next section: no table in this one
            }
            if (l.startsWith("|")) {
                start = i;
                break;
            }
        }
        if (start < 0) {
            lines.add(heading + 1, "");
            lines.add(heading + 2, table);
            return String.join("\n", lines);
        }
        int end = start;
        while (end < lines.size() && lines.get(end).strip().startsWith("|")) {
            end++;
        }
        List<String> out = new ArrayList<>(lines.subList(0, start));
        out.add(table);
        out.addAll(lines.subList(end, lines.size()));
        return String.join("\n", out);
    }

    /** The grading table (Markdown, without a final newline). */
    public static String table(GradingPlan.Plan plan) {
        Assignment a = plan.assignment();
        StringBuilder b = new StringBuilder("| part | points |\n| --- | --- |\n");
        List<GradingPlan.Item> tests = plan.of(GradingPlan.Kind.TEST);
        if (!tests.isEmpty() || a.tests().visiblePoints() > 0) {
            List<String> classes = new ArrayList<>();
            for (String v : a.tests().visible()) {
                String c = v.substring(v.lastIndexOf('/') + 1).replaceFirst("\\.java$", "");
                classes.add("`" + c + "`");
            }
            b.append("| visible tests (").append(String.join(", ", classes)).append(", tag `").append(a.tests().tag())
                    .append("`): ").append(tests.size()).append(tests.size() == 1 ? " test" : " tests")
                    .append(", the points shared equally | ").append(a.tests().visiblePoints()).append(" |\n");
        }
        for (GradingPlan.Item c : plan.of(GradingPlan.Kind.CASE)) {
            b.append("| data case \"").append(c.name().replace("|", "\\|")).append("\" | ")
                    .append(GradingPlan.points(c.cents())).append(" |\n");
        }
        if (!plan.hidden().isEmpty()) {
            boolean tests0 = plan.hidden().stream().anyMatch(i -> i.kind() == GradingPlan.Kind.TEST);
            boolean cases0 = plan.hidden().stream().anyMatch(i -> i.kind() == GradingPlan.Kind.CASE);
            b.append("| ").append(tests0 && cases0 ? "hidden tests and data cases" : tests0 ? "hidden tests" : "hidden data cases")
                    .append(", graded after submission | ").append(GradingPlan.points(plan.hiddenCents())).append(" |\n");
        }
        for (GradingPlan.Item s : plan.of(GradingPlan.Kind.SCENE)) {
            b.append("| `").append(s.name()).append("` matches its reference (tolerance ")
                    .append(GradingPlan.percent(s.tolerance())).append(")")
                    .append(s.cents() == 0 ? ", feedback only: graded and explained pixel by pixel, no points" : "")
                    .append(" | ").append(GradingPlan.points(s.cents())).append(" |\n");
        }
        b.append("| **total** | **").append(a.points()).append("** |");
        return b.toString();
    }
}
