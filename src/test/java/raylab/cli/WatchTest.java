package raylab.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code render --watch} renders, then renders again after a save (here of the scene file), on a
 * cleared screen, keeping the PNG fresh; a signal (Ctrl-C) stops it cleanly.
 */
class WatchTest {
    @TempDir
    Path dir;

    @Test
    void aSaveBringsTheSecondResult() throws Exception {
        Path scene = dir.resolve("s.json");
        Path png = dir.resolve("s.png");
        Files.writeString(scene, Files.readString(Path.of("scenes/sphere.json")));
        Path out = dir.resolve("out.txt");
        Path err = dir.resolve("err.txt");
        // raylab.home: a folder without target/raylab.jar, so that no quick build runs.
        Process p = ChildJvm.start(List.of("-Draylab.home=" + dir), Map.of(), out, err,
                "render", "--watch", scene.toString(), "-o", png.toString(), "--quiet");
        try {
            waitFor(out, "raylab: waiting for the next save ...", 1, p);
            int first = ImageIO.read(png.toFile()).getRGB(0, 0);
            Files.writeString(scene, Files.readString(scene).replace("[0.1, 0.1, 0.12]", "[1, 0, 0]"));
            waitFor(out, "raylab: waiting for the next save ...", 2, p);
            String text = Files.readString(out, StandardCharsets.UTF_8);
            assertTrue(text.contains(Watch.CLEAR + "raylab render " + scene + " -o " + png + " --quiet  (run 2 at "),
                    "the second run on a cleared screen:\n" + text);
            BufferedImage second = ImageIO.read(png.toFile());
            assertEquals(0xFF0000, second.getRGB(0, 0) & 0xFFFFFF, "the background of the second render (first was "
                    + Integer.toHexString(first) + ")");
        } finally {
            p.destroy(); // SIGTERM, as Ctrl-C: the shutdown hook says so
        }
        assertTrue(p.waitFor(20, TimeUnit.SECONDS), "the watcher stops");
        assertTrue(Files.readString(out).strip().endsWith("raylab: stopped watching"), Files.readString(out));
        assertFalse(Files.readString(err).contains("Exception"), Files.readString(err));
    }

    /** Waits (at most 60 s) until {@code line} has been printed {@code times} times. */
    static void waitFor(Path file, String line, int times, Process p) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < end) {
            String text = Files.readString(file, StandardCharsets.UTF_8);
            if (text.split(java.util.regex.Pattern.quote(line), -1).length - 1 >= times) {
                return;
            }
            assertTrue(p.isAlive(), "the watcher ended early:\n" + text);
            Thread.sleep(100);
        }
        throw new AssertionError("\"" + line + "\" not printed " + times + " times within 60 s:\n" + Files.readString(file));
    }
}
