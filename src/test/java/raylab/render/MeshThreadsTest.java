package raylab.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.math.Color;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;

/**
 * Mesh scenes (packed mesh engine, per-thread traversal stacks) render bit for bit the same image
 * with 1, 2 and 7 threads, with the same counters.
 */
class MeshThreadsTest {
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"scenes/mesh.json", "scenes/showcase.json"})
    void meshImagesAreBitIdenticalFor1And2And7Threads(String file) throws Exception {
        Scene scene = SceneLoader.load(Path.of(file));
        Renderer one = new Renderer(scene);
        Image reference = one.render(1, null);
        for (int threads : new int[] {2, 7}) {
            Renderer r = new Renderer(scene);
            Image image = r.render(threads, null);
            long differ = 0;
            for (int y = 0; y < scene.height; y++) {
                for (int x = 0; x < scene.width; x++) {
                    Color a = reference.get(x, y);
                    Color b = image.get(x, y);
                    if (Double.doubleToRawLongBits(a.r) != Double.doubleToRawLongBits(b.r)
                            || Double.doubleToRawLongBits(a.g) != Double.doubleToRawLongBits(b.g)
                            || Double.doubleToRawLongBits(a.b) != Double.doubleToRawLongBits(b.b)) {
                        differ++;
                    }
                }
            }
            assertEquals(0, differ, file + ": pixels that differ between 1 and " + threads + " threads");
            assertEquals(one.stats().intersectionTests, r.stats().intersectionTests, threads + " threads: tests");
            assertEquals(one.stats().shadowRaysBlocked, r.stats().shadowRaysBlocked, threads + " threads: blocked");
        }
        assertTrue(one.stats().intersectionTests > 0, "the scene traces something");
    }
}
