package raylab.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

import raylab.render.PngFiles;
import raylab.render.Renderer;

/**
 * Every bundled scene, rendered by the current reference solution, is its checked-in reference
 * image (scenes/reference/NAME.png), pixel for pixel: a reference image that the reference no
 * longer renders would grade students against a picture nobody can make. The only allowance is
 * for the last bit of Math.pow, which may differ between JVMs and can tip an 8-bit rounding: a
 * channel may differ by 1/255 in at most 0.01% of the pixels, never by more.
 */
class SceneReferenceTest {
    static final Path SCENES = Path.of("scenes");
    /** Fraction of pixels allowed to differ by exactly 1/255 in some channel. */
    static final double OFF_BY_ONE = 0.0001;

    static List<Path> sceneFiles() throws IOException {
        try (Stream<Path> s = Files.list(SCENES)) {
            return s.filter(p -> p.toString().endsWith(".json") && !p.getFileName().toString().equals("scene.schema.json"))
                    .sorted().toList();
        }
    }

    @TestFactory
    Stream<DynamicTest> everySceneIsItsReferenceImage() throws IOException {
        return sceneFiles().stream().map(scene -> DynamicTest.dynamicTest(scene.getFileName().toString(), () -> {
            String name = scene.getFileName().toString().replaceFirst("\\.json$", "");
            Path ref = SCENES.resolve("reference").resolve(name + ".png");
            String fix = "\n  if the reference renderer changed on purpose, re-render it: ./raylab reference " + scene;
            assertTrue(Files.isRegularFile(ref), () -> "no reference image " + ref + fix);
            Scene s = SceneLoader.load(scene);
            BufferedImage actual = new Renderer(s).render(2, null).toBufferedImage();
            BufferedImage expected = PngFiles.read(ref);
            assertEquals(expected.getWidth() + "x" + expected.getHeight(), actual.getWidth() + "x" + actual.getHeight(),
                    () -> "scene " + scene + ": size of " + ref + fix);
            long offByOne = 0;
            String first = null;
            for (int y = 0; y < actual.getHeight(); y++) {
                for (int x = 0; x < actual.getWidth(); x++) {
                    int a = actual.getRGB(x, y);
                    int e = expected.getRGB(x, y);
                    int diff = 0;
                    for (int shift = 0; shift <= 16; shift += 8) {
                        diff = Math.max(diff, Math.abs(((a >> shift) & 0xFF) - ((e >> shift) & 0xFF)));
                    }
                    if (diff == 0) {
                        continue;
                    }
                    String where = String.format("pixel (%d, %d): rendered #%06X, reference #%06X", x, y,
                            a & 0xFFFFFF, e & 0xFFFFFF);
                    if (diff > 1) {
                        fail("scene " + scene + " is not its reference image " + ref + ": " + where + fix);
                    }
                    offByOne++;
                    if (first == null) {
                        first = where;
                    }
                }
            }
            long allowed = (long) Math.floor(OFF_BY_ONE * actual.getWidth() * actual.getHeight());
            long n = offByOne;
            String f = first;
            assertTrue(n <= allowed, () -> "scene " + scene + " is not its reference image " + ref + ": " + n
                    + " pixels differ by 1/255 (allowed " + allowed + "), first " + f + fix);
        }));
    }
}
