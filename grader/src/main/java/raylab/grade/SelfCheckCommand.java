package raylab.grade;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

import raylab.cli.OptionalCommand;

/**
 * {@code raylab self-check}: the course checks itself ({@link CourseCheck}); one line per problem
 * and exit status 1 when there is any. {@code bundle} runs the same check on the bundle's own
 * files, and Gradescope's {@code setup.sh} runs this command in the image (it also builds the
 * grader's cache).
 */
@Command(name = "self-check", mixinStandardHelpOptions = true,
        description = {"Check the course before students see it (instructors): points add up, the grader's tests",
            "compile and pass on the reference, every graded scene's variants keep its point, and the reference",
            "solution graded with these files scores full marks. One line per problem."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:the course is ready", "1:a problem (one line each)"})
public final class SelfCheckCommand implements Callable<Integer>, OptionalCommand {
    @Spec
    CommandSpec spec;

    @Option(names = "--root", paramLabel = "DIR", description = "The course's root (default: current directory).")
    Path root = Path.of(".");

    @Option(names = "--cache", paramLabel = "DIR", description = "Cache of built grader classes (default: ROOT/target/grader-cache).")
    Path cache;

    @Option(names = "--milestone", paramLabel = "M", description = "Check only these milestones (repeatable).")
    List<String> milestones = new ArrayList<>();

    @Option(names = "--quiet", description = "Print only the problems.")
    boolean quiet;

    @Override
    public Integer call() {
        Path r = root.toAbsolutePath().normalize();
        Grader.Options o = Grader.Options.defaults(r);
        if (cache != null) {
            o = new Grader.Options(r, o.milestones(), o.limits(), o.sceneLimit(), o.sceneHeapMb(), cache.toAbsolutePath(),
                    o.sandboxUser(), o.parallel(), o.sandboxMode());
        }
        return report(CourseCheck.problems(r, milestones, o, s -> {
            if (!quiet) {
                spec.commandLine().getErr().println(s);
            }
        }), spec.commandLine().getErr());
    }

    /** Prints the problems, one line each, and gives the exit status: 0 for none, 1 otherwise. */
    static int report(List<String> problems, java.io.PrintWriter err) {
        for (String p : problems) {
            err.println("raylab: course problem: " + p);
        }
        err.flush();
        return problems.isEmpty() ? 0 : 1;
    }
}
