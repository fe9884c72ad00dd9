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
        TestLauncher.Outcome o = TestLauncher.run(classPath(classes), classes, List.of("demo"), List.of(),
                TestLauncher.Limits.DEFAULT, dir, expected);
        Map<String, TestResult> byMethod = o.results().stream()
                .collect(Collectors.toMap(TestResult::method, r -> r));
        assertTrue(o.finished(), "run should finish: " + o.problem());
        assertEquals(TestResult.Status.PASSED, byMethod.get("passes").status());
        assertTrue(byMethod.get("passes").output().contains("hello"), "output captured: " + byMethod.get("passes"));
        assertEquals(TestResult.Status.FAILED, byMethod.get("fails").status());
        assertTrue(byMethod.get("fails").message().contains("one is not two"), byMethod.get("fails").message());
    }

    @Test
    void systemExitInATestFailsItAndTheRestClosed() throws Exception {
        Path classes = compile("ExitTest", """
                package demo;
                import org.junit.jupiter.api.*;
                @TestMethodOrder(MethodOrderer.MethodName.class)
                class ExitTest {
                    @Test void a_fine() { }
                    @Test void b_exits() { System.out.println("RAYLAB-forged RESULT {}"); System.exit(0); }
                    @Test void c_never() { }
                }
                """);
        List<TestResult> expected = TestLauncher.discover(classPath(classes), classes, List.of(), List.of(), dir);
        TestLauncher.Outcome o = TestLauncher.run(classPath(classes), classes, List.of(), List.of(),
                new TestLauncher.Limits(256, Duration.ofSeconds(60), 5, 1024), dir, expected);
        Map<String, TestResult.Status> s = o.results().stream()
                .collect(Collectors.toMap(TestResult::method, TestResult::status));
        assertFalse(o.finished(), "the child exited early");
        assertEquals(TestResult.Status.PASSED, s.get("a_fine"));
        assertEquals(TestResult.Status.CRASHED, s.get("b_exits"));
        assertEquals(TestResult.Status.MISSING, s.get("c_never"));
    }
}
