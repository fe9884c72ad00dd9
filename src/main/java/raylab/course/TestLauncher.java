package raylab.course;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * Runs JUnit tests in a separate JVM ({@link TestMain}) with a memory cap and time limits, and
 * collects a result for every test it was asked about: what the child did not report as passed
 * is not passed (fail closed).
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
     * @param problem  why it did not (timed out, exited early...), empty if it did
     */
    public record Outcome(List<TestResult> results, boolean finished, String problem) {
        public long passed() {
            return results.stream().filter(r -> r.status().passed()).count();
        }
    }

    private static final ObjectMapper JSON = new ObjectMapper();

    private TestLauncher() {
    }

    /**
     * Lists the tests a selection holds, without running them (discovery in a child JVM).
     */
    public static List<TestResult> discover(List<Path> classPath, Path testClasses, List<String> tags,
            List<String> classes, Path workDir) throws IOException {
        Outcome o = launch(classPath, testClasses, tags, classes, Limits.DEFAULT, workDir, true, List.of(), List.of());
        if (!o.finished()) {
            throw new IOException("test discovery failed: " + o.problem());
        }
        return o.results();
    }

    /**
     * Runs the selected tests. {@code expected} (from {@link #discover}) are the tests that must
     * report: any of them without a report is returned as MISSING, TIMED_OUT or CRASHED.
     */
    public static Outcome run(List<Path> classPath, Path testClasses, List<String> tags, List<String> classes,
            Limits limits, Path workDir, List<TestResult> expected) throws IOException {
        return launch(classPath, testClasses, tags, classes, limits, workDir, false, expected, List.of());
    }

    /**
     * As {@link #run}, with the child's command line prefixed by {@code wrapper} (for example
     * {@code setpriv --reuid=... --} to run it as an unprivileged user); empty for none.
     */
    public static Outcome run(List<Path> classPath, Path testClasses, List<String> tags, List<String> classes,
            Limits limits, Path workDir, List<TestResult> expected, List<String> wrapper) throws IOException {
        return launch(classPath, testClasses, tags, classes, limits, workDir, false, expected, wrapper);
    }

    private static Outcome launch(List<Path> classPath, Path testClasses, List<String> tags, List<String> classes,
            Limits limits, Path workDir, boolean list, List<TestResult> expected, List<String> wrapper)
            throws IOException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(wrapper);
        cmd.addAll(List.of(java, "-Xmx" + limits.heapMegabytes() + "m", "-Xss1m",
                "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-Djava.awt.headless=true",
                "-Dfile.encoding=UTF-8", "-cp",
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
            cmd.add("--class");
            cmd.add(c);
        }
        if (list) {
            cmd.add("--list");
        }
        byte[] raw = new byte[16];
        new SecureRandom().nextBytes(raw);
        String token = "RAYLAB-" + HexFormat.of().formatHex(raw);

        ProcessBuilder pb = new ProcessBuilder(cmd).directory(workDir.toFile())
                .redirectError(ProcessBuilder.Redirect.DISCARD);
        pb.environment().keySet().removeIf(k -> k.startsWith("JAVA_TOOL") || k.startsWith("_JAVA_OPTIONS")
                || k.equals("JDK_JAVA_OPTIONS"));
        Process p = pb.start();
        try (OutputStream stdin = p.getOutputStream()) {
            stdin.write((token + "\n").getBytes(StandardCharsets.UTF_8));
        } catch (IOException ignored) {
            // the child died at once; reported below
        }
        Map<String, TestResult> results = new LinkedHashMap<>();
        List<String> containerFailures = new ArrayList<>();
        String[] current = {null};
        boolean[] ended = {false};
        Thread reader = new Thread(() -> readProtocol(p.getInputStream(), token, results, current, ended,
                containerFailures), "raylab-test-reader");
        reader.setDaemon(true);
        reader.start();

        boolean exited;
        try {
            exited = p.waitFor(limits.wallClock().toMillis(), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            exited = false;
        }
        String problem = "";
        if (!exited) {
            kill(p);
            problem = "stopped after " + limits.wallClock().toSeconds() + " s (time limit for the whole run)";
        }
        try {
            reader.join(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        kill(p);
        synchronized (results) {
            if (exited && !ended[0]) {
                problem = "the test JVM ended early (exit status " + p.exitValue()
                        + ": System.exit, a crash, or out of memory)";
            }
            if (!containerFailures.isEmpty() && problem.isEmpty()) {
                problem = String.join("; ", containerFailures);
            }
            List<TestResult> out = new ArrayList<>();
            for (TestResult e : expected) {
                TestResult r = results.remove(e.id());
                if (r == null) {
                    String why;
                    TestResult.Status s;
                    if (e.id().equals(current[0])) {
                        s = exited ? TestResult.Status.CRASHED : TestResult.Status.TIMED_OUT;
                        why = "this test was running when " + (problem.isEmpty() ? "the run stopped" : problem);
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
            return new Outcome(out, ended[0] && exited, problem);
        }
    }

    private static void readProtocol(InputStream in, String token, Map<String, TestResult> results,
            String[] current, boolean[] ended, List<String> containerFailures) {
        String prefix = token + " ";
        try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
            String line;
            long total = 0;
            while ((line = r.readLine()) != null) {
                total += line.length();
                if (!line.startsWith(prefix)) {
                    if (total > 64L * 1024 * 1024) {
                        break; // a flood of output outside the protocol: stop listening
                    }
                    continue;
                }
                String rest = line.substring(prefix.length());
                synchronized (results) {
                    if (rest.startsWith("START ")) {
                        current[0] = rest.substring(6);
                    } else if (rest.startsWith("RESULT ")) {
                        TestResult t = JSON.readValue(rest.substring(7), TestResult.class);
                        results.put(t.id(), t);
                    } else if (rest.startsWith("CONTAINER ")) {
                        String s = rest.substring(10);
                        int k = s.indexOf(' ');
                        String id = k < 0 ? s : s.substring(0, k);
                        int c = id.indexOf("[class:");
                        String cls = c < 0 ? id : id.substring(c + 7, Math.max(c + 7, id.indexOf(']', c)));
                        containerFailures.add(cls + " failed before its tests ran: " + (k < 0 ? "" : s.substring(k + 1)));
                    } else if (rest.equals("END")) {
                        ended[0] = true;
                    }
                }
            }
        } catch (IOException e) {
            // the child went away; what was read stands
        }
    }

    private static void kill(Process p) {
        p.descendants().forEach(ProcessHandle::destroyForcibly);
        p.destroyForcibly();
        try {
            p.waitFor(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
