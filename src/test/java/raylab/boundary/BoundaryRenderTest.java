package raylab.boundary;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.File;
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
import raylab.course.SolutionRegions;
import raylab.render.PngFiles;
import raylab.render.Renderer;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;

/**
 * A render replayed across the process boundary: a JVM with the stand-in Sphere (generated from
 * the starter's Sphere.java) renders scenes/sphere.json while the reference Sphere.intersect runs
 * in a student process; the image is bit-identical to the direct render in this JVM.
 */
class BoundaryRenderTest {
    @TempDir
    Path dir;

    @Test
    void aReplayedRenderIsBitIdenticalToTheDirectOne() throws Exception {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        String starter = SolutionRegions.toStudent("Sphere.java",
                Files.readString(root.resolve("src/main/java/raylab/surface/Sphere.java")), Set.of());
        String standIn = StandIns.forwarding(starter, "raylab.surface.Sphere", Set.of("intersect"));
        assertTrue(standIn.contains("raylab.boundary.Remote.call(this, \"raylab.surface.Sphere\", \"intersect\""),
                () -> "the stand-in forwards intersect: " + standIn);
        List<Path> classDirs = StudentProcessTest.classDirs();
        Path standIns = dir.resolve("standins");
        StandIns.compile(Map.of("raylab/surface/Sphere.java", standIn), classDirs, standIns);

        Path config = dir.resolve("student.properties");
        Remote.writeConfig(config, new StudentProcess.Config(StudentJvm.javaCommand(classDirs, 128,
                List.of("raylab.surface.Sphere")), null, Set.of("raylab.surface.Sphere"), 60_000, 1));
        List<String> cp = new ArrayList<>();
        cp.add(standIns.toString());
        cp.add(System.getProperty("java.class.path"));
        Path scene = root.resolve("scenes/sphere.json");
        Path png = dir.resolve("replayed.png");
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the raylab launcher starts a command
        cmd.addAll(List.of("-Draylab.boundary=" + config, "-Djava.awt.headless=true", "-cp",
                String.join(File.pathSeparator, cp), "raylab.boundary.TrustedRender", scene.toString(), png.toString(),
                "scenes/sphere.json"));
        Process p = new ProcessBuilder(cmd)
                .redirectErrorStream(true).redirectOutput(dir.resolve("log.txt").toFile()).start();
        assertTrue(p.waitFor(300, TimeUnit.SECONDS), "the replayed render finished");
        Path err = Path.of(png + ".err");
        assertTrue(Files.isRegularFile(png), () -> "no image; error: " + (Files.exists(err) ? read(err) : "none")
                + "; log: " + read(dir.resolve("log.txt")));

        Scene s = SceneLoader.load(scene);
        BufferedImage direct = new Renderer(s).render(1, null).toBufferedImage();
        BufferedImage replayed = PngFiles.read(png);
        assertEquals(direct.getWidth(), replayed.getWidth(), "width");
        assertEquals(direct.getHeight(), replayed.getHeight(), "height");
        int differ = 0;
        for (int y = 0; y < direct.getHeight(); y++) {
            for (int x = 0; x < direct.getWidth(); x++) {
                if (direct.getRGB(x, y) != replayed.getRGB(x, y)) {
                    differ++;
                }
            }
        }
        assertEquals(0, differ, "pixels that differ between the direct and the replayed render");
    }

    private static String read(Path f) {
        try {
            return Files.readString(f, StandardCharsets.UTF_8);
        } catch (java.io.IOException e) {
            return "(unreadable)";
        }
    }
}
