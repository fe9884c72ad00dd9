package raylab.bench;

import java.util.ArrayList;
import java.util.List;

import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Surface;

/**
 * The rays of the shared Embree harness ({@code ../shared/bench/embree/embree_bench.cpp}), traced
 * through raylab's {@link Surface} API: a pinhole camera at (0.3, 0.4, 3.2) looking at the origin,
 * up +y, vertical field of view 40°, one ray through each pixel centre (t from 0); then, for the
 * shadow variant, one ray per hit from the hit point toward the point light (3, 4, 5) with t in
 * [10⁻⁴, 1]. The camera and the ray directions are computed in float with the harness's formulas,
 * then widened to double, so both programs trace the same rays (up to the last bit of a float).
 *
 * <p>Rows are dealt to threads as the harness does (thread i takes rows i, i + T, ...), each thread
 * with its own record and counters, so nothing is shared while tracing.
 */
public final class MeshBench {
    /** A Lambertian grey for meshes loaded by the bench. */
    public static final Lambertian GREY = new Lambertian(new Color(0.8, 0.8, 0.8), Color.BLACK, "m");

    private final Surface scene;
    private final int width;
    private final int height;
    private final float ux, uy, uz, vx, vy, vz, wx, wy, wz, th, tw;
    private static final float EYE_X = 0.3f, EYE_Y = 0.4f, EYE_Z = 3.2f;
    private static final float LIGHT_X = 3, LIGHT_Y = 4, LIGHT_Z = 5;

    /** Counts of one pass. */
    public record Pass(double seconds, long rays, long hits, long occluded, double cpuSeconds) {
        public double mraysPerSecond() {
            return rays / seconds / 1e6;
        }

        /** Rays per second of the tracing threads' CPU time (for a loaded machine). */
        public double mraysPerCpuSecond() {
            return rays / cpuSeconds / 1e6;
        }
    }

    private static final java.lang.management.ThreadMXBean THREADS = java.lang.management.ManagementFactory
            .getThreadMXBean();

    public MeshBench(Surface scene, int width, int height) {
        this.scene = scene;
        this.width = width;
        this.height = height;
        // w = norm(eye − target), u = norm(up × w), v = w × u, as the harness.
        float[] w = norm(EYE_X, EYE_Y, EYE_Z);
        float[] u = norm(1 * w[2] - 0 * w[1], 0 * w[0] - 0 * w[2], 0 * w[1] - 1 * w[0]);
        wx = w[0];
        wy = w[1];
        wz = w[2];
        ux = u[0];
        uy = u[1];
        uz = u[2];
        vx = wy * uz - wz * uy;
        vy = wz * ux - wx * uz;
        vz = wx * uy - wy * ux;
        th = (float) Math.tan(40.f * 3.14159265f / 360.f);
        tw = th * width / height;
    }

    private static float[] norm(float x, float y, float z) {
        float l = (float) Math.sqrt(x * x + y * y + z * z);
        float s = 1 / l;
        return new float[] {x * s, y * s, z * s};
    }

    /** The eye ray through the centre of pixel (x, y), as the harness makes it (in float). */
    public Ray primaryRay(int x, int y) {
        return primaryRay(new Vec3(EYE_X, EYE_Y, EYE_Z), x, y);
    }

    private Ray primaryRay(Vec3 eye, int x, int y) {
        float sx = (2 * (x + 0.5f) / width - 1) * tw;
        float sy = (1 - 2 * (y + 0.5f) / height) * th;
        float dx = ux * sx + vx * sy + wx * -1;
        float dy = uy * sx + vy * sy + wy * -1;
        float dz = uz * sx + vz * sy + wz * -1;
        return new Ray(eye, new Vec3(dx, dy, dz));
    }

    /** One pass over all pixels with {@code threads} threads; shadow rays when {@code shadows}. */
    public Pass run(int threads, boolean shadows) {
        long[][] counts = new long[threads][];
        List<Thread> ts = new ArrayList<>();
        long t0 = System.nanoTime();
        if (threads == 1) {
            counts[0] = rows(0, 1, shadows);
        } else {
            for (int i = 0; i < threads; i++) {
                int id = i;
                Thread t = new Thread(() -> counts[id] = rows(id, threads, shadows), "raylab-bench-" + i);
                t.start();
                ts.add(t);
            }
            for (Thread t : ts) {
                try {
                    t.join();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IllegalStateException("interrupted", e);
                }
            }
        }
        double seconds = (System.nanoTime() - t0) / 1e9;
        long hits = 0;
        long occluded = 0;
        long cpu = 0;
        for (long[] c : counts) {
            hits += c[0];
            occluded += c[1];
            cpu += c[2];
        }
        long rays = (long) width * height + (shadows ? hits : 0);
        return new Pass(seconds, rays, hits, occluded, cpu / 1e9);
    }

    private long[] rows(int first, int step, boolean shadows) {
        long cpu0 = THREADS.getCurrentThreadCpuTime();
        IntersectionRecord rec = new IntersectionRecord();
        IntersectionRecord scratch = new IntersectionRecord();
        Vec3 eye = new Vec3(EYE_X, EYE_Y, EYE_Z);
        long hits = 0;
        long occluded = 0;
        for (int y = first; y < height; y += step) {
            for (int x = 0; x < width; x++) {
                Ray ray = primaryRay(eye, x, y);
                rec.reset();
                if (!scene.intersect(rec, ray)) {
                    continue;
                }
                hits++;
                if (!shadows) {
                    continue;
                }
                float t = (float) rec.t;
                float px = EYE_X + (float) ray.d.x * t;
                float py = EYE_Y + (float) ray.d.y * t;
                float pz = EYE_Z + (float) ray.d.z * t;
                Ray shadow = new Ray(new Vec3(px, py, pz), new Vec3(LIGHT_X - px, LIGHT_Y - py, LIGHT_Z - pz),
                        1e-4f, 1.0);
                if (scene.intersectsAny(shadow, scratch)) {
                    occluded++;
                }
            }
        }
        return new long[] {hits, occluded, THREADS.getCurrentThreadCpuTime() - cpu0};
    }
}
