package raylab.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

import raylab.camera.OrthographicCamera;
import raylab.camera.PerspectiveCamera;
import raylab.course.NotImplemented;
import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.FlatColor;
import raylab.material.Lambertian;
import raylab.material.Material;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.scene.Sampler;
import raylab.scene.Scene;
import raylab.surface.Box;
import raylab.surface.Sphere;
import raylab.surface.Triangle;

/** Renderer: thread-count independence, sample placement, counters, non-finite pixels, errors. */
class RendererTest {
    static Scene busyScene(int spp, Sampler sampler) {
        Material red = new BlinnPhong(new Color(0.7, 0.2, 0.2), new Color(0.4, 0.4, 0.4), 40, new Color(0.1, 0, 0), "red");
        Material grey = new Lambertian(new Color(0.6, 0.6, 0.6), new Color(0.05, 0.05, 0.05), "grey");
        Material blue = new BlinnPhong(new Color(0.1, 0.2, 0.8), new Color(0.2, 0.2, 0.2), 8, Color.BLACK, "blue");
        int w = 50;
        int h = 37; // not multiples of the tile size
        return Scene.builder().size(w, h).samplesPerPixel(spp).sampler(sampler)
                .camera(new PerspectiveCamera(new Vec3(0, 2, 8), new Vec3(0, -0.25, -1), new Vec3(0, 1, 0), 45, w, h))
                .background(new Color(0.05, 0.1, 0.2)).ambient(new Color(0.2, 0.2, 0.2))
                .add(new Box(new Vec3(-6, -1, -6), new Vec3(6, 0, 6), grey, "floor"))
                .add(new Sphere(new Vec3(-1, 1, 0), 1, red, "ball"))
                .add(new Sphere(new Vec3(1.5, 0.6, 1), 0.6, blue, "small ball"))
                .add(new Box(new Vec3(1, 0, -2), new Vec3(2.5, 2, -1), grey, "block"))
                .add(new Triangle(new Vec3(-3, 0, -3), new Vec3(0, 0, -3.5), new Vec3(-1.5, 3, -3.2), blue, "sail"))
                .add(new PointLight(new Vec3(4, 6, 5), new Color(0.8, 0.7, 0.6), true, "key"))
                .add(new PointLight(new Vec3(-5, 3, 2), new Color(0.2, 0.3, 0.5), true, "fill"))
                .build();
    }

    static void assertSameImage(Image expected, Image actual, String what) {
        assertEquals(expected.width, actual.width, what + ": width");
        assertEquals(expected.height, actual.height, what + ": height");
        for (int y = 0; y < expected.height; y++) {
            for (int x = 0; x < expected.width; x++) {
                Color a = expected.get(x, y);
                Color b = actual.get(x, y);
                boolean same = Double.doubleToRawLongBits(a.r) == Double.doubleToRawLongBits(b.r)
                        && Double.doubleToRawLongBits(a.g) == Double.doubleToRawLongBits(b.g)
                        && Double.doubleToRawLongBits(a.b) == Double.doubleToRawLongBits(b.b);
                assertTrue(same, what + ": pixel (" + x + ", " + y + ") is " + b + ", expected " + a);
            }
        }
    }

    @ParameterizedTest(name = "{0}")
    @EnumSource(Sampler.class)
    void imageIsBitIdenticalWhateverTheThreadCount(Sampler sampler) {
        Scene scene = busyScene(4, sampler);
        Renderer one = new Renderer(scene);
        Image reference = one.render(1, null);
        assertTrue(one.stats().shadowRays > 0 && one.stats().shadowRaysBlocked > 0,
                "the scene exercises shadows: " + one.stats().shadowRays + " shadow rays");
        assertTrue(one.stats().specularEvaluations > 0, "the scene exercises specular");
        for (int threads : new int[] {2, 3, 8}) {
            Renderer r = new Renderer(scene);
            assertSameImage(reference, r.render(threads, null), threads + " threads vs 1, " + sampler);
            assertEquals(one.stats().eyeRays, r.stats().eyeRays, threads + " threads: eye rays");
            assertEquals(one.stats().shadowRays, r.stats().shadowRays, threads + " threads: shadow rays");
            assertEquals(one.stats().shadowRaysBlocked, r.stats().shadowRaysBlocked, threads + " threads: blocked");
            assertEquals(one.stats().intersectionTests, r.stats().intersectionTests, threads + " threads: tests");
            assertEquals(one.stats().specularEvaluations, r.stats().specularEvaluations, threads + " threads: specular");
        }
        assertSameImage(reference, new Renderer(scene).render(1, null), "a second render with 1 thread");
    }

    @Test
    void everyTileIsReportedOnce() {
        Scene scene = busyScene(1, Sampler.STRATIFIED);
        int tiles = ((50 + Renderer.TILE - 1) / Renderer.TILE) * ((37 + Renderer.TILE - 1) / Renderer.TILE);
        ConcurrentHashMap<Integer, AtomicInteger> seen = new ConcurrentHashMap<>();
        new Renderer(scene).render(3, t -> seen.computeIfAbsent(t, k -> new AtomicInteger()).incrementAndGet());
        assertEquals(tiles, seen.size(), "tiles reported: " + seen.keySet());
        seen.forEach((t, n) -> assertEquals(1, n.get(), "tile " + t + " reported " + n.get() + " times"));
    }

    @ParameterizedTest(name = "spp {0}")
    @ValueSource(ints = {1, 4, 5, 16})
    void eyeRaysPerPixel(int spp) {
        Renderer r = new Renderer(busyScene(spp, Sampler.STRATIFIED));
        r.render(2, null);
        assertEquals((long) spp * 50 * 37, r.stats().eyeRays, spp + " per pixel over 50 x 37");
        assertEquals(0, r.stats().nonFinitePixels, "no non-finite pixels in a sane scene");
    }

    /** A material that produces NaN radiance. */
    static final class NaNMaterial extends Lambertian {
        NaNMaterial() {
            super(Color.WHITE, Color.BLACK, "nan");
        }

        @Override
        public Color diffuse(Vec3 n, Vec3 l, Color I) {
            return new Color(Double.NaN, 0.5, 0.5);
        }
    }

    @ParameterizedTest(name = "spp {0}")
    @ValueSource(ints = {1, 4})
    void nonFiniteRadianceIsCountedAndDrawnMagenta(int spp) {
        // camera and light at the centre of a sphere: every eye ray hits its inside, lit
        Scene scene = Scene.builder().size(20, 10).samplesPerPixel(spp)
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 90, 20, 10))
                .add(new Sphere(Vec3.ZERO, 10, new NaNMaterial(), "nan sphere"))
                .add(new PointLight(Vec3.ZERO, Color.WHITE, true, "centre")).build();
        Renderer r = new Renderer(scene);
        Image img = r.render(2, null);
        assertEquals(200, r.stats().nonFinitePixels, "all 20 x 10 pixels are NaN, each counted once");
        assertEquals(0xFF00FF, Image.toRgb8(img.get(3, 4)), "NaN pixel drawn magenta");
        assertEquals(0xFF00FF, img.toBufferedImage().getRGB(19, 9) & 0xFFFFFF, "magenta in the picture");
    }

    @ParameterizedTest(name = "{0} threads")
    @ValueSource(ints = {1, 4})
    void studentStubErrorReachesTheCaller(int threads) {
        Material stub = new Lambertian(Color.WHITE, Color.BLACK, "stub") {
            @Override
            public Color diffuse(Vec3 n, Vec3 l, Color I) {
                throw new NotImplemented("lambert", "Lambertian.diffuse");
            }
        };
        Scene scene = Scene.builder().size(40, 40)
                .camera(new PerspectiveCamera(Vec3.ZERO, new Vec3(0, 0, -1), new Vec3(0, 1, 0), 60, 40, 40))
                .add(new Sphere(new Vec3(0, 0, -3), 1, stub, "s"))
                .add(new PointLight(new Vec3(0, 0, 0), Color.WHITE, true, "l")).build();
        NotImplemented e = assertThrows(NotImplemented.class, () -> new Renderer(scene).render(threads, null),
                "the stub's exception, unwrapped");
        assertEquals("lambert", e.milestone(), "milestone named");
    }

    /**
     * Orthographic view, 8x8 pixels of 1x1 world unit: pixel ix covers world x in [ix − 4, ix − 3].
     * A white box from world x = edge on; background black.
     */
    static Image coverage(double edge, int spp, Sampler sampler) {
        Scene scene = Scene.builder().size(8, 8).samplesPerPixel(spp).sampler(sampler)
                .camera(new OrthographicCamera(new Vec3(0, 0, 5), new Vec3(0, 0, -1), new Vec3(0, 1, 0), 8, 8, 8))
                .add(new Box(new Vec3(edge, -10, -1), new Vec3(10, 10, 0), new FlatColor(Color.WHITE, "white"), "box"))
                .build();
        return new Renderer(scene).render(1, null);
    }

    @ParameterizedTest(name = "{0}")
    @EnumSource(Sampler.class)
    void samplesStayInsideTheirPixel(Sampler sampler) {
        Image img = coverage(0, 16, sampler); // edge on the border between pixels 3 and 4
        for (int y = 0; y < 8; y++) {
            for (int x = 0; x < 8; x++) {
                double expected = x >= 4 ? 1 : 0;
                assertEquals(expected, img.get(x, y).r, 0,
                        sampler + ": pixel (" + x + ", " + y + ") must be " + (x >= 4 ? "inside" : "outside") + " the box");
            }
        }
    }

    @ParameterizedTest(name = "spp {0}")
    @ValueSource(ints = {4, 16})
    void stratifiedSamplesSplitAHalfCoveredPixelExactly(int spp) {
        Image img = coverage(0.5, spp, Sampler.STRATIFIED); // edge through the middle of pixel column 4
        for (int y = 0; y < 8; y++) {
            assertEquals(0.5, img.get(4, y).r, 0, "stratified " + spp + ": half of the grid cells of pixel (4, " + y + ")");
            assertEquals(0.0, img.get(3, y).r, 0, "pixel (3, " + y + ")");
            assertEquals(1.0, img.get(5, y).r, 0, "pixel (5, " + y + ")");
        }
        Image random = coverage(0.5, spp, Sampler.RANDOM);
        boolean notHalf = false;
        for (int y = 0; y < 8; y++) {
            double c = random.get(4, y).r;
            assertTrue(c >= 0 && c <= 1, "random coverage in [0, 1]: " + c);
            notHalf |= c != 0.5;
        }
        assertTrue(notHalf, "random samples are not on a grid: some half-covered pixel is not exactly 0.5");
    }
}
