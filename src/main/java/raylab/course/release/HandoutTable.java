package raylab.course.release;

import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import raylab.course.Assignment;
import raylab.course.GradingPlan;

/**
 * The points in a handout, generated from {@code assignment.json} (through {@link GradingPlan},
 * as check and the grader count them): the total in the title line
 * {@code # Milestone N — Title (20 points)} and the table of the {@code ## Grading} section.
 * {@code raylab release} writes the starter's handouts with it, and
 * {@code raylab assignment add-scene} rewrites the instructor's.
 */
public final class HandoutTable {
    private static final Pattern TITLE = Pattern.compile("(?m)^(# .*\\()(\\d+(?:\\.\\d+)?)( points\\)\\s*)$");

    private HandoutTable() {
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
                    .append(GradingPlan.percent(s.tolerance())).append(") | ").append(GradingPlan.points(s.cents())).append(" |\n");
        }
        b.append("| **total** | **").append(a.points()).append("** |");
        return b.toString();
    }
}
