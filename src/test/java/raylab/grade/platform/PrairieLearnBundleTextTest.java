package raylab.grade.platform;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.Assignments;

/**
 * A PrairieLearn bundle says what students will see of the hidden tests (issue 36, item 6): with
 * or without a due date, every grading counts them; the question and the README say they are one
 * total row, withheld until the due date or (without one) always. Nothing says they are graded
 * "after the due date" only, which PrairieLearn's regrade would never do.
 */
class PrairieLearnBundleTextTest {
    @TempDir
    Path dir;

    @Test
    void theQuestionAndTheReadmeSayWhatStudentsSeeWithAndWithoutADueDate() throws Exception {
        Path root = Path.of("").toAbsolutePath();
        Assignments all = Assignments.load(root);
        Path jar = Files.writeString(dir.resolve("raylab.jar"), "jar");
        for (Instant due : new Instant[] {null, Instant.parse("2027-03-01T23:59:00Z")}) {
            Path out = dir.resolve(due == null ? "no-due" : "due");
            PrairieLearnBundle.write(root, all, jar, List.of(), out, false, due, "prairielearn/grader-java", 300);
            String html = Files.readString(out.resolve("questions/raylab/box/question.html"));
            String readme = Files.readString(out.resolve("README.md"));
            assertTrue(html.contains("Your score includes the hidden tests and data cases, graded at every submission"), html);
            assertTrue(html.contains("one row with their total"), html);
            assertFalse(html.contains("graded after the due date"), html);
            if (due == null) {
                assertFalse(html.contains("until the due date"), "no due date: withheld always: " + html);
                assertTrue(readme.contains("No due date given: every grading counts the hidden tests"), readme);
                assertTrue(Files.notExists(out.resolve("serverFilesCourse/raylab/due.txt")));
            } else {
                assertTrue(html.contains("withheld until the due date"), html);
                assertTrue(readme.contains("Due 2027-03-01T23:59:00Z: every grading counts the hidden tests"), readme);
            }
        }
    }
}
