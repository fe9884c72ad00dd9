package raylab.course.release;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import raylab.course.JavaBuild;
import raylab.course.release.ReleaseVerifier.Check;

/**
 * Runs the starter README's commands in a copy of the starter, as a student would: the Maven
 * wrapper build (offline, from the local repository), {@code ./raylab --help} (which must list
 * every {@code ./raylab COMMAND} the README mentions), rendering the first scene (which must stop
 * with exit status 3 naming milestone sphere) and {@code ./raylab check sphere}.
 */
final class BuildCheck {
    private final Path starter;
    private final Path copy;

    BuildCheck(Path starter, Path work) {
        this.starter = starter;
        this.copy = work.resolve("build-check");
    }

    /** The outcome of one command. */
    record Ran(int status, String output) {
    }

    List<Check> run() throws IOException, InterruptedException {
        List<Check> out = new ArrayList<>();
        if (!Files.isExecutable(Path.of("/bin/sh"))) {
            out.add(new Check("README commands", false, "no /bin/sh here: run them by hand"));
            return out;
        }
        JavaBuild.deleteTree(copy);
        copyTree(starter, copy);

        Ran build = sh(600, "./mvnw", "-q", "-o", "-B", "-DskipTests", "package");
        boolean built = build.status() == 0 && Files.isRegularFile(copy.resolve("target/raylab.jar"));
        out.add(new Check("starter: ./mvnw -o -DskipTests package builds target/raylab.jar", built,
                built ? "" : "exit " + build.status() + ": " + tail(build.output())));
        if (!built) {
            return out;
        }
        Ran help = sh(60, "./raylab", "--help");
        String readme = Files.readString(copy.resolve("README.md"), StandardCharsets.UTF_8);
        Set<String> mentioned = new LinkedHashSet<>();
        Matcher m = Pattern.compile("\\./raylab ([a-z][a-z-]*)").matcher(readme);
        while (m.find()) {
            mentioned.add(m.group(1));
        }
        List<String> missing = new ArrayList<>();
        for (String c : mentioned) {
            if (!Pattern.compile("(?m)^\\s+" + Pattern.quote(c) + "\\b").matcher(help.output()).find()) {
                missing.add(c);
            }
        }
        out.add(new Check("starter: ./raylab --help lists the README's commands " + mentioned,
                help.status() == 0 && missing.isEmpty(),
                help.status() != 0 ? "exit " + help.status() + ": " + tail(help.output())
                        : missing.isEmpty() ? "" : "missing: " + String.join(", ", missing)));

        Ran render = sh(120, "./raylab", "render", "scenes/sphere.json");
        boolean named = render.status() == 3 && render.output().contains("'sphere'");
        out.add(new Check("starter: ./raylab render scenes/sphere.json stops naming milestone 'sphere'", named,
                "exit " + render.status() + ", \"" + ReleaseVerifier.abbreviate(tail(render.output()), 140) + "\""));

        Ran check = sh(300, "./raylab", "check", "sphere");
        boolean table = check.status() == 1 && Pattern.compile("(?m)^\\s*sphere\\b.*\\b0/\\d+").matcher(check.output()).find();
        out.add(new Check("starter: ./raylab check sphere runs and reports 0 tests passed", table,
                "exit " + check.status() + (table ? "" : ": " + tail(check.output()))));
        return out;
    }

    private Ran sh(long seconds, String... cmd) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(copy.toFile()).redirectErrorStream(true);
        pb.environment().put("JAVA_HOME", System.getProperty("java.home"));
        pb.environment().keySet().removeIf(k -> k.equals("MAVEN_PROJECTBASEDIR") || k.equals("MAVEN_CMD_LINE_ARGS")
                || k.startsWith("JAVA_TOOL") || k.equals("_JAVA_OPTIONS") || k.equals("JDK_JAVA_OPTIONS"));
        Path log = Files.createTempFile(copy.getParent(), "cmd", ".log");
        pb.redirectOutput(log.toFile());
        Process p = pb.start();
        p.getOutputStream().close();
        if (!p.waitFor(seconds, TimeUnit.SECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            p.waitFor(5, TimeUnit.SECONDS);
            Files.deleteIfExists(log);
            return new Ran(-1, String.join(" ", cmd) + " did not finish within " + seconds + " s");
        }
        String text = Files.readString(log, StandardCharsets.UTF_8);
        Files.deleteIfExists(log);
        return new Ran(p.exitValue(), text);
    }

    static String tail(String output) {
        String[] lines = output.strip().split("\n");
        return lines.length == 0 ? "" : lines[lines.length - 1].strip();
    }

    private static void copyTree(Path from, Path to) throws IOException {
        for (String rel : Release.projectFiles(from)) {
            Path dst = to.resolve(rel);
            Files.createDirectories(dst.getParent());
            Files.copy(from.resolve(rel), dst, StandardCopyOption.COPY_ATTRIBUTES);
        }
    }
}
