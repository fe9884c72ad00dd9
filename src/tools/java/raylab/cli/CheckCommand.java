package raylab.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.MilestoneCheck;

/** {@code raylab check [MILESTONE]}: runs the visible tests, renders the scenes, says what to do next. */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = {"Run the visible tests of one milestone (or all) and compare its scenes with the references.",
            "Shows the first failures in full (message and hint) under their handout names, a points table with the",
            "autograder's points for everything you can run here, and a table: tests passed, scenes matching, what next."},
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

    @Option(names = "--classroom50", paramLabel = "FILE",
            description = "Also write Classroom 50's result.json to FILE (what its autograder.py runs).")
    Path classroom50;

    @Option(names = "--watch", description = "Run again after every save of one of your files (clearing the screen"
            + " each time); Ctrl-C stops.")
    boolean watch;

    @Override
    public Integer call() throws Exception {
        if (watch) {
            return Watch.again(spec, List.of());
        }
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
        // What the grader builds differently: it never uses the student's copy of the framework,
        // nor the student's files of another milestone. A milestone that will not compile there
        // scores 0 in the table and in Classroom 50's result, as the grader will score it.
        raylab.course.GradedBuild.Drift drift = SubmitCheckCommand.drift(root,
                SubmitCheckCommand.projectFiles(root, selected), SubmitCheckCommand.projectFiles(root, all.all()),
                all.all(), raylab.course.JavaBuild.ownClassPath());
        Map<String, List<String>> wontCompile = SubmitCheckCommand.wontCompile(root, selected, all.all(), drift,
                raylab.course.JavaBuild.ownClassPath());
        printTable(out, outcomes, wontCompile);
        boolean breaks = SubmitCheckCommand.printDrift(out, drift);
        out.flush();
        if (classroom50 != null) {
            raylab.course.Classroom50Result.write(classroom50, outcomes, wontCompile, System.getenv(), root);
        }
        return !breaks && outcomes.stream().allMatch(MilestoneCheck.Outcome::done) ? Main.OK : Main.FAILED;
    }

    /** How many failures are shown in full (message and hint); the rest get one line each. */
    static final int FULL = 3;

    static void printDetails(PrintWriter out, MilestoneCheck.Outcome o) {
        List<String> lines = new ArrayList<>();
        if (!o.problem().isEmpty()) {
            lines.add("  " + o.problem());
        }
        List<MilestoneCheck.Outcome.Row> rows = o.rows();
        List<MilestoneCheck.Outcome.Row> failing = rows.stream()
                .filter(r -> !r.passed() && r.ran() && r.item().kind() != raylab.course.GradingPlan.Kind.SCENE).toList();
        if (failing.size() > 1 && failing.stream().map(r -> r.message()).distinct().count() == 1) {
            lines.add("  FAIL all " + failing.size() + " failing tests: " + oneLine(failing.get(0).message()));
        } else {
            int shown = 0;
            for (MilestoneCheck.Outcome.Row r : failing) {
                String name = (r.item().kind() == raylab.course.GradingPlan.Kind.CASE ? "data case " : "")
                        + "\"" + r.item().name() + "\"";
                if (shown++ < FULL) {
                    lines.add("  FAIL " + name);
                    for (String l : r.message().strip().split("\n")) {
                        lines.add("       " + l);
                    }
                } else {
                    lines.add("  FAIL " + name + ": " + oneLine(r.message()));
                }
            }
        }
        for (MilestoneCheck.SceneOutcome s : o.scenes()) {
            lines.add("  " + sceneWord(s) + " " + s.scene().scene() + ": "
                    + oneLine(s.message()).replaceFirst("^(MATCH|DIFFERS): ", ""));
            if (s.status() == MilestoneCheck.SceneStatus.DIFFERS) { // issue 40: the worst pixel's first difference
                raylab.inspect.Inspection.checkLine(s.scene().scene()).ifPresent(l -> lines.add("          " + l));
            }
        }
        if (!lines.isEmpty()) {
            out.println(o.assignment().id() + ":");
            lines.forEach(out::println);
        }
        printPoints(out, o);
    }

    /**
     * The points of everything the student can run locally, with the autograder's points and
     * tolerances (both read them from assignment.json through GradingPlan), and a line for what is hidden.
     */
    static void printPoints(PrintWriter out, MilestoneCheck.Outcome o) {
        if (o.plan() == null) {
            return;
        }
        List<MilestoneCheck.Outcome.Row> rows = o.rows();
        out.println(o.assignment().id() + ": points you can check here (the autograder gives the same)");
        for (MilestoneCheck.Outcome.Row r : rows) {
            raylab.course.GradingPlan.Item i = r.item();
            String status = i.kind() == raylab.course.GradingPlan.Kind.SCENE ? o.scenes().stream()
                    .filter(s -> s.scene().scene().equals(i.key())).findFirst().map(CheckCommand::sceneWord)
                    .orElse(r.passed() ? "MATCH  " : "DIFFERS") : (r.passed() ? "pass   " : "FAIL   ");
            String pts = raylab.course.GradingPlan.points(r.passed() ? i.cents() : 0) + "/"
                    + raylab.course.GradingPlan.points(i.cents());
            String name = switch (i.kind()) {
                case TEST -> "\"" + i.name() + "\"";
                case CASE -> "data case \"" + i.name() + "\"";
                case SCENE -> i.name() + " (tolerance " + raylab.course.GradingPlan.percent(i.tolerance()) + ")";
            };
            out.printf("  %s %-11s %s%n", status, pts, name);
        }
        out.println("  visible total: " + raylab.course.GradingPlan.points(o.earnedCents()) + " / "
                + raylab.course.GradingPlan.points(o.plan().visibleCents()) + " points");
        String hidden = o.plan().hiddenLine();
        if (!hidden.isEmpty()) {
            out.println("  " + hidden);
        }
        out.println();
    }

    /** MATCH, DIFFERS, or why the scene has no picture to compare (the same words as render --compare). */
    static String sceneWord(MilestoneCheck.SceneOutcome s) {
        return switch (s.status()) {
            case MATCH -> "MATCH  ";
            case DIFFERS -> "DIFFERS";
            case NOT_IMPLEMENTED -> "NOT IMPLEMENTED";
            case ERROR -> "ERROR  ";
        };
    }

    private static String oneLine(String s) {
        String t = s == null ? "" : s.strip();
        int nl = t.indexOf('\n');
        t = nl < 0 ? t : t.substring(0, nl);
        return raylab.course.MilestoneCheck.oneLine(t, 160);
    }

    static void printTable(PrintWriter out, List<MilestoneCheck.Outcome> outcomes) {
        printTable(out, outcomes, Map.of());
    }

    /** The summary table; a milestone of {@code wontCompile} scores 0, as at the grader. */
    static void printTable(PrintWriter out, List<MilestoneCheck.Outcome> outcomes, Map<String, List<String>> wontCompile) {
        String fmt = "%-10s %-14s %-16s %-15s %s%n";
        out.println();
        out.printf(fmt, "milestone", "tests passed", "scenes matching", "visible points", "next");
        long earned = 0;
        long visible = 0;
        for (MilestoneCheck.Outcome o : outcomes) {
            boolean breaks = wontCompile.containsKey(o.assignment().id());
            String tests = o.problem().isEmpty() || !o.tests().isEmpty()
                    ? o.testsPassed() + "/" + o.testCount() : "-";
            long mine = breaks ? 0 : o.earnedCents();
            String points = o.plan() == null ? "-" : raylab.course.GradingPlan.points(mine) + "/"
                    + raylab.course.GradingPlan.points(o.plan().visibleCents());
            if (o.plan() != null) {
                earned += mine;
                visible += o.plan().visibleCents();
            }
            out.printf(fmt, o.assignment().id(), tests, o.scenesMatching() + "/" + o.scenes().size(), points,
                    breaks ? "will not compile at the grader (below): 0 points there" : o.nextStep());
        }
        out.println("visible total: " + raylab.course.GradingPlan.points(earned) + " / "
                + raylab.course.GradingPlan.points(visible) + " points"
                + (outcomes.size() > 1 ? " (" + outcomes.size() + " milestones)" : "")
                + "; hidden tests and data cases are graded after you submit");
    }
}
