package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.shading.Shadows;
import raylab.surface.Box;

/**
 * Load is never the student's fault, and the grader's own work is bounded (a real student
 * process, {@link StudentProcessTest#start}): a call beside CPU hogs (32 busy processes on its
 * core) is not stopped although its wall time passes the wall limit; the grader's time
 * answering a question is not the student's; the grader's CPU time answering one call's
 * questions has a bound of its own; a process killed from outside is called again, and killed
 * twice is a {@link GradingFailure}; a frame check stops a call before it is sent; a test's
 * calls together stop at the test's limit; a call that sleeps is still stopped by its wall
 * limit (3 × budget + 5 s).
 */
class StudentProcessLoadTest {
    static final double WALL_LIMIT_S = 3 * 1.0 + 5; // for a budget of 1 s

    @Test
    void aCallBesideCpuHogsIsNotStoppedThoughItsWallTimePassesTheLimit() throws Exception {
        try (StudentProcess p = StudentProcessTest.start(1_000)) {
            // Work of about 0.6 s of the student process's CPU time, measured in it on this machine.
            p.call("raylab.remote.Echo", "work", null, 20);
            long c0 = p.studentCpuNanos();
            p.call("raylab.remote.Echo", "work", null, 40);
            double perMillion = Math.max(1e-4, (p.studentCpuNanos() - c0) / 1e9 / 40);
            int millions = (int) Math.max(1, Math.round(0.6 / perMillion));
            // The student process and the hogs on one core (taskset, util-linux like the sandbox's
            // tools): the call gets about 1/33 of it, 0.6 s of CPU in about 20 s of wall time, and
            // the machine's other cores stay free for the tests beside this one.
            String core = lastAllowedCore();
            int hogs = 32;
            assertEquals(0, new ProcessBuilder("taskset", "-a", "-p", "-c", core, Long.toString(p.pid()))
                    .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start().waitFor(),
                    "the student process pinned to core " + core);
            List<Process> busy = new ArrayList<>();
            try {
                for (int i = 0; i < hogs; i++) {
                    busy.add(new ProcessBuilder("taskset", "-c", core, "sh", "-c", "while :; do :; done").start());
                }
                Thread.sleep(500);
                long t0 = System.nanoTime();
                long cpu0 = p.studentCpuNanos();
                assertEquals(millions, p.call("raylab.remote.Echo", "work", null, millions),
                        "beside " + hogs + " busy processes the call is not stopped");
                double wall = (System.nanoTime() - t0) / 1e9;
                double cpu = (p.studentCpuNanos() - cpu0) / 1e9;
                System.out.printf("StudentProcessLoadTest: %d million roots, %.2f s of CPU, %.1f s of wall time beside %d"
                        + " busy processes%n", millions, cpu, wall, hogs);
                assertEquals(1, p.starts(), "not restarted");
                assertTrue(wall > WALL_LIMIT_S, "the hogs made the call's wall time (" + wall + " s) pass the wall limit ("
                        + WALL_LIMIT_S + " s), which once stopped it; else this test shows nothing");
            } finally {
                for (Process b : busy) {
                    b.destroyForcibly();
                }
            }
        }
    }

    /** The last CPU this JVM may run on (/proc/self/status, "Cpus_allowed_list: 0-1,4"): the hogs' core. */
    static String lastAllowedCore() throws java.io.IOException {
        for (String line : java.nio.file.Files.readAllLines(java.nio.file.Path.of("/proc/self/status"))) {
            if (line.startsWith("Cpus_allowed_list:")) {
                String[] ranges = line.substring(line.indexOf(':') + 1).trim().split(",");
                String last = ranges[ranges.length - 1];
                return last.substring(last.indexOf('-') + 1);
            }
        }
        return Integer.toString(Runtime.getRuntime().availableProcessors() - 1);
    }

    /** A blocker whose every answer takes {@code sleepMillis} of wall time and {@code spinMillis} of CPU time. */
    static Box slowBlocker(long sleepMillis, long spinMillis) {
        return new Box(new Vec3(-1, 1, -1), new Vec3(1, 1.5, 1), null, "lid") {
            @Override
            public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
                try {
                    Thread.sleep(sleepMillis);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                java.lang.management.ThreadMXBean t = java.lang.management.ManagementFactory.getThreadMXBean();
                long end = t.getCurrentThreadCpuTime() + spinMillis * 1_000_000L;
                double x = 0;
                while (t.getCurrentThreadCpuTime() < end) {
                    x += Math.sqrt(x + 1);
                }
                return x >= 0 && super.intersectsAny(ray, scratch);
            }
        };
    }

    static final PointLight LIGHT = new PointLight(new Vec3(0, 5, 0), new Color(1, 1, 1), true, "sun");

    @Test
    void theGradersTimeAnsweringIsNotTheStudents() {
        try (StudentProcess p = StudentProcessTest.start(1_000)) {
            Box blocker = slowBlocker(9_000, 0); // more than the wall limit, all of it the grader's
            long t0 = System.nanoTime();
            Object got = p.call("raylab.shading.Shadows", "isShadowed", null, blocker, new Vec3(0, 0, 0), new Vec3(0, 1, 0),
                    LIGHT, new IntersectionRecord());
            double wall = (System.nanoTime() - t0) / 1e9;
            assertEquals(Shadows.isShadowed(new Box(new Vec3(-1, 1, -1), new Vec3(1, 1.5, 1), null, "lid"), new Vec3(0, 0, 0),
                    new Vec3(0, 1, 0), LIGHT, new IntersectionRecord()), got, "answered, after " + wall + " s");
            assertTrue(wall > WALL_LIMIT_S, "the call took " + wall + " s");
            assertEquals(1, p.starts(), "not stopped");
        }
    }

    @Test
    void theGradersCpuTimeAnsweringOneCallIsBounded() {
        try (StudentProcess p = StudentProcessTest.start(1_000)) {
            Box blocker = slowBlocker(0, 1_500); // 1.5 s of the grader's CPU for one question: over the 1 s bound
            StudentTimeout e = assertThrows(StudentTimeout.class, () -> p.call("raylab.shading.Shadows", "isShadowed", null,
                    blocker, new Vec3(0, 0, 0), new Vec3(0, 1, 0), LIGHT, new IntersectionRecord()));
            assertTrue(e.getMessage().startsWith("your code asked the grader so much during one call that answering took"
                    + " more than 1.0 s of the grader's CPU time"), e.getMessage());
            assertEquals(2.0, p.call("raylab.remote.Echo", "echo", null, 2.0), "a fresh process answers");
            assertEquals(2, p.starts());
        }
    }

    /** Kills the call's student process with SIGKILL {@code times} times, each 1 s after it started. */
    private static Thread killer(StudentProcess p, int times) {
        Thread t = new Thread(() -> {
            long last = -1;
            for (int k = 0; k < times; k++) {
                long pid;
                while ((pid = p.pid()) == last || pid < 0) {
                    sleep(20);
                }
                sleep(1_000);
                ProcessHandle.of(pid).ifPresent(h -> {
                    h.descendants().forEach(ProcessHandle::destroyForcibly);
                    h.destroyForcibly();
                });
                last = pid;
            }
        });
        t.setDaemon(true);
        t.start();
        return t;
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Test
    void aProcessKilledFromOutsideIsCalledAgainAndKilledTwiceIsAGradingFailure() throws Exception {
        try (StudentProcess p = StudentProcessTest.start(20_000)) {
            assertEquals(1.0, p.call("raylab.remote.Echo", "echo", null, 1.0));
            Thread once = killer(p, 1);
            assertEquals(3_000L, p.call("raylab.remote.Echo", "nap", null, 3_000L), "called again in a fresh process");
            once.join();
            assertEquals(1, p.starts(), "the fresh process is not counted against the student");
            Thread twice = killer(p, 2);
            GradingFailure f = assertThrows(GradingFailure.class, () -> p.call("raylab.remote.Echo", "nap", null, 3_000L));
            twice.join();
            assertTrue(f.getMessage().startsWith("the student process was killed twice during one call by something other"
                    + " than the grader or the student's code"), f.getMessage());
            assertEquals(4.0, p.call("raylab.remote.Echo", "echo", null, 4.0), "the next call runs");
        }
    }

    @Test
    void aFrameCheckStopsACallBeforeItIsSent() {
        try (StudentProcess p = StudentProcessTest.start(20_000)) {
            AtomicBoolean late = new AtomicBoolean();
            p.beforeEachFrame(() -> {
                if (late.get()) {
                    throw new IllegalStateException("late");
                }
            });
            assertEquals(1.0, p.call("raylab.remote.Echo", "echo", null, 1.0));
            late.set(true);
            assertThrows(IllegalStateException.class, () -> p.call("raylab.remote.Echo", "echo", null, 2.0));
            late.set(false);
            assertEquals(3.0, p.call("raylab.remote.Echo", "echo", null, 3.0), "the process goes on");
            assertEquals(1, p.starts());
        }
    }

    @Test
    void aTestsCallsTogetherAreStoppedAtTheTestsLimitOfTheStudentsTime() {
        try (StudentProcess p = StudentProcessTest.start(20_000)) {
            p.startTest(2_500_000_000L);
            assertEquals(1_000L, p.call("raylab.remote.Echo", "nap", null, 1_000L));
            assertEquals(1_000L, p.call("raylab.remote.Echo", "nap", null, 1_000L));
            StudentTimeout e = assertThrows(StudentTimeout.class, () -> p.call("raylab.remote.Echo", "nap", null, 5_000L));
            assertEquals("your code took longer than 2.5 s in this test and was stopped (an endless loop?)", e.getMessage());
            p.startTest(2_500_000_000L);
            assertEquals(1_000L, p.call("raylab.remote.Echo", "nap", null, 1_000L), "the next test has its own time");
        }
    }

    @Test
    void aCallThatSleepsIsStillStoppedByTheWallLimit() {
        try (StudentProcess p = StudentProcessTest.start(1_000)) {
            long t0 = System.nanoTime();
            assertThrows(StudentTimeout.class, () -> p.call("raylab.remote.Echo", "nap", null, 60_000L));
            double wall = (System.nanoTime() - t0) / 1e9;
            assertTrue(wall >= WALL_LIMIT_S && wall < 40, "stopped after " + wall + " s");
        }
    }
}
