package raylab.course;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Compiles a set of sources again only when an input changed: the sources themselves and the
 * class path's jars and folders' own time (not the files in {@code target/incremental}, which a
 * student's edit changes, as the visible tests compile against the student's classes' unchanged
 * signatures). {@code raylab check} compiles the visible tests this way, so that the loop
 * edit -> check does not compile the same tests every time.
 */
public final class BuildCache {
    private static final String STAMP = ".inputs";

    private BuildCache() {
    }

    /** As {@link JavaBuild#compile}, skipped when {@code out} holds the classes of exactly these inputs. */
    public static JavaBuild.Result compile(List<Path> sources, List<Path> classPath, Path out) throws IOException {
        String inputs = fingerprint(sources, classPath);
        Path stamp = out.resolve(STAMP);
        if (Files.isRegularFile(stamp) && Files.readString(stamp, StandardCharsets.UTF_8).equals(inputs)) {
            return new JavaBuild.Result(true, List.of());
        }
        delete(out);
        JavaBuild.Result r = JavaBuild.compile(sources, classPath, out);
        if (r.success()) {
            Files.writeString(stamp, inputs, StandardCharsets.UTF_8);
        }
        return r;
    }

    /** One line per input: path, size and time of each source; path and time of each class path entry. */
    static String fingerprint(List<Path> sources, List<Path> classPath) throws IOException {
        List<String> lines = new ArrayList<>();
        for (Path p : sources) {
            lines.add("src " + p.toAbsolutePath().normalize() + " " + (Files.exists(p) ? Files.size(p) + " "
                    + Files.getLastModifiedTime(p).toMillis() : "missing"));
        }
        for (Path p : classPath) {
            boolean overlay = p.getFileName() != null && p.getFileName().toString().equals("incremental");
            lines.add("cp " + p.toAbsolutePath().normalize() + " " + (overlay || !Files.exists(p) ? ""
                    : Files.isDirectory(p) ? "dir" : Files.size(p) + " " + Files.getLastModifiedTime(p).toMillis()));
        }
        return String.join("\n", lines) + "\n";
    }

    /** What {@link TestLauncher#discover} found, with the inputs it was found for. */
    record Discovered(String key, List<TestResult> tests) {
    }

    /**
     * {@link TestLauncher#discover}, its answer kept in {@code cache} while the compiled test
     * folders (each stamped by {@link #compile}) and the selected classes stay the same: the
     * discovery needs a JVM of its own.
     */
    public static List<TestResult> discover(List<Path> classPath, List<String> classes, Path workDir,
            List<Path> compiled, Path cache) throws IOException {
        StringBuilder key = new StringBuilder(String.join(",", classes)).append('\n');
        for (Path d : compiled) {
            Path stamp = d.resolve(STAMP);
            if (!Files.isRegularFile(stamp)) {
                return TestLauncher.discover(classPath, null, List.of(), classes, workDir);
            }
            key.append(Files.readString(stamp, StandardCharsets.UTF_8));
        }
        var json = new com.fasterxml.jackson.databind.ObjectMapper();
        if (Files.isRegularFile(cache)) {
            try {
                Discovered d = json.readValue(cache.toFile(), Discovered.class);
                if (d.key().equals(key.toString())) {
                    return d.tests();
                }
            } catch (IOException e) {
                // unreadable: discover again
            }
        }
        List<TestResult> found = TestLauncher.discover(classPath, null, List.of(), classes, workDir);
        json.writeValue(cache.toFile(), new Discovered(key.toString(), found));
        return found;
    }

    private static void delete(Path p) throws IOException {
        if (!Files.exists(p)) {
            return;
        }
        try (var s = Files.walk(p)) {
            for (Path q : s.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(q);
            }
        }
    }
}
