package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.Watchdog;

/**
 * An endless loop in each graded method is stopped and named ("your code has run for 5 s in
 * Lambertian.diffuse (Lambertian.java:38) without returning: an endless loop?") by {@code render},
 * {@code trace} and {@code check}, after the watchdog's bound ({@link Watchdog#FLOOR}: the
 * reference finishes a tile, a pixel or a visible test in far less) instead of the old 300 s of a
 * render or 10 s of each test. Each case runs raylab in a JVM of its own with the looping file
 * compiled first on the class path.
 */
class EndlessLoopTest {
    /** The graded methods: file, method, and the pixel of its milestone's first scene traced. */
    static final Map<String, String> METHODS = new LinkedHashMap<>();
    static final Path ROOT = Path.of("").toAbsolutePath();
    static Path dir;
    static Map<String, Assignment> owner = new LinkedHashMap<>();

    @BeforeAll
    static void overlays() throws IOException {
        dir = Files.createTempDirectory("raylab-endless");
        for (Assignment a : Assignments.load(ROOT).all()) {
            for (Assignment.StudentFile f : a.files()) {
                for (String m : f.methods()) {
                    METHODS.put(m, f.path());
                    owner.put(m, a);
                }
            }
        }
        for (var e : METHODS.entrySet()) {
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
    }

    static Stream<String> methods() throws IOException {
        List<String> out = new ArrayList<>();
        for (Assignment a : Assignments.load(Path.of("").toAbsolutePath()).all()) {
            a.files().forEach(f -> out.addAll(f.methods()));
        }
        return out.stream();
    }

    /** raylab ARGS in a JVM whose class path starts with the looping file of {@code method}. */
    static String[] run(String method, String... args) throws Exception {
        Path out = Files.createTempFile(dir, "out", ".txt");
        Path err = Files.createTempFile(dir, "err", ".txt");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", dir.resolve(method) + File.pathSeparator + System.getProperty("java.class.path"),
                "raylab.cli.Main"));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).directory(ROOT.toFile()).redirectOutput(out.toFile())
                .redirectError(err.toFile()).start();
        // A guard only (the old limit): the assertions are on what raylab says.
        if (!p.waitFor(300, TimeUnit.SECONDS)) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
        }
        return new String[] {Integer.toString(p.waitFor()), Files.readString(out), Files.readString(err)};
    }

    /** The sentence naming {@code method} in its own file, after at least the bound. */
    static void assertNamed(String method, String text) {
        String cls = method.substring(0, method.indexOf('.'));
        Matcher m = Pattern.compile("your code has run for (\\d+) s in " + Pattern.quote(method) + " \\("
                + Pattern.quote(cls) + "\\.java:\\d+\\) without returning: an endless loop\\?").matcher(text);
        assertTrue(m.find(), "the loop in " + method + " named:\n" + text);
        assertTrue(Long.parseLong(m.group(1)) >= Watchdog.FLOOR.toSeconds(), "stopped after the bound: " + m.group());
    }

    @ParameterizedTest
    @MethodSource("methods")
    void renderStopsAndNamesIt(String method) throws Exception {
        String scene = owner.get(method).scenes().get(0).scene();
        String[] r = run(method, "render", scene, "-o", dir.resolve(method + ".png").toString(), "--quiet",
                "--threads", "2");
        assertEquals("1", r[0], "exit status; stderr: " + r[2]);
        assertNamed(method, r[2]);
        assertTrue(r[2].contains("while rendering " + scene), r[2]);
        assertTrue(!Files.exists(dir.resolve(method + ".png")), "no picture written");
    }

    @ParameterizedTest
    @MethodSource("methods")
    void traceStopsAndNamesIt(String method) throws Exception {
        String scene = owner.get(method).scenes().get(0).scene();
        raylab.scene.Scene sc = raylab.scene.SceneLoader.load(ROOT.resolve(scene));
        String x = Integer.toString(sc.width / 2);
        String y = Integer.toString(sc.height / 2);
        String[] r = run(method, "trace", scene, "--pixel", x, y);
        assertEquals("1", r[0], "exit status; stdout: " + r[1] + " stderr: " + r[2]);
        assertNamed(method, r[2]);
        assertTrue(r[2].contains("while tracing pixel (" + x + ", " + y + ") of " + scene), r[2]);
    }

    /** check: every visible test that reaches the loop and every scene of the milestone say where it is. */
    @ParameterizedTest
    @MethodSource("methods")
    void checkStopsAndNamesIt(String method) throws Exception {
        Assignment a = owner.get(method);
        String[] r = run(method, "check", a.id(), "--threads", "2");
        assertEquals("1", r[0], "exit status; stdout: " + r[1] + " stderr: " + r[2]);
        assertNamed(method, r[1]);
        for (Assignment.GradedScene g : a.scenes()) {
            assertTrue(r[1].lines().anyMatch(l -> l.contains(g.scene()) && l.contains("without returning: an endless loop?")),
                    "scene " + g.scene() + " names the loop:\n" + r[1]);
        }
    }

    /**
     * The grader (with its process boundary, where the student's code runs in a JVM of its own):
     * each test that reaches the loop is reported with the same sentence, not as a bare timeout.
     */
    @org.junit.jupiter.api.Test
    void theGraderNamesIt() throws Exception {
        String method = "Lambertian.diffuse";
        Path sub = Files.createDirectories(dir.resolve("submission"));
        Files.copy(dir.resolve("src-" + method).resolve("raylab/material/Lambertian.java"), sub.resolve("Lambertian.java"));
        Files.copy(ROOT.resolve("src/main/java/raylab/shading/Shading.java"), sub.resolve("Shading.java"));
        Path results = dir.resolve("results");
        java.io.StringWriter err = new java.io.StringWriter();
        int status = Main.run(new java.io.PrintWriter(new java.io.StringWriter(), true), new java.io.PrintWriter(err, true),
                "grade", sub.toString(), "--out", results.toString(), "--root", ROOT.toString(), "--quiet",
                "--milestone", "lambert", "--test-timeout", "8", "--milestone-timeout", "240", "--scene-timeout", "10",
                "--heap", "256", "--sandbox-user", "");
        assertEquals(0, status, err::toString);
        String report = Files.readString(results.resolve("results.json"));
        assertNamed(method, report);
    }
}
