package raylab.course;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * Builds milestone code in layers: a base tree compiled once, and per milestone an overlay of a
 * few files compiled against it and put first on the class path. The release check (solution of
 * one milestone over the stubs) and the grader (one student file over the reference) both work
 * this way. Also runs a render in a child JVM on such a class path.
 */
public final class MilestoneBuild {
    private MilestoneBuild() {
    }

    /** Compiles every .java under {@code sourceRoot} into {@code out}. */
    public static JavaBuild.Result compileTree(Path sourceRoot, List<Path> classPath, Path out) throws IOException {
        return JavaBuild.compile(JavaBuild.sourcesUnder(sourceRoot), classPath, out);
    }

    /**
     * Writes {@code text} for each relative path under {@code overlaySrc} and compiles those
     * files against the layers below ({@code below}) into {@code overlayOut}.
     */
    public static JavaBuild.Result compileOverlay(java.util.Map<String, String> files, Path overlaySrc,
            List<Path> below, Path overlayOut) throws IOException {
        List<Path> sources = new ArrayList<>();
        for (var e : files.entrySet()) {
            Path p = overlaySrc.resolve(e.getKey());
            Files.createDirectories(p.getParent());
            Files.writeString(p, e.getValue(), StandardCharsets.UTF_8);
            sources.add(p);
        }
        return JavaBuild.compile(sources, below, overlayOut);
    }

    /** The instructor's text of a file with only the given milestones' solutions kept. */
    public static String withSolutions(Path file, String relativeName, Set<String> keep) throws IOException {
        String text = Files.readString(file, StandardCharsets.UTF_8);
        return SolutionRegions.toStudent(relativeName, text, keep);
    }

    /** Layers, first wins: the given directories, then this JVM's own class path (libraries). */
    public static List<Path> classPath(Path... layers) {
        List<Path> cp = new ArrayList<>();
        for (Path p : layers) {
            if (p != null) {
                cp.add(p);
            }
        }
        cp.addAll(JavaBuild.ownClassPath());
        return cp;
    }

    /** The outcome of a render in a child JVM: exit status and the last line it wrote to stderr. */
    public record RenderOutcome(int exitStatus, String message, boolean timedOut) {
    }

    /**
     * Runs {@code raylab render SCENE -o OUT --quiet} in a child JVM on {@code classPath}, with a
     * memory cap and a time limit, and returns its exit status and error line.
     */
    public static RenderOutcome renderInChild(List<Path> classPath, Path scene, Path out, Duration limit,
            int heapMegabytes, Path workDir) throws IOException {
        return renderInChild(classPath, scene, out, limit, heapMegabytes, workDir, List.of());
    }

    /** As above, with the child's command line prefixed by {@code wrapper} (empty for none). */
    public static RenderOutcome renderInChild(List<Path> classPath, Path scene, Path out, Duration limit,
            int heapMegabytes, Path workDir, List<String> wrapper) throws IOException {
        String java = JavaBuild.javaExecutable();
        List<String> cmd = new ArrayList<>(wrapper);
        cmd.addAll(List.of(java, "-Xmx" + heapMegabytes + "m", "-Djava.awt.headless=true"));
        // A render of seconds: the quick JIT alone and one GC thread cost less CPU than the full JIT.
        cmd.addAll(JavaBuild.QUICK_JVM);
        cmd.addAll(List.of("-cp",
                String.join(File.pathSeparator, classPath.stream().map(Path::toString).toList()),
                "raylab.cli.Main", "render", scene.toAbsolutePath().toString(), "-o", out.toAbsolutePath().toString(),
                "--quiet", "--threads", "2"));
        Path err = Files.createTempFile(workDir, "render", ".err");
        Process p = new ProcessBuilder(cmd).directory(workDir.toFile())
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(err.toFile()).start();
        try {
            boolean done = p.waitFor(limit.toMillis(), TimeUnit.MILLISECONDS);
            if (!done) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
                p.waitFor(5, TimeUnit.SECONDS);
                return new RenderOutcome(-1, "render stopped after " + limit.toSeconds() + " s", true);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            p.destroyForcibly();
            return new RenderOutcome(-1, "interrupted", true);
        }
        String last = "";
        byte[] bytes = Files.readAllBytes(err);
        String text = new String(bytes, 0, Math.min(bytes.length, 64 * 1024), StandardCharsets.UTF_8).strip();
        if (!text.isEmpty()) {
            String[] lines = text.split("\n");
            last = lines[lines.length - 1];
        }
        Files.deleteIfExists(err);
        return new RenderOutcome(p.exitValue(), last, false);
    }
}
