package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.Watchdog;

/**
 * An endless loop in each graded method is stopped and named ("your code has run for 2 s in
 * Lambertian.diffuse (Lambertian.java:38) without returning: an endless loop?") by {@code render},
 * {@code trace}, {@code check} and the grader (its student process, for its tests and its
 * renders), after the watchdog's bound ({@link Watchdog#FLOOR} of CPU time: the reference finishes
 * a tile, a pixel, a call or a visible test in far less) instead of the old 300 s of a render or
 * 10 s of each test. Each command runs in a JVM of its own with the looping file compiled first on
 * the class path (the grader: in the submission, one grading for the first method of each
 * milestone together and one for the others). The runs go four at a time, each {@code check}
 * after the one before (they share target/check), the gradings side by side over the grader's
 * cache built before them.
 *
 * <p>The loops are stopped after {@link #FLOOR_MILLIS} of CPU time instead of the production
 * floor of 2 s: every command runs with the test knob {@link Watchdog#FLOOR_ENV} set (its child
 * JVMs inherit it; the grader hands its bound to the student process), as the length of the
 * bound is not what this class is about (raylab.course.WatchdogTest holds the production bound).
 * A loop burns CPU until it is stopped, so this is CPU saved, not only waiting.
 */
class EndlessLoopTest {
    static final Path ROOT = Path.of("").toAbsolutePath();
    /** The watchdog's floor in these runs (ms, {@link Watchdog#FLOOR_ENV}). */
    static final long FLOOR_MILLIS = 500;
    /** Graded method (Class.method) to its file and milestone. */
    static final Map<String, String> FILE = new LinkedHashMap<>();
    static final Map<String, Assignment> OWNER = new LinkedHashMap<>();
    static Path dir;
    static ExecutorService pool;

    @BeforeAll
    static void overlays() throws IOException {
        dir = Files.createTempDirectory("raylab-endless");
        for (Assignment a : Assignments.load(ROOT).all()) {
            for (Assignment.StudentFile f : a.files()) {
                for (String m : f.methods()) {
                    FILE.put(m, f.path());
                    OWNER.put(m, a);
                }
            }
        }
        for (var e : FILE.entrySet()) {
            String name = e.getKey().substring(e.getKey().indexOf('.') + 1);
            String text = Files.readString(ROOT.resolve(e.getValue()));
            Matcher decl = Pattern.compile("\\n    public [^\\n;=]*\\b" + name + "\\([^)]*\\)\\s*\\{").matcher(text);
            assertTrue(decl.find(), "the declaration of " + e.getKey());
            String looping = text.substring(0, decl.end()) + " for (long spin = 1; spin != 0; spin = System.nanoTime() | 1) { }"
                    + text.substring(decl.end());
            String rel = e.getValue().substring("src/main/java/".length());
            JavaBuild.Result r = MilestoneBuild.compileOverlay(Map.of(rel, looping), dir.resolve("src-" + e.getKey()),
                    JavaBuild.ownClassPath(), dir.resolve(e.getKey()));
            assertTrue(r.success(), e.getKey() + ": " + r.errors());
        }
        // The grader's cache built once here, so that the gradings can run side by side.
        raylab.grade.SharedGraderCache.build(ROOT);
        pool = Executors.newFixedThreadPool(4);
    }

    @AfterAll
    static void stop() {
        pool.shutdownNow();
        JavaBuild.deleteTreeQuietly(dir); // the overlays, the submissions and the runs' outputs
    }

    /** What a run of raylab said: exit status, standard output, standard error. */
    record Ran(int status, String out, String err) {
        String both() {
            return out + "\n" + err;
        }
    }

    /** raylab ARGS in a JVM whose class path starts with {@code first} (null: none). */
    static Ran run(Path first, String... args) throws Exception {
        return run(first, 300, args);
    }

    /** As {@link #run(Path, String...)}, stopped after {@code guardSeconds} (a guard only). */
    static Ran run(Path first, int guardSeconds, String... args) throws Exception {
        Path out = Files.createTempFile(dir, "out", ".txt");
        Path err = Files.createTempFile(dir, "err", ".txt");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-cp", (first == null ? "" : first + File.pathSeparator)
                + System.getProperty("java.class.path"), "raylab.cli.Main"));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(ROOT.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile());
        pb.environment().put(Watchdog.FLOOR_ENV, Long.toString(FLOOR_MILLIS));
        Process p = pb.start();
        // A guard only (the old limit): the assertions are on what raylab says.
        if (!p.waitFor(guardSeconds, TimeUnit.SECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
        return new Ran(p.waitFor(), Files.readString(out), Files.readString(err));
    }

    /**
     * {@code render --watch} (which runs {@code render} in a JVM of its own at each save), until it
     * waits for the next save: what it printed. Its home is an empty folder, so that it builds
     * nothing and watches no file of this project.
     */
    static String renderWatch(String method) throws Exception {
        Path out = Files.createTempFile(dir, "watch", ".txt");
        Path home = Files.createDirectories(dir.resolve("watch-home-" + method));
        String scene = OWNER.get(method).scenes().get(0).scene();
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-Draylab.home=" + home,
                "-cp", dir.resolve(method) + File.pathSeparator + System.getProperty("java.class.path"),
                "raylab.cli.Main", "render", scene, "--watch", "-o", dir.resolve(method + "-watch.png").toString(),
                "--quiet", "--threads", "1"));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(ROOT.toFile()).redirectErrorStream(true)
                .redirectOutput(out.toFile());
        pb.environment().put(Watchdog.FLOOR_ENV, Long.toString(FLOOR_MILLIS));
        Process p = pb.start();
        try {
            // A guard only (the old limit): the assertion is on what it says.
            for (long end = System.nanoTime() + 300_000_000_000L; System.nanoTime() < end && p.isAlive()
                    && !Files.readString(out).contains("waiting for the next save");) {
                Thread.sleep(200);
            }
        } finally {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            p.waitFor();
        }
        return Files.readString(out);
    }

    /**
     * The sentence naming {@code method} in its own file, after at least the bound ({@link #FLOOR_MILLIS}:
     * the sentence gives whole seconds, at least 1).
     */
    static void assertNamed(String method, String text) {
        String cls = method.substring(0, method.indexOf('.'));
        Matcher m = Pattern.compile("your code has run for (\\d+) s in " + Pattern.quote(method) + " \\("
                + Pattern.quote(cls) + "\\.java:\\d+\\) without returning: an endless loop\\?").matcher(text);
        assertTrue(m.find(), "the loop in " + method + " named:\n" + text);
        long bound = Math.max(1, java.time.Duration.ofMillis(FLOOR_MILLIS).toSeconds());
        assertTrue(Long.parseLong(m.group(1)) >= bound, "stopped after the bound (" + bound + " s): " + m.group());
    }

    /**
     * Every sentence of the grader's student process for {@code method} gives the CPU time its
     * serving thread used (the bound and at most a few of the watchdog's polls), not the wall time
     * it falls back on without a CPU clock ({@link Watchdog#WALL_TIMES} times the bound): the
     * sandbox mounts no /proc, and the process reads the thread's clock instead.
     */
    static void assertCountedInCpuTime(String method, String text) {
        Matcher m = Pattern.compile("your code has run for (\\d+) s in " + Pattern.quote(method) + " ").matcher(text);
        int n = 0;
        while (m.find()) {
            n++;
            long said = Long.parseLong(m.group(1));
            assertTrue(said * 1000 < Watchdog.WALL_TIMES * FLOOR_MILLIS, "counted in CPU time, below "
                    + Watchdog.WALL_TIMES + " x " + FLOOR_MILLIS + " ms of wall time: " + m.group());
        }
        assertTrue(n > 0, "the loop in " + method + " named:\n" + text);
    }

    static Ran render(String method) throws Exception {
        String scene = OWNER.get(method).scenes().get(0).scene();
        return run(dir.resolve(method), "render", scene, "-o", dir.resolve(method + ".png").toString(), "--quiet",
                "--threads", "1");
    }

    static Ran trace(String method) throws Exception {
        String scene = OWNER.get(method).scenes().get(0).scene();
        raylab.scene.Scene sc = raylab.scene.SceneLoader.load(ROOT.resolve(scene));
        return run(dir.resolve(method), "trace", scene, "--pixel", Integer.toString(sc.width / 2),
                Integer.toString(sc.height / 2));
    }

    /**
     * The grader, with its process boundary (the student's code runs in a JVM of its own), every
     * milestone: a submission with the looping files of {@code methods} (one per milestone) and
     * the reference's other files of their milestones.
     */
    static Ran grade(String name, List<String> methods) throws Exception {
        Path sub = Files.createDirectories(dir.resolve("submission-" + name));
        for (String method : methods) {
            for (Assignment.StudentFile f : OWNER.get(method).files()) {
                Path looping = dir.resolve("src-" + method).resolve(f.path().substring("src/main/java/".length()));
                Path to = sub.resolve(Path.of(f.path()).getFileName().toString());
                if (Files.isRegularFile(looping) || !Files.exists(to)) {
                    Files.copy(Files.isRegularFile(looping) ? looping : ROOT.resolve(f.path()), to,
                            java.nio.file.StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
        Path results = dir.resolve("results-" + name);
        Ran r = run(null, 900, "grade", sub.toString(), "--out", results.toString(), "--root", ROOT.toString(), "--quiet",
                "--sandbox-user", "", "--seed", "7");
        Path json = results.resolve("results.json");
        return new Ran(r.status(), Files.isRegularFile(json) ? Files.readString(json) : "", r.err());
    }

    /** The methods graded together: one per milestone (the first of each), then the others. */
    static List<List<String>> gradings() {
        List<List<String>> out = new ArrayList<>();
        for (String method : FILE.keySet()) {
            List<String> into = out.stream().filter(g -> g.stream().noneMatch(m -> OWNER.get(m) == OWNER.get(method)))
                    .findFirst().orElse(null);
            if (into == null) {
                into = new ArrayList<>();
                out.add(into);
            }
            into.add(method);
        }
        return out;
    }

    @TestFactory
    Stream<DynamicTest> aLoopInEachMethodIsStoppedAndNamedByEachCommand() throws Exception {
        Map<String, Future<Ran>> runs = new LinkedHashMap<>();
        // check for each method's milestone, one after the other in one task: they share
        // target/check and its build (and each run has the whole-run wall clock of its own).
        Map<String, Ran> checks = new java.util.concurrent.ConcurrentHashMap<>();
        Future<?> checking = pool.submit(() -> {
            for (String method : FILE.keySet()) {
                checks.put(method, run(dir.resolve(method), "check", OWNER.get(method).id(), "--threads", "1"));
            }
            return null;
        });
        // The gradings side by side, over the cache built before them.
        Map<String, Future<Ran>> grades = new java.util.concurrent.ConcurrentHashMap<>();
        int n = 0;
        for (List<String> methods : gradings()) {
            String name = "g" + ++n;
            Future<Ran> r = pool.submit(() -> grade(name, methods));
            methods.forEach(m -> grades.put(m, r));
        }
        String watched = FILE.keySet().iterator().next();
        Future<String> watching = pool.submit(() -> renderWatch(watched));
        for (String method : FILE.keySet()) {
            runs.put("render " + method, pool.submit((Callable<Ran>) () -> render(method)));
            runs.put("trace " + method, pool.submit((Callable<Ran>) () -> trace(method)));
        }
        List<DynamicTest> tests = new ArrayList<>();
        tests.add(DynamicTest.dynamicTest("render --watch names " + watched + " and waits for the next save", () -> {
            String said = watching.get();
            assertNamed(watched, said);
            assertTrue(said.contains("waiting for the next save"), said);
        }));
        for (String method : FILE.keySet()) {
            String scene = OWNER.get(method).scenes().get(0).scene();
            tests.add(DynamicTest.dynamicTest("render stops and names " + method, () -> {
                Ran r = runs.get("render " + method).get();
                assertEquals(1, r.status(), "exit status; stderr: " + r.err());
                assertNamed(method, r.err());
                assertTrue(r.err().contains(" while rendering " + scene), r.err());
                assertEquals(1, r.err().strip().lines().count(), "one line: " + r.err());
                assertFalse(Files.exists(dir.resolve(method + ".png")), "no picture written");
            }));
            tests.add(DynamicTest.dynamicTest("trace stops and names " + method, () -> {
                Ran r = runs.get("trace " + method).get();
                assertEquals(1, r.status(), "exit status; stdout: " + r.out() + " stderr: " + r.err());
                assertNamed(method, r.err());
                assertTrue(r.err().contains(" while tracing pixel ("), r.err());
            }));
            tests.add(DynamicTest.dynamicTest("check stops and names " + method, () -> {
                checking.get();
                Ran r = checks.get(method);
                assertEquals(1, r.status(), "exit status; stdout: " + r.out() + " stderr: " + r.err());
                assertNamed(method, r.out());
                for (Assignment.GradedScene g : OWNER.get(method).scenes()) {
                    assertTrue(r.out().lines().anyMatch(l -> l.contains(g.scene())
                            && l.contains("without returning: an endless loop?")),
                            "scene " + g.scene() + " names the loop:\n" + r.out());
                }
            }));
            tests.add(DynamicTest.dynamicTest("the grader stops and names " + method, () -> {
                Ran r = grades.get(method).get();
                assertEquals(0, r.status(), "exit status; stderr: " + r.err());
                assertNamed(method, r.out());
                assertCountedInCpuTime(method, r.out());
                assertTrue(r.out().contains("\"score\""), "graded: " + r.out());
            }));
        }
        return tests.stream();
    }
}
