package raylab.course;

import java.time.Duration;
import java.util.Collection;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

/**
 * Names student code that stopped making progress: a daemon thread that, when no unit of work
 * (a tile of a render, a pixel of a trace, a test) has finished for {@link #bound()}, looks at the
 * stacks of every thread and, if one is inside a student file, reports where: "your code has run
 * for 2 s in Lambertian.diffuse (Lambertian.java:41) without returning: an endless loop?" (the
 * student's frames of a thread dump, innermost first, as raylab.cli.StudentFault names an exception
 * with the same helpers).
 * While no thread is in student code (the framework itself is busy) it keeps waiting.
 *
 * <p>The bound: {@link #TIMES_REFERENCE} times the reference's own time for one unit of work,
 * at least {@link #FLOOR} (the reference finishes a tile, a pixel, a call of the grader's or a
 * visible test in far less, so the floor rules: no reference time per unit is recorded yet, and
 * {@code bound(0)} is the floor). It is counted in CPU time of this process (the machine's load is
 * not the student's: a busy loop uses a CPU all the time it runs), or, for code that waits instead
 * of running, in wall time at {@link #WALL_TIMES} times the bound. Shared by {@code render},
 * {@code trace} and {@code check} (its renders and its tests); the grader's student process has a
 * watchdog of its own with the same bound and sentence ({@code raylab.remote.StudentServer}).
 * The tests of the watchdog lower the floor with {@link #FLOOR_ENV}; nothing else sets it.
 */
public final class Watchdog implements AutoCloseable {
    /** The shortest bound: no unit of work of the reference comes near it. */
    public static final Duration FLOOR = Duration.ofSeconds(2);
    /** How many times the reference's time a unit may take before it counts as stuck. */
    public static final int TIMES_REFERENCE = 4;
    /** How many times the bound a unit may take in wall time (code that sleeps or waits uses no CPU). */
    public static final int WALL_TIMES = 6;
    private static final long POLL_MS = 100;

    private volatile Duration bound;
    private volatile String message;
    private final Collection<String> studentFiles;
    private final Consumer<String> onStuck;
    /** Units of work finished so far; the watchdog's clocks start again when it changes. */
    private final AtomicLong units = new AtomicLong();
    private final Thread thread;
    private volatile boolean closed;

    private Watchdog(Duration bound, Collection<String> studentFiles, Consumer<String> onStuck) {
        this.bound = bound;
        this.studentFiles = studentFiles;
        this.onStuck = onStuck;
        this.thread = new Thread(this::watch, "raylab-watchdog");
        thread.setDaemon(true);
    }

    /**
     * The environment variable that replaces {@link #FLOOR}, in milliseconds: a knob for the tests
     * of the watchdog itself (raylab.cli.EndlessLoopTest), so that their loops are stopped after
     * a fraction of a second of CPU time instead of 2 s. Unset (as everywhere but in those tests),
     * or not a whole number of at least {@value #FLOOR_KNOB_MIN_MILLIS}, the floor is {@link #FLOOR}.
     * Child processes inherit it ({@code check}'s test JVM); the grader passes its bound to the
     * student process as an option ({@code raylab.remote.StudentServer#STUCK_AFTER}).
     */
    public static final String FLOOR_ENV = "RAYLAB_WATCHDOG_FLOOR_MS";
    /** The smallest floor {@link #FLOOR_ENV} may set (ms): the watchdog looks every 100 ms. */
    public static final long FLOOR_KNOB_MIN_MILLIS = 200;

    /** The floor in force: {@link #FLOOR}, unless {@link #FLOOR_ENV} sets another. */
    public static Duration floor() {
        return floor(System.getenv(FLOOR_ENV));
    }

    /** The floor that {@code knob} (the value of {@link #FLOOR_ENV}, null if unset) sets. */
    static Duration floor(String knob) {
        if (knob == null || !knob.strip().matches("\\d{1,9}")) {
            return FLOOR;
        }
        long ms = Long.parseLong(knob.strip());
        return ms >= FLOOR_KNOB_MIN_MILLIS ? Duration.ofMillis(ms) : FLOOR;
    }

    /** The bound for a unit of work whose reference time is {@code referenceMillis} (0 if unknown). */
    public static Duration bound(long referenceMillis) {
        Duration floor = floor();
        Duration derived = Duration.ofMillis(Math.max(0, referenceMillis) * TIMES_REFERENCE);
        return derived.compareTo(floor) > 0 ? derived : floor;
    }

    /**
     * Starts watching: {@code onStuck} gets the sentence, from the watchdog's thread, when no
     * {@link #progress()} came for {@code bound} while some thread is in a student file. A loop
     * that never returns cannot be asked to stop, and no thread is stopped from outside (no
     * {@code Thread.stop}, which JDK 20 and later refuse): {@code onStuck} ends the JVM that runs
     * it, after saying where it is ({@link #endJvm}); a caller that cannot end it is called again
     * after each further bound.
     */
    public static Watchdog start(Duration bound, Collection<String> studentFiles, Consumer<String> onStuck) {
        Watchdog w = new Watchdog(bound, studentFiles, onStuck);
        w.thread.start();
        return w;
    }

    /** The bound this watchdog waits. */
    public Duration bound() {
        return bound;
    }

    /** A unit of work finished (any thread). */
    public void progress() {
        units.incrementAndGet();
    }

    private void watch() {
        long seen = -1;
        long wall0 = 0;
        long cpu0 = 0;
        try {
            while (!closed) {
                Thread.sleep(POLL_MS);
                long u = units.get();
                long wall = System.nanoTime();
                long cpu = cpuNanos();
                if (u != seen) {
                    seen = u;
                    wall0 = wall;
                    cpu0 = cpu;
                    continue;
                }
                Duration idle = idle(wall - wall0, cpu < 0 ? -1 : cpu - cpu0, bound);
                if (closed || idle == null) {
                    continue;
                }
                Optional<String> where = stuck(Thread.getAllStackTraces(), studentFiles, idle);
                if (where.isPresent() && !closed) {
                    message = where.get();
                    onStuck.accept(message);
                    seen = -1;
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * How long a unit of work has run, when that is past {@code bound}, else null: its CPU time
     * ({@code cpuNanos}, −1 where unknown: then its wall time) at the bound, or its wall time at
     * {@link #WALL_TIMES} times the bound.
     */
    public static Duration idle(long wallNanos, long cpuNanos, Duration bound) {
        long b = bound.toNanos();
        if (cpuNanos >= 0 ? cpuNanos >= b : wallNanos >= b) {
            return Duration.ofNanos(cpuNanos >= 0 ? cpuNanos : wallNanos);
        }
        return wallNanos >= WALL_TIMES * b ? Duration.ofNanos(wallNanos) : null;
    }

    /**
     * As {@link #idle(long, long, Duration)} in CPU time only, for the grader's student process,
     * whose wall time is bounded by the grader in the student's own time (its waits for a CPU left
     * out, {@code raylab.boundary.StudentProcess}); where this process cannot read a CPU clock
     * ({@link #threadCpuNanos} says −1) in wall time at {@link #WALL_TIMES} times the bound.
     */
    public static Duration cpuIdle(long wallNanos, long cpuNanos, Duration bound) {
        if (cpuNanos >= 0) {
            return cpuNanos >= bound.toNanos() ? Duration.ofNanos(cpuNanos) : null;
        }
        // No CPU clock: only the wall time at WALL_TIMES x the bound.
        return wallNanos >= WALL_TIMES * bound.toNanos() ? Duration.ofNanos(wallNanos) : null;
    }

    /** The CPU time of this process so far (ns), or −1 where the system does not say (no /proc). */
    public static long cpuNanos() {
        return ProcessHandle.current().info().totalCpuDuration().map(Duration::toNanos).orElse(-1L);
    }

    /**
     * The CPU time {@code thread} has used so far (ns), or −1 where this JVM cannot say: it was
     * started without the {@code java.management} module, or the thread has ended. Unlike
     * {@link #cpuNanos()} it reads no /proc: HotSpot on Linux asks the kernel for the thread's
     * own clock ({@code pthread_getcpuclockid}, {@code clock_gettime}), so it also counts in the
     * grader's sandbox, which mounts no /proc.
     */
    public static long threadCpuNanos(Thread thread) {
        return ModuleLayer.boot().findModule("java.management").isPresent() ? ThreadClock.nanos(thread) : -1;
    }

    /** Apart, so that a JVM without java.management never loads it. */
    private static final class ThreadClock {
        private static final java.lang.management.ThreadMXBean THREADS = java.lang.management.ManagementFactory
                .getThreadMXBean();

        static long nanos(Thread thread) {
            try {
                return THREADS.isThreadCpuTimeSupported() ? THREADS.getThreadCpuTime(thread.getId()) : -1;
            } catch (UnsupportedOperationException e) {
                return -1; // measuring thread CPU time switched off
            }
        }
    }

    /**
     * The sentence for the first thread of {@code stacks} that is inside a student file, or empty:
     * "your code has run for 2 s in Sphere.intersect (Sphere.java:41) without returning: an
     * endless loop? [called from ...]".
     */
    public static Optional<String> stuck(Map<Thread, StackTraceElement[]> stacks, Collection<String> studentFiles,
            Duration idle) {
        for (Map.Entry<Thread, StackTraceElement[]> e : stacks.entrySet()) {
            if (e.getKey() == Thread.currentThread()) {
                continue;
            }
            List<StackTraceElement> frames = java.util.Arrays.stream(e.getValue())
                    .filter(f -> studentFiles.contains(sourceOf(f))).toList();
            if (!frames.isEmpty()) {
                return Optional.of(sentence(frames, idle));
            }
        }
        return Optional.empty();
    }

    /** The sentence for a thread whose student frames (innermost first) have run for {@code idle}. */
    static String sentence(List<StackTraceElement> frames, Duration idle) {
        StringBuilder b = new StringBuilder("your code has run for ").append(Math.max(1, idle.toSeconds()))
                .append(" s in ").append(place(frames.get(0)))
                .append(" without returning: an endless loop?");
        return b.append(calledFrom(frames)).toString();
    }

    /** The last sentence said, or null while nothing was stuck. */
    public String message() {
        return message;
    }

    /**
     * Says {@code line} on {@code err} and ends this JVM with {@code status} at once (no shutdown
     * hook, no thread waits: the stuck one never would). What the command wrote so far is flushed
     * first; a file it was writing is left unfinished only where its own temporary name keeps it
     * from view (the PNG writer's).
     */
    public static void endJvm(java.io.PrintWriter err, String line, int status) {
        System.out.flush();
        err.println(line);
        err.flush();
        System.err.flush();
        Runtime.getRuntime().halt(status);
    }

    /** Sets the bound for the next unit of work (a test of its own reference time) and counts as progress. */
    public void next(Duration newBound) {
        bound = newBound;
        message = null;
        progress();
    }

    /** The student files when no assignment.json can be read (the seven of the course). */
    public static final List<String> DEFAULT_FILES = List.of("src/main/java/raylab/surface/Sphere.java",
            "src/main/java/raylab/surface/Box.java", "src/main/java/raylab/surface/Triangle.java",
            "src/main/java/raylab/material/Lambertian.java", "src/main/java/raylab/shading/Shading.java",
            "src/main/java/raylab/shading/Shadows.java", "src/main/java/raylab/material/BlinnPhong.java");

    /** The student files of the project at {@code root}, '/'-separated relative paths. */
    public static List<String> studentFiles(java.nio.file.Path root) {
        try {
            List<String> files = new java.util.ArrayList<>();
            for (Assignment a : Assignments.load(root).all()) {
                for (Assignment.StudentFile f : a.files()) {
                    files.add(f.path().replace('\\', '/'));
                }
            }
            return files.isEmpty() ? DEFAULT_FILES : files;
        } catch (java.io.IOException | RuntimeException e) {
            return DEFAULT_FILES;
        }
    }

    /** At most this many student frames are named. */
    public static final int FRAMES = 4;

    /** The source path of a frame's class: src/main/java/raylab/surface/Sphere.java for raylab.surface.Sphere$1. */
    public static String sourceOf(StackTraceElement e) {
        String cls = e.getClassName();
        int dollar = cls.indexOf('$');
        String outer = dollar < 0 ? cls : cls.substring(0, dollar);
        return "src/main/java/" + outer.replace('.', '/') + ".java";
    }

    /** Sphere.intersect (Sphere.java:37) */
    public static String place(StackTraceElement e) {
        String cls = e.getClassName();
        String simple = cls.substring(cls.lastIndexOf('.') + 1);
        return simple + "." + e.getMethodName() + " (" + e.getFileName() + ":" + e.getLineNumber() + ")";
    }

    /** " [called from Shading.shade (Shading.java:40) < ...]" for the frames after the first, or "". */
    public static String calledFrom(List<StackTraceElement> frames) {
        if (frames.size() <= 1) {
            return "";
        }
        StringBuilder b = new StringBuilder(" [called from ");
        for (int i = 1; i < Math.min(frames.size(), FRAMES); i++) {
            b.append(i == 1 ? "" : " < ").append(place(frames.get(i)));
        }
        return b.append(frames.size() > FRAMES ? " < ...]" : "]").toString();
    }

    @Override
    public void close() {
        closed = true;
        thread.interrupt();
    }
}
