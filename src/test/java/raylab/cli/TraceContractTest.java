package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.SolutionRegions;

/**
 * {@code raylab trace} marks a broken rule of intersect on the line where it happens: a Sphere
 * that dropped the range check records the sphere behind the camera (t &lt; 0), and the trace says
 * so on that surface's line and on the hit line. The reference Sphere on the same scene breaks
 * no rule, and a normal left unnormalized is marked on its line.
 */
class TraceContractTest {
    @TempDir
    Path dir;

    private static final String SCENE = """
            {
              "image": {"width": 21, "height": 21},
              "camera": {"type": "perspective", "eye": [0, 0, 0], "lookAt": [0, 0, -1], "up": [0, 1, 0], "fov": 40},
              "background": [0, 0, 0],
              "materials": {"white": {"type": "flat", "color": [1, 1, 1]}},
              "surfaces": [
                {"type": "sphere", "name": "behind camera", "center": [0, 0, 5], "radius": 1, "material": "white"},
                {"type": "sphere", "name": "ahead", "center": [0, 0, -5], "radius": 1, "material": "white"}
              ]
            }
            """;

    /** The reference Sphere with one edit, compiled over raylab; null edit: the reference itself. */
    private Path sphere(String from, String to) throws IOException {
        Path src = Path.of("src/main/java/raylab/surface/Sphere.java").toAbsolutePath();
        String text = SolutionRegions.toStudent("Sphere.java", Files.readString(src), Set.of("sphere"));
        if (from != null) {
            assertTrue(text.contains(from), "the edit applies: " + from);
            text = text.replace(from, to);
        }
        Path out = dir.resolve("classes-" + Math.abs(String.valueOf(from).hashCode()));
        JavaBuild.Result r = MilestoneBuild.compileOverlay(Map.of("raylab/surface/Sphere.java", text),
                dir.resolve("src-" + out.getFileName()), JavaBuild.ownClassPath(), out);
        assertTrue(r.success(), r.errors().toString());
        return out;
    }

    private String trace(Path classes) throws IOException, InterruptedException {
        Path scene = dir.resolve("behind.json");
        Files.writeString(scene, SCENE);
        List<Path> cp = new ArrayList<>(List.of(classes));
        cp.addAll(JavaBuild.ownClassPath());
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-cp", String.join(File.pathSeparator, cp.stream().map(Path::toString).toList()),
                "raylab.cli.Main", "trace", scene.toString(), "--pixel", "10", "10"));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), out);
        return out;
    }

    @Test
    void aHitBehindTheCameraIsMarkedWithTheRangeRule() throws Exception {
        String bug = trace(sphere("double t = t0;\n        if (!ray.inRange(t) || t >= outRecord.t) {",
                "double t = t0;\n        if (t >= outRecord.t) {"));
        System.out.println(bug);
        String surfaceLine = bug.lines().filter(l -> l.contains("\"behind camera\": hit at t = -")).findFirst()
                .orElseThrow(() -> new AssertionError("no line for the sphere behind the camera:\n" + bug));
        assertTrue(surfaceLine.contains(ContractCheck.MARK + "the recorded t = ")
                && surfaceLine.contains("must lie in [tMin, tMax] = [0, Infinity]: a hit behind the ray's start does not count"),
                surfaceLine);
        String hitLine = bug.lines().filter(l -> l.startsWith("  hit \"behind camera\" at t = -")).findFirst()
                .orElseThrow(() -> new AssertionError(bug));
        assertTrue(hitLine.contains(ContractCheck.MARK + "the recorded t = "), hitLine);

        String ok = trace(sphere(null, null));
        assertFalse(ok.contains(ContractCheck.MARK), "the reference breaks no rule:\n" + ok);
        assertTrue(ok.contains("every rule of intersect holds") && ok.contains("hit \"ahead\" at t = "), ok);

        String unnormalized = trace(sphere("Vec3 normal = fromCenter.normalize();", "Vec3 normal = fromCenter.times(2);"));
        assertTrue(unnormalized.lines().anyMatch(l -> l.startsWith("    normal n = ")
                && l.contains(ContractCheck.MARK + "the normal must be unit length, its length is 2")), unnormalized);
    }
}
