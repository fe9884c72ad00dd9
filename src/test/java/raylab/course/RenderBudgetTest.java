package raylab.course;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The renders' limit after a milestone's tests ({@code --then-render}) is the student's CPU time:
 * the grader's time starting the render's student process is not taken from it. Before, the limit
 * was a wall-clock deadline fixed before the process started, so on a loaded machine (a process
 * start of seconds) the reference solution's triangle scenes were stopped as "more than 2 s of CPU
 * time" after about 1.2 s of it, and lost their points.
 */
class RenderBudgetTest {
    @TempDir
    Path dir;

    /** A boundary whose process start takes a while, and which records what the renders are given. */
    static final class SlowStart implements BoundaryHooks {
        final long startMillis;
        final List<String> calls = new ArrayList<>();
        long budget = -1;

        SlowStart(long startMillis) {
            this.startMillis = startMillis;
        }

        @Override
        public void warmUp() {
        }

        @Override
        public void switchTo(Path config) {
            calls.add("switchTo " + config.getFileName());
            try {
                Thread.sleep(startMillis);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public void startTest(long limitNanos) {
        }

        @Override
        public long studentNanos() {
            return 0;
        }

        @Override
        public long studentCpuNanos() {
            return 0;
        }

        @Override
        public void renderAll(List<String> scenes, long cpuBudgetNanos, PrintStream times) {
            calls.add("renderAll " + scenes);
            budget = cpuBudgetNanos;
        }
    }

    @Test
    void theStudentProcessesStartIsNotTakenFromTheRendersBudget() throws Exception {
        Path list = Files.writeString(dir.resolve("scenes.txt"), "scene.json\nout.png\nscene\n");
        SlowStart boundary = new SlowStart(300);
        TestMain.render(new String[] {dir.resolve("render.properties").toString(), list.toString(), "4"}, boundary);
        assertEquals(List.of("switchTo render.properties", "renderAll [scene.json, out.png, scene]"), boundary.calls,
                "a new student process, then the renders");
        assertEquals(4_000_000_000L, boundary.budget,
                "the renders get the whole 4 s of the student's CPU time, after a process start of 300 ms");
        long ms = Long.parseLong(Files.readString(dir.resolve("millis.txt")).trim());
        assertEquals(0, ms / 1000, "the renders' own wall time is written (" + ms + " ms), without the process start");
    }
}
