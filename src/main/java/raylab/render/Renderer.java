package raylab.render;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.function.IntConsumer;

import raylab.math.Color;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.scene.Sampler;
import raylab.scene.Scene;
import raylab.surface.Surface;

/**
 * Renders a scene by its plan, in square tiles shared among threads.
 *
 * <p>Each pixel depends only on the scene and its own coordinates (samples inside a pixel come
 * from a random generator seeded by the pixel's position), so the image is bit for bit the same
 * whatever the number of threads or the order in which tiles finish.
 *
 * <p>Scheduling is work stealing over tiles: each thread owns a contiguous run of tiles (row-major,
 * so neighbouring tiles share cache) and takes them from its own cursor, which no other thread
 * touches until it runs out of its own tiles and steals from the others' cursors. The cursors sit
 * 64 bytes apart, so the hot path shares no mutable counter.
 */
public final class Renderer {
    /** Tile edge in pixels. */
    public static final int TILE = 16;

    private final Scene scene;
    private final RenderPlan plan;
    private final Surface root;
    private final Mode mode;
    private final long buildNanos;
    private RenderStats stats = new RenderStats();
    private long renderNanos;

    public Renderer(Scene scene, RenderPlan plan, Mode mode) {
        this.scene = scene;
        this.plan = plan;
        this.mode = mode;
        long t0 = System.nanoTime();
        this.root = plan.root(scene);
        this.buildNanos = System.nanoTime() - t0;
    }

    public Renderer(Scene scene) {
        this(scene, new RenderPlan(scene), Mode.FULL);
    }

    /** The surface rays are traced against (a BVH, a group or the one surface). */
    public Surface root() {
        return root;
    }

    /** Renders with the given number of threads; {@code tileDone} hears each finished tile. */
    public Image render(int threads, IntConsumer tileDone) {
        int tilesX = (scene.width + TILE - 1) / TILE;
        int tilesY = (scene.height + TILE - 1) / TILE;
        int tiles = tilesX * tilesY;
        Image image = new Image(scene.width, scene.height);
        long t0 = System.nanoTime();
        int n = Math.max(1, Math.min(threads, tiles));
        Tiles next = new Tiles(tiles, n);
        List<RenderStats> perThread = new ArrayList<>();
        if (n == 1) {
            RenderStats s = new RenderStats();
            perThread.add(s);
            work(image, next, 0, tilesX, s, tileDone);
        } else {
            ExecutorService pool = Executors.newFixedThreadPool(n, r -> {
                Thread t = new Thread(r, "raylab-render");
                t.setDaemon(true);
                return t;
            });
            try {
                List<Future<?>> futures = new ArrayList<>();
                for (int i = 0; i < n; i++) {
                    RenderStats s = new RenderStats();
                    perThread.add(s);
                    int id = i;
                    futures.add(pool.submit(() -> work(image, next, id, tilesX, s, tileDone)));
                }
                for (Future<?> f : futures) {
                    f.get();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("render interrupted", e);
            } catch (ExecutionException e) {
                next.stop();
                Throwable cause = e.getCause();
                if (cause instanceof RuntimeException re) {
                    throw re;
                }
                if (cause instanceof Error err) {
                    throw err;
                }
                throw new IllegalStateException(cause);
            } finally {
                pool.shutdownNow();
            }
        }
        stats = new RenderStats();
        for (RenderStats s : perThread) {
            stats.add(s);
        }
        renderNanos = System.nanoTime() - t0;
        return image;
    }

    /** Per-thread runs of tile indices with their cursors, 16 ints (64 bytes) apart. */
    private static final class Tiles {
        private final AtomicIntegerArray cursor;
        private final int[] end;

        Tiles(int tiles, int threads) {
            cursor = new AtomicIntegerArray(16 * threads);
            end = new int[threads];
            for (int i = 0; i < threads; i++) {
                cursor.set(16 * i, (int) ((long) tiles * i / threads));
                end[i] = (int) ((long) tiles * (i + 1) / threads);
            }
        }

        /** The next tile for thread {@code self}: its own first, then stolen; −1 when none is left. */
        int next(int self) {
            int n = end.length;
            for (int k = 0; k < n; k++) {
                int owner = self + k < n ? self + k : self + k - n;
                if (cursor.get(16 * owner) < end[owner]) {
                    int tile = cursor.getAndIncrement(16 * owner);
                    if (tile < end[owner]) {
                        return tile;
                    }
                }
            }
            return -1;
        }

        /** No more tiles for anyone (a thread failed). */
        void stop() {
            for (int i = 0; i < end.length; i++) {
                cursor.set(16 * i, end[i]);
            }
        }
    }

    private void work(Image image, Tiles next, int self, int tilesX, RenderStats stats,
            IntConsumer tileDone) {
        Shader shader = new Shader(scene, root, plan, mode);
        IntersectionRecord rec = new IntersectionRecord();
        int tile;
        while ((tile = next.next(self)) >= 0) {
            int x0 = (tile % tilesX) * TILE;
            int y0 = (tile / tilesX) * TILE;
            int x1 = Math.min(scene.width, x0 + TILE);
            int y1 = Math.min(scene.height, y0 + TILE);
            for (int y = y0; y < y1; y++) {
                for (int x = x0; x < x1; x++) {
                    Color c = pixel(x, y, shader, rec, stats);
                    if (!c.isFinite()) {
                        stats.nonFinitePixels++;
                    }
                    image.set(x, y, c);
                }
            }
            if (tileDone != null) {
                tileDone.accept(tile);
            }
        }
    }

    /** The colour of pixel (x, y): one ray through its centre, or the average of its samples. */
    public Color pixel(int x, int y, Shader shader, IntersectionRecord rec, RenderStats stats) {
        int spp = plan.samplesPerPixel;
        if (spp <= 1) {
            return trace(scene.camera.rayThroughPixelCenter(x, y), shader, rec, stats);
        }
        SplittableRandom random = new SplittableRandom(pixelSeed(x, y));
        double r = 0;
        double g = 0;
        double b = 0;
        int k = (int) Math.round(Math.sqrt(spp));
        boolean grid = scene.sampler == Sampler.STRATIFIED && k * k == spp;
        for (int i = 0; i < spp; i++) {
            double sx;
            double sy;
            if (grid) {
                sx = x + ((i % k) + random.nextDouble()) / k;
                sy = y + ((i / k) + random.nextDouble()) / k;
            } else {
                sx = x + random.nextDouble();
                sy = y + random.nextDouble();
            }
            Color c = trace(scene.camera.generateRay(sx, sy), shader, rec, stats);
            r += c.r;
            g += c.g;
            b += c.b;
        }
        return new Color(r / spp, g / spp, b / spp);
    }

    /** The radiance along one eye ray. */
    public Color trace(Ray ray, Shader shader, IntersectionRecord rec, RenderStats stats) {
        stats.eyeRays++;
        rec.reset();
        boolean hit = root.intersect(rec, ray);
        stats.intersectionTests += rec.tests;
        rec.tests = 0;
        if (!hit) {
            return scene.background;
        }
        return shader.shade(ray, rec, stats);
    }

    /** A seed that depends only on the pixel's coordinates. */
    static long pixelSeed(int x, int y) {
        long h = 0x9E3779B97F4A7C15L * (x + 1) + 0xC2B2AE3D27D4EB4FL * (y + 1);
        return h ^ (h >>> 31);
    }

    /** Counters of the last render. */
    public RenderStats stats() {
        return stats;
    }

    /** Time to build the acceleration structure (or group), in nanoseconds. */
    public long buildNanos() {
        return buildNanos;
    }

    /** Wall time of the last render, in nanoseconds. */
    public long renderNanos() {
        return renderNanos;
    }

    public RenderPlan plan() {
        return plan;
    }

    public Scene scene() {
        return scene;
    }
}
