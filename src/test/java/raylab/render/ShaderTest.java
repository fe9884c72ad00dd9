package raylab.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.camera.PerspectiveCamera;
import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.FlatColor;
import raylab.material.Lambertian;
import raylab.material.Material;
import raylab.material.NormalColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.scene.Scene;
import raylab.surface.Box;
import raylab.surface.Sphere;
import raylab.surface.Surface;

/**
 * The shader against the lecture's sum, worked out by hand:
 * L = ka·Ia + Σ_i [kd·I_i·max(0, n·l_i) + ks·I_i·max(0, n·h_i)^p].
 *
 * <p>Set-up: camera at the origin looking down −z; sphere c = (0,0,−5), r = 1, hit by the ray
 * d = (0,0,−1) at x = (0,0,−4) with n = v = (0,0,1). Light 1 at (0,0,2): l = (0,0,1), n·l = 1,
 * n·h = 1. Light 2 at (3,0,0): l = (3,0,4)/5, n·l = 0.8, v + l = (0.6,0,1.8), so with p = 2
 * (n·h)² = 1.8²/3.6 = 0.9.
 */
class ShaderTest {
    static final Color KD = new Color(0.6, 0.5, 0.4);
    static final Color KS = new Color(0.3, 0.3, 0.2);
    static final Color KA = new Color(0.2, 0.3, 0.4);
    static final Color IA = new Color(0.1, 0.2, 0.5);
    static final Color I1 = new Color(1, 0.5, 0.25);
    static final Color I2 = new Color(0.2, 0.4, 0.8);
    static final Material SHINY = new BlinnPhong(KD, KS, 2, KA, "shiny");
    static final PointLight L1 = new PointLight(new Vec3(0, 0, 2), I1, true, "L1");
    static final PointLight L2 = new PointLight(new Vec3(3, 0, 0), I2, true, "L2");
    static final Ray AXIS = new Ray(Vec3.ZERO, new Vec3(0, 0, -1));
    /** On the shadow ray from (0,0,−4) to light 1, behind the camera. */
    static final Box BLOCKS_L1 = new Box(new Vec3(-0.3, -0.3, 0.5), new Vec3(0.3, 0.3, 1.5), SHINY, "blocks L1");
    /** On the shadow ray from (0,0,−4) to light 2, around (1.5, 0, −2). */
    static final Box BLOCKS_L2 = new Box(new Vec3(1.3, -0.2, -2.2), new Vec3(1.7, 0.2, -1.8), SHINY, "blocks L2");
    /** Off every ray of the set-up. */
    static final Box ASIDE = new Box(new Vec3(-5, 3, -6), new Vec3(-4, 4, -5), SHINY, "aside");

    static Scene.Builder base(Material m) {
        return Scene.builder().size(8, 8)
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 8, 8))
                .add(new Sphere(new Vec3(0, 0, -5), 1, m, "sphere"));
    }

    /** Traces one ray and shades its hit as the renderer would. */
    static Color shade(Scene scene, Ray ray, Mode mode, RenderStats stats) {
        RenderPlan plan = new RenderPlan(scene);
        Surface root = plan.root(scene);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(root.intersect(rec, ray), "the ray " + ray + " must hit the scene");
        return new Shader(scene, root, plan, mode).shade(ray, rec, stats);
    }

    static Color shade(Scene scene, Ray ray, Mode mode) {
        return shade(scene, ray, mode, new RenderStats());
    }

    static void assertColor(Color expected, Color actual, double tol, String what) {
        assertEquals(expected.r, actual.r, tol, what + ": red of " + actual + ", expected " + expected);
        assertEquals(expected.g, actual.g, tol, what + ": green of " + actual + ", expected " + expected);
        assertEquals(expected.b, actual.b, tol, what + ": blue of " + actual + ", expected " + expected);
    }

    // By hand: ambient + light 1 (diffuse + specular) + light 2 (0.8 diffuse + 0.9 specular)
    // red   0.2·0.1 + 0.6·1 + 0.3·1 + 0.6·0.2·0.8 + 0.3·0.2·0.9   = 0.02 + 0.9 + 0.096 + 0.054
    // green 0.3·0.2 + 0.5·0.5 + 0.3·0.5 + 0.5·0.4·0.8 + 0.3·0.4·0.9 = 0.06 + 0.4 + 0.16 + 0.108
    // blue  0.4·0.5 + 0.4·0.25 + 0.2·0.25 + 0.4·0.8·0.8 + 0.2·0.8·0.9 = 0.2 + 0.15 + 0.256 + 0.144
    static final Color FULL_SUM = new Color(1.07, 0.728, 0.75);

    @Test
    void fullSumWithTwoColouredLightsAndAmbient() {
        Scene scene = base(SHINY).ambient(IA).add(L1).add(L2).build();
        RenderStats stats = new RenderStats();
        assertColor(FULL_SUM, shade(scene, AXIS, Mode.FULL, stats), 1e-12, "L at (0,0,-4)");
        assertEquals(2, stats.specularEvaluations, "one specular term per light");
        assertEquals(0, stats.shadowRays, "one convex sphere: no shadow rays");
    }

    @Test
    void fullSumWithShadowRaysThatAreNotBlocked() {
        Scene scene = base(SHINY).ambient(IA).add(L1).add(L2).add(ASIDE).build();
        RenderStats stats = new RenderStats();
        assertColor(FULL_SUM, shade(scene, AXIS, Mode.FULL, stats), 1e-12, "L at (0,0,-4), nothing in the way");
        assertEquals(2, stats.shadowRays, "a shadow ray per light");
        assertEquals(0, stats.shadowRaysBlocked, "none blocked");
    }

    @Test
    void shadowedLightContributesNothing() {
        Scene scene = base(SHINY).ambient(IA).add(L1).add(L2).add(BLOCKS_L2).build();
        RenderStats stats = new RenderStats();
        // ambient + light 1 only: (0.02 + 0.9, 0.06 + 0.4, 0.2 + 0.15)
        assertColor(new Color(0.92, 0.46, 0.35), shade(scene, AXIS, Mode.FULL, stats), 1e-12,
                "light 2 blocked by " + BLOCKS_L2);
        assertEquals(2, stats.shadowRays, "shadow rays");
        assertEquals(1, stats.shadowRaysBlocked, "blocked shadow rays");
        assertEquals(1, stats.specularEvaluations, "no specular term for the blocked light");
    }

    @Test
    void lightBehindTheSurfaceContributesNothingNotEvenSpecular() {
        // From x = (0,0,-4): l ~ (10, 0, -0.5)/|..|, so n·l < 0; yet n·h > 0, so a specular term
        // computed anyway would not be zero.
        PointLight behind = new PointLight(new Vec3(10, 0, -4.5), Color.WHITE, true, "behind");
        Vec3 l = behind.position.minus(new Vec3(0, 0, -4)).normalize();
        Vec3 h = new Vec3(0, 0, 1).plus(l).normalize();
        assertTrue(l.z < 0 && h.z > 0, "set-up: n·l < 0 but n·h > 0");
        Scene scene = base(SHINY).add(behind).add(ASIDE).build();
        RenderStats stats = new RenderStats();
        assertEquals(Color.BLACK, shade(scene, AXIS, Mode.FULL, stats), "light behind the surface");
        assertEquals(0, stats.specularEvaluations, "no specular term evaluated");
        assertEquals(0, stats.shadowRays, "no shadow ray toward a light behind the surface");
    }

    @Test
    void normalFacesTheRayOnTheBackSide() {
        // Camera inside the sphere: the ray hits the far side, outward normal (0,0,-1), facing (0,0,1).
        Material matte = new Lambertian(new Color(0.5, 0.25, 1), Color.BLACK, "matte");
        PointLight inside = new PointLight(new Vec3(0, 0, -5.5), new Color(1, 1, 0.5), true, "inside");
        Scene scene = base(matte).add(inside).build();
        Ray fromCentre = new Ray(new Vec3(0, 0, -5), new Vec3(0, 0, -1));
        IntersectionRecord rec = new IntersectionRecord();
        scene.surfaces.get(0).intersect(rec, fromCentre);
        assertEquals(new Vec3(0, 0, -1), rec.normal, "record keeps the outward normal");
        // facing n = (0,0,1), l = (0,0,1): L = kd·I·1
        assertColor(new Color(0.5, 0.25, 0.5), shade(scene, fromCentre, Mode.FULL), 1e-12,
                "back side lit from inside");
        assertColor(new Color(0.5, 0.5, 1), shade(scene, fromCentre, Mode.NORMALS), 1e-12,
                "NORMALS shows the facing normal (0,0,1)");
        Vec3 flipped = Shader.facing(new Vec3(0, 0, -1), new Vec3(0, 0, -1));
        assertEquals(1.0, flipped.z, "back side: flipped to (0,0,1), got " + flipped);
        assertEquals(0.0, flipped.x * flipped.x + flipped.y * flipped.y, "flipped: " + flipped);
        assertEquals(new Vec3(0, 0, 1), Shader.facing(new Vec3(0, 0, 1), new Vec3(0, 0, -1)), "front side: kept");
        assertEquals(new Vec3(0.6, 0, 0.8), Shader.facing(new Vec3(0.6, 0, 0.8), new Vec3(1, 0, 0)).negate(),
                "d·n = 0.6 > 0: the ray meets the back side, flipped");
    }

    @Test
    void unlitMaterialsIgnoreLights() {
        Color c = new Color(0.3, 0.7, 0.1);
        Scene flat = base(new FlatColor(c, "flat")).ambient(IA).add(L1).add(L2).add(BLOCKS_L2).build();
        assertEquals(c, shade(flat, AXIS, Mode.FULL), "flat colour whatever the lights");
        Scene normals = base(new NormalColor("normals")).ambient(IA).add(L1).add(L2).build();
        assertColor(new Color(0.5, 0.5, 1), shade(normals, AXIS, Mode.FULL), 1e-12, "normal (0,0,1) as colour");
        Ray side = new Ray(Vec3.ZERO, new Vec3(1, 0, -5));  // hits the sphere at (1,0,-5)? close to it
        IntersectionRecord rec = new IntersectionRecord();
        normals.surfaces.get(0).intersect(rec, side);
        assertColor(NormalColor.of(rec.normal), shade(normals, side, Mode.FULL), 1e-12, "normal colour off axis");
    }

    @Test
    void debugModes() {
        Scene scene = base(SHINY).ambient(IA).add(L1).add(L2).add(ASIDE).build();
        // DIFFUSE: kd·I1·1 + kd·I2·0.8
        assertColor(new Color(0.696, 0.41, 0.356), shade(scene, AXIS, Mode.DIFFUSE), 1e-12, "DIFFUSE");
        // SPECULAR: ks·I1·1 + ks·I2·0.9
        assertColor(new Color(0.354, 0.258, 0.194), shade(scene, AXIS, Mode.SPECULAR), 1e-12, "SPECULAR");
        assertEquals(Color.WHITE, shade(scene, AXIS, Mode.SHADOWS), "SHADOWS: both lights visible");
        assertColor(new Color(0.5, 0.5, 1), shade(scene, AXIS, Mode.NORMALS), 1e-12, "NORMALS");

        Scene oneBlocked = base(SHINY).ambient(IA).add(L1).add(L2).add(BLOCKS_L2).build();
        assertColor(new Color(0.6, 0.25, 0.1), shade(oneBlocked, AXIS, Mode.DIFFUSE), 1e-12, "DIFFUSE, light 2 blocked");
        assertColor(new Color(0.3, 0.15, 0.05), shade(oneBlocked, AXIS, Mode.SPECULAR), 1e-12, "SPECULAR, light 2 blocked");
        assertColor(new Color(0.5, 0.5, 0.5), shade(oneBlocked, AXIS, Mode.SHADOWS), 1e-12, "SHADOWS: one of two lights");

        Scene bothBlocked = base(SHINY).ambient(IA).add(L1).add(L2).add(BLOCKS_L1).add(BLOCKS_L2).build();
        assertEquals(Color.BLACK, shade(bothBlocked, AXIS, Mode.SHADOWS), "SHADOWS: all lights blocked");
        assertEquals(Color.BLACK, shade(bothBlocked, AXIS, Mode.DIFFUSE), "DIFFUSE: all lights blocked");
        assertColor(KA.times(IA), shade(bothBlocked, AXIS, Mode.FULL), 1e-12, "FULL: only ambient left");
    }

    @Test
    void depthIsGreyAndDarkerFartherAway() {
        Scene scene = base(SHINY).add(new Sphere(new Vec3(3, 0, -12), 1, SHINY, "far")).add(L1).build();
        Color near = shade(scene, AXIS, Mode.DEPTH);
        Color far = shade(scene, new Ray(Vec3.ZERO, new Vec3(3, 0, -12)), Mode.DEPTH);
        for (Color c : new Color[] {near, far}) {
            assertTrue(c.r == c.g && c.g == c.b, "DEPTH is grey: " + c);
            assertTrue(c.r >= 0 && c.r <= 1, "DEPTH in [0, 1]: " + c);
        }
        assertTrue(near.r > far.r, "nearer is whiter: near " + near + " (t=4), far " + far + " (about 11.4)");
        assertTrue(near.r > 0.8, "the nearest hit is almost white: " + near);
        assertTrue(near.r - far.r > 0.3, "about 7.4 units deeper is clearly darker: near " + near + ", far " + far);
    }

    /** Random rays and lights, against the sum written out independently with its own quadratic. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4})
    void randomPointsMatchTheSum(long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        Vec3 c = new Vec3(0, 0, -5);
        double radius = 1;
        for (int i = 0; i < 200; i++) {
            Color kd = new Color(r.nextDouble(), r.nextDouble(), r.nextDouble());
            Color ks = new Color(r.nextDouble(), r.nextDouble(), r.nextDouble());
            Color ka = new Color(r.nextDouble(), r.nextDouble(), r.nextDouble());
            Color ia = new Color(r.nextDouble(0, 0.3), r.nextDouble(0, 0.3), r.nextDouble(0, 0.3));
            double p = r.nextDouble(1, 100);
            PointLight[] lights = new PointLight[2];
            for (int k = 0; k < 2; k++) {
                lights[k] = new PointLight(new Vec3(r.nextDouble(-10, 10), r.nextDouble(-10, 10), r.nextDouble(-4, 5)),
                        new Color(r.nextDouble(), r.nextDouble(), r.nextDouble()), true, "L" + k);
            }
            Scene scene = base(new BlinnPhong(kd, ks, p, ka, "m")).ambient(ia).add(lights[0]).add(lights[1]).build();
            Vec3 d = new Vec3(r.nextDouble(-0.18, 0.18), r.nextDouble(-0.18, 0.18), -1).times(r.nextDouble(0.5, 3));
            // closest root of |t d - c|^2 = r^2 (eye at the origin)
            double a = d.dot(d);
            double b = d.dot(c);
            double disc = b * b - a * (c.dot(c) - radius * radius);
            if (disc < 0) {
                continue;
            }
            double t = (b - Math.sqrt(disc)) / a;
            Vec3 x = d.times(t);
            Vec3 n = x.minus(c).times(1 / radius);
            Vec3 v = d.normalize().negate();
            Color expected = ka.times(ia);
            for (PointLight light : lights) {
                Vec3 l = light.position.minus(x).normalize();
                double nl = n.dot(l);
                if (nl <= 0) {
                    continue;
                }
                Vec3 h = l.plus(v).normalize();
                expected = expected.plus(kd.times(light.intensity).times(nl))
                        .plus(ks.times(light.intensity).times(Math.pow(Math.max(0, n.dot(h)), p)));
            }
            Ray ray = new Ray(Vec3.ZERO, d);
            assertColor(expected, shade(scene, ray, Mode.FULL), 1e-9,
                    "seed " + seed + ", case " + i + ", ray " + ray + ", x=" + x + ", p=" + p);
        }
    }

    // A light exactly at the shaded point: l = 0/0 is NaN, and NaN must not get through n·l > 0.

    @ParameterizedTest(name = "light casts shadows: {0}")
    @ValueSource(booleans = {false, true})
    void lightExactlyAtThePointContributesNothing(boolean shadows) {
        PointLight atX = new PointLight(new Vec3(0, 0, -4), I1, shadows, "at x");
        Scene scene = base(SHINY).ambient(IA).add(atX).build();
        Color c = shade(scene, AXIS, Mode.FULL);
        assertTrue(c.isFinite(), "a light exactly at x must not make the pixel NaN: " + c);
        assertColor(KA.times(IA), c, 0, "only ka·Ia: the light at x has no direction and adds nothing");
        // One pixel, whose centre ray is the axis: it sees exactly x = (0, 0, −4).
        Scene onePixel = scene.toBuilder().size(1, 1)
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 1, 1)).build();
        for (RenderPlan plan : new RenderPlan[] {new RenderPlan(onePixel), RenderPlan.bruteForce(onePixel)}) {
            Renderer r = new Renderer(onePixel, plan, Mode.FULL);
            Image image = r.render(1, null);
            assertEquals(0, r.stats().nonFinitePixels, "NaN pixels (brute force: " + plan.bruteForce + ")");
            assertColor(KA.times(IA), image.get(0, 0), 0, "the pixel seeing x (brute force: " + plan.bruteForce + ")");
        }
    }
}
