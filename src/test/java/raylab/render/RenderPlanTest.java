package raylab.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.camera.PerspectiveCamera;
import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.FlatColor;
import raylab.material.Lambertian;
import raylab.material.Material;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.scene.Effects;
import raylab.scene.Scene;
import raylab.surface.Box;
import raylab.surface.Bvh;
import raylab.surface.Group;
import raylab.surface.Mesh;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/** "Simulate only what the scene calls for", proven by renders with counters and trap materials. */
class RenderPlanTest {
    static final Color KD = new Color(0.7, 0.6, 0.5);
    static final Color KA = new Color(0.2, 0.2, 0.2);

    /** Lambertian whose specular code must never run. */
    static final class MatteTrap extends Lambertian {
        MatteTrap(Color ka) {
            super(KD, ka, "matte trap");
        }

        @Override
        public Color specular(Vec3 n, Vec3 l, Vec3 v, Color I) {
            throw new IllegalStateException("specular() called on a Lambertian material");
        }
    }

    /** Blinn-Phong with ks = 0: its specular code must never run. */
    static final class DullPhongTrap extends BlinnPhong {
        DullPhongTrap() {
            super(KD, Color.BLACK, 20, KA, "dull phong trap");
        }

        @Override
        public Color specular(Vec3 n, Vec3 l, Vec3 v, Color I) {
            throw new IllegalStateException("specular() called although ks = 0");
        }
    }

    /** A material whose ka must not be asked for. */
    static final class NoKaTrap extends Lambertian {
        NoKaTrap() {
            super(KD, KA, "no-ka trap");
        }

        @Override
        public Color ka() {
            throw new IllegalStateException("ka() called although the ambient term is off");
        }
    }

    static PointLight light(double x, double y, double z, boolean shadows) {
        return new PointLight(new Vec3(x, y, z), new Color(0.8, 0.8, 0.8), shadows, "light@" + x + "," + y + "," + z);
    }

    /** A sphere resting over a floor box, seen from the front; two materials given. */
    static Scene.Builder twoSurfaces(Material sphere, Material floor) {
        return Scene.builder().size(24, 16)
                .camera(new PerspectiveCamera(new Vec3(0, 1, 6), new Vec3(0, -0.2, -1), new Vec3(0, 1, 0), 50, 24, 16))
                .add(new Sphere(new Vec3(0, 1, 0), 1, sphere, "ball"))
                .add(new Box(new Vec3(-5, -0.5, -5), new Vec3(5, 0, 5), floor, "floor"));
    }

    static Renderer render(Scene scene) {
        Renderer r = new Renderer(scene);
        r.render(2, null);
        return r;
    }

    // (1) specular only for materials with ks > 0

    @Test
    void lambertianOnlySceneNeverEvaluatesSpecular() {
        MatteTrap m = new MatteTrap(KA);
        Scene scene = twoSurfaces(m, m).ambient(new Color(0.1, 0.1, 0.1)).add(light(3, 5, 4, true)).build();
        Renderer r = render(scene);
        assertFalse(r.plan().specular, "plan: no specular for a Lambertian-only scene");
        assertEquals(0, r.stats().specularEvaluations, "no specular evaluations");
        assertTrue(r.stats().eyeRays > 0, "the scene was rendered");
    }

    @Test
    void blinnPhongWithZeroKsNeverEvaluatesSpecular() {
        DullPhongTrap m = new DullPhongTrap();
        Scene scene = twoSurfaces(m, new MatteTrap(KA)).add(light(3, 5, 4, true)).add(light(-4, 3, 2, true)).build();
        Renderer r = render(scene);
        assertFalse(r.plan().specular, "plan: ks = 0 everywhere");
        assertEquals(0, r.stats().specularEvaluations, "no specular evaluations");
    }

    @Test
    void materialWithKsEvaluatesSpecularOnlyForItself() {
        BlinnPhong shiny = new BlinnPhong(KD, new Color(0.5, 0.5, 0.5), 30, KA, "shiny");
        Scene scene = twoSurfaces(shiny, new DullPhongTrap()).add(light(3, 5, 4, true)).build();
        Renderer r = render(scene);
        assertTrue(r.plan().specular, "plan: one material has ks > 0");
        assertTrue(r.stats().specularEvaluations > 0, "specular evaluated for the shiny sphere");
        assertTrue(r.stats().specularEvaluations < r.stats().eyeRays,
                "but not for the floor (ks = 0): " + r.stats().specularEvaluations + " of " + r.stats().eyeRays);
    }

    @Test
    void specularSwitchedOffByTheScene() {
        BlinnPhong shinyTrap = new BlinnPhong(KD, new Color(0.5, 0.5, 0.5), 30, KA, "shiny trap") {
            @Override
            public Color specular(Vec3 n, Vec3 l, Vec3 v, Color I) {
                throw new IllegalStateException("specular() called although the scene switched it off");
            }
        };
        Scene scene = twoSurfaces(shinyTrap, shinyTrap).add(light(3, 5, 4, true))
                .effects(new Effects(null, false, null, null)).build();
        Renderer r = render(scene);
        assertFalse(r.plan().specular, "plan: specular off by the scene");
        assertEquals(0, r.stats().specularEvaluations, "no specular evaluations");
    }

    // (2), (3) shadow rays only where a light casts shadows and something can block it

    @Test
    void noShadowRaysWhenNoLightCastsShadows() {
        Lambertian m = new Lambertian(KD, KA, "m");
        Scene scene = twoSurfaces(m, m).add(light(3, 5, 4, false)).add(light(-3, 5, 4, false)).build();
        Renderer r = render(scene);
        assertArrayEquals(new boolean[] {false, false}, r.plan().shadows, "plan: no shadows per light");
        assertEquals(0, r.stats().shadowRays, "no shadow rays");
    }

    @Test
    void noShadowRaysWhenTheSceneSwitchesThemOff() {
        Lambertian m = new Lambertian(KD, KA, "m");
        Scene scene = twoSurfaces(m, m).add(light(3, 5, 4, true))
                .effects(new Effects(false, null, null, null)).build();
        Renderer r = render(scene);
        assertFalse(r.plan().anyShadows(), "plan: shadows off");
        assertEquals(0, r.stats().shadowRays, "no shadow rays");
    }

    @Test
    void shadowRaysOnlyTowardLightsThatCastShadows() {
        Lambertian m = new Lambertian(KD, KA, "m");
        Scene scene = twoSurfaces(m, m).add(light(3, 5, 4, true)).add(light(-3, 5, 4, false)).build();
        Renderer r = render(scene);
        assertArrayEquals(new boolean[] {true, false}, r.plan().shadows, "plan: shadows for the first light only");
        assertTrue(r.stats().shadowRays > 0, "shadow rays toward the first light");
        assertTrue(r.stats().shadowRaysBlocked > 0, "the ball shadows the floor");
        // every eye ray hits something lit by light 1 at most once: one shadow ray per eye ray at most
        assertTrue(r.stats().shadowRays <= r.stats().eyeRays,
                "one light with shadows: at most one shadow ray per eye ray, got " + r.stats().shadowRays
                        + " for " + r.stats().eyeRays);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"sphere", "box"})
    void singleConvexSurfaceTracesNoShadowRays(String kind) {
        Lambertian m = new Lambertian(KD, KA, "m");
        Surface s = kind.equals("sphere") ? new Sphere(new Vec3(0, 0, -4), 1, m, "s")
                : new Box(new Vec3(-1, -1, -5), new Vec3(1, 1, -3), m, "b");
        Scene scene = Scene.builder().size(16, 16)
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 16, 16))
                .add(s).add(light(2, 3, 0, true)).add(light(-2, -1, -2, true)).build();
        Renderer r = render(scene);
        assertFalse(r.plan().anyShadows(), "plan: a single convex " + kind + " seen from outside cannot shadow itself");
        assertEquals(0, r.stats().shadowRays, "no shadow rays for a single " + kind);
    }

    static boolean sameImage(Image a, Image b) {
        for (int y = 0; y < a.height; y++) {
            for (int x = 0; x < a.width; x++) {
                if (!a.get(x, y).equals(b.get(x, y))) {
                    return false;
                }
            }
        }
        return true;
    }

    /** From inside, the far wall blocks a light outside for every point of the near wall. */
    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"sphere", "box"})
    void cameraInsideASingleConvexSurfaceTracesShadowRays(String kind) {
        Lambertian m = new Lambertian(KD, KA, "m");
        Surface s = kind.equals("sphere") ? new Sphere(Vec3.ZERO, 5, m, "room")
                : new Box(new Vec3(-5, -5, -5), new Vec3(5, 5, 5), m, "room");
        Scene scene = Scene.builder().size(16, 12).ambient(new Color(0.1, 0.1, 0.1))
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 90, 16, 12))
                .add(s).add(light(0, 0, 9, true)).build();
        Renderer r = render(scene);
        assertTrue(r.plan().anyShadows(), "camera inside the " + kind + ": shadows must be on");
        assertLine(r.plan().describe(), "shadows of", l -> l.endsWith(" on"), "saying on");
        assertEquals(r.stats().shadowRays, r.stats().shadowRaysBlocked,
                "every shadow ray toward the light outside is blocked by the " + kind + " itself");
        // Every pixel is in shadow: ka·Ia only.
        Image img = new Renderer(scene).render(1, null);
        Color ambient = KA.times(new Color(0.1, 0.1, 0.1));
        assertEquals(ambient, img.get(8, 6), "a point of the inner wall sees only ka·Ia");
        Image brute = new Renderer(scene, RenderPlan.bruteForce(scene), Mode.FULL).render(1, null);
        assertTrue(sameImage(img, brute), "plan and brute force give the same image");
    }

    @Test
    void orthographicCameraOrEyeOnTheSurfaceGetsNoConvexityShortcut() {
        Lambertian m = new Lambertian(KD, KA, "m");
        Sphere ball = new Sphere(new Vec3(0, 0, -4), 1, m, "s");
        Scene ortho = Scene.builder().size(8, 8)
                .camera(new raylab.camera.OrthographicCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 3, 8, 8))
                .add(ball).add(light(2, 3, 0, true)).build();
        assertTrue(new RenderPlan(ortho).anyShadows(), "orthographic rays start on a rectangle: no shortcut");
        Scene onSurface = Scene.builder().size(8, 8)
                .camera(new PerspectiveCamera(new Vec3(0, 0, -3), new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 8, 8))
                .add(ball).add(light(2, 3, 0, true)).build();
        assertTrue(new RenderPlan(onSurface).anyShadows(), "eye exactly on the sphere: no shortcut");
    }

    @Test
    void bruteForcePlanLeavesNothingOut() {
        BlinnPhong dull = new BlinnPhong(KD, Color.BLACK, 20, KA, "dull");
        List<Triangle> tris = List.of(
                new Triangle(new Vec3(-2, -1, -4), new Vec3(2, -1, -4), new Vec3(0, 2, -4), dull, "t0"),
                new Triangle(new Vec3(-0.3, -0.3, -2), new Vec3(0.3, -0.3, -2), new Vec3(0, 0.3, -2), dull, "t1"));
        Scene scene = Scene.builder().size(8, 8)
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 8, 8))
                .add(new Sphere(new Vec3(0, 0, -10), 1, dull, "s")).add(new Mesh(tris, "mesh"))
                .add(light(1, 1, 0, true)).add(light(-1, 1, 0, false))
                .effects(new Effects(null, null, null, true)).build();
        RenderPlan brute = RenderPlan.bruteForce(scene);
        assertTrue(brute.bruteForce && brute.lighting && brute.ambient && brute.specular, "every effect on");
        assertArrayEquals(new boolean[] {true, false}, brute.shadows,
                "a shadow ray toward every light that casts shadows (the scene's own switch is kept)");
        assertFalse(brute.acceleration, "no BVH, even when the scene asks for one");
        Surface root = brute.root(scene);
        assertInstanceOf(Group.class, root, "a linear group");
        assertEquals(List.of("s", "t0", "t1"), ((Group) root).members().stream().map(Surface::name).toList(),
                "the mesh split into its triangles, in order");
        assertLine(brute.describe(), "brute force", l -> l.contains("off"), "saying every shortcut is off");
        Renderer r = new Renderer(scene, brute, Mode.FULL);
        r.render(1, null);
        assertTrue(r.stats().specularEvaluations > 0, "specular evaluated although ks = 0");
    }

    @Test
    void singleNonConvexSurfaceDoesTraceShadowRays() {
        Lambertian m = new Lambertian(KD, KA, "m");
        List<Triangle> tris = List.of(
                new Triangle(new Vec3(-2, -1, -4), new Vec3(2, -1, -4), new Vec3(0, 2, -4), m, "back"),
                new Triangle(new Vec3(-0.3, -0.3, -2), new Vec3(0.3, -0.3, -2), new Vec3(0, 0.3, -2), m, "front"));
        Scene scene = Scene.builder().size(16, 16)
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 16, 16))
                .add(new Mesh(tris, "mesh")).add(light(0, 0, 0, true)).build();
        Renderer r = render(scene);
        assertTrue(r.plan().anyShadows(), "a mesh is not convex: shadows on");
        assertTrue(r.stats().shadowRays > 0, "shadow rays traced");
    }

    // (4) ambient only when Ia and some ka are non-zero

    @Test
    void ambientOffWhenIaIsBlackAndKaIsNeverAsked() {
        NoKaTrap m = new NoKaTrap();
        Scene scene = twoSurfaces(m, m).ambient(Color.BLACK).add(light(3, 5, 4, true)).build();
        Renderer r = render(scene);
        assertFalse(r.plan().ambient, "plan: Ia = 0, no ambient term");
    }

    @Test
    void ambientOffWhenSwitchedOffAndKaIsNeverAsked() {
        NoKaTrap m = new NoKaTrap();
        Scene scene = twoSurfaces(m, m).ambient(new Color(0.3, 0.3, 0.3)).add(light(3, 5, 4, true))
                .effects(new Effects(null, null, false, null)).build();
        Renderer r = render(scene);
        assertFalse(r.plan().ambient, "plan: ambient switched off");
    }

    @Test
    void ambientOffWhenEveryKaIsBlack() {
        Lambertian m = new Lambertian(KD, Color.BLACK, "no ka");
        Scene scene = twoSurfaces(m, new FlatColor(Color.WHITE, "flat")).ambient(new Color(0.3, 0.3, 0.3))
                .add(light(3, 5, 4, true)).build();
        assertFalse(new RenderPlan(scene).ambient, "plan: no lit material has ka > 0");
    }

    @Test
    void ambientOnAddsKaTimesIa() {
        Lambertian m = new Lambertian(KD, new Color(0.5, 0.25, 1), "m");
        Scene dark = twoSurfaces(m, m).build(); // no lights, no ambient: all black
        Scene lit = dark.toBuilder().ambient(new Color(0.2, 0.4, 0.1)).build();
        assertFalse(new RenderPlan(dark).ambient, "plan: Ia = 0");
        Renderer r = new Renderer(lit);
        assertTrue(r.plan().ambient, "plan: Ia and ka non-zero");
        Image img = r.render(1, null);
        // pixel in the middle sees the ball: only ka·Ia = (0.1, 0.1, 0.1)
        Color c = img.get(12, 8);
        assertEquals(0.1, c.r, 1e-15, "red of ka o Ia at the ball: " + c);
        assertEquals(0.1, c.g, 1e-15, "green of ka o Ia at the ball: " + c);
        assertEquals(0.1, c.b, 1e-15, "blue of ka o Ia at the ball: " + c);
    }

    // (5) eye rays

    @ParameterizedTest(name = "spp {0}")
    @ValueSource(ints = {1, 4, 9, 3})
    void eyeRaysAreSamplesTimesPixels(int spp) {
        Lambertian m = new Lambertian(KD, KA, "m");
        Scene scene = twoSurfaces(m, m).add(light(3, 5, 4, true)).samplesPerPixel(spp).build();
        Renderer r = render(scene);
        assertEquals(spp, r.plan().samplesPerPixel, "plan samples");
        assertEquals((long) spp * 24 * 16, r.stats().eyeRays, spp + " samples x 24 x 16 pixels");
    }

    // (6) acceleration

    static Scene spheres(int n, Effects effects) {
        Lambertian m = new Lambertian(KD, KA, "m");
        Scene.Builder b = Scene.builder().size(8, 8)
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 8, 8))
                .effects(effects);
        for (int i = 0; i < n; i++) {
            b.add(new Sphere(new Vec3(i % 5 - 2, i / 5 - 2, -10 - i), 0.4, m, "s" + i));
        }
        return b.build();
    }

    @Test
    void accelerationFromTheThresholdOn() {
        int t = RenderPlan.ACCELERATION_THRESHOLD;
        Scene below = spheres(t - 1, Effects.AUTO);
        RenderPlan pb = new RenderPlan(below);
        assertFalse(pb.acceleration, (t - 1) + " primitives: linear");
        assertInstanceOf(Group.class, pb.root(below), "root below the threshold");
        Scene at = spheres(t, Effects.AUTO);
        RenderPlan pa = new RenderPlan(at);
        assertTrue(pa.acceleration, t + " primitives: BVH");
        assertInstanceOf(Bvh.class, pa.root(at), "root at the threshold");
        Scene one = spheres(1, Effects.AUTO);
        Surface oneRoot = new RenderPlan(one).root(one);
        assertTrue(oneRoot == one.surfaces.get(0) || oneRoot instanceof Group,
                "a single surface: itself or a linear group as root, got " + oneRoot.getClass().getSimpleName());
    }

    @Test
    void explicitAccelerationOverridesTheCount() {
        Scene manyOff = spheres(100, new Effects(null, null, null, false));
        RenderPlan off = new RenderPlan(manyOff);
        assertFalse(off.acceleration, "switched off with 100 primitives");
        assertInstanceOf(Group.class, off.root(manyOff), "root when switched off");
        Scene fewOn = spheres(2, new Effects(null, null, null, true));
        RenderPlan on = new RenderPlan(fewOn);
        assertTrue(on.acceleration, "switched on with 2 primitives");
        assertInstanceOf(Bvh.class, on.root(fewOn), "root when switched on");
    }

    @Test
    void meshTrianglesCountAsPrimitives() {
        Lambertian m = new Lambertian(KD, KA, "m");
        List<Triangle> tris = new ArrayList<>();
        for (int i = 0; i < RenderPlan.ACCELERATION_THRESHOLD; i++) {
            tris.add(new Triangle(new Vec3(i, 0, -5), new Vec3(i + 1, 0, -5), new Vec3(i, 1, -5), m, "t" + i));
        }
        Scene scene = Scene.builder()
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 8, 8))
                .add(new Mesh(tris, "mesh")).build();
        RenderPlan plan = new RenderPlan(scene);
        assertTrue(plan.acceleration, "one mesh of " + tris.size() + " triangles is over the threshold");
        assertInstanceOf(Bvh.class, plan.root(scene), "root");
    }

    // (7) describe

    static void assertLine(List<String> lines, String what, Predicate<String> test, String expected) {
        assertTrue(lines.stream().anyMatch(l -> l.contains(what) && test.test(l)),
                "describe() must have a '" + what + "' line " + expected + "; got:\n" + String.join("\n", lines));
    }

    @Test
    void describeMentionsEveryDecisionWithItsReason() {
        BlinnPhong shiny = new BlinnPhong(KD, new Color(0.5, 0.5, 0.5), 30, KA, "shiny");
        PointLight sun = new PointLight(new Vec3(3, 5, 4), Color.WHITE, true, "sun");
        PointLight lamp = new PointLight(new Vec3(-3, 5, 4), Color.WHITE, false, "lamp");
        Scene on = twoSurfaces(shiny, shiny).ambient(new Color(0.1, 0.1, 0.1)).add(sun).add(lamp)
                .samplesPerPixel(4).build();
        List<String> d = new RenderPlan(on).describe();
        assertLine(d, "lighting", l -> l.contains("2 light"), "counting 2 lights");
        assertLine(d, "ambient", l -> l.contains("on"), "saying on");
        assertLine(d, "specular", l -> l.contains("on"), "saying on");
        assertLine(d, "shadows of sun", l -> l.contains("on"), "saying on");
        assertLine(d, "shadows of lamp", l -> l.contains("casts no shadows"), "giving the reason");
        assertLine(d, "samples", l -> l.contains("4"), "with 4 per pixel");
        assertLine(d, "acceleration", l -> l.contains("off") && l.contains("2"), "off for 2 primitives");

        Lambertian matte = new Lambertian(KD, Color.BLACK, "matte");
        Scene off = Scene.builder()
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 8, 8))
                .add(new Sphere(new Vec3(0, 0, -4), 1, matte, "s")).add(sun).build();
        List<String> d2 = new RenderPlan(off).describe();
        assertLine(d2, "ambient", l -> l.contains("Ia is zero"), "with the reason Ia = 0");
        assertLine(d2, "specular", l -> l.contains("ks"), "with the reason ks = 0");
        assertLine(d2, "shadows of sun", l -> l.contains("convex"), "with the convexity reason");
        assertLine(d2, "samples", l -> l.contains("1 per pixel"), "with 1 per pixel");

        Scene noLights = twoSurfaces(matte, matte).build();
        assertLine(new RenderPlan(noLights).describe(), "lighting", l -> l.contains("no lights"), "off: no lights");
        Scene unlit = twoSurfaces(new FlatColor(Color.WHITE, "f"), new FlatColor(Color.WHITE, "f")).add(sun).build();
        assertLine(new RenderPlan(unlit).describe(), "lighting", l -> l.contains("no material"), "off: unlit");
        assertLine(new RenderPlan(spheres(40, Effects.AUTO)).describe(), "acceleration",
                l -> l.contains("BVH") && l.contains("40"), "BVH over 40 primitives");
    }
}
