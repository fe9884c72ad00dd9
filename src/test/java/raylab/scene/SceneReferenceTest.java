package raylab.scene;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

import raylab.render.ImageCompare;
import raylab.render.PngFiles;
import raylab.render.Renderer;

/**
 * Every bundled scene, rendered by the reference solution, matches its checked-in reference image
 * (scenes/reference/NAME.png). Fewer than 0.1% of pixels may differ by more than 2/255, which
 * allows for last-bit differences of Math.pow between JVMs and nothing more.
 */
class SceneReferenceTest {
    static final Path SCENES = Path.of("scenes");
    static final double ALLOWED = 0.001;

    static List<Path> sceneFiles() throws IOException {
        try (Stream<Path> s = Files.list(SCENES)) {
            return s.filter(p -> p.toString().endsWith(".json") && !p.getFileName().toString().equals("scene.schema.json"))
                    .sorted().toList();
        }
    }

    @TestFactory
    Stream<DynamicTest> everySceneMatchesItsReference() throws IOException {
        return sceneFiles().stream().map(scene -> DynamicTest.dynamicTest(scene.getFileName().toString(), () -> {
            String name = scene.getFileName().toString().replaceFirst("\\.json$", "");
            Path ref = SCENES.resolve("reference").resolve(name + ".png");
            assertTrue(Files.isRegularFile(ref), () -> "no reference image " + ref
                    + " (render it with: ./raylab render " + scene + " -o " + ref + ")");
            Scene s = SceneLoader.load(scene);
            BufferedImage actual = new Renderer(s).render(2, null).toBufferedImage();
            ImageCompare.Result r = ImageCompare.compare(actual, PngFiles.read(ref));
            assertTrue(r.matches(ALLOWED), () -> scene + " differs from " + ref + ": " + r.summary());
        }));
    }
}
