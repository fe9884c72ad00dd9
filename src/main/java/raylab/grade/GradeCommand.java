package raylab.grade;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.stream.Stream;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import raylab.course.TestLauncher;

/** {@code raylab grade SUBMISSION --out DIR}: the autograder (instructor tree only). */
@Command(name = "grade", mixinStandardHelpOptions = true,
        description = {"Grade a student's submission milestone by milestone (instructors and autograders).",
            "SUBMISSION is a directory or a zip, in the release's layout or flat. Writes results.json (Gradescope),",
            "classroom.json/.b64 (GitHub Classroom), junit.xml and report.html into --out, and prints a table.",
            "Details: grader/README.md."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:graded (whatever the score)", "1:the grader could not grade (results.json still written)",
            "2:bad option, or no such submission"})
public final class GradeCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "SUBMISSION", description = "Directory or zip of the student's files.")
    Path submission;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Where to write the results.")
    Path out;

    @Option(names = "--milestone", paramLabel = "M", description = "Grade only these milestones (repeatable).")
    List<String> milestones = new ArrayList<>();

    @Option(names = "--root", paramLabel = "DIR", description = "The instructor's project root (default: current directory).")
    Path root = Path.of(".");

    @Option(names = "--test-timeout", paramLabel = "S", description = "Time limit of one test, seconds (default: ${DEFAULT-VALUE}).")
    int testTimeout = 10;

    @Option(names = "--milestone-timeout", paramLabel = "S",
            description = "Time limit of one milestone's test JVM, seconds (default: ${DEFAULT-VALUE}).")
    int milestoneTimeout = 120;

    @Option(names = "--scene-timeout", paramLabel = "S", description = "Time limit of one scene render, seconds (default: ${DEFAULT-VALUE}).")
    int sceneTimeout = 60;

    @Option(names = "--heap", paramLabel = "MB", description = "Heap of each child JVM, MB (default: ${DEFAULT-VALUE}).")
    int heap = 512;

    @Option(names = "--sandbox-user", paramLabel = "USER",
            description = "Unprivileged user for student code when run as root (default: raylab-student; \"\" for none).")
    String sandboxUser;

    @Option(names = "--cache", paramLabel = "DIR", description = "Cache of built grader classes (default: ROOT/target/grader-cache).")
    Path cache;

    @Option(names = "--quiet", description = "Print only the total score.")
    boolean quiet;

    @Override
    public Integer call() throws IOException {
        if (!Files.isDirectory(submission) && !Files.isRegularFile(submission)) {
            // A wrong path is a bad option (exit 2, one line), not a submission scored 0.
            throw raylab.cli.UserError.badInput(raylab.scene.Display.path(submission) + ": "
                    + (Files.exists(submission, java.nio.file.LinkOption.NOFOLLOW_LINKS)
                            ? "not a directory or a zip file" : "no such file or directory")
                    + " (the submission to grade)");
        }
        PrintStream stdout = new PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.out), true,
                StandardCharsets.UTF_8);
        Files.createDirectories(out);
        Set<String> before = list(out);
        Grader.Options o = Grader.Options.defaults(root.toAbsolutePath().normalize())
                .withMilestones(milestones)
                .withLimits(new TestLauncher.Limits(heap, Duration.ofSeconds(milestoneTimeout), testTimeout, 16 * 1024),
                        Duration.ofSeconds(sceneTimeout))
                .withSandboxUser(sandboxUser);
        o = new Grader.Options(o.root(), o.milestones(), o.limits(), o.sceneLimit(), heap, cache == null
                ? o.cacheDir() : cache.toAbsolutePath(), o.sandboxUser(), o.parallel());
        long t0 = System.nanoTime();
        GradeReport report;
        int status = 0;
        try {
            report = new Grader(o, s -> {
                if (!quiet) {
                    System.err.println(s);
                }
            }).grade(submission);
        } catch (IOException | RuntimeException e) {
            report = Grader.failed(e.getMessage() == null ? e.toString() : e.getMessage(), (System.nanoTime() - t0) / 1e9);
            System.err.println("raylab: grading failed: " + report.notes().get(0));
            status = 1;
        }
        removeStrayFiles(out, before);
        Reports.writeAll(report, out);
        if (quiet) {
            stdout.println(Reports.summary(report).lines().findFirst().orElse(""));
        } else {
            Reports.table(report, stdout);
            stdout.println("Results: " + out.resolve("results.json") + ", report: " + out.resolve("report.html"));
        }
        return status;
    }

    private static Set<String> list(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            Set<String> names = new HashSet<>();
            s.forEach(p -> names.add(p.getFileName().toString()));
            return names;
        }
    }

    /** Files that appeared in the output directory during grading and that the grader did not write. */
    private static void removeStrayFiles(Path out, Set<String> before) throws IOException {
        for (String name : list(out)) {
            if (!before.contains(name)) {
                Path p = out.resolve(name);
                System.err.println("raylab: removing " + p + ", which appeared during grading (not written by the grader)");
                GraderSetup.deleteTree(p);
            }
        }
    }
}
