package raylab.grade;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import raylab.cli.OptionalCommand;
import raylab.cli.UserError;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;
import raylab.course.SourceRoots;

/**
 * {@code raylab bundle TARGET --out PATH}: what a grading platform needs.
 * <ul>
 * <li>{@code gradescope}: Gradescope's autograder zip. It holds setup.sh and run_autograder at its
 * top, the grader jar and what grading reads (assignments, the grader's tests, the visible tests,
 * scenes with their references). Nothing is downloaded at grading time; setup.sh installs a JDK
 * only if the image has none.</li>
 * <li>{@code prairielearn}: a folder to copy into a PrairieLearn course repository, see
 * {@link raylab.grade.platform.PrairieLearnBundle}.</li>
 * <li>{@code classroom50}: a folder for the teacher's {@code classroom50} repository, see
 * {@link raylab.grade.platform.Classroom50Bundle}.</li>
 * </ul>
 */
@Command(name = "bundle", mixinStandardHelpOptions = true,
        description = {"Build what a grading platform needs (instructors): gradescope (a zip), prairielearn or",
            "classroom50 (a new folder). Details: grader/README.md, docs/instructors.md."})
public final class BundleCommand implements Callable<Integer>, OptionalCommand {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "TARGET", description = "gradescope, prairielearn or classroom50")
    String target;

    @Option(names = "--out", required = true, paramLabel = "PATH",
            description = "The zip (gradescope) or the new folder (prairielearn, classroom50) to write.")
    Path out;

    @Option(names = "--questions", paramLabel = "MODE",
            description = "prairielearn: one question per milestone (per-milestone, the default) or one for the whole assignment (whole).")
    String questions = "per-milestone";

    @Option(names = "--due", paramLabel = "INSTANT",
            description = "prairielearn: the due date (ISO 8601, e.g. 2027-03-01T23:59:00Z); gradings after it include"
                    + " the hidden tests. Without it PrairieLearn grades the visible parts only.")
    String due;

    @Option(names = "--image", paramLabel = "IMAGE", description = "prairielearn: the grading image (default: ${DEFAULT-VALUE}).")
    String image = "prairielearn/grader-java";

    @Option(names = "--timeout", paramLabel = "S",
            description = "prairielearn: the grading job's time limit, seconds, at most 600 (default: 300 per milestone, 600 whole).")
    Integer timeout;

    @Option(names = "--assignment", paramLabel = "SLUG", description = "classroom50: the assignment slug (default: ${DEFAULT-VALUE}).")
    String assignment = "raylab";

    @Option(names = "--java", paramLabel = "V", description = "classroom50: the runtime's Java version (default: ${DEFAULT-VALUE}).")
    String javaVersion = "21";

    @Option(names = "--root", paramLabel = "DIR", description = "The instructor's project root (default: current directory).")
    Path root = Path.of(".");

    @Option(names = "--jar", paramLabel = "JAR", description = "The grader jar (default: the running jar, or ROOT/target/raylab.jar).")
    Path jar;

    static final String SETUP = """
            #!/usr/bin/env bash
            # Gradescope setup: runs once when the autograder image is built. Any failure stops the
            # build (set -e), so a broken course never becomes a "successful" image.
            set -euo pipefail
            AG="${AUTOGRADER_ROOT:-/autograder}"
            # A JDK 17 or newer must be the one the grader uses, whatever the base image has (the
            # JDK 8 or 11 of an older image stays installed but is not used).
            java_major() { # the Java feature version of the java binary $1 (1.8 -> 8), or 0
              "$1" -XshowSettings:properties -version 2>&1 | sed -n 's/^ *java.specification.version = //p' \\
                | sed 's/^1\\.//' | cut -d. -f1 | grep -E '^[0-9]+$' || echo 0
            }
            jdk_ok() { # $1: a JDK's bin folder
              [ -x "$1/java" ] && [ -x "$1/javac" ] && [ "$(java_major "$1/java")" -ge 17 ]
            }
            JDK_BIN=""
            for d in "$(dirname "$(readlink -f "$(command -v javac 2>/dev/null || echo /nonexistent)")")" \\
                     /usr/lib/jvm/*/bin; do
              if jdk_ok "$d"; then JDK_BIN="$d"; break; fi
            done
            if [ -z "$JDK_BIN" ]; then
              apt-get update -q
              DEBIAN_FRONTEND=noninteractive apt-get install -y -q openjdk-17-jdk-headless \\
                || { echo "raylab setup: no JDK 17 package for this image; choose Gradescope's Ubuntu 22.04 base image" >&2; exit 1; }
              for d in /usr/lib/jvm/java-17-openjdk-*/bin; do
                if jdk_ok "$d"; then JDK_BIN="$d"; break; fi
              done
            fi
            if [ -z "$JDK_BIN" ]; then
              echo "raylab setup: no JDK 17 or newer found after installing one" >&2
              exit 1
            fi
            # run_autograder reads the JDK from here (not from PATH, where an older java may come first).
            echo "$JDK_BIN/java" > "$AG/source/java-path"
            echo "raylab setup: using $JDK_BIN/java ($("$JDK_BIN/java" -version 2>&1 | head -1))"
            if [ -n "${RAYLAB_SETUP_JDK_ONLY:-}" ]; then exit 0; fi # for tests: the JDK's choice alone
            # The unprivileged user that runs student code (the grader switches to it when root).
            if [ "$(id -u)" = 0 ] && ! id raylab-student >/dev/null 2>&1; then
              useradd -M -s /usr/sbin/nologin raylab-student
            fi
            # Students' code must not read the grader's sources, jar or reference images.
            chmod 700 "$AG/source"
            # The course checks itself with the files of this zip: the grader's tests compile and pass
            # on the reference, points add up, every graded scene's variants keep their point, and the
            # reference solution graded as a submission scores full marks; one line per problem, and the
            # build fails. It also builds the grader's classes and test list once, into the image (each
            # build folder private, 700; student code only sees links to the files it needs).
            mkdir -p "$AG/cache"
            (cd "$AG/source" && "$JDK_BIN/java" JVM_OPTIONS -jar raylab.jar self-check --root "$AG/source" \\
                --cache "$AG/cache" --quiet)
            chmod 755 "$AG/cache"
            """.replace("JVM_OPTIONS", JvmOptions.graderLine());

    static final String RUN = """
            #!/usr/bin/env bash
            # Gradescope entry point: grades /autograder/submission into /autograder/results.
            AG="${AUTOGRADER_ROOT:-/autograder}"
            mkdir -p "$AG/results"
            cd "$AG/source" || exit 1
            JAVA="$(cat "$AG/source/java-path" 2>/dev/null || echo java)"
            "$JAVA" JVM_OPTIONS -jar raylab.jar grade "$AG/submission" --out "$AG/results" --root "$AG/source" \\
                --cache "$AG/cache" --quiet 2>&1
            status=$?
            if [ "$status" -ne 0 ] || [ ! -s "$AG/results/results.json" ]; then
              # The grading failed: no points were decided. Without results.json Gradescope tells the
              # student "The autograder failed to execute correctly" and records no score (Gradescope's
              # autograder documentation, Troubleshooting); the cause is in this output, which only
              # instructors see.
              echo "raylab: the grading failed (exit status $status): no score was recorded; the cause is above"
              if [ -f "$AG/results/results.json" ]; then
                mv "$AG/results/results.json" "$AG/grading-failed-results.json"
              fi
              exit 1
            fi
            exit 0
            """.replace("JVM_OPTIONS", JvmOptions.graderLine());

    @Option(names = "--no-self-check", description = {"Skip the course's self-check (raylab self-check) on the bundle's files:",
        "only to look at a bundle, never for one that students will use."})
    boolean noSelfCheck;

    @Override
    public Integer call() throws IOException {
        if (!List.of("gradescope", "prairielearn", "classroom50").contains(target)) {
            throw UserError.badInput("unknown bundle target '" + target + "' (known: gradescope, prairielearn, classroom50)");
        }
        Path r = root.toAbsolutePath().normalize();
        if (target.equals("classroom50")) {
            Assignments all = Assignments.load(r);
            if (!noSelfCheck) {
                selfCheck(r, graderFiles(r, all));
            }
            raylab.grade.platform.Classroom50Bundle.write(all, assignment, javaVersion, out);
            spec.commandLine().getOut().println("wrote " + out + ": copy autograders/" + assignment + "/ into CLASSROOM/autograders/ of the"
                    + " classroom50 repository and add assignment.json's fields to the assignment (see its README.md)");
            return 0;
        }
        Path j = jar;
        if (j == null) {
            Path code = GraderSetup.codeSource();
            j = Files.isRegularFile(code) ? code : r.resolve("target/raylab.jar");
        }
        if (!Files.isRegularFile(j)) {
            throw UserError.badInput(j + " does not exist: build it first with ./mvnw -DskipTests package");
        }
        Assignments all = Assignments.load(r);
        List<Path> files = graderFiles(r, all);
        if (!noSelfCheck) {
            selfCheck(r, files);
        }
        if (target.equals("prairielearn")) {
            if (!List.of("per-milestone", "whole").contains(questions)) {
                throw UserError.badInput("--questions: per-milestone or whole, got '" + questions + "'");
            }
            java.time.Instant dueAt = null;
            if (due != null) {
                try {
                    dueAt = java.time.Instant.parse(due);
                } catch (java.time.format.DateTimeParseException e) {
                    throw UserError.badInput("--due: an ISO 8601 instant such as 2027-03-01T23:59:00Z, got '" + due + "'");
                }
            }
            int t = timeout == null ? (questions.equals("whole") ? 600 : 300) : timeout;
            if (t < 1 || t > 600) {
                throw UserError.badInput("--timeout: 1 to 600 seconds (PrairieLearn's limit), got " + t);
            }
            raylab.grade.platform.PrairieLearnBundle.write(r, all, j, files, out, questions.equals("whole"), dueAt, image, t);
            spec.commandLine().getOut().println("wrote " + out + ": copy serverFilesCourse/ and questions/ into the PrairieLearn"
                    + " course repository (see its README.md)");
            return 0;
        }
        if (out.toAbsolutePath().getParent() != null) {
            Files.createDirectories(out.toAbsolutePath().getParent());
        }
        Path tmp = Files.createTempFile(out.toAbsolutePath().getParent(), ".bundle", ".zip");
        try (OutputStream os = Files.newOutputStream(tmp); ZipOutputStream zip = new ZipOutputStream(os)) {
            put(zip, "setup.sh", SETUP.getBytes(StandardCharsets.UTF_8));
            put(zip, "run_autograder", RUN.getBytes(StandardCharsets.UTF_8));
            put(zip, "raylab.jar", Files.readAllBytes(j));
            for (Path f : files) {
                put(zip, r.relativize(f).toString().replace('\\', '/'), Files.readAllBytes(f));
            }
        }
        Files.move(tmp, out, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        spec.commandLine().getOut().println("wrote " + out + " (" + (Files.size(out) / 1024) + " KiB): upload it as the "
                + "Gradescope autograder (Ubuntu base image)");
        return 0;
    }

    /**
     * The course's self-check ({@link CourseCheck}) on a copy of exactly the files the bundle
     * holds: one line per problem on standard error, and a refusal (exit status 1) when there is any.
     * A check that passed before on the same files with the same raylab and JDK is not run again
     * ({@link PassedChecks}); standard error says so, and which record to delete to run it.
     */
    private void selfCheck(Path r, List<Path> files) throws IOException {
        java.io.PrintWriter err = spec.commandLine().getErr();
        Path record = PassedChecks.record(r, files);
        java.util.Optional<String> passed = PassedChecks.passedOn(record);
        if (passed.isPresent()) {
            err.println("raylab: the course's self-check passed on exactly these files with this raylab and JDK at "
                    + passed.get() + ": not run again (delete " + r.relativize(record) + " to run it)");
            err.flush();
            return;
        }
        Path staged = Files.createTempDirectory("raylab-bundle-check");
        try {
            for (Path f : files) {
                Path t = staged.resolve(r.relativize(f).toString());
                Files.createDirectories(t.getParent());
                Files.copy(f, t);
            }
            Grader.Options o = Grader.Options.defaults(staged);
            o = new Grader.Options(staged, o.milestones(), o.limits(), o.sceneLimit(), o.sceneHeapMb(),
                    staged.resolve("target/grader-cache"), o.sandboxUser(), o.parallel(), o.sandboxMode());
            err.println("raylab: checking the course with the bundle's own files (raylab self-check; takes a few minutes)");
            err.flush();
            List<String> problems = CourseCheck.problems(staged, List.of(), o, s -> { });
            if (SelfCheckCommand.report(problems, err) != 0) {
                throw new UserError(problems.size() + " course problem" + (problems.size() == 1 ? "" : "s")
                        + " (above): nothing was written to " + out, 1);
            }
            try {
                PassedChecks.remember(record);
            } catch (IOException e) {
                err.println("raylab: the check passed, but could not be recorded (" + e.getMessage()
                        + "): the next bundle checks again");
            }
        } finally {
            JavaBuild.deleteTreeQuietly(staged);
        }
    }

    /** What grading reads besides the jar: assignments, the grader's tests, scenes, helpers, visible tests, framework sources. */
    static List<Path> graderFiles(Path r, Assignments all) throws IOException {
        List<Path> files = new ArrayList<>();
        files.addAll(walk(r.resolve("assignments")));
        files.addAll(walk(r.resolve("grader/tests")));
        files.addAll(walk(r.resolve("scenes")));
        files.addAll(walk(r.resolve("src/test/java/raylab/testing")));
        // The lab's sources: the cache builds the public stubs and stand-ins from them; the lab's and
        // the tools' sources say which classes the public framework has (docs/architecture.md).
        files.addAll(walk(r.resolve(SourceRoots.LAB)));
        files.addAll(walk(r.resolve(SourceRoots.LAB_RESOURCES)));
        files.addAll(walk(r.resolve(SourceRoots.TOOLS)));
        for (Assignment a : all.all()) {
            for (String v : a.tests().visible()) {
                files.add(r.resolve(v));
            }
        }
        return files.stream().distinct().sorted().filter(Files::isRegularFile).toList();
    }

    private static List<Path> walk(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> s = Files.walk(dir)) {
            return s.filter(Files::isRegularFile).toList();
        }
    }

    private static void put(ZipOutputStream zip, String name, byte[] bytes) throws IOException {
        zip.putNextEntry(new ZipEntry(name));
        zip.write(bytes);
        zip.closeEntry();
    }
}
