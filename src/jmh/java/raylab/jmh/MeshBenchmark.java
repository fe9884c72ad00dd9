package raylab.jmh;

import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

import raylab.bench.Icosphere;
import raylab.bench.MeshBench;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Bvh;
import raylab.surface.Mesh;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * Nanoseconds per ray of the packed mesh engine on the Embree harness's mesh (displaced
 * icosphere, level 6 = 81,920 triangles, or level 4): eye rays in a random order, in pixel order
 * and one ray repeated (which separates the cost of the arithmetic from that of cache misses and
 * mispredicted branches), against the generic object tree
 * ({@link Bvh} over {@link Triangle} objects, which is what the student path traces), and per
 * test of the triangle kernels: the packed kernel (a one-triangle mesh) and Triangle.intersect.
 *
 * <pre>
 *   ./mvnw -Pjmh -DskipTests package &amp;&amp; java -jar target/benchmarks.jar MeshBenchmark
 * </pre>
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
@Fork(1)
@State(Scope.Thread)
public class MeshBenchmark {
    static final int RAYS = 4096;

    @Param({"6"})
    int level;

    Mesh mesh;
    Bvh objects;
    Ray[] primary = new Ray[RAYS];
    Ray[] pixelOrder = new Ray[RAYS];
    Ray[] sameRay = new Ray[RAYS];
    Ray[] shadow = new Ray[RAYS];
    Mesh oneTriangle;
    Triangle triangle;
    Ray[] triangleRays = new Ray[RAYS];
    IntersectionRecord rec = new IntersectionRecord();

    @Setup(Level.Trial)
    public void setUp() {
        mesh = new Mesh(Icosphere.triangles(level), MeshBench.GREY, "ico");
        objects = new Bvh(mesh.triangles(), "objects");
        SplittableRandom r = new SplittableRandom(1);
        Vec3 eye = new Vec3(0.3, 0.4, 3.2);
        for (int i = 0; i < RAYS; i++) {
            // Eye rays through the harness's field of view, in a random (incoherent) order.
            Vec3 d = new Vec3(-0.3 + r.nextDouble(-1.2, 1.2), -0.4 + r.nextDouble(-0.9, 0.9), -3.2);
            primary[i] = new Ray(eye, d);
            IntersectionRecord h = new IntersectionRecord();
            Vec3 p = mesh.intersect(h, primary[i]) ? h.point : new Vec3(0, 0, 1.5);
            shadow[i] = new Ray(p, new Vec3(3, 4, 5).minus(p), 1e-4, 1);
        }
        // The harness's eye rays of four whole rows across the middle of the 1024 x 768 image, in
        // pixel order (coherent: neighbours share their path through the tree), and the middle
        // pixel's ray RAYS times (its nodes and triangles stay in cache, every branch repeats).
        MeshBench harness = new MeshBench(mesh, 1024, 768);
        for (int i = 0; i < RAYS; i++) {
            pixelOrder[i] = harness.primaryRay(i % 1024, 382 + i / 1024);
            sameRay[i] = harness.primaryRay(512, 384);
        }
        Vec3 a = new Vec3(-1, -1, 0);
        Vec3 b = new Vec3(1, -1, 0.2);
        Vec3 c = new Vec3(0, 1, -0.1);
        triangle = new Triangle(a, b, c, MeshBench.GREY, "t");
        oneTriangle = new Mesh(java.util.List.of(triangle), "one");
        for (int i = 0; i < RAYS; i++) {
            Vec3 o = new Vec3(r.nextDouble(-2, 2), r.nextDouble(-2, 2), 5);
            triangleRays[i] = new Ray(o, new Vec3(r.nextDouble(-1.5, 1.5), r.nextDouble(-1.5, 1.5), -5).minus(new Vec3(0, 0, 0)));
        }
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int packedClosestHit() {
        return closestHits(mesh, primary);
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int packedPixelOrder() {
        return closestHits(mesh, pixelOrder);
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int packedSameRay() {
        return closestHits(mesh, sameRay);
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int packedAnyHit() {
        int hits = 0;
        for (Ray ray : shadow) {
            hits += mesh.intersectsAny(ray, rec) ? 1 : 0;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int objectTreeClosestHit() {
        return closestHits(objects, primary);
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int packedKernel() {
        return closestHits(oneTriangle, triangleRays);
    }

    @Benchmark
    @OperationsPerInvocation(RAYS)
    public int triangleIntersect() {
        return closestHits(triangle, triangleRays);
    }

    /** Closest hits of the rays on the surface, each traced from a reset record. */
    private int closestHits(Surface surface, Ray[] rays) {
        int hits = 0;
        for (Ray ray : rays) {
            rec.reset();
            hits += surface.intersect(rec, ray) ? 1 : 0;
        }
        return hits;
    }
}
