package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Optional;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The bundle command's record of a passed self-check ({@link PassedChecks}) names exactly the
 * files checked: the same files give the same record in any order; a changed byte, a renamed
 * file or one more file give another, so the check runs again. A record says when it passed and
 * is written whole.
 */
class PassedChecksTest {
    @TempDir
    Path root;

    private List<Path> course() throws IOException {
        Path a = root.resolve("assignments/01-sphere/assignment.json");
        Path b = root.resolve("grader/tests/raylab/hidden/Hidden.java");
        Files.createDirectories(a.getParent());
        Files.createDirectories(b.getParent());
        Files.writeString(a, "{\"id\": \"sphere\"}\n");
        Files.writeString(b, "class Hidden {}\n");
        return List.of(a, b);
    }

    @Test
    void theRecordNamesExactlyTheFilesChecked() throws IOException {
        List<Path> files = course();
        Path record = PassedChecks.record(root, files);
        assertEquals(root.resolve(PassedChecks.FOLDER), record.getParent());
        assertEquals(record, PassedChecks.record(root, List.of(files.get(1), files.get(0))), "the same files in another order");

        Files.writeString(files.get(1), "class Hidden { }\n");
        Path changed = PassedChecks.record(root, files);
        assertNotEquals(record, changed, "one byte more in a file");

        Path renamed = files.get(1).resolveSibling("Hidden2.java");
        Files.move(files.get(1), renamed);
        assertNotEquals(changed, PassedChecks.record(root, List.of(files.get(0), renamed)), "a file renamed");

        Path more = root.resolve("scenes/sphere.json");
        Files.createDirectories(more.getParent());
        Files.writeString(more, "{}");
        assertNotEquals(PassedChecks.record(root, List.of(files.get(0), renamed)),
                PassedChecks.record(root, List.of(files.get(0), renamed, more)), "one more file");
    }

    @Test
    void aPassIsRecordedWholeWithItsTime() throws IOException {
        Path record = PassedChecks.record(root, course());
        assertEquals(Optional.empty(), PassedChecks.passedOn(record), "no record before the check passed");
        Instant before = Instant.now();
        PassedChecks.remember(record);
        String when = PassedChecks.passedOn(record).orElseThrow();
        Instant at = Instant.parse(when);
        assertTrue(!at.isBefore(before.minusSeconds(1)) && !at.isAfter(Instant.now()), "passed at " + when + ", checked from " + before);
        try (var s = Files.list(record.getParent())) {
            assertEquals(List.of(record.getFileName().toString()), s.map(p -> p.getFileName().toString()).toList(),
                    "the record alone, no temporary file beside it");
        }
    }
}
