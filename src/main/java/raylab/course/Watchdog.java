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
 * for 5 s in Lambertian.diffuse (Lambertian.java:41) without returning: an endless loop?" (the
 * student's frames of a thread dump, innermost first, as raylab.cli.StudentFault names an exception
 * with the same helpers).
 * While no thread is in student code (the framework itself is busy) it keeps waiting.
 *
 * <p>The bound: a few times the reference's own time for one unit of work, with a floor of
 * {@link #FLOOR} (the reference finishes a tile or a pixel in milliseconds, so the floor rules
 * for renders and traces). Shared by {@code render}, {@code trace}, {@code check} (its renders and
 * its tests) and the grader's test JVM.
 */
public final class Watchdog implements AutoCloseable {
    /** The shortest bound: no unit of work of the reference comes near it. */
    public static final Duration FLOOR = Duration.ofSeconds(5);
    /** How many times the reference's time a unit may take before it counts as stuck. */
    public static final int TIMES_REFERENCE = 4;
    private static final long POLL_MS = 100;

    private volatile Duration bound;
    private final boolean stopThreads;
    private volatile String message;
    private final Collection<String> studentFiles;
    private final Consumer<String> onStuck;
    private final AtomicLong last = new AtomicLong(System.nanoTime());
    private final Thread thread;
    private volatile boolean closed;

    private Watchdog(Duration bound, Collection<String> studentFiles, Consumer<String> onStuck, boolean stopThreads) {
        this.bound = bound;
        this.stopThreads = stopThreads;
        this.studentFiles = studentFiles;
        this.onStuck = onStuck;
        this.thread = new Thread(this::watch, "raylab-watchdog");
        thread.setDaemon(true);
    }

    /** The bound for a unit of work whose reference time is {@code referenceMillis} (0 if unknown). */
    public static Duration bound(long referenceMillis) {
        Duration derived = Duration.ofMillis(Math.max(0, referenceMillis) * TIMES_REFERENCE);
        return derived.compareTo(FLOOR) > 0 ? derived : FLOOR;
    }

    /**
     * Starts watching: {@code onStuck} gets the sentence once, from the watchdog's thread, when no
     * {@link #progress()} came for {@code bound} while some thread is in a student file; with
     * {@code stopThreads}, the threads in student code are then stopped ({@link #message()} says why).
     */
    public static Watchdog start(Duration bound, Collection<String> studentFiles, Consumer<String> onStuck,
            boolean stopThreads) {
        Watchdog w = new Watchdog(bound, studentFiles, onStuck, stopThreads);
        w.thread.start();
        return w;
    }

    /** The bound this watchdog waits. */
    public Duration bound() {
        return bound;
    }

    /** A unit of work finished (any thread). */
    public void progress() {
        last.set(System.nanoTime());
    }

    private void watch() {
        try {
            while (!closed) {
                Thread.sleep(POLL_MS);
                long idle = System.nanoTime() - last.get();
                if (closed || idle < bound.toNanos()) {
                    continue;
                }
                Optional<String> where = stuck(Thread.getAllStackTraces(), studentFiles, Duration.ofNanos(idle));
                if (where.isPresent() && !closed) {
                    message = where.get();
                    onStuck.accept(message);
                    if (stopThreads) {
                        stopStudentThreads();
                    }
                    last.set(System.nanoTime());
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * The sentence for the first thread of {@code stacks} that is inside a student file, or empty:
     * "your code has run for 5 s in Sphere.intersect (Sphere.java:41) without returning: an
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
     * Ends the stuck student code: each thread in a student file gets a {@link ThreadDeath} where
     * it is (a loop that never returns cannot be asked to stop), until {@link #close()}. On a JVM
     * without Thread.stop, the sentence goes to standard error and the JVM exits with status 1.
     */
    @SuppressWarnings({"deprecation", "removal"})
    private void stopStudentThreads() throws InterruptedException {
        java.util.Set<Thread> stuck = new java.util.HashSet<>();
        Thread.getAllStackTraces().forEach((t, st) -> {
            if (t != Thread.currentThread() && inStudentCode(st)) {
                stuck.add(t);
            }
        });
        while (!closed && !stuck.isEmpty()) {
            for (Thread t : List.copyOf(stuck)) {
                if (!t.isAlive() || !inStudentCode(t.getStackTrace())) {
                    stuck.remove(t);
                    continue;
                }
                try {
                    t.stop();
                } catch (UnsupportedOperationException noStop) {
                    System.err.println("raylab: " + message);
                    System.err.flush();
                    Runtime.getRuntime().halt(1);
                }
            }
            Thread.sleep(10);
        }
    }

    private boolean inStudentCode(StackTraceElement[] stack) {
        return java.util.Arrays.stream(stack).anyMatch(f -> studentFiles.contains(sourceOf(f)));
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
