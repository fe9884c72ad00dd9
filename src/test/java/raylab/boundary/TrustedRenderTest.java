package raylab.boundary;

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
 * {@link TrustedRender#renderAll}'s time limit: once the deadline has passed, each scene left
 * says so ({@code OUT.png.timeout}, which the grader reports as "the renders took longer than
 * N s") and leaves no image and no error line; nothing is asked of a student process.
 */
class TrustedRenderTest {
    @TempDir
    Path dir;

    @Test
    void aPassedDeadlineMarksEveryRemainingSceneAsLate() throws Exception {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        Path a = dir.resolve("a.png");
        Path b = dir.resolve("b.png");
        ByteArrayOutputStream times = new ByteArrayOutputStream();
        TrustedRender.renderAll(List.of(root.resolve("scenes/sphere.json").toString(), a.toString(), "scenes/sphere.json",
                root.resolve("scenes/boxes.json").toString(), b.toString(), "scenes/boxes.json"),
                System.nanoTime() - 1, new PrintStream(times, true, StandardCharsets.UTF_8));
        for (Path png : List.of(a, b)) {
            assertTrue(Files.isRegularFile(Path.of(png + ".timeout")), png + ".timeout is written");
            assertFalse(Files.exists(png), png + " is not written");
            assertFalse(Files.exists(Path.of(png + ".err")), png + ".err is not written");
        }
    }
}
