package raylab.grade;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

import raylab.grade.GradeReport.Kind;

/**
 * Writes a {@link GradeReport} in the formats course staff use: Gradescope's results.json,
 * JUnit XML, a self-contained HTML report, and a console table (PrairieLearn's results.json:
 * {@link raylab.grade.platform.PrairieLearn}). Each file is
 * written to a temporary name and renamed, so a reader never sees half a file.
 */
public final class Reports {
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    /** Every output file name the grader writes into the output directory. */
    public static final List<String> FILES = List.of("results.json", "junit.xml", "report.html");

    private Reports() {
    }

    /** Writes all files into {@code out}. */
    public static void writeAll(GradeReport r, Path out) throws IOException {
        Files.createDirectories(out);
        write(out.resolve("results.json"), gradescope(r));
        write(out.resolve("junit.xml"), junitXml(r));
        write(out.resolve("report.html"), html(r));
    }

    static void write(Path target, String text) throws IOException {
        Path tmp = Files.createTempFile(target.getParent(), "." + target.getFileName(), ".tmp");
        try {
            Files.writeString(tmp, text, StandardCharsets.UTF_8);
            try {
                Files.setPosixFilePermissions(tmp, java.nio.file.attribute.PosixFilePermissions.fromString("rw-r--r--"));
            } catch (UnsupportedOperationException notPosix) {
                // keep the default
            }
            Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    private static String fmt(double v) {
        String s = String.format(Locale.ROOT, "%.2f", v);
        return s.endsWith(".00") ? s.substring(0, s.length() - 3) : s;
    }

    /** A summary for the top of every report. */
    static String summary(GradeReport r) {
        StringBuilder b = new StringBuilder();
        if (r.failed()) {
            b.append("Grading failed, no points decided: ").append(r.failure()).append('\n');
        } else {
            b.append("Score: ").append(fmt(r.score())).append(" / ").append(fmt(r.maxScore())).append('\n');
        }
        for (GradeReport.Milestone m : r.milestones()) {
            b.append(String.format(Locale.ROOT, "  %-10s %6s / %-6s %s%n", m.id(), fmt(m.score()), fmt(m.maxScore()),
                    m.title()));
            for (String n : m.notes()) {
                b.append("      ").append(n.replace("\n", "\n      ")).append('\n');
            }
        }
        if (!r.accepted().isEmpty()) {
            b.append("Graded files:\n");
            r.accepted().forEach(a -> b.append("  ").append(a).append('\n'));
        }
        if (!r.ignored().isEmpty()) {
            b.append("Ignored (only the files of the assignments are graded):\n");
            r.ignored().stream().limit(50).forEach(a -> b.append("  ").append(a).append('\n'));
            if (r.ignored().size() > 50) {
                b.append("  ... and ").append(r.ignored().size() - 50).append(" more\n");
            }
        }
        for (String n : r.notes()) {
            b.append(n).append('\n');
        }
        return b.toString();
    }

    /**
     * Gradescope's results.json. The top-level {@code output} is HTML ({@code output_format:
     * "html"} in Gradescope's autograder specification): visible scores, what to fix first, each
     * scene's images and every failed visible test's message, see {@link HtmlReport}. Each test's
     * own output is text, with its zero-point note. Scores are rounded to cents; a milestone's
     * tests add up to its points exactly.
     *
     * <p>What Gradescope shows before the due date: the top-level {@code output} always (so it
     * holds no hidden score, total or message), each test entry by its {@code visibility}
     * (hidden tests carry the assignment's {@code hiddenVisibility}), standard output never
     * ({@code stdout_visibility: "hidden"}), and the top-level {@code score} only when no test is
     * hidden ("If test cases are hidden, students will not be able to see their total score",
     * Gradescope's autograder specification, Controlling test case visibility). So the total
     * stays the full grade, hidden tests included, and is shown once they are.
     */
    public static String gradescope(GradeReport r) throws IOException {
        Map<String, Object> root = new LinkedHashMap<>();
        if (r.failed()) {
            // No score and no tests: none was decided, and a part's 0 is not the student's.
            // Gradescope's own run_autograder (bundle gradescope) does not upload this file at all,
            // so that Gradescope says "The autograder failed to execute correctly"; grade-all's
            // status column says "grading failed" and its next run grades the student again.
            root.put("execution_time", Math.round(r.seconds()));
            root.put("output", GradeReport.FAILED_FOR_STUDENTS);
            Map<String, Object> extra = new LinkedHashMap<>();
            extra.put("grading_failed", true);
            List<String> parts = failedParts(r);
            if (!parts.isEmpty()) {
                extra.put(GradingStatus.FAILED_TESTS, parts);
            }
            root.put("extra_data", extra);
            root.put("visibility", "visible");
            root.put("stdout_visibility", "hidden");
            root.put("tests", List.of());
            return JSON.writeValueAsString(root);
        }
        root.put("score", GradeReport.round(r.score()));
        root.put("execution_time", Math.round(r.seconds()));
        root.put("output", HtmlReport.forStudents(r));
        root.put("output_format", "html");
        root.put("test_output_format", "text");
        root.put("visibility", "visible");
        root.put("stdout_visibility", "hidden");
        List<Map<String, Object>> tests = new ArrayList<>();
        for (Numbered n : numbered(r)) {
            GradeReport.Test t = n.test();
            Map<String, Object> j = new LinkedHashMap<>();
            j.put("name", n.milestone() + ": " + t.name() + (t.kind() == Kind.HIDDEN ? " (hidden test)" : ""));
            j.put("number", n.number());
            j.put("score", GradeReport.round(t.score()));
            j.put("max_score", GradeReport.round(t.maxScore()));
            j.put("status", t.passed() ? "passed" : "failed");
            String out = t.passed() ? "" : t.message();
            if (t.images() != null && !t.images().metric().isEmpty() && t.passed()) {
                out = t.images().metric();
            }
            if (!t.note().isEmpty()) {
                out += (out.isEmpty() ? "" : "\n\n") + "Note (no points taken): " + t.note();
            }
            if (!t.output().isBlank()) {
                out += (out.isEmpty() ? "" : "\n\n") + (t.output().contains("more bytes of output dropped")
                        ? "Output (the output past the cap was dropped):\n" : "Output:\n") + t.output();
            }
            j.put("output", out);
            j.put("tags", List.of(n.milestone(), t.kind().label()));
            j.put("visibility", t.visibility());
            tests.add(j);
        }
        root.put("tests", tests);
        return JSON.writeValueAsString(root);
    }

    /**
     * The numbers ("milestone.test", as in a graded results.json) of the parts whose grading
     * failed on the grader's side, as a value for grade-all's status column: their messages hold
     * the student's output too, so their text decides nothing.
     */
    private static List<String> failedParts(GradeReport r) {
        return numbered(r).stream().filter(n -> n.test().status() == GradingStatus.GRADING_FAILED)
                .map(Numbered::number).toList();
    }

    /** A graded item and its number in Gradescope's results.json: "2.5", the fifth of the second milestone. */
    private record Numbered(String number, String milestone, GradeReport.Test test) {
    }

    private static List<Numbered> numbered(GradeReport r) {
        List<Numbered> all = new ArrayList<>();
        for (int mi = 0; mi < r.milestones().size(); mi++) {
            GradeReport.Milestone m = r.milestones().get(mi);
            for (int ti = 0; ti < m.tests().size(); ti++) {
                all.add(new Numbered((mi + 1) + "." + (ti + 1), m.id(), m.tests().get(ti)));
            }
        }
        return all;
    }

    static String xml(String s) {
        if (s == null) {
            return "";
        }
        StringBuilder b = new StringBuilder();
        for (char c : s.toCharArray()) {
            switch (c) {
                case '<' -> b.append("&lt;");
                case '>' -> b.append("&gt;");
                case '&' -> b.append("&amp;");
                case '"' -> b.append("&quot;");
                case '\'' -> b.append("&#39;");
                default -> {
                    if (c < 0x20 && c != '\n' && c != '\t' && c != '\r') {
                        b.append('?');
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        return b.toString();
    }

    /** JUnit XML: one testsuite per milestone. */
    public static String junitXml(GradeReport r) {
        StringBuilder b = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        long failures = r.milestones().stream().flatMap(m -> m.tests().stream()).filter(t -> !t.passed()).count();
        long total = r.milestones().stream().mapToLong(m -> m.tests().size()).sum();
        b.append("<testsuites name=\"raylab\" tests=\"").append(total).append("\" failures=\"").append(failures)
                .append("\" time=\"").append(String.format(Locale.ROOT, "%.3f", r.seconds())).append("\">\n");
        for (GradeReport.Milestone m : r.milestones()) {
            long f = m.tests().stream().filter(t -> !t.passed()).count();
            b.append("  <testsuite name=\"").append(xml(m.id())).append("\" tests=\"").append(m.tests().size())
                    .append("\" failures=\"").append(f).append("\">\n");
            b.append("    <properties><property name=\"score\" value=\"").append(fmt(m.score()))
                    .append("\"/><property name=\"max_score\" value=\"").append(fmt(m.maxScore())).append("\"/></properties>\n");
            for (GradeReport.Test t : m.tests()) {
                b.append("    <testcase classname=\"").append(xml(m.id() + "." + t.kind().label())).append("\" name=\"")
                        .append(xml(t.name())).append("\" time=\"")
                        .append(String.format(Locale.ROOT, "%.3f", t.millis() / 1000.0)).append("\">");
                if (!t.passed()) {
                    String first = GraderSetup.firstLine(t.message());
                    b.append("\n      <failure message=\"").append(xml(first)).append("\">").append(xml(t.message()))
                            .append("</failure>\n    ");
                }
                b.append("</testcase>\n");
            }
            b.append("  </testsuite>\n");
        }
        b.append("</testsuites>\n");
        return b.toString();
    }

    /** The console table. */
    public static void table(GradeReport r, PrintStream out) {
        out.println(String.format(Locale.ROOT, "%-10s %-9s %-52s %7s  %s", "milestone", "kind", "test", "points", "result"));
        for (GradeReport.Milestone m : r.milestones()) {
            for (GradeReport.Test t : m.tests()) {
                String name = t.name().length() > 52 ? t.name().substring(0, 49) + "..." : t.name();
                out.println(String.format(Locale.ROOT, "%-10s %-9s %-52s %7s  %s", m.id(), t.kind().label(), name,
                        fmt(t.score()) + "/" + fmt(t.maxScore()),
                        t.passed() ? "pass" : "FAIL: " + clip(GraderSetup.firstLine(t.message()), 100)));
            }
        }
        out.println();
        out.print(summary(r));
    }

    private static String clip(String s, int n) {
        return s.length() <= n ? s : s.substring(0, n - 3) + "...";
    }

    /** One self-contained HTML page for instructors: everything, see {@link HtmlReport}. */
    public static String html(GradeReport r) {
        return HtmlReport.forInstructors(r);
    }
}
