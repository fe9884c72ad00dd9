package raylab.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.time.Duration;

import org.junit.jupiter.api.Test;

/**
 * The watchdog's bound as production has it (2 s of CPU time, 12 s of wall time where there is no
 * CPU clock or the code waits), and the test knob {@link Watchdog#FLOOR_ENV} that only the tests
 * of the watchdog set.
 */
class WatchdogTest {
    static final long S = 1_000_000_000L;

    @Test
    void theProductionBoundIsTwoSecondsOfCpuAndTwelveOfWallTime() {
        assertNull(System.getenv(Watchdog.FLOOR_ENV), "the test run itself leaves the knob unset, as production does");
        assertEquals(Duration.ofSeconds(2), Watchdog.FLOOR, "the floor");
        assertEquals(Duration.ofSeconds(2), Watchdog.floor(), "the floor in force");
        assertEquals(Duration.ofSeconds(2), Watchdog.bound(0), "the bound of a unit without a reference time");
        Duration b = Watchdog.bound(0);
        // CPU time: stuck at 2 s, not before.
        assertNull(Watchdog.idle(1 * S, 2 * S - 1, b), "1.999... s of CPU time");
        assertEquals(Duration.ofSeconds(2), Watchdog.idle(3 * S, 2 * S, b), "2 s of CPU time");
        assertNull(Watchdog.cpuIdle(30 * S, 2 * S - 1, b), "the student process: CPU time only");
        assertEquals(Duration.ofSeconds(2), Watchdog.cpuIdle(30 * S, 2 * S, b), "the student process at 2 s of CPU");
        // Wall time: 6 x 2 s = 12 s for code that waits, and for the sandboxed student process without /proc.
        assertEquals(6, Watchdog.WALL_TIMES);
        assertNull(Watchdog.idle(12 * S - 1, S / 10, b), "code that waits, at 11.999... s of wall time");
        assertEquals(Duration.ofSeconds(12), Watchdog.idle(12 * S, S / 10, b), "code that waits, at 12 s");
        assertNull(Watchdog.cpuIdle(12 * S - 1, -1, b), "no CPU clock (the grader's sandbox), 11.999... s of wall time");
        assertEquals(Duration.ofSeconds(12), Watchdog.cpuIdle(12 * S, -1, b), "no CPU clock, 12 s of wall time");
        assertEquals(Duration.ofSeconds(8), Watchdog.bound(2_000), "4 x a reference time of 2 s");
    }

    @Test
    void theKnobSetsTheFloorOnlyToAWholeNumberOfAtLeast200Milliseconds() {
        assertEquals(Duration.ofSeconds(2), Watchdog.floor(null), "unset");
        assertEquals(Duration.ofMillis(400), Watchdog.floor("400"));
        assertEquals(Duration.ofMillis(400), Watchdog.floor(" 400\n"));
        assertEquals(Duration.ofMillis(200), Watchdog.floor("200"));
        assertEquals(Duration.ofMillis(5_000), Watchdog.floor("5000"));
        for (String bad : new String[] {"", "199", "0", "-400", "0.4", "400ms", "abc", "9999999999"}) {
            assertEquals(Duration.ofSeconds(2), Watchdog.floor(bad), "the knob '" + bad + "'");
        }
    }
}
