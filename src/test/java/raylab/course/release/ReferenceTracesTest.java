package raylab.course.release;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The release's reference traces and their verification: the traces written for every published
 * scene of this tree give every pixel's colour within one 8-bit step of its reference image and,
 * at seeded random pixels of every scene, the reference's ray tree as the comparison sees it (no
 * first difference with the live reference); an image that no longer matches its trace is reported.
 */
class ReferenceTracesTest {
    @TempDir
    Path dir;

    @Test
    void everyPublishedTraceMatchesItsReferenceImageAndAChangedImageIsReported() throws Exception {
        Path root = Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
        SortedMap<String, byte[]> files = new TreeMap<>();
        try (Stream<Path> s = Files.walk(root.resolve("scenes"))) {
            for (Path p : s.filter(Files::isRegularFile).toList()) {
                files.put(root.relativize(p).toString().replace('\\', '/'), Files.readAllBytes(p));
            }
        }
        List<String> published = ReferenceTraces.published(files.keySet());
        assertTrue(published.contains("scenes/diffuse-ambient.json") && published.size() >= 15,
                "every scene with a reference image is published: " + published);
        ReferenceTraces.add(root, files);
        long total = 0;
        for (Map.Entry<String, byte[]> e : files.entrySet()) {
            Path p = dir.resolve(e.getKey());
            Files.createDirectories(p.getParent());
            Files.write(p, e.getValue());
            total += e.getKey().startsWith("scenes/traces/") ? e.getValue().length : 0;
        }
        System.out.println("traces of " + published.size() + " published scenes: " + total + " bytes");
        assertEquals(List.of(), ReferenceTraces.problems(dir, new ArrayList<>(files.keySet())),
                "every trace gives its reference image's colours");

        assertEquals(2, raylab.inspect.TraceFile.strideFor(2000, 1000),
                "a scene of 2000x1000 (over MAX_TRACED) keeps every 2nd pixel of every 2nd row (1000x500)");
        assertEquals(3, raylab.inspect.TraceFile.strideFor(3000, 2000),
                "a scene of 3000x2000 keeps every 3rd pixel of every 3rd row (1000x667)");

        long seed = 4040;
        java.util.SplittableRandom random = new java.util.SplittableRandom(seed);
        for (String scene : published) {
            raylab.scene.Scene sc = raylab.scene.SceneLoader.load(dir.resolve(scene));
            raylab.inspect.TraceFile stored = raylab.inspect.TraceFile.read(dir.resolve(ReferenceTraces.traceOf(scene)), sc);
            raylab.inspect.Tracer live = new raylab.inspect.Tracer(sc);
            int stride = raylab.inspect.TraceFile.strideFor(sc.width, sc.height);
            assertEquals(stride, stored.stride, scene + ": the trace's stride");
            assertEquals(1, stride, scene + " (" + sc.width + "x" + sc.height + "): every pixel of a published scene"
                    + " is traced (up to " + raylab.inspect.TraceFile.MAX_TRACED + " pixels)");
            for (int k = 0; k < 300; k++) {
                int[] p = stored.traced(random.nextInt(sc.width), random.nextInt(sc.height));
                int x = p[0];
                int y = p[1];
                assertTrue(stored.isTraced(x, y) && x < sc.width && y < sc.height, "a traced pixel: " + x + ", " + y);
                raylab.inspect.RayTree a = live.trace(x, y);
                raylab.inspect.RayTree b = stored.tree(x, y);
                var d = raylab.inspect.FirstDifference.of(a, b, sc);
                String where = "seed " + seed + ", " + scene + " pixel (" + x + ", " + y + ")";
                assertTrue(d.isEmpty(), () -> where + ": expected the live and the stored reference tree to agree,"
                        + " got " + d.get().line());
                assertEquals(a.surface, b.surface, where + ": surface");
            }
        }

        Path png = dir.resolve("scenes/reference/diffuse.png");
        BufferedImage img = ImageIO.read(png.toFile());
        int rgb = img.getRGB(200, 150);
        int g = (rgb >> 8) & 0xFF;
        img.setRGB(200, 150, (rgb & ~0xFF00) | ((g < 128 ? g + 3 : g - 3) << 8));
        ImageIO.write(img, "png", png.toFile());
        List<String> problems = ReferenceTraces.problems(dir, new ArrayList<>(files.keySet()));
        assertEquals(1, problems.size(), "one image changed: " + problems);
        assertTrue(problems.get(0).startsWith("scenes/traces/diffuse.trace: 1 pixels differ"),
                "expected the changed pixel of diffuse.png reported, was: " + problems);
    }
}
