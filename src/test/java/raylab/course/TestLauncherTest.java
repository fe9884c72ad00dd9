package raylab.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The child-JVM test runner reports every test, and fails closed when the child dies. */
class TestLauncherTest {
    @TempDir
    Path dir;

    private Path compile(String className, String source) throws Exception {
        Path src = dir.resolve("src/demo/" + className + ".java");
        Files.createDirectories(src.getParent());
        Files.writeString(src, source);
        Path out = dir.resolve("classes");
        JavaBuild.Result r = JavaBuild.compile(List.of(src), JavaBuild.ownClassPath(), out);
        assertTrue(r.success(), () -> "demo test should compile: " + r.errors());
        return out;
    }

    private List<Path> classPath(Path classes) {
        List<Path> cp = new ArrayList<>();
        cp.add(classes);
        cp.addAll(JavaBuild.ownClassPath());
        return cp;
    }

    @Test
    void reportsPassAndFailWithMessages() throws Exception {
        Path classes = compile("DemoTest", """
                package demo;
                import org.junit.jupiter.api.*;
                class DemoTest {
                    @Test @Tag("demo") void passes() { System.out.println("hello"); }
                    @Test @Tag("demo") void fails() { Assertions.assertEquals(1, 2, "one is not two"); }
                    @Test @Tag("other") void notSelected() { }
                }
                """);
        List<TestResult> expected = TestLauncher.discover(classPath(classes), classes, List.of("demo"), List.of(), dir);
        assertEquals(2, expected.size(), "discovered: " + expected);
        TestLauncher.Run o = TestLauncher.run(classPath(classes), classes, List.of("demo"), List.of(),
                TestLauncher.Limits.DEFAULT, dir, expected);
        Map<String, TestResult> byMethod = o.results().stream()
                .collect(Collectors.toMap(TestResult::method, r -> r));
        assertTrue(o.finished(), "run should finish: " + o.problem());
        assertEquals(TestResult.Status.PASSED, byMethod.get("passes").status());
        assertTrue(byMethod.get("passes").output().contains("hello"), "output captured: " + byMethod.get("passes"));
        assertEquals(TestResult.Status.FAILED, byMethod.get("fails").status());
        assertTrue(byMethod.get("fails").message().contains("one is not two"), byMethod.get("fails").message());
    }

    /** Three tests in order: one that passes, one that ends its JVM (after a forged report line), one never run. */
    private Path exitTest() throws Exception {
        return compile("ExitTest", """
                package demo;
                import org.junit.jupiter.api.*;
                @TestMethodOrder(MethodOrderer.MethodName.class)
                class ExitTest {
                    @Test void a_fine() { }
                    @Test void b_exits() { System.out.println("RAYLAB-forged RESULT {}"); System.exit(0); }
                    @Test void c_never() { }
                }
                """);
    }

    @Test
    void systemExitInATestFailsItAndTheRestClosed() throws Exception {
        Path classes = exitTest();
        List<TestResult> expected = TestLauncher.discover(classPath(classes), classes, List.of(), List.of(), dir);
        TestLauncher.Run o = TestLauncher.run(classPath(classes), classes, List.of(), List.of(),
                new TestLauncher.Limits(256, Duration.ofSeconds(60), 5, 1024), dir, expected);
        Map<String, TestResult.Status> s = o.results().stream()
                .collect(Collectors.toMap(TestResult::method, TestResult::status));
        assertFalse(o.finished(), "the child exited early");
        assertEquals(TestResult.Status.PASSED, s.get("a_fine"));
        assertEquals(TestResult.Status.CRASHED, s.get("b_exits"));
        assertEquals(TestResult.Status.MISSING, s.get("c_never"));
    }

    /**
     * A trusted JVM (it runs no student code) that ends early fails every test it did not report as
     * the grading's failure, not the student's: before its first test (here it cannot start at
     * all) and during a test (here a test ends the JVM); the same JVM for student code
     * ({@code check}) stays the student's.
     */
    @Test
    void aTrustedJvmThatEndsBeforeItsFirstTestIsTheGradingsFailure() throws Exception {
        Path classes = exitTest();
        List<TestResult> expected = TestLauncher.discover(classPath(classes), classes, List.of(), List.of(), dir);
        assertEquals(3, expected.size(), "discovered: " + expected);
        List<String> badOption = List.of("-XX:+RaylabNoSuchOption");
        TestLauncher.Run trusted = TestLauncher.runTrusted(classPath(classes), classes, List.of(),
                TestLauncher.Limits.DEFAULT, dir, expected, badOption);
        assertEquals(3, trusted.results().size(), "every test reported: " + trusted.results());
        for (TestResult r : trusted.results()) {
            assertTrue(r.gradingFailed(), "the grading's failure: " + r);
            assertTrue(r.message().contains("(exit status 1) before it started a test"), r.message());
            assertTrue(r.message().contains("(it said: Unrecognized VM option 'RaylabNoSuchOption')"),
                    "the JVM's own words, for the course staff: " + r.message());
        }
        TestLauncher.Run student = TestLauncher.run(classPath(classes), classes, List.of(), List.of(),
                TestLauncher.Limits.DEFAULT, dir, expected, List.of(), badOption);
        for (TestResult r : student.results()) {
            assertFalse(r.gradingFailed(), "a JVM that runs student code: the student's run: " + r);
            assertEquals(TestResult.Status.MISSING, r.status(), r.toString());
        }
        Map<String, TestResult> ended = TestLauncher.runTrusted(classPath(classes), classes, List.of(),
                TestLauncher.Limits.DEFAULT, dir, expected, List.of()).results().stream()
                .collect(Collectors.toMap(TestResult::method, t -> t));
        assertEquals(TestResult.Status.PASSED, ended.get("a_fine").status(), ended.toString());
        assertFalse(ended.get("a_fine").gradingFailed(), "reported before the JVM ended: " + ended);
        assertTrue(ended.get("b_exits").gradingFailed(), "the grading's failure: " + ended.get("b_exits"));
        assertTrue(ended.get("b_exits").message().contains("ended early (exit status 0) during this test"),
                ended.get("b_exits").message());
        assertTrue(ended.get("c_never").gradingFailed(), "the grading's failure: " + ended.get("c_never"));
        assertTrue(ended.get("c_never").message().contains("ended early (exit status 0) before this test"),
                ended.get("c_never").message());
    }

    /**
     * A test JVM behind the process boundary runs no code of the student's: its own memory or stack
     * running out is the grading's failure; in a JVM that runs the student's code ({@code check}),
     * and for any other exception, it stays the test's failure.
     */
    @Test
    void aTrustedJvmsOwnMemoryIsTheGradingsFailure() {
        assertTrue(TestMain.gradersFault(new OutOfMemoryError("Java heap space"), true));
        assertTrue(TestMain.gradersFault(new StackOverflowError(), true));
        assertFalse(TestMain.gradersFault(new OutOfMemoryError("Java heap space"), false));
        assertFalse(TestMain.gradersFault(new AssertionError("expected: <4.0> but was: <6.0>"), true));
        assertFalse(TestMain.gradersFault(new IllegalStateException("the student's answer"), true));
        assertFalse(TestMain.gradersFault(null, true));
        assertTrue(TestMain.gradersFault(new GraderFaultError(), false));
    }

    private static final class GraderFaultError extends RuntimeException implements GraderFault {
        private static final long serialVersionUID = 1L;
    }

    /**
     * Text on the test JVM's standard output without a newline at its end (what a student's
     * {@code System.out.print("t = ")} was, when the student process's output reached the channel
     * before the capture was in place) does not run into the next frame: that frame, and every
     * frame after it, still counts.
     */
    @Test
    void textWithoutANewlineBeforeAFrameLeavesTheFrameWhole() throws Exception {
        byte[] key = new byte[32];
        new java.util.SplittableRandom(11).nextBytes(key);
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        java.io.PrintStream out = new java.io.PrintStream(bytes, true, "UTF-8");
        TestMain.Channel ch = new TestMain.Channel(out, key);
        ch.send("START a");
        out.print("t = ");
        ch.send("RESULT {\"id\":\"a\"}");
        out.print("(output cut at 64 KiB)");
        ch.send("END");
        javax.crypto.Mac mac = javax.crypto.Mac.getInstance("HmacSHA256");
        mac.init(new javax.crypto.spec.SecretKeySpec(key, "HmacSHA256"));
        long[] seq = {0};
        List<String> reports = new java.util.ArrayList<>();
        for (String line : bytes.toString("UTF-8").split("\n")) {
            String r = TestLauncher.verify(mac, line, seq);
            if (r != null) {
                reports.add(r);
            }
        }
        assertEquals(List.of("START a", "RESULT {\"id\":\"a\"}", "END"), reports, bytes.toString("UTF-8"));
    }

    /** The report channel: only lines with the key's MAC and the next sequence number count. */
    @Test
    void reportLinesNeedTheKeyAndTheNextSequenceNumber() throws Exception {
        byte[] key = new byte[32];
        new java.util.SplittableRandom(7).nextBytes(key);
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        TestMain.Channel ch = new TestMain.Channel(new java.io.PrintStream(bytes, true, "UTF-8"), key);
        ch.send("START a");
        ch.send("RESULT {\"id\":\"a\"}");
        ch.send("END");
        // Each frame is a line of its own, between newlines; the empty lines between them are skipped.
        String[] lines = bytes.toString("UTF-8").strip().split("\n+");
        javax.crypto.Mac mac = javax.crypto.Mac.getInstance("HmacSHA256");
        mac.init(new javax.crypto.spec.SecretKeySpec(key, "HmacSHA256"));
        long[] seq = {0};
        assertEquals("START a", TestLauncher.verify(mac, lines[0], seq));
        // Replayed, reordered, altered or keyless lines are not reports.
        assertEquals(null, TestLauncher.verify(mac, lines[0], seq));
        assertEquals(null, TestLauncher.verify(mac, lines[2], seq));
        assertEquals(null, TestLauncher.verify(mac, lines[1].replace("\"a\"", "\"b\""), seq));
        assertEquals(null, TestLauncher.verify(mac, "R2 " + "0".repeat(64) + " 2 RESULT {}", seq));
        assertEquals("RESULT {\"id\":\"a\"}", TestLauncher.verify(mac, lines[1], seq));
        javax.crypto.Mac other = javax.crypto.Mac.getInstance("HmacSHA256");
        other.init(new javax.crypto.spec.SecretKeySpec(new byte[32], "HmacSHA256"));
        assertEquals(null, TestLauncher.verify(other, lines[2], new long[] {2}));
        assertEquals("END", TestLauncher.verify(mac, lines[2], seq));
    }

    /** Forged lines printed by a test, in any format, do not turn its failure into a pass. */
    @Test
    void forgedLinesFromInsideTheTestJvmAreIgnored() throws Exception {
        Path classes = compile("ForgeTest", """
                package demo;
                import org.junit.jupiter.api.*;
                import java.io.*;
                class ForgeTest {
                    @Test void fails() throws Exception {
                        PrintStream raw = new PrintStream(new FileOutputStream(FileDescriptor.out), true);
                        String id = "[engine:junit-jupiter]/[class:demo.ForgeTest]/[method:fails()]";
                        String json = "{\\"id\\":\\"" + id + "\\",\\"className\\":\\"demo.ForgeTest\\",\\"method\\":\\"fails\\","
                                + "\\"displayName\\":\\"fails()\\",\\"status\\":\\"PASSED\\",\\"message\\":\\"\\",\\"output\\":\\"\\",\\"millis\\":1}";
                        for (int seq = 1; seq < 20; seq++) {
                            raw.println("R2 " + "0".repeat(64) + " " + seq + " RESULT " + json);
                        }
                        Assertions.fail("really failed");
                    }
                }
                """);
        List<TestResult> expected = TestLauncher.discover(classPath(classes), classes, List.of(), List.of(), dir);
        TestLauncher.Run o = TestLauncher.run(classPath(classes), classes, List.of(), List.of(),
                new TestLauncher.Limits(256, Duration.ofSeconds(60), 5, 1024), dir, expected);
        assertEquals(1, o.results().size(), o.results().toString());
        assertEquals(TestResult.Status.FAILED, o.results().get(0).status());
        assertTrue(o.results().get(0).message().contains("really failed"), o.results().get(0).message());
    }

    /**
     * The grader's test JVM: the classes after {@code --then-boundary} run after the others have
     * ended, with the student process the second file describes (a new process, not the first).
     */
    @Test
    void thenBoundaryRunsTheSecondGroupAfterTheFirstWithANewStudentProcess() throws Exception {
        String probe = """
                    static String probe() {
                        raylab.boundary.StudentProcess p = raylab.boundary.Remote.process();
                        return "config " + java.nio.file.Path.of(System.getProperty("raylab.boundary")).getFileName()
                                + " process " + System.identityHashCode(p) + " starts " + p.starts();
                    }
                """;
        compile("FirstTest", """
                package demo;
                import org.junit.jupiter.api.*;
                class FirstTest {
                    static volatile boolean ended;
                %s
                    @Test void first() throws Exception { System.out.println(probe()); Thread.sleep(200); ended = true; }
                }
                """.formatted(probe));
        Path classes = compile("SecondTest", """
                package demo;
                import org.junit.jupiter.api.*;
                class SecondTest {
                %s
                    @Test void second() throws Exception {
                        System.out.println(probe());
                        java.lang.reflect.Field f = Class.forName("demo.FirstTest").getDeclaredField("ended");
                        f.setAccessible(true);
                        Assertions.assertTrue(f.getBoolean(null), "the first group ended before the second began");
                    }
                }
                """.formatted(probe));
        Path first = dir.resolve("first.properties");
        Path second = dir.resolve("second.properties");
        for (Path f : List.of(first, second)) {
            raylab.boundary.Remote.writeConfig(f, new raylab.boundary.StudentProcess.Config(
                    raylab.boundary.StudentJvm.javaCommand(JavaBuild.ownClassPath(), 64, List.of()), null,
                    java.util.Set.of(), 10_000, 0));
        }
        List<TestResult> expected = TestLauncher.discover(classPath(classes), classes, List.of(),
                List.of("demo.FirstTest", "demo.SecondTest"), dir);
        assertEquals(2, expected.size(), "discovered: " + expected);
        TestLauncher.Run o = TestLauncher.run(classPath(classes), classes, List.of(),
                List.of("demo.FirstTest", TestLauncher.thenBoundary(second), "demo.SecondTest"),
                TestLauncher.Limits.DEFAULT, dir, expected, List.of(), List.of("-Draylab.boundary=" + first));
        assertTrue(o.finished(), "run should finish: " + o.problem());
        Map<String, TestResult> byMethod = o.results().stream().collect(Collectors.toMap(TestResult::method, r -> r));
        assertEquals(TestResult.Status.PASSED, byMethod.get("first").status(), byMethod.get("first").toString());
        assertEquals(TestResult.Status.PASSED, byMethod.get("second").status(), byMethod.get("second").toString());
        String a = byMethod.get("first").output().trim();
        String b = byMethod.get("second").output().trim();
        assertTrue(a.startsWith("config first.properties process ") && a.endsWith(" starts 1"), a);
        assertTrue(b.startsWith("config second.properties process ") && b.endsWith(" starts 1"), b);
        assertFalse(a.split(" ")[3].equals(b.split(" ")[3]), "a new student process: " + a + " / " + b);
    }
}
