package raylab.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.MilestoneCheck;
import raylab.course.TestResult;

/** {@code raylab check [MILESTONE]}: runs the visible tests, renders the scenes, says what to do next. */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = {"Run the visible tests of one milestone (or all) and compare its scenes with the references.",
            "Ends with a table: tests passed, scenes matching, and what to look at next."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every test passed and every scene matched", "1:something did not",
            "2:unknown milestone, or not run from the project folder"})
public final class CheckCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "MILESTONE",
            description = "sphere, box, triangle, lambert, shadows or phong (default: all).")
    String milestone;

    @Option(names = "--threads", paramLabel = "N", description = "Render threads (default: all cores, ${DEFAULT-VALUE}).")
    int threads = Runtime.getRuntime().availableProcessors();

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        Path root = Path.of("").toAbsolutePath();
        if (threads < 1) {
            throw UserError.badInput("--threads must be at least 1, got " + threads);
        }
        Assignments all;
        try {
            all = Assignments.load(root);
        } catch (IOException e) {
            throw UserError.badInput(e.getMessage());
        }
        List<Assignment> selected;
        if (milestone == null) {
            selected = all.all();
        } else {
            selected = all.byId(milestone).map(List::of).orElseThrow(() -> UserError.badInput(
                    "unknown milestone '" + milestone + "': valid ids are " + String.join(", ", all.ids())));
        }
        List<MilestoneCheck.Outcome> outcomes = MilestoneCheck.run(root, selected, threads, line -> {
            out.println(line);
            out.flush();
        });
        out.println();
        for (MilestoneCheck.Outcome o : outcomes) {
            printDetails(out, o);
        }
        printTable(out, outcomes);
        out.flush();
        return outcomes.stream().allMatch(MilestoneCheck.Outcome::done) ? Main.OK : Main.FAILED;
    }

    private static void printDetails(PrintWriter out, MilestoneCheck.Outcome o) {
        List<String> lines = new ArrayList<>();
        if (!o.problem().isEmpty()) {
            lines.add("  " + o.problem());
        }
        List<TestResult> failing = o.tests().stream().filter(t -> !t.status().passed()).toList();
        if (failing.size() > 1 && failing.stream().map(TestResult::message).distinct().count() == 1) {
            lines.add("  FAIL all " + failing.size() + " failing tests: " + oneLine(failing.get(0).message()));
        } else {
            for (TestResult t : failing.subList(0, Math.min(5, failing.size()))) {
                String c = t.className().substring(t.className().lastIndexOf('.') + 1);
                lines.add("  FAIL " + c + "." + t.method() + ": " + oneLine(t.message()));
            }
            if (failing.size() > 5) {
                lines.add("  ... and " + (failing.size() - 5) + " more failing tests (./mvnw test -Dgroups="
                        + o.assignment().id() + " shows them all)");
            }
        }
        for (MilestoneCheck.SceneOutcome s : o.scenes()) {
            lines.add("  " + (s.matches() ? "match " : "scene ") + s.scene().scene() + ": " + oneLine(s.message()));
        }
        if (!lines.isEmpty()) {
            out.println(o.assignment().id() + ":");
            lines.forEach(out::println);
        }
    }

    private static String oneLine(String s) {
        String t = s == null ? "" : s.strip();
        int nl = t.indexOf('\n');
        t = nl < 0 ? t : t.substring(0, nl);
        return t.length() <= 160 ? t : t.substring(0, 157) + "...";
    }

    static void printTable(PrintWriter out, List<MilestoneCheck.Outcome> outcomes) {
        String fmt = "%-10s %-14s %-16s %s%n";
        out.println();
        out.printf(fmt, "milestone", "tests passed", "scenes matching", "next");
        for (MilestoneCheck.Outcome o : outcomes) {
            String tests = o.problem().isEmpty() || !o.tests().isEmpty()
                    ? o.testsPassed() + "/" + o.tests().size() : "-";
            out.printf(fmt, o.assignment().id(), tests, o.scenesMatching() + "/" + o.scenes().size(), o.nextStep());
        }
    }
}
