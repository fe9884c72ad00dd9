package raylab.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The grader's intake ({@link Submission}) with two copies of a graded file: the copy at the
 * release's path wins whatever its place in the zip; with no copy there, neither is graded and
 * the reason names both paths. A stale backup never wins by coming first.
 */
class SubmissionCopiesTest {
    static final String SPHERE = "src/main/java/raylab/surface/Sphere.java";
    static final String CURRENT = "package raylab.surface;\n// current\n";
    static final String STALE = "package raylab.surface;\n// stale backup\n";
    static List<Assignment> assignments;

    @TempDir
    Path dir;

    @BeforeAll
    static void load() throws IOException {
        assignments = Assignments.load(Path.of(".")).all();
    }

    Path zip(String... namesAndTexts) throws IOException {
        Path zip = dir.resolve("submission.zip");
        try (OutputStream f = Files.newOutputStream(zip); ZipOutputStream z = new ZipOutputStream(f)) {
            for (int i = 0; i < namesAndTexts.length; i += 2) {
                z.putNextEntry(new ZipEntry(namesAndTexts[i]));
                z.write(namesAndTexts[i + 1].getBytes(StandardCharsets.UTF_8));
                z.closeEntry();
            }
        }
        return zip;
    }

    @Test
    void theCopyAtTheReleasePathWinsEvenAfterABackup() throws IOException {
        Submission s = Submission.read(zip("backup/Sphere.java", STALE, "raylab/" + SPHERE, CURRENT), assignments);
        assertEquals(CURRENT, s.files().get(SPHERE), "the copy graded");
        assertEquals("raylab/" + SPHERE, s.sources().get(SPHERE));
        assertEquals(List.of("backup/Sphere.java", "raylab/" + SPHERE), s.duplicates().get(SPHERE));
        assertTrue(s.conflicts().isEmpty(), "no conflict: " + s.conflicts());
        assertTrue(s.ignored().contains("backup/Sphere.java: another copy of Sphere.java, not graded (the copy at raylab/"
                + SPHERE + " is, being at " + SPHERE + ")"), "ignored: " + s.ignored());
    }

    @Test
    void twoCopiesNeitherAtTheReleasePathAreBothLeftOut() throws IOException {
        Submission s = Submission.read(zip("backup/Sphere.java", STALE, "Sphere.java", CURRENT), assignments);
        assertEquals(null, s.files().get(SPHERE), "neither copy graded");
        String why = "2 copies of Sphere.java (backup/Sphere.java, Sphere.java) and none at " + SPHERE
                + ": neither is graded (keep one copy, at " + SPHERE + ")";
        assertEquals(why, s.conflicts().get(SPHERE));
        assertTrue(s.ignored().contains(why), "ignored: " + s.ignored());
    }

    @Test
    void twoCopiesBothAtTheReleasePathAreBothLeftOut() throws IOException {
        Submission s = Submission.read(zip("a/" + SPHERE, STALE, "b/" + SPHERE, CURRENT), assignments);
        assertEquals(null, s.files().get(SPHERE), "neither copy graded");
        assertTrue(s.conflicts().get(SPHERE).contains("and more than one at " + SPHERE), s.conflicts().toString());
    }

    @Test
    void oneFlatCopyIsTaken() throws IOException {
        Submission s = Submission.read(zip("Sphere.java", CURRENT), assignments);
        assertEquals(CURRENT, s.files().get(SPHERE));
        assertTrue(s.duplicates().isEmpty() && s.conflicts().isEmpty(), s.duplicates() + " " + s.conflicts());
    }
}
