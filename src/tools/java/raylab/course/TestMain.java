package raylab.course;

import java.io.ByteArrayOutputStream;
import java.io.FileDescriptor;
import java.io.FileOutputStream;
import java.io.InputStream;
import java.io.FileInputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.discovery.DiscoverySelectors;
import org.junit.platform.engine.support.descriptor.MethodSource;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.TagFilter;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The test runner inside a child JVM started by {@link TestLauncher}. Not for people to run.
 *
 * <p>It reads a one-line key (hex) from standard input, then runs the selected JUnit tests and
 * reports each on the original standard output through a {@link Channel} as {@code START id},
 * {@code RESULT json} and finally {@code END}, each line authenticated with the key. What the
 * tests print goes to a capped buffer attached to their result.
 * Arguments: {@code --test-classes DIR} (scanned for tests), {@code --tag T} (repeatable),
 * {@code --class NAME} (repeatable), {@code --timeout S} (per test), {@code --output-cap BYTES},
 * {@code --list} (report the discovered tests without running them), {@code --watchdog} (name and
 * end a test stuck in student code, {@link Watchdog}), {@code --skip FILE} (leave out the tests
 * whose unique ids, or whose parents' ids, are lines of FILE), {@code --then-boundary FILE}
 * (in the grader's process: the classes named after it run after the ones before it, each group
 * to its end, with a new student process described by FILE; see {@link BoundaryHooks}),
 * {@code --then-render FILE ARGS SECONDS} (in the grader's process, after every test has been
 * reported: the scenes listed in the file ARGS, one line each of SCENE.json, OUT.png and NAME,
 * rendered by the {@link BoundaryHooks} with a new student process described by
 * FILE, stopped after SECONDS).
 *
 * <p>One job: the child side of {@link TestLauncher}'s protocol, with the listener that turns JUnit's
 * events into its lines.
 */
public final class TestMain {
    private TestMain() {
    }

    public static void main(String[] args) throws Exception {
        // The key: one line of hex on standard input, read byte by byte (no buffer keeps a copy).
        FileInputStream stdin = new FileInputStream(FileDescriptor.in);
        byte[] hex = new byte[128];
        int n = 0;
        for (int b; n < hex.length && (b = stdin.read()) >= 0 && b != '\n';) {
            hex[n++] = (byte) b;
        }
        if (n == 0) {
            System.err.println("TestMain: expected a key on standard input");
            System.exit(2);
        }
        byte[] key = HexFormat.of().parseHex(new String(hex, 0, n, StandardCharsets.US_ASCII));
        Arrays.fill(hex, (byte) 0);
        System.setIn(InputStream.nullInputStream());
        Channel channel = new Channel(new PrintStream(new FileOutputStream(FileDescriptor.out), true,
                StandardCharsets.UTF_8), key);
        Arrays.fill(key, (byte) 0);

        Path testClasses = null;
        List<String> tags = new ArrayList<>();
        List<String> classes = new ArrayList<>();
        // Groups of classes run one after the other; a group after the first has its own student process.
        List<List<String>> groups = new ArrayList<>(List.of(classes));
        List<String> groupBoundary = new ArrayList<>(java.util.Collections.singletonList(null));
        int timeout = 10;
        int cap = 16 * 1024;
        boolean list = false;
        String[] render = null;
        Set<String> skip = Set.of();
        boolean watch = false;
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--test-classes" -> testClasses = Path.of(args[++i]);
                case "--tag" -> tags.add(args[++i]);
                case "--class" -> groups.get(groups.size() - 1).add(args[++i]);
                case "--then-boundary" -> {
                    groups.add(new ArrayList<>());
                    groupBoundary.add(args[++i]);
                }
                case "--then-render" -> render = new String[] {args[++i], args[++i], args[++i]};
                case "--timeout" -> timeout = Integer.parseInt(args[++i]);
                case "--output-cap" -> cap = Integer.parseInt(args[++i]);
                case "--list" -> list = true;
                case "--watchdog" -> watch = true;
                case "--skip" -> skip = Set.copyOf(java.nio.file.Files.readAllLines(Path.of(args[++i]),
                        StandardCharsets.UTF_8));
                default -> throw new IllegalArgumentException("unknown argument " + args[i]);
            }
        }
        // Whatever runs here prints into the capture, never onto the channel (standard output):
        // from now on, before the student process starts.
        CappedBuffer captured = new CappedBuffer(cap);
        PrintStream capture = new PrintStream(captured, true, StandardCharsets.UTF_8);
        System.setOut(capture);
        System.setErr(capture);
        // In the grader's process: start the student process before the first test's clock runs.
        java.util.Optional<BoundaryHooks> boundary = BoundaryHooks.find();
        if (System.getProperty("raylab.boundary") != null && !list) {
            try {
                boundary.ifPresent(BoundaryHooks::warmUp);
            } catch (RuntimeException e) {
                // the first call starts it, or reports why it cannot
            }
        }
        Launcher launcher = LauncherFactory.create();
        ObjectMapper json = new ObjectMapper();
        if (list) {
            LauncherDiscoveryRequest req = request(classes, testClasses, tags, timeout, Set.of());
            TestPlan plan = launcher.discover(req);
            for (TestIdentifier root : plan.getRoots()) {
                for (TestIdentifier t : plan.getDescendants(root)) {
                    if (t.isTest()) {
                        channel.send("RESULT " + json.writeValueAsString(
                                toResult(t, TestResult.Status.MISSING, "", "", 0)));
                    }
                }
            }
            channel.send("END");
            System.exit(0);
        }
        Map<String, Long> started = new ConcurrentHashMap<>();
        // Through the boundary a test's limit is the student's own time in its calls (StudentTime);
        // JUnit's clock, on wall time, is only a guard against a grader that hangs.
        StudentTime studentTime = System.getProperty("raylab.boundary") != null ? new StudentTime(timeout, boundary) : null;
        int junitTimeout = studentTime == null ? timeout : StudentTime.guardSeconds(timeout);
        // With --watchdog (check: the student's code, never the reference's own run), a test whose
        // code has not returned for the bound is named where it is stuck (its student frames),
        // long before the per-test timeout: the test is reported with that sentence, and
        // this JVM ends (a loop cannot be stopped from outside); the launcher runs the tests not
        // reported yet in a new one ("STUCK", TestLauncher). Behind the grader's process boundary
        // the student's code runs in another JVM, whose own watchdog names it (StudentServer).
        TestIdentifier[] running = {null};
        List<String> watchedFiles = Watchdog.studentFiles(Path.of("").toAbsolutePath());
        java.util.concurrent.atomic.AtomicBoolean ending = new java.util.concurrent.atomic.AtomicBoolean();
        Watchdog watchdog = studentTime != null || !watch ? null : Watchdog.start(Watchdog.bound(0),
                watchedFiles, stuck -> {
                    TestIdentifier t = running[0];
                    if (t == null || !ending.compareAndSet(false, true)) {
                        return; // between tests, or the test's end already says it
                    }
                    String id = t.getUniqueId();
                    long t0 = started.getOrDefault(id, System.nanoTime());
                    try {
                        channel.send("RESULT " + json.writeValueAsString(toResult(t, TestResult.Status.TIMED_OUT,
                                stuck, captured.text(), (System.nanoTime() - t0) / 1_000_000)));
                    } catch (Exception e) {
                        channel.send("ERROR " + e.getClass().getSimpleName());
                    }
                    channel.send("STUCK " + id);
                    Runtime.getRuntime().halt(STUCK_EXIT);
                });
        TestExecutionListener listener = new TestExecutionListener() {
            @Override
            public void executionStarted(TestIdentifier t) {
                if (t.isTest()) {
                    captured.reset();
                    if (watchdog != null) {
                        watchdog.next(Watchdog.bound(0));
                    }
                    running[0] = t;
                    started.put(t.getUniqueId(), System.nanoTime());
                    if (studentTime != null) {
                        studentTime.start(t.getUniqueId());
                    }
                    channel.send("START " + t.getUniqueId());
                }
            }

            @Override
            public void executionSkipped(TestIdentifier t, String reason) {
                if (t.isTest()) {
                    send(t, TestResult.Status.ABORTED, "skipped: " + reason, 0);
                }
            }

            @Override
            public void executionFinished(TestIdentifier t, TestExecutionResult r) {
                if (!t.isTest()) {
                    if (r.getStatus() != TestExecutionResult.Status.SUCCESSFUL) {
                        // A class-level failure (for example an exception in a static initializer):
                        // the tests below it are reported by the launcher as not run.
                        channel.send("CONTAINER " + t.getUniqueId() + " " + firstLines(r));
                    }
                    return;
                }
                long t0 = started.getOrDefault(t.getUniqueId(), System.nanoTime());
                long ms = (System.nanoTime() - t0) / 1_000_000;
                TestResult.Status s = switch (r.getStatus()) {
                    case SUCCESSFUL -> TestResult.Status.PASSED;
                    case ABORTED -> TestResult.Status.ABORTED;
                    case FAILED -> isTimeout(r) ? TestResult.Status.TIMED_OUT : TestResult.Status.FAILED;
                };
                if (watchdog != null && s == TestResult.Status.TIMED_OUT) {
                    // JUnit's wall clock came first (a loaded machine: the bound is in CPU time), and
                    // the test's thread may still run: named and ended as the watchdog does.
                    java.util.Optional<String> where = Watchdog.stuck(Thread.getAllStackTraces(),
                            watchedFiles, java.time.Duration.ofMillis(ms));
                    if (where.isPresent() && ending.compareAndSet(false, true)) {
                        send(t, s, where.get(), ms);
                        channel.send("STUCK " + t.getUniqueId());
                        Runtime.getRuntime().halt(STUCK_EXIT);
                    }
                }
                if (watchdog != null) {
                    watchdog.next(Watchdog.bound(0));
                }
                if (s == TestResult.Status.TIMED_OUT && studentTime != null) {
                    // The guard fired: the student's code, if its own time reached the limit; else
                    // the machine or the grader, which is no failure of the student's (no points decided).
                    String own = studentTime.overLimit(t.getUniqueId(), ms);
                    if (own == null) {
                        send(t, TestResult.Status.FAILED, studentTime.notTheStudents(ms), ms, true);
                    } else {
                        send(t, s, own, ms);
                    }
                    return;
                }
                boolean graders = gradersFault(r.getThrowable().orElse(null), System.getProperty("raylab.boundary") != null);
                send(t, s, s == TestResult.Status.PASSED ? "" : firstLines(r), ms, s != TestResult.Status.PASSED && graders);
            }

            private void send(TestIdentifier t, TestResult.Status s, String message, long ms) {
                send(t, s, message, ms, false);
            }

            private void send(TestIdentifier t, TestResult.Status s, String message, long ms, boolean gradingFailed) {
                try {
                    channel.send("RESULT " + json.writeValueAsString(toResult(t, s, message, captured.text(), ms,
                            gradingFailed)));
                } catch (Exception e) {
                    channel.send("ERROR " + e.getClass().getSimpleName());
                }
            }
        };
        for (int g = 0; g < groups.size(); g++) {
            if (groups.get(g).isEmpty() && (g > 0 || groups.size() > 1)) {
                continue; // an empty group runs nothing (only a lone empty list means: scan --test-classes)
            }
            if (groupBoundary.get(g) != null) {
                // The student process of the groups before ends here: nothing it saw reaches this group.
                present(boundary).switchTo(Path.of(groupBoundary.get(g)));
            }
            launcher.execute(request(groups.get(g), testClasses, tags, junitTimeout, skip), listener);
        }
        channel.send("END");
        if (render != null) {
            render(render, present(boundary));
        }
        // Stray threads started by the code under test must not keep this JVM alive.
        Runtime.getRuntime().halt(0);
    }

    /**
     * The scenes of {@code --then-render}: a new student process (nothing a test passed to student
     * code reaches a picture), then the renders; next to the list their time in ms
     * ({@code millis.txt}) and, with RAYLAB_GRADE_TIMES, their phases ({@code times.txt}).
     */
    static void render(String[] render, BoundaryHooks boundary) throws Exception {
        Path list = Path.of(render[1]);
        long budget = Long.parseLong(render[2]) * 1_000_000_000L;
        // Starting the process is the grader's time, on a loaded machine seconds of it: the
        // renders' limit is the student's CPU time, counted from the first scene on.
        boundary.switchTo(Path.of(render[0]));
        long t0 = System.nanoTime();
        try (PrintStream times = new PrintStream(list.resolveSibling("times.txt").toFile(), StandardCharsets.UTF_8)) {
            boundary.renderAll(java.nio.file.Files.readAllLines(list), budget, times);
        }
        java.nio.file.Files.writeString(list.resolveSibling("millis.txt"),
                Long.toString((System.nanoTime() - t0) / 1_000_000));
    }

    /**
     * Whether a test that ended with {@code thrown} failed on the grading's side: a
     * {@link GraderFault}, or, behind the process boundary (where this JVM runs no code of the
     * student's), this JVM's own memory or stack running out ({@link VirtualMachineError}).
     */
    static boolean gradersFault(Throwable thrown, boolean behindBoundary) {
        return thrown instanceof GraderFault || (behindBoundary && thrown instanceof VirtualMachineError);
    }

    /** The process boundary, which {@code --then-boundary} and {@code --then-render} need. */
    private static BoundaryHooks present(java.util.Optional<BoundaryHooks> boundary) {
        return boundary.orElseThrow(() -> new IllegalStateException(
                "--then-boundary and --then-render need the grader's process boundary, which this build does not have"));
    }

    /** Whether {@code id} is one of {@code skip} or below one of them. */
    static boolean skipped(Set<String> skip, String id) {
        for (int k = id.length(); k > 0; k = id.lastIndexOf("/[", k - 1)) {
            if (skip.contains(id.substring(0, k))) {
                return true;
            }
        }
        return false;
    }

    /** The exit status of a JVM ended by a stuck test (after its report and "STUCK"). */
    public static final int STUCK_EXIT = 86;

    /**
     * The tests to run: without the tests whose unique ids are in {@code skip} (already reported
     * by an earlier JVM of the same run; a parameterized or dynamic test is left out whole when
     * its id is there, as the launcher lists it).
     */
    private static LauncherDiscoveryRequest request(List<String> classes, Path testClasses, List<String> tags,
            int timeout, Set<String> skip) {
        LauncherDiscoveryRequestBuilder request = LauncherDiscoveryRequestBuilder.request()
                .configurationParameter("junit.jupiter.execution.timeout.default", timeout + " s")
                .configurationParameter("junit.jupiter.execution.timeout.mode", "enabled")
                .configurationParameter("junit.jupiter.execution.timeout.thread.mode.default", "SEPARATE_THREAD")
                .configurationParameter("junit.jupiter.extensions.autodetection.enabled", "false");
        if (!classes.isEmpty()) {
            for (String c : classes) {
                request.selectors(DiscoverySelectors.selectClass(c));
            }
        } else if (testClasses != null) {
            request.selectors(DiscoverySelectors.selectClasspathRoots(Set.of(testClasses)));
        }
        if (!tags.isEmpty()) {
            request.filters(TagFilter.includeTags(tags));
        }
        if (!skip.isEmpty()) {
            request.filters((org.junit.platform.launcher.PostDiscoveryFilter) d -> skipped(skip, d.getUniqueId().toString())
                    ? org.junit.platform.engine.FilterResult.excluded("reported by an earlier run")
                    : org.junit.platform.engine.FilterResult.included("not reported yet"));
        }
        return request.build();
    }

    /**
     * The report channel: each line is {@code R2 SEQ MAC PAYLOAD}, MAC = HMAC-SHA256 over
     * {@code SEQ PAYLOAD} with the key the parent sent; the parent accepts only lines whose MAC
     * checks and whose SEQ follows the last one. Output written to file descriptor 1 by anything
     * else cannot be taken for a report without the key, which is kept only inside a
     * {@link Mac} (a java.base object that code on the class path cannot open by reflection).
     */
    static final class Channel {
        private final PrintStream out;
        private final Mac mac;
        private long seq;

        Channel(PrintStream out, byte[] key) throws java.security.GeneralSecurityException {
            this.out = out;
            this.mac = Mac.getInstance("HmacSHA256");
            this.mac.init(new SecretKeySpec(key, "HmacSHA256"));
        }

        /**
         * One signed line, on a line of its own: it starts with a newline too, so that text some
         * code wrote to this JVM's standard output without one (a library, the JVM itself) never
         * runs into it; the reader skips the empty lines.
         */
        synchronized void send(String payload) {
            String body = (++seq) + " " + payload.replace('\n', ' ').replace('\r', ' ');
            String tag = HexFormat.of().formatHex(mac.doFinal(body.getBytes(StandardCharsets.UTF_8)));
            out.print("\nR2 " + tag + " " + body + "\n");
            out.flush();
        }
    }

    static TestResult toResult(TestIdentifier t, TestResult.Status s, String message, String output, long ms) {
        return toResult(t, s, message, output, ms, false);
    }

    static TestResult toResult(TestIdentifier t, TestResult.Status s, String message, String output, long ms,
            boolean gradingFailed) {
        String cls = "";
        String method = t.getDisplayName();
        if (t.getSource().orElse(null) instanceof MethodSource m) {
            cls = m.getClassName();
            method = m.getMethodName();
        } else {
            String id = t.getUniqueId();
            int k = id.indexOf("[class:");
            if (k >= 0) {
                cls = id.substring(k + 7, id.indexOf(']', k));
            }
        }
        return new TestResult(t.getUniqueId(), cls, method, t.getDisplayName(), s, message, output, ms, gradingFailed);
    }

    static boolean isTimeout(TestExecutionResult r) {
        return r.getThrowable().map(e -> e instanceof java.util.concurrent.TimeoutException
                || e.getClass().getName().endsWith("TimeoutException")).orElse(false);
    }

    static String firstLines(TestExecutionResult r) {
        return r.getThrowable().map(e -> {
            String m = e.getMessage();
            String text = (m == null || m.isBlank()) ? e.getClass().getName() : m;
            if (e instanceof StackOverflowError) {
                text = "StackOverflowError (endless recursion?)";
            } else if (e instanceof OutOfMemoryError) {
                text = "OutOfMemoryError: the test used more memory than allowed";
            } else if (!(e instanceof AssertionError) && !(e instanceof NotImplemented)) {
                // A grader fault is the cause the grader shows (TestResult.gradingFailed), not an exception of the student's.
                text = e instanceof GraderFault ? text : e.getClass().getSimpleName() + ": " + text;
                StackTraceElement[] st = e.getStackTrace();
                for (StackTraceElement el : st) {
                    if (el.getClassName().startsWith("raylab.") && !isMachinery(el.getClassName())) {
                        text += " (at " + el.getClassName() + "." + el.getMethodName() + ":" + el.getLineNumber() + ")";
                        break;
                    }
                }
            }
            return text.length() > 2000 ? text.substring(0, 2000) + " ..." : text;
        }).orElse("");
    }

    /** The grading's own packages: where a student has nothing to look at. */
    private static final List<String> MACHINERY = List.of("raylab.boundary.", "raylab.grade.", "raylab.remote.",
            "raylab.course.", "raylab.cli.");

    /**
     * Whether {@code className} is the grading's machinery (the boundary, the grader, the test
     * launcher): a failure's "(at ...)" names the first place a student can open instead, their
     * code, the framework or the test.
     */
    static boolean isMachinery(String className) {
        return MACHINERY.stream().anyMatch(className::startsWith) && !className.equals(NotImplemented.class.getName());
    }

    /** Keeps the first {@code cap} bytes written, and counts the rest. */
    static final class CappedBuffer extends OutputStream {
        private final int cap;
        private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        private long dropped;

        CappedBuffer(int cap) {
            this.cap = cap;
        }

        @Override
        public synchronized void write(int b) {
            if (bytes.size() < cap) {
                bytes.write(b);
            } else {
                dropped++;
            }
        }

        @Override
        public synchronized void write(byte[] b, int off, int len) {
            int room = Math.max(0, cap - bytes.size());
            int n = Math.min(room, len);
            bytes.write(b, off, n);
            dropped += len - n;
        }

        synchronized void reset() {
            bytes.reset();
            dropped = 0;
        }

        synchronized String text() {
            String s = bytes.toString(StandardCharsets.UTF_8);
            return dropped > 0 ? s + "\n[... " + dropped + " more bytes of output dropped]" : s;
        }
    }
}
