package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The release of this very tree: written twice it is the same byte for byte, and its
 * verification passes (so {@code ./mvnw test} fails when a change would break the starter).
 * Set {@code -Draylab.release.buildCheck=false} to leave out the README commands (a nested
 * Maven build) when iterating.
 */
class ReleaseTest {
    @TempDir
    Path dir;

    @Test
    void releaseIsReproducibleAndVerifies() throws IOException {
        Path root = Path.of("").toAbsolutePath();
        Path first = dir.resolve("first");
        Path second = dir.resolve("second");
        Release.write(root, first, false);
        Release.write(root, second, false);
        List<String> files = Release.projectFiles(first);
        assertEquals(files, Release.projectFiles(second), "the same files");
        List<String> differ = new ArrayList<>();
        for (String f : files) {
            if (!Arrays.equals(Files.readAllBytes(first.resolve(f)), Files.readAllBytes(second.resolve(f)))
                    || Files.isExecutable(first.resolve(f)) != Files.isExecutable(second.resolve(f))) {
                differ.add(f);
            }
        }
        assertEquals(List.of(), differ, "files that differ between two releases");
        assertFalse(Files.exists(dir.resolve(".first.partial-" + ProcessHandle.current().pid())),
                "no partial folder left behind");

        boolean buildCheck = !"false".equals(System.getProperty("raylab.release.buildCheck"));
        ReleaseVerifier.Report report = ReleaseVerifier.verify(root, first, dir.resolve("work"),
                new ReleaseVerifier.Options(buildCheck, 2));
        String failures = report.checks().stream().filter(c -> !c.passed()).map(Object::toString)
                .collect(Collectors.joining("\n"));
        assertTrue(report.passed(), "release verification failed:\n" + failures);
        assertTrue(report.checks().size() > 20, "expected the full set of checks, got " + report.checks());
        assertEquals(List.of(), Release.projectFiles(first).stream().filter(f -> !files.contains(f)).toList(),
                "verification wrote nothing into the starter");
    }

    @Test
    void refusesANonEmptyFolderWithoutForce() throws IOException {
        Path out = dir.resolve("busy");
        Files.createDirectories(out);
        Files.writeString(out.resolve("keep.txt"), "mine");
        IOException e = org.junit.jupiter.api.Assertions.assertThrows(IOException.class,
                () -> Release.write(Path.of(""), out, false));
        assertTrue(e.getMessage().endsWith("not empty (use --force to replace it)"), e.getMessage());
        assertEquals("mine", Files.readString(out.resolve("keep.txt")), "the folder is untouched");
    }
}
