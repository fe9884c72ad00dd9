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
import raylab.cli.UserError;
import raylab.course.Assignment;
import raylab.course.Assignments;

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
public final class BundleCommand implements Callable<Integer> {
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
            # Gradescope setup: runs once when the autograder image is built.
            set -euo pipefail
            AG="${AUTOGRADER_ROOT:-/autograder}"
            if ! command -v javac >/dev/null 2>&1; then
              apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q openjdk-17-jdk-headless
            fi
            # The unprivileged user that runs student code (the grader switches to it when root).
            if [ "$(id -u)" = 0 ] && ! id raylab-student >/dev/null 2>&1; then
              useradd -M -s /usr/sbin/nologin raylab-student || true
            fi
            # Students' code must not read the grader's sources, jar or reference images.
            chmod 700 "$AG/source" || true
            # Build the grader's classes and test list once, into the image. The grader keeps each build
            # folder private (700); student code only sees links to the files it needs, in its own box.
            mkdir -p "$AG/cache" "$AG/source/warmup-submission"
            (cd "$AG/source" && java JVM_OPTIONS -jar raylab.jar grade warmup-submission --out /tmp/raylab-warmup \\
                --root "$AG/source" --cache "$AG/cache" --quiet) || true
            chmod 755 "$AG/cache"
            """.replace("JVM_OPTIONS", JvmOptions.graderLine());

    static final String RUN = """
            #!/usr/bin/env bash
            # Gradescope entry point: grades /autograder/submission into /autograder/results.
            AG="${AUTOGRADER_ROOT:-/autograder}"
            mkdir -p "$AG/results"
            cd "$AG/source" || exit 1
            java JVM_OPTIONS -jar raylab.jar grade "$AG/submission" --out "$AG/results" --root "$AG/source" \\
                --cache "$AG/cache" --quiet
            if [ ! -s "$AG/results/results.json" ]; then
              echo '{"score": 0, "output": "The autograder could not run. Please tell the course staff."}' \\
                > "$AG/results/results.json"
            fi
            exit 0
            """.replace("JVM_OPTIONS", JvmOptions.graderLine());

    @Override
    public Integer call() throws IOException {
        if (!List.of("gradescope", "prairielearn", "classroom50").contains(target)) {
            throw UserError.badInput("unknown bundle target '" + target + "' (known: gradescope, prairielearn, classroom50)");
        }
        Path r = root.toAbsolutePath().normalize();
        if (target.equals("classroom50")) {
            Assignments all = Assignments.load(r);
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

    /** What grading reads besides the jar: assignments, the grader's tests, scenes, helpers, visible tests, framework sources. */
    static List<Path> graderFiles(Path r, Assignments all) throws IOException {
        List<Path> files = new ArrayList<>();
        files.addAll(walk(r.resolve("assignments")));
        files.addAll(walk(r.resolve("grader/tests")));
        files.addAll(walk(r.resolve("scenes")));
        files.addAll(walk(r.resolve("src/test/java/raylab/testing")));
        // The framework's sources: the cache builds the public stubs and stand-ins from them.
        files.addAll(walk(r.resolve("src/main/java")));
        files.addAll(walk(r.resolve("src/main/resources")));
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
