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
import raylab.cli.OptionalCommand;
import raylab.course.JavaBuild;
import raylab.course.TestLauncher;

/** {@code raylab grade SUBMISSION --out DIR}: the autograder (instructor tree only). */
@Command(name = "grade", mixinStandardHelpOptions = true,
        description = {"Grade a student's submission milestone by milestone (instructors and autograders).",
            "SUBMISSION is a directory or a zip, in the release's layout or flat. Writes results.json (Gradescope),",
            "junit.xml and report.html into --out (and PrairieLearn's results.json with --prairielearn), and prints a table.",
            "Details: grader/README.md."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:graded (whatever the score)", "1:the grading failed, no points decided: the grader could not grade, or a part of it failed on the"
                + " grader's side (results.json still written, without a score)",
            "2:bad option, or no such submission (results.json still written)"})
public final class GradeCommand implements Callable<Integer>, OptionalCommand {
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

    @Option(names = "--sandbox", paramLabel = "MODE", hidden = true,
            description = "Isolation of student code: auto (default), namespace, user, none (for tests).")
    String sandbox = "auto";

    @Option(names = "--quiet", description = "Print only the total score.")
    boolean quiet;

    @Option(names = "--prairielearn", paramLabel = "FILE",
            description = "Also write PrairieLearn's external-grading results.json to FILE (see grader/README.md).")
    Path prairielearn;

    @Option(names = "--after-due-date",
            description = "With --prairielearn: include the hidden tests (a regrade after the due date).")
    boolean afterDueDate;

    @Option(names = "--seed", paramLabel = "N", description = {"Seed of the graded scenes' variants (default: drawn fresh;",
        "the report names it, so that a regrade with --seed N grades the same variants)."})
    Long seed;

    @Option(names = "--die-with-parent", hidden = true,
            description = "End (with every process it started) when standard input closes: grade-all's pipe.")
    boolean dieWithParent;

    @Option(names = "--lock", paramLabel = "FILE", hidden = true,
            description = "Hold a lock on FILE while grading; refuse (exit 1) if another grading holds it 60 s.")
    Path lock;

    @Override
    public Integer call() throws IOException {
        if (dieWithParent) {
            raylab.grade.platform.ClassScale.dieWithParent("raylab grade");
        }
        if (lock == null) {
            return grade();
        }
        Files.createDirectories(lock.toAbsolutePath().getParent());
        // A grading being stopped (its grade-all was killed) lets go within moments; a live one does not.
        try (raylab.grade.platform.ClassScale.Lock l = raylab.grade.platform.ClassScale.Lock.take(lock, 60_000)) {
            if (l == null) {
                System.err.println("raylab: another grading is writing " + out + " (" + lock + " is locked); not graded");
                return 1;
            }
            return grade();
        }
    }

    private int grade() throws IOException {
        if (!Files.isDirectory(submission) && !Files.isRegularFile(submission)) {
            // A wrong path is a bad option (exit 2, one line), not a submission scored 0.
            throw raylab.cli.UserError.badInput(raylab.scene.Display.path(submission) + ": "
                    + (Files.exists(submission, java.nio.file.LinkOption.NOFOLLOW_LINKS)
                            ? "not a directory or a zip file" : "no such file or directory")
                    + " (the submission to grade)");
        }
        PrintStream stdout = new PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.out), true,
                StandardCharsets.UTF_8);
        Grader.Options o = Grader.Options.defaults(root.toAbsolutePath().normalize())
                .withMilestones(milestones)
                .withLimits(new TestLauncher.Limits(heap, Duration.ofSeconds(milestoneTimeout), testTimeout, 16 * 1024),
                        Duration.ofSeconds(sceneTimeout))
                .withSandboxUser(sandboxUser);
        o = new Grader.Options(o.root(), o.milestones(), o.limits(), o.sceneLimit(), heap, cache == null
                ? o.cacheDir() : cache.toAbsolutePath(), o.sandboxUser(), o.parallel()).withSandboxMode(mode(sandbox));
        Path pl = prairielearn == null ? null : prairielearn.toAbsolutePath();
        boolean after = afterDueDate;
        return run(o, seed == null ? GradedScenes.freshSeed() : seed, submission, out, s -> {
            if (!quiet) {
                System.err.println(s);
            }
        }, quiet, stdout, pl == null ? null : report -> {
            try {
                Files.createDirectories(pl.getParent());
                Reports.write(pl, raylab.grade.platform.PrairieLearn.results(report, after));
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        });
    }

    private static Sandbox.Isolation mode(String s) {
        for (Sandbox.Isolation m : Sandbox.Isolation.values()) {
            if (m.name().equalsIgnoreCase(s)) {
                return m;
            }
        }
        throw new picocli.CommandLine.ParameterException(new picocli.CommandLine(new GradeCommand()),
                "--sandbox: one of auto, namespace, user, none");
    }

    /**
     * Grades and writes the results, whatever happens: any {@link Throwable} of the grader itself
     * (a {@code StackOverflowError} or an {@code OutOfMemoryError} included) becomes a results.json
     * with score 0 that names the failure, and exit status 1. A submission that does not exist is
     * exit status 2 (with a results.json too). The results are written after the last child
     * process is gone, then read back and rewritten if anything changed them.
     */
    static int run(Grader.Options o, Path submission, Path out, java.util.function.Consumer<String> log, boolean quiet,
            PrintStream stdout) {
        return run(o, GradedScenes.freshSeed(), submission, out, log, quiet, stdout, null);
    }

    /**
     * As above, with the seed of the graded scenes' variants; {@code also} writes a platform's
     * file from the same report (after the others).
     */
    static int run(Grader.Options o, long seed, Path submission, Path out, java.util.function.Consumer<String> log,
            boolean quiet, PrintStream stdout, java.util.function.Consumer<GradeReport> also) {
        long t0 = System.nanoTime();
        GradeReport report = null;
        int status = 0;
        Set<String> before = Set.of();
        try {
            Files.createDirectories(out);
            before = list(out);
            if (!Files.exists(submission, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
                report = Grader.nothingSubmitted(submission + ": no such file or directory (nothing was submitted)",
                        (System.nanoTime() - t0) / 1e9);
                System.err.println("raylab: " + oneLine(submission + ": no such file or directory"));
                status = 2;
            } else {
                report = new Grader(o, log).seed(seed).grade(submission);
                if (report.failed()) {
                    // A milestone the course's setup cannot grade, or a part that failed on the
                    // grader's side: no grade was decided.
                    System.err.println("raylab: grading failed: " + oneLine(report.failure()));
                    status = 1;
                }
            }
        } catch (Throwable e) {
            report = null;
            String why = describe(e);
            try {
                report = Grader.failed(why, (System.nanoTime() - t0) / 1e9);
            } catch (Throwable again) {
                // no memory even for that: the minimal file below
            }
            System.err.println("raylab: grading failed: " + why);
            status = 1;
        }
        try {
            removeStrayFiles(out, before);
            Reports.writeAll(report, out);
            // Re-verify: what is on disk is what the grader wrote (nothing of the submission runs any more).
            String expected = Reports.gradescope(report);
            if (!expected.equals(Files.readString(out.resolve("results.json"), StandardCharsets.UTF_8))) {
                System.err.println("raylab: results.json changed after it was written; written again");
                Reports.writeAll(report, out);
            }
            if (also != null && report != null) {
                also.accept(report);
            }
            if (quiet) {
                stdout.println(Reports.summary(report).lines().findFirst().orElse(""));
            } else {
                Reports.table(report, stdout);
                stdout.println("Results: " + out.resolve("results.json") + ", report: " + out.resolve("report.html"));
            }
        } catch (Throwable e) {
            writeMinimal(out);
            System.err.println("raylab: grading failed: " + (report == null ? "the grader failed" : String.join("; ", report.notes())));
            System.err.println("raylab: writing the reports failed: " + describe(e));
            return status == 0 ? 1 : status;
        }
        return status;
    }

    /** One line naming a failure of the grader: its type, message and where it happened. */
    static String describe(Throwable e) {
        String type = e.getClass().getSimpleName();
        String msg = e instanceof StackOverflowError ? "endless recursion in the grader"
                : e instanceof OutOfMemoryError ? "the grader ran out of memory" : e.getMessage();
        String where = "";
        for (StackTraceElement el : e.getStackTrace()) {
            if (el.getClassName().startsWith("raylab.")) {
                where = " (at " + el.getClassName() + "." + el.getMethodName() + ":" + el.getLineNumber() + ")";
                break;
            }
        }
        String s = (e instanceof java.io.IOException || e instanceof RuntimeException) && msg != null ? msg
                : type + (msg == null ? "" : ": " + msg) + where;
        return oneLine(s);
    }

    /** The text on one line: control characters (newlines included) escaped. */
    static String oneLine(String s) {
        StringBuilder b = new StringBuilder();
        for (char c : String.valueOf(s).toCharArray()) {
            b.append(Character.isISOControl(c) ? String.format("\\u%04x", (int) c) : String.valueOf(c));
        }
        return b.toString();
    }

    /**
     * A results.json built without any library, for when even the reports could not be written:
     * a failed grading ({@link GradeReport#FAILED_FOR_STUDENTS}, no score); the cause goes to
     * standard error, for the course staff.
     */
    private static void writeMinimal(Path out) {
        StringBuilder b = new StringBuilder();
        String text = GradeReport.FAILED_FOR_STUDENTS;
        for (char c : text.toCharArray()) {
            if (c == '"' || c == '\\') {
                b.append('\\').append(c);
            } else if (c < 32) {
                b.append(String.format("\\u%04x", (int) c));
            } else {
                b.append(c);
            }
        }
        try {
            Files.createDirectories(out);
            Files.writeString(out.resolve("results.json"), "{\"execution_time\": 0, \"output\": \"" + b
                    + "\", \"extra_data\": {\"grading_failed\": true}, \"tests\": []}\n", StandardCharsets.UTF_8);
        } catch (Throwable ignored) {
            // nothing more can be done
        }
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
                JavaBuild.deleteTreeQuietly(p);
            }
        }
    }
}
