package raylab.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import raylab.math.Color;
import raylab.ray.IntersectionRecord;
import raylab.render.Mode;
import raylab.render.RenderPlan;
import raylab.render.RenderStats;
import raylab.render.Renderer;
import raylab.render.Shader;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;

/**
 * The reference agrees with an independent, deliberately plain renderer ({@link PlainRenderer})
 * on seeded random scenes and on every bundled scene. A pixel whose result rounding could tip
 * (the plain renderer says which: near misses, edges, near ties, blockers within δ of the point or
 * the light) is skipped and counted; every other pixel must agree to 1e-6 in linear radiance.
 * A disagreement fails with the pixel, both colours and a trace of each renderer.
 */
class SecondRendererTest {
    /** Agreement of linear radiance: rounding differences are around 1e-12. */
    static final double TOLERANCE = 1e-6;
    /** At most this fraction of all compared pixels may be too close to call. */
    static final double MAX_FRAGILE = 0.05;

    static final AtomicLong COMPARED = new AtomicLong();
    static final AtomicLong FRAGILE = new AtomicLong();

    static Stream<Long> seeds() {
        return RandomScenes.seeds().stream();
    }

    static List<Path> bundled() throws IOException {
        try (Stream<Path> s = Files.list(Path.of("scenes"))) {
            return s.filter(p -> p.toString().endsWith(".json") && !p.getFileName().toString().equals("scene.schema.json"))
                    .sorted().toList();
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void randomScenesAgree(long seed) {
        RandomScenes.Generated g = RandomScenes.generate(seed);
        Scene scene = g.load();
        compare(scene, 1, () -> g.describe());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("bundled")
    void bundledScenesAgree(Path file) throws Exception {
        Scene scene = SceneLoader.load(file);
        assertEquals(1, scene.samplesPerPixel, "the comparison traces pixel centres: " + file);
        // Every pixel of small scenes; a regular grid of about 1500 pixels of larger ones.
        int stride = (int) Math.max(1, Math.floor(Math.sqrt((double) scene.width * scene.height / 1500)));
        compare(scene, stride, () -> "bundled scene " + file + "\n  render it: ./raylab render " + file);
    }

    static void compare(Scene scene, int stride, java.util.function.Supplier<String> what) {
        RenderPlan plan = new RenderPlan(scene);
        Renderer reference = new Renderer(scene, plan, Mode.FULL);
        Shader shader = new Shader(scene, reference.root(), plan, Mode.FULL);
        IntersectionRecord rec = new IntersectionRecord();
        RenderStats stats = new RenderStats();
        PlainRenderer plain = new PlainRenderer(scene);
        for (int y = stride / 2; y < scene.height; y += stride) {
            for (int x = stride / 2; x < scene.width; x += stride) {
                COMPARED.incrementAndGet();
                // The reference's pixel exactly as its renderer computes it (only fewer of them).
                Color c = reference.pixel(x, y, shader, rec, stats);
                int px = x;
                int py = y;
                assertTrue(c.isFinite(), () -> "NaN/infinite pixel (" + px + ", " + py + ") in " + what.get());
                PlainRenderer.Pixel p = plain.pixel(x, y, false);
                if (p.fragile()) {
                    FRAGILE.incrementAndGet();
                    continue;
                }
                if (!close(c.r, p.r()) || !close(c.g, p.g()) || !close(c.b, p.b())) {
                    fail("pixel (" + x + ", " + y + ") differs between the reference and the plain renderer in "
                            + what.get() + "\n  reference: " + c + "\n  plain:     " + p
                            + "\n  reference trace:\n" + ReferenceTrace.of(scene, plan, x, y)
                            + "\n  plain trace:" + plain.pixel(x, y, true).trace());
                }
            }
        }
    }

    static boolean close(double a, double b) {
        return Math.abs(a - b) <= TOLERANCE * Math.max(1, Math.abs(b));
    }

    @AfterAll
    static void fragileIsRare() {
        long n = COMPARED.get();
        long f = FRAGILE.get();
        System.out.printf("SecondRendererTest: %d pixels compared, %d (%.2f%%) too close to call and skipped%n", n, f,
                n == 0 ? 0.0 : 100.0 * f / n);
        assertTrue(f <= MAX_FRAGILE * n, "too many fragile pixels: " + f + " of " + n
                + "; the comparison would prove little");
    }
}
