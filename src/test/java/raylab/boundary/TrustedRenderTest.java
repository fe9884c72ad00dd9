package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@link TrustedRender#renderAll}'s time limit: once its budget of CPU time is spent, each scene left
 * says so ({@code OUT.png.timeout}, which the grader reports as "the renders took longer than
 * N s") and leaves no image and no error line; nothing is asked of a student process.
 */
class TrustedRenderTest {
    @TempDir
    Path dir;

    @Test
    void aSpentBudgetMarksEveryRemainingSceneAsLate() throws Exception {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        Path a = dir.resolve("a.png");
        Path b = dir.resolve("b.png");
        ByteArrayOutputStream times = new ByteArrayOutputStream();
        TrustedRender.renderAll(List.of(root.resolve("scenes/sphere.json").toString(), a.toString(), "scenes/sphere.json",
                root.resolve("scenes/boxes.json").toString(), b.toString(), "scenes/boxes.json"),
                -1, new PrintStream(times, true, StandardCharsets.UTF_8));
        for (Path png : List.of(a, b)) {
            assertTrue(Files.isRegularFile(Path.of(png + ".timeout")), png + ".timeout is written");
            assertFalse(Files.exists(png), png + " is not written");
            assertFalse(Files.exists(Path.of(png + ".err")), png + ".err is not written");
        }
    }

    /**
     * Whose a scene's failure is: the student's code's (its exception, its time, anything else the
     * render threw) or the grading's, marked beside the image (a {@link GradingFailure}; this JVM's
     * own memory or stack, since it runs no code of the student's).
     */
    @Test
    void theRenderJvmsOwnMemoryIsMarkedAsTheGradingsFailure() throws Exception {
        record Case(Throwable thrown, String line, boolean graders) {
        }
        List<Case> cases = List.of(
                new Case(new StudentException("java.lang.OutOfMemoryError", "your code ran out of memory", List.of(), ""),
                        null, false),
                new Case(new IllegalArgumentException("bad normal"), "java.lang.IllegalArgumentException: bad normal", false),
                new Case(new GradingFailure("killed twice"), "killed twice", true),
                new Case(new OutOfMemoryError("Java heap space"),
                        "the grader's render JVM: java.lang.OutOfMemoryError: Java heap space", true),
                new Case(new StackOverflowError(), "the grader's render JVM: java.lang.StackOverflowError", true));
        for (int i = 0; i < cases.size(); i++) {
            Case c = cases.get(i);
            Path out = dir.resolve("scene" + i + ".png");
            String line = TrustedRender.failure(c.thrown(), out);
            if (c.line() != null) {
                assertEquals(c.line(), line, c.thrown().toString());
            }
            assertEquals(c.graders(), Files.exists(Path.of(out + GradingFailure.RENDER_MARKER)), c.thrown().toString());
        }
    }
}
