package raylab.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import raylab.math.Color;
import raylab.render.Image;
import raylab.render.Mode;
import raylab.render.RenderPlan;
import raylab.render.Renderer;
import raylab.scene.Scene;

/**
 * Every decision of the render plan is a proven no-op: seeded random scenes ({@link RandomScenes})
 * rendered with the plan and with {@link RenderPlan#bruteForce} (no shortcut, linear group of all
 * primitives instead of a BVH) give the same image, bit for bit in linear radiance.
 *
 * <p>The one documented exception (docs/shading.md, "Ties"): when two primitives are hit at
 * exactly the same smallest t, which one the eye ray reports depends on the order they are
 * tested in, and a BVH tests them in another order than the scene lists them. A pixel may then
 * differ, but only if its eye ray has such an exact tie (checked primitive by primitive); such
 * pixels are counted and printed. Every scene must also be free of NaN and infinite pixels.
 *
 * <p>{@code -Dscenes=N} runs N scenes (default 300); {@code -Dseed=S} replays one. A failing
 * scene is written to target/failing-scenes/seed-S.json, renderable with {@code ./raylab render}.
 */
class PlanVersusBruteForceTest {
    static final AtomicLong PIXELS = new AtomicLong();
    static final AtomicLong TIES = new AtomicLong();
    static final AtomicLong SHADOW_RAYS_SAVED = new AtomicLong();
    static final AtomicLong SCENES = new AtomicLong();

    static Stream<Long> seeds() {
        return RandomScenes.seeds().stream();
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void planAndBruteForceRenderTheSameImage(long seed) {
        RandomScenes.Generated g = RandomScenes.generate(seed);
        Scene scene = g.load();
        RenderPlan plan = new RenderPlan(scene);
        RenderPlan brute = RenderPlan.bruteForce(scene);
        Renderer planned = new Renderer(scene, plan, Mode.FULL);
        Renderer forced = new Renderer(scene, brute, Mode.FULL);
        Image a = planned.render(1, null);
        Image b = forced.render(1, null);
        assertEquals(0, planned.stats().nonFinitePixels, () -> "NaN/infinite pixels with the plan in " + g.describe());
        assertEquals(0, forced.stats().nonFinitePixels, () -> "NaN/infinite pixels in brute force in " + g.describe());
        SCENES.incrementAndGet();
        SHADOW_RAYS_SAVED.addAndGet(forced.stats().shadowRays - planned.stats().shadowRays);
        for (int y = 0; y < scene.height; y++) {
            for (int x = 0; x < scene.width; x++) {
                PIXELS.incrementAndGet();
                Color ca = a.get(x, y);
                Color cb = b.get(x, y);
                if (same(ca, cb)) {
                    continue;
                }
                if (scene.samplesPerPixel == 1 && ReferenceTrace.tie(scene, x, y)) {
                    TIES.incrementAndGet();
                    System.out.printf("PlanVersusBruteForceTest: seed %d pixel (%d, %d) differs at an exact tie"
                            + " of two primitives (allowed): %s vs %s%n", seed, x, y, ca, cb);
                    continue;
                }
                fail("pixel (" + x + ", " + y + ") differs between the plan and brute force in " + g.describe()
                        + "\n  plan:        " + ca + "\n  brute force: " + cb
                        + "\n  plan decisions:\n" + String.join("\n", plan.describe())
                        + "\n  trace with the plan:\n" + ReferenceTrace.of(scene, plan, x, y)
                        + "\n  trace in brute force:\n" + ReferenceTrace.of(scene, brute, x, y));
            }
        }
    }

    static boolean same(Color a, Color b) {
        return Double.doubleToLongBits(a.r) == Double.doubleToLongBits(b.r)
                && Double.doubleToLongBits(a.g) == Double.doubleToLongBits(b.g)
                && Double.doubleToLongBits(a.b) == Double.doubleToLongBits(b.b);
    }

    @AfterAll
    static void summary() {
        System.out.printf("PlanVersusBruteForceTest: %d scenes, %d pixels, %d differing at exact ties,"
                + " %d shadow rays the plan did not need%n", SCENES.get(), PIXELS.get(), TIES.get(),
                SHADOW_RAYS_SAVED.get());
    }

}
