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
 * {@code raylab bundle gradescope --out autograder.zip}: Gradescope's autograder zip. It holds
 * setup.sh and run_autograder at its top, the grader jar and what grading reads (assignments,
 * the grader's tests, the visible tests, scenes with their references). Nothing is downloaded
 * at grading time; setup.sh installs a JDK only if the image has none.
 */
@Command(name = "bundle", mixinStandardHelpOptions = true,
        description = {"Build an autograder bundle (instructors). Only target: gradescope."})
public final class BundleCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "TARGET", description = "gradescope")
    String target;

    @Option(names = "--out", required = true, paramLabel = "ZIP", description = "The zip to write.")
    Path out;

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
            (cd "$AG/source" && java -jar raylab.jar grade warmup-submission --out /tmp/raylab-warmup \\
                --root "$AG/source" --cache "$AG/cache" --quiet) || true
            chmod 755 "$AG/cache"
            """;

    static final String RUN = """
            #!/usr/bin/env bash
            # Gradescope entry point: grades /autograder/submission into /autograder/results.
            AG="${AUTOGRADER_ROOT:-/autograder}"
            mkdir -p "$AG/results"
            cd "$AG/source" || exit 1
            java -jar raylab.jar grade "$AG/submission" --out "$AG/results" --root "$AG/source" \\
                --cache "$AG/cache" --quiet
            if [ ! -s "$AG/results/results.json" ]; then
              echo '{"score": 0, "output": "The autograder could not run. Please tell the course staff."}' \\
                > "$AG/results/results.json"
            fi
            exit 0
            """;

    @Override
    public Integer call() throws IOException {
        if (!"gradescope".equals(target)) {
            throw UserError.badInput("unknown bundle target '" + target + "' (known: gradescope)");
        }
        Path r = root.toAbsolutePath().normalize();
        Path j = jar;
        if (j == null) {
            Path code = GraderSetup.codeSource();
            j = Files.isRegularFile(code) ? code : r.resolve("target/raylab.jar");
        }
        if (!Files.isRegularFile(j)) {
            throw UserError.badInput(j + " does not exist: build it first with ./mvnw -DskipTests package");
        }
        Assignments all = Assignments.load(r);
        List<Path> files = new ArrayList<>();
        files.addAll(walk(r.resolve("assignments")));
        files.addAll(walk(r.resolve("grader/tests")));
        files.addAll(walk(r.resolve("scenes")));
        files.addAll(walk(r.resolve("src/test/java/raylab/testing")));
        for (Assignment a : all.all()) {
            for (String v : a.tests().visible()) {
                files.add(r.resolve(v));
            }
        }
        if (out.toAbsolutePath().getParent() != null) {
            Files.createDirectories(out.toAbsolutePath().getParent());
        }
        Path tmp = Files.createTempFile(out.toAbsolutePath().getParent(), ".bundle", ".zip");
        try (OutputStream os = Files.newOutputStream(tmp); ZipOutputStream zip = new ZipOutputStream(os)) {
            put(zip, "setup.sh", SETUP.getBytes(StandardCharsets.UTF_8));
            put(zip, "run_autograder", RUN.getBytes(StandardCharsets.UTF_8));
            put(zip, "raylab.jar", Files.readAllBytes(j));
            for (Path f : files.stream().distinct().sorted().toList()) {
                if (Files.isRegularFile(f)) {
                    put(zip, r.relativize(f).toString().replace('\\', '/'), Files.readAllBytes(f));
                }
            }
        }
        Files.move(tmp, out, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        spec.commandLine().getOut().println("wrote " + out + " (" + (Files.size(out) / 1024) + " KiB): upload it as the "
                + "Gradescope autograder (Ubuntu base image)");
        return 0;
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
