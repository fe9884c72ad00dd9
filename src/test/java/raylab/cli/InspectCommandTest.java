package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import raylab.inspect.TraceFile;
import raylab.inspect.Tracer;
import raylab.scene.SceneLoader;

/** {@code raylab inspect}: its text mode and its bad input (one line, exit 2, never a stack trace). */
class InspectCommandTest {
    @TempDir
    Path dir;

    private static String[] run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = Main.run(new PrintWriter(out, true), new PrintWriter(err, true), args);
        return new String[] {Integer.toString(status), out.toString(), err.toString()};
    }

    @Test
    void aSceneWithoutAReferenceTraceIsBadInput() {
        String[] r = run("inspect", "scenes/sphere.json", "--print");
        assertEquals("2", r[0], "exit status: " + r[2]);
        assertTrue(r[2].startsWith("raylab: no reference trace for scenes/sphere.json") && r[2].strip().lines().count() == 1,
                "one line naming the missing trace, was: " + r[2]);
    }

    @Test
    void printWithTheReferenceFindsNoDifferenceAndAPixelOutsideIsBadInput() throws Exception {
        Path scenes = dir.resolve("scenes");
        Files.createDirectories(scenes.resolve("reference"));
        Files.copy(Path.of("scenes/sphere.json"), scenes.resolve("sphere.json"));
        Files.copy(Path.of("scenes/reference/sphere.png"), scenes.resolve("reference/sphere.png"));
        Path json = scenes.resolve("sphere.json");
        TraceFile.write(new Tracer(SceneLoader.load(json)), TraceFile.pathFor(json));
        String[] r = run("inspect", json.toString(), "--print", "--threads", "1");
        assertEquals("0", r[0], "exit status: " + r[1] + r[2]);
        assertTrue(r[1].startsWith("no difference"), "expected no difference for the reference, was: " + r[1]);
        String[] p = run("inspect", json.toString(), "--print", "--pixel", "160", "120");
        assertEquals("0", p[0], "exit status: " + p[1] + p[2]);
        String[] bad = run("inspect", json.toString(), "--print", "--pixel", "320", "0");
        assertEquals("2", bad[0], "exit status: " + bad[2]);
        assertTrue(bad[2].contains("pixel (320, 0) is outside the 320x240 image"), "was: " + bad[2]);
        String[] port = run("inspect", json.toString(), "--port", "70000");
        assertEquals("2", port[0], "exit status: " + port[2]);
        assertTrue(port[2].contains("--port must be between 0 and 65535"), "was: " + port[2]);
    }
}
