package raylab.oracle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.stream.LongStream;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import raylab.material.FlatColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.render.Image;
import raylab.render.Mode;
import raylab.render.RenderPlan;
import raylab.render.Renderer;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;
import raylab.surface.Mesh;
import raylab.surface.Triangle;

/**
 * The t = 0 rule for triangles (docs/shading.md: eye rays have the closed range [0, +∞), a hit at
 * t = 0 counts): with the eye exactly in a triangle's plane and inside the triangle, every eye ray
 * that is not parallel to the plane hits the triangle at t = 0, so the whole image shows it. The
 * plane is tilted (x + 2y + 3z = 0 moved by a seeded integer offset and scaled by a seeded power
 * of two, so the eye stays exactly in it), which makes the watertight test's t come out as
 * ±1e-16 before the rule: a negative one used to drop the hit (24% of the pixels showed the
 * background). Checked four ways: the image (every pixel the triangle's colour), the second
 * renderer, brute force, and the packed mesh kernel against {@link Triangle#intersect} ray by
 * ray, t bit for bit.
 */
class EyeInTrianglePlaneTest {
    static final double[][] TRIANGLE = {{-5, 4, -1}, {7, -2, -1}, {1, -5, 3}};
    static final double[] EYE = {2, -1, 0};

    static Stream<Long> seeds() {
        return LongStream.range(0, 6).boxed();
    }

    /** The scene of seed s: offset o (integers, 0 for seed 0) and scale 2^k. */
    static String sceneJson(long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        double[] o = seed == 0 ? new double[3] : new double[] {r.nextInt(-50, 51), r.nextInt(-50, 51), r.nextInt(-50, 51)};
        double s = seed == 0 ? 1 : Math.scalb(1.0, r.nextInt(-20, 21));
        StringBuilder v = new StringBuilder();
        for (double[] p : TRIANGLE) {
            v.append(v.length() == 0 ? "" : ", ").append(point(p, o, s));
        }
        // Looking along the plane's normal (1, 2, 3) with a wide field of view: rays on both sides.
        double[] look = {EYE[0] + 1, EYE[1] + 2, EYE[2] + 3};
        return String.format(Locale.ROOT, """
                {
                  "image": {"width": 64, "height": 48},
                  "camera": {"type": "perspective", "eye": %s, "lookAt": %s, "up": [0, 0, 1], "fov": 150},
                  "background": [0, 0, 0],
                  "materials": {"orange": {"type": "flat", "color": [1, 0.5, 0.25]}},
                  "surfaces": [{"type": "triangle", "name": "around the eye", "vertices": [%s], "material": "orange"}]
                }
                """, point(EYE, o, s), point(look, o, s), v);
    }

    static String point(double[] p, double[] o, double s) {
        return String.format(Locale.ROOT, "[%s, %s, %s]", (p[0] + o[0]) * s, (p[1] + o[1]) * s, (p[2] + o[2]) * s);
    }

    static Scene load(long seed) throws Exception {
        return SceneLoader.parse(sceneJson(seed), Path.of("eye-in-plane-" + seed + ".json"));
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void everyEyeRayHitsTheTriangleAtTZero(long seed) throws Exception {
        Scene scene = load(seed);
        Image image = new Renderer(scene, new RenderPlan(scene), Mode.FULL).render(1, null);
        Triangle tri = triangle(scene);
        Color orange = ((FlatColor) tri.material()).color;
        int background = 0;
        IntersectionRecord rec = new IntersectionRecord();
        for (int y = 0; y < scene.height; y++) {
            for (int x = 0; x < scene.width; x++) {
                Ray ray = scene.camera.rayThroughPixelCenter(x, y);
                rec.reset();
                boolean hit = tri.intersect(rec, ray);
                assertTrue(hit, "seed " + seed + " pixel (" + x + ", " + y + "): eye ray " + ray
                        + " starts inside the triangle in its plane: expected a hit at t = 0, got a miss");
                // A t within the test's rounding bound of 0 is 0.
                assertEquals(0.0, rec.t, "seed " + seed + " pixel (" + x + ", " + y + "): t of " + ray);
                if (!image.get(x, y).equals(orange)) {
                    background++;
                }
            }
        }
        assertEquals(0, background, "seed " + seed + ": pixels not showing the triangle (expected none)");
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void theSecondRendererAgrees(long seed) throws Exception {
        Scene scene = load(seed);
        long before = SecondRendererTest.COMPARED.get();
        long fragileBefore = SecondRendererTest.FRAGILE.get();
        SecondRendererTest.compare(scene, 1, () -> "eye-in-plane scene, seed " + seed + ":\n" + sceneJson(seed));
        long compared = SecondRendererTest.COMPARED.get() - before;
        long fragile = SecondRendererTest.FRAGILE.get() - fragileBefore;
        assertTrue(fragile <= compared / 10, "seed " + seed + ": " + fragile + " of " + compared
                + " pixels too close to call (expected at most 10%): the comparison would prove little");
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void bruteForceAgrees(long seed) throws Exception {
        Scene scene = load(seed);
        Image a = new Renderer(scene, new RenderPlan(scene), Mode.FULL).render(1, null);
        Image b = new Renderer(scene, RenderPlan.bruteForce(scene), Mode.FULL).render(1, null);
        for (int y = 0; y < scene.height; y++) {
            for (int x = 0; x < scene.width; x++) {
                assertEquals(b.get(x, y), a.get(x, y), "seed " + seed + " pixel (" + x + ", " + y + "): plan vs brute force");
            }
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void thePackedKernelCountsTZeroBitForBit(long seed) throws Exception {
        Scene scene = load(seed);
        Triangle tri = triangle(scene);
        Mesh mesh = new Mesh(List.of(tri), "mesh");
        assertTrue(mesh.usesPackedKernel(), "the reference build's packed kernel");
        SplittableRandom r = new SplittableRandom(seed);
        IntersectionRecord a = new IntersectionRecord();
        IntersectionRecord b = new IntersectionRecord();
        for (int i = 0; i < 2000; i++) {
            Vec3 d = new Vec3(r.nextDouble(-1, 1), r.nextDouble(-1, 1), r.nextDouble(-1, 1));
            Ray ray = new Ray(scene.camera.eye, d);
            a.reset();
            b.reset();
            boolean ha = tri.intersect(a, ray);
            boolean hb = mesh.intersect(b, ray);
            String what = "seed " + seed + " ray " + i + " " + ray;
            assertEquals(ha, hb, what + ": Triangle.intersect vs the packed kernel");
            assertTrue(ha && a.t == 0, what + ": a hit at t = 0 expected, got " + (ha ? "t = " + a.t : "a miss"));
            assertEquals(Double.doubleToRawLongBits(a.t), Double.doubleToRawLongBits(b.t),
                    what + ": t " + a.t + " vs " + b.t);
            assertEquals(a.point, b.point, what + ": point");
            assertEquals(a.normal, b.normal, what + ": normal");
            a.reset();
            assertTrue(mesh.intersectsAny(ray, a), what + ": any-hit");
            // A shadow-like ray with tMin > 0 is not blocked by a surface at its start.
            Ray open = new Ray(scene.camera.eye, d, Double.MIN_VALUE, Math.nextDown(1.0));
            a.reset();
            b.reset();
            assertEquals(tri.intersect(a, open), mesh.intersect(b, open), what + ": open range");
            assertEquals(Double.doubleToRawLongBits(a.t), Double.doubleToRawLongBits(b.t), what + ": open range t");
        }
    }

    static Triangle triangle(Scene scene) {
        List<Triangle> found = new java.util.ArrayList<>();
        for (raylab.surface.Surface s : scene.surfaces) {
            collect(s, found);
        }
        assertEquals(1, found.size(), "one triangle in the scene");
        return found.get(0);
    }

    static void collect(raylab.surface.Surface s, List<Triangle> out) {
        if (s instanceof Triangle t) {
            out.add(t);
        } else if (s instanceof raylab.surface.Group g) {
            for (raylab.surface.Surface m : g.members()) {
                collect(m, out);
            }
        }
    }
}
