package raylab.course;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import javax.crypto.Mac;
import javax.crypto.spec.SecretKeySpec;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Runs JUnit tests in a separate JVM ({@link TestMain}) with a memory cap and time limits, and
 * collects a result for every test it was asked about: what the child did not report as passed
 * is not passed (fail closed).
 *
 * <p>One job: the parent side of the test JVM's authenticated protocol, from its start to a
 * fail-closed result for every expected test.
 */
public final class TestLauncher {
    /** Limits of one child JVM. */
    public record Limits(int heapMegabytes, Duration wallClock, int perTestSeconds, int outputCapBytes) {
        public static final Limits DEFAULT = new Limits(512, Duration.ofSeconds(120), 10, 16 * 1024);
    }

    /**
     * What one child run produced.
     *
     * @param results  one result per test reported or expected, in order
     * @param finished whether the child reached the end of its run
     * @param problem  why it did not (timed out, exited early...), empty if it did: for people
     *                 to read; code asks {@code timedOut} and {@code cutOff}
     * @param timedOut whether the run was stopped at its wall-clock limit
     * @param cutOff   the id of the test that was running when the run stopped (its result says
     *                 so in its message), or null
     */
    public record Run(List<TestResult> results, boolean finished, String problem, boolean timedOut, String cutOff) {
        public long passed() {
            return results.stream().filter(r -> r.status().passed()).count();
        }
    }

    private static final ObjectMapper JSON = new ObjectMapper();

    /**
     * The only modules a child JVM sees: no {@code jdk.unsupported} (no {@code sun.misc.Unsafe}),
     * no {@code java.instrument}, {@code jdk.attach}, {@code jdk.jdi} or management modules.
     */
    public static final String CHILD_MODULES = "java.base,java.desktop,java.logging,java.xml,java.sql";

    private TestLauncher() {
    }

    /**
     * Lists the tests a selection holds, without running them (discovery in a child JVM).
     */
    public static List<TestResult> discover(List<Path> classPath, Path testClasses, List<String> tags,
            List<String> classes, Path workDir) throws IOException {
        Run o = launch(classPath, testClasses, tags, classes, Limits.DEFAULT, workDir, true, List.of(), List.of(), List.of());
        if (!o.finished()) {
            throw new IOException("test discovery failed: " + o.problem());
        }
        return o.results();
    }

    /**
     * Runs the selected tests. {@code expected} (from {@link #discover}) are the tests that must
     * report: any of them without a report is returned as MISSING, TIMED_OUT or CRASHED.
     */
    private static final String THEN_BOUNDARY = "--then-boundary=";

    /**
     * An entry of {@code classes} for {@link #run}: the classes after it run after those before
     * it, with a new student process described by {@code config} ({@code TestMain --then-boundary}).
     */
    public static String thenBoundary(Path config) {
        return THEN_BOUNDARY + config;
    }

    private static final String WATCHDOG = "--watchdog";

    /**
     * An entry of {@code classes} for {@link #run}: a test stuck in student code is named and its
     * JVM ended ({@link Watchdog}); the tests not reported yet run in a new JVM, except the rest of
     * the stuck test's class (its other tests would most likely be stuck in the same loop: they
     * are reported as not run, with the stuck one named). For {@code check}; never for a run of
     * the reference, whose tests are what the bound is measured against.
     */
    public static String watchdog() {
        return WATCHDOG;
    }

    private static final String THEN_RENDER = "--then-render=";

    /**
     * An entry of {@code classes} for {@link #run}, the last one: after every test, the scenes
     * listed in {@code list} are rendered with a new student process described by {@code config},
     * stopped after {@code seconds} ({@code TestMain --then-render}).
     */
    public static String thenRender(Path config, Path list, long seconds) {
        return THEN_RENDER + config + "\0" + list + "\0" + seconds;
    }

    public static Run run(List<Path> classPath, Path testClasses, List<String> tags, List<String> classes,
            Limits limits, Path workDir, List<TestResult> expected) throws IOException {
        return launch(classPath, testClasses, tags, classes, limits, workDir, false, expected, List.of(), List.of());
    }

    /**
     * As {@link #run}, with the child's command line prefixed by {@code wrapper} (for example
     * {@code setpriv --reuid=... --} to run it as an unprivileged user); empty for none.
     */
    public static Run run(List<Path> classPath, Path testClasses, List<String> tags, List<String> classes,
            Limits limits, Path workDir, List<TestResult> expected, List<String> wrapper) throws IOException {
        return launch(classPath, testClasses, tags, classes, limits, workDir, false, expected, wrapper, List.of());
    }

    /**
     * As {@link #run}, with more options for the child JVM ({@code -Dname=value}), for example the
     * student process of the grader's process ({@code raylab.boundary}).
     */
    public static Run run(List<Path> classPath, Path testClasses, List<String> tags, List<String> classes,
            Limits limits, Path workDir, List<TestResult> expected, List<String> wrapper, List<String> jvmOptions)
            throws IOException {
        return launch(classPath, testClasses, tags, classes, limits, workDir, false, expected, wrapper, jvmOptions,
                true);
    }

    /**
     * As {@link #run}, for a JVM that runs no student code (the grader's process behind the
     * process boundary, whose stand-ins call a student process): it sees every module of the
     * JDK, since {@code --limit-modules} would turn class data sharing off and only guards a
     * JVM where student code runs.
     *
     * <p>There every limit of the student's is in the student's own time (each call's, each
     * test's: {@link StudentTime}; the renders'), so the JVM's wall clock is only a guard, at
     * {@link #GUARD_FACTOR} × {@code limits.wallClock()}: when it fires, the tests not reported
     * fail as a grading failure ({@link TestResult#gradingFailed()}), not as the student's. So do
     * all of them when the JVM ends before it starts a test (it did not start, or the course's
     * tests could not be discovered).
     */
    public static Run runTrusted(List<Path> classPath, Path testClasses, List<String> classes, Limits limits,
            Path workDir, List<TestResult> expected, List<String> jvmOptions) throws IOException {
        Limits guard = new Limits(limits.heapMegabytes(), limits.wallClock().multipliedBy(GUARD_FACTOR),
                limits.perTestSeconds(), limits.outputCapBytes());
        return launch(classPath, testClasses, List.of(), classes, guard, workDir, false, expected, List.of(),
                jvmOptions, false, true);
    }

    /** How much longer than its limits the wall clock of a trusted JVM runs ({@link #runTrusted}). */
    public static final int GUARD_FACTOR = 3;

    private static Run launch(List<Path> classPath, Path testClasses, List<String> tags, List<String> classes,
            Limits limits, Path workDir, boolean list, List<TestResult> expected, List<String> wrapper,
            List<String> jvmOptions) throws IOException {
        return launch(classPath, testClasses, tags, classes, limits, workDir, list, expected, wrapper, jvmOptions,
                true);
    }

    private static Run launch(List<Path> classPath, Path testClasses, List<String> tags, List<String> classes,
            Limits limits, Path workDir, boolean list, List<TestResult> expected, List<String> wrapper,
            List<String> jvmOptions, boolean limitModules) throws IOException {
        return launch(classPath, testClasses, tags, classes, limits, workDir, list, expected, wrapper, jvmOptions,
                limitModules, false);
    }

    private static Run launch(List<Path> classPath, Path testClasses, List<String> tags, List<String> classes,
            Limits limits, Path workDir, boolean list, List<TestResult> expected, List<String> wrapper,
            List<String> jvmOptions, boolean limitModules, boolean wallIsGuard) throws IOException {
        String java = JavaBuild.javaExecutable();
        List<String> cmd = new ArrayList<>(wrapper);
        cmd.add(java);
        cmd.addAll(List.of("-Xmx" + limits.heapMegabytes() + "m", "-Xss1m"));
        cmd.addAll(JavaBuild.QUICK_JVM);
        cmd.addAll(List.of("-Djava.awt.headless=true", "-XX:+DisableAttachMechanism", "-XX:-UsePerfData"));
        cmd.addAll(jvmOptions); // after the defaults, so that they can change them
        if (limitModules) {
            cmd.addAll(List.of("--limit-modules", CHILD_MODULES));
        }
        cmd.addAll(List.of("-Dfile.encoding=UTF-8", "-cp",
                classPath.stream().map(Path::toString).collect(Collectors.joining(File.pathSeparator)),
                TestMain.class.getName(), "--timeout", Integer.toString(limits.perTestSeconds()),
                "--output-cap", Integer.toString(limits.outputCapBytes())));
        if (testClasses != null) {
            cmd.add("--test-classes");
            cmd.add(testClasses.toString());
        }
        for (String t : tags) {
            cmd.add("--tag");
            cmd.add(t);
        }
        for (String c : classes) {
            if (c.startsWith(THEN_RENDER)) {
                cmd.add("--then-render");
                cmd.addAll(List.of(c.substring(THEN_RENDER.length()).split("\0", 3)));
            } else if (c.equals(WATCHDOG)) {
                cmd.add(WATCHDOG);
            } else if (c.startsWith(THEN_BOUNDARY)) {
                cmd.add("--then-boundary");
                cmd.add(c.substring(THEN_BOUNDARY.length()));
            } else {
                cmd.add("--class");
                cmd.add(c);
            }
        }
        if (list) {
            cmd.add("--list");
        }
        Map<String, TestResult> results = new LinkedHashMap<>();
        List<String> containerFailures = new ArrayList<>();
        String[] current = {null};
        boolean[] ended = {false};
        String[] stuck = {null};
        long deadline = System.nanoTime() + limits.wallClock().toNanos();
        Process p;
        boolean exited;
        String problem = "";
        Path skipFile = null;
        int runs = 0;
        List<String> stuckIds = new ArrayList<>();
        FirstLine errLine = null;
        while (true) {
            // A test stuck in student code ended its JVM after its report ("STUCK", TestMain):
            // the tests not reported yet run in a new JVM, for as long as the run's wall clock lasts.
            List<String> command = new ArrayList<>(cmd);
            if (skipFile != null) {
                command.add("--skip");
                command.add(skipFile.toString());
            }
            byte[] key = new byte[32];
            new SecureRandom().nextBytes(key);

            // A trusted JVM's standard error is the JVM's and the grader's own (the student's code
            // runs in its student process): its first line names why it did not start.
            boolean keepErr = wallIsGuard && System.getenv("RAYLAB_DEBUG_CHILD") == null;
            ProcessBuilder pb = new ProcessBuilder(command).directory(workDir.toFile())
                    .redirectError(keepErr ? ProcessBuilder.Redirect.PIPE
                            : System.getenv("RAYLAB_DEBUG_CHILD") == null ? ProcessBuilder.Redirect.DISCARD
                            : ProcessBuilder.Redirect.appendTo(new File(System.getenv("RAYLAB_DEBUG_CHILD"))));
            pb.environment().keySet().removeIf(k -> k.startsWith("JAVA_TOOL") || k.startsWith("_JAVA_OPTIONS")
                    || k.equals("JDK_JAVA_OPTIONS"));
            Process child = pb.start();
            p = child;
            runs++;
            if (keepErr) {
                errLine = new FirstLine(child.getErrorStream());
            }
            try (OutputStream stdin = child.getOutputStream()) {
                stdin.write((HexFormat.of().formatHex(key) + "\n").getBytes(StandardCharsets.UTF_8));
            } catch (IOException ignored) {
                // the child died at once; reported below
            }
            stuck[0] = null;
            Thread reader = new Thread(() -> readProtocol(child.getInputStream(), key, results, current, ended,
                    containerFailures, stuck), "raylab-test-reader");
            reader.setDaemon(true);
            reader.start();

            try {
                exited = child.waitFor(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                exited = false;
            }
            if (!exited) {
                JavaBuild.stop(child);
                problem = "stopped after " + limits.wallClock().toSeconds() + " s (time limit for the whole run)";
            }
            try {
                reader.join(5000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            JavaBuild.stop(child);
            synchronized (results) {
                if (stuck[0] != null) {
                    stuckIds.add(stuck[0]);
                }
                if (!exited || ended[0] || stuck[0] == null || !results.containsKey(stuck[0]) || list
                        || runs > expected.size() + 1) {
                    break;
                }
                current[0] = null;
                if (skipFile == null) {
                    skipFile = Files.createTempFile(workDir, "reported", ".txt");
                }
                List<String> skip = reportedIds(results.keySet());
                stuckIds.forEach(id -> skip.add(classOf(id)));
                Files.write(skipFile, skip, StandardCharsets.UTF_8);
            }
        }
        if (skipFile != null) {
            Files.deleteIfExists(skipFile);
        }
        synchronized (results) {
            if (exited && !ended[0]) {
                problem = "the test JVM ended early (exit status " + p.exitValue()
                        + ": System.exit, a crash, or out of memory)";
            }
            if (!containerFailures.isEmpty() && problem.isEmpty()) {
                problem = String.join("; ", containerFailures);
            }
            // A trusted JVM runs no student code (the student's runs in its student process): one
            // that ended before its END line, other than by stopping a test stuck in the student's
            // code (a STUCK line), failed on the grading's side, not the student's. Before it said a
            // word of the protocol it did not start or could not discover the course's tests (a bad
            // JVM option, a broken test class); later it crashed or ran out of its own memory.
            boolean crashed = exited && !ended[0] && stuck[0] == null;
            boolean silent = crashed && results.isEmpty() && current[0] == null && stuckIds.isEmpty()
                    && containerFailures.isEmpty();
            String said = silent && errLine != null ? errLine.get() : "";
            List<TestResult> out = new ArrayList<>();
            String cutOff = null;
            for (TestResult e : expected) {
                TestResult r = results.remove(e.id());
                if (r == null && wallIsGuard && !exited) {
                    r = e.gradingFailure("the grader's test JVM was " + problem + ", although every limit"
                            + " of the student's code is in its own time: the machine or the grader was too slow");
                } else if (r == null && wallIsGuard && silent) {
                    r = e.gradingFailure("the grader's test JVM ended (exit status " + p.exitValue() + ") before it"
                            + " started a test: it did not start, or the course's tests could not be discovered"
                            + (said.isEmpty() ? "" : " (it said: " + said + ")"));
                } else if (r == null && wallIsGuard && crashed && stuckCase(stuckIds, e.id()) == null
                        && stuckIds.stream().noneMatch(st -> e.id().startsWith(classOf(st) + "/"))) {
                    r = e.gradingFailure("the grader's test JVM ended early (exit status " + p.exitValue() + ")"
                            + (e.id().equals(current[0]) ? " during this test" : " before this test")
                            + ": it runs no code of the student's, so a crash or its own memory, not the student's code");
                } else if (r == null) {
                    String why;
                    TestResult.Status s;
                    if (e.id().equals(current[0])) {
                        s = exited ? TestResult.Status.CRASHED : TestResult.Status.TIMED_OUT;
                        why = "this test was running when " + (problem.isEmpty() ? "the run stopped" : problem);
                        cutOff = e.id();
                    } else if (stuckCase(stuckIds, e.id()) != null) {
                        s = TestResult.Status.MISSING;
                        why = "not run: case " + stuckCase(stuckIds, e.id()) + " of this test was stuck, see it";
                    } else if (stuckIds.stream().anyMatch(st -> e.id().startsWith(classOf(st) + "/"))) {
                        s = TestResult.Status.MISSING;
                        why = "not run: a test of this class was stuck in your code (see it): fix that, then check again";
                    } else {
                        s = TestResult.Status.MISSING;
                        why = "no result was reported for this test"
                                + (containerFailures.isEmpty() ? "" : " (" + String.join("; ", containerFailures) + ")")
                                + (problem.isEmpty() ? "" : " (" + problem + ")");
                    }
                    r = e.with(s, why);
                }
                out.add(r);
            }
            out.addAll(results.values()); // reported but not expected: kept for the record
            return new Run(out, ended[0] && exited, problem, !exited, cutOff);
        }
    }

    /**
     * The payload of an authentic protocol line ({@code R2 MAC SEQ PAYLOAD}, see
     * {@link TestMain.Channel}) with the next sequence number, else null.
     */
    public static String verify(Mac mac, String line, long[] seq) {
        if (!line.startsWith("R2 ") || line.length() < 3 + 64 + 3) {
            return null;
        }
        String tag = line.substring(3, 3 + 64);
        String body = line.substring(3 + 64 + 1);
        byte[] want = mac.doFinal(body.getBytes(StandardCharsets.UTF_8));
        byte[] got;
        try {
            got = HexFormat.of().parseHex(tag);
        } catch (IllegalArgumentException e) {
            return null;
        }
        if (!MessageDigest.isEqual(want, got)) {
            return null;
        }
        int k = body.indexOf(' ');
        if (k < 0 || !body.substring(0, k).equals(Long.toString(seq[0] + 1))) {
            return null;
        }
        seq[0]++;
        return body.substring(k + 1);
    }

    /** The id of the test class of test {@code id} ("[engine:junit-jupiter]/[class:raylab.SphereTest]"). */
    static String classOf(String id) {
        int k = id.indexOf("/[class:");
        int end = k < 0 ? -1 : id.indexOf(']', k);
        return end < 0 ? id : id.substring(0, end + 1);
    }

    /** Which case ("#3") of the parameterized or dynamic test of {@code id} was stuck, or null. */
    private static String stuckCase(List<String> stuckIds, String id) {
        for (String st : stuckIds) {
            List<String> ids = reportedIds(List.of(st));
            if (ids.size() > 1 && id.startsWith(ids.get(1) + "/")) {
                String seg = st.substring(ids.get(1).length() + 2, st.length() - 1);
                return seg.substring(seg.indexOf(':') + 1);
            }
        }
        return null;
    }

    /**
     * The ids a new JVM leaves out after a stuck test ({@code TestMain --skip}): each reported
     * test, and the parameterized or dynamic test of a reported invocation (its other invocations
     * are then not run: they report as missing, after the one that was stuck).
     */
    static List<String> reportedIds(java.util.Collection<String> reported) {
        java.util.Set<String> out = new java.util.LinkedHashSet<>();
        for (String id : reported) {
            out.add(id);
            int k = id.lastIndexOf("/[");
            if (k > 0 && (id.startsWith("[test-template-invocation:", k + 1) || id.startsWith("[dynamic-test:", k + 1))) {
                out.add(id.substring(0, k));
            }
        }
        return new ArrayList<>(out);
    }

    private static void readProtocol(InputStream in, byte[] key, Map<String, TestResult> results,
            String[] current, boolean[] ended, List<String> containerFailures, String[] stuck) {
        Mac mac;
        try {
            mac = Mac.getInstance("HmacSHA256");
            mac.init(new SecretKeySpec(key, "HmacSHA256"));
        } catch (java.security.GeneralSecurityException e) {
            throw new IllegalStateException(e);
        }
        long[] seq = {0};
        try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
            String line;
            long total = 0;
            while ((line = r.readLine()) != null) {
                total += line.length();
                String rest = verify(mac, line, seq);
                if (rest == null) {
                    if (total > 64L * 1024 * 1024) {
                        break; // a flood of output outside the protocol: stop listening
                    }
                    continue;
                }
                synchronized (results) {
                    if (rest.startsWith("START ")) {
                        current[0] = rest.substring(6);
                    } else if (rest.startsWith("RESULT ")) {
                        TestResult t = JSON.readValue(rest.substring(7), TestResult.class);
                        TestResult before = results.putIfAbsent(t.id(), t);
                        if (before != null) {
                            // JUnit reports a test once: a second report is not trusted, whatever it says.
                            results.put(t.id(), t.with(TestResult.Status.FAILED, "this test was reported twice"));
                        }
                    } else if (rest.startsWith("CONTAINER ")) {
                        String s = rest.substring(10);
                        int k = s.indexOf(' ');
                        String id = k < 0 ? s : s.substring(0, k);
                        int c = id.indexOf("[class:");
                        String cls = c < 0 ? id : id.substring(c + 7, Math.max(c + 7, id.indexOf(']', c)));
                        containerFailures.add(cls + " failed before its tests ran: " + (k < 0 ? "" : s.substring(k + 1)));
                    } else if (rest.startsWith("STUCK ")) {
                        stuck[0] = rest.substring(6);
                    } else if (rest.equals("END")) {
                        ended[0] = true;
                    }
                }
            }
        } catch (IOException e) {
            // the child went away; what was read stands
        }
    }
}
