package raylab.jmh;

import java.util.SplittableRandom;
import java.util.concurrent.TimeUnit;

import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;

import raylab.light.PointLight;
import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.numerics.BoxMethods;
import raylab.numerics.ShadowOffsets;
import raylab.numerics.SphereMethods;
import raylab.numerics.TriangleMethods;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.study.EarlierOffsets;
import raylab.surface.Box;
import raylab.surface.Group;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * Nanoseconds per intersection of each method that {@code raylab study} compares, measured by
 * JMH over the same kind of inputs as the study: 1024 (shape, ray) pairs, about half of them hits.
 *
 * <pre>
 *   ./mvnw -Pjmh -DskipTests package &amp;&amp; java -jar target/benchmarks.jar
 * </pre>
 */
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Warmup(iterations = 5, time = 1)
@Measurement(iterations = 5, time = 1)
@Fork(1)
@State(Scope.Thread)
public class IntersectionBenchmark {
    static final int N = 1024;
    static final Lambertian GREY = new Lambertian(Color.WHITE, Color.BLACK, "grey");

    Sphere[] spheres = new Sphere[N];
    Ray[] sphereRays = new Ray[N];
    Triangle[] triangles = new Triangle[N];
    Ray[] triangleRays = new Ray[N];
    Box box;
    Ray[] boxRays = new Ray[N];
    Surface shadowScene;
    PointLight light;
    Vec3[] shadowPoints = new Vec3[N];
    Vec3[] shadowNormals = new Vec3[N];
    IntersectionRecord rec = new IntersectionRecord();

    static Vec3 unit(SplittableRandom r) {
        double z = 2 * r.nextDouble() - 1;
        double phi = 2 * Math.PI * r.nextDouble();
        double s = Math.sqrt(1 - z * z);
        return new Vec3(s * Math.cos(phi), s * Math.sin(phi), z);
    }

    static Vec3 random(SplittableRandom r, double scale) {
        return new Vec3(scale * (2 * r.nextDouble() - 1), scale * (2 * r.nextDouble() - 1), scale * (2 * r.nextDouble() - 1));
    }

    @Setup
    public void setup() {
        SplittableRandom r = new SplittableRandom(20240521L);
        for (int i = 0; i < N; i++) {
            // Unit sphere 10 units away, ray aimed within 1.2 radii of its centre.
            Vec3 p = random(r, 1);
            Vec3 u = unit(r);
            Vec3 c = p.plus(u.times(10));
            Vec3 target = c.plus(u.cross(unit(r)).normalize().times(1.2 * r.nextDouble()));
            spheres[i] = new Sphere(c, 1, GREY, "s");
            sphereRays[i] = new Ray(p, target.minus(p).normalize());
            // Random triangle, ray toward a point near its centroid.
            Vec3 a = random(r, 1);
            Vec3 b = random(r, 1);
            Vec3 cc = random(r, 1);
            triangles[i] = new Triangle(a, b, cc, GREY, "t");
            Vec3 aim = a.plus(b).plus(cc).times(1.0 / 3).plus(random(r, 0.6));
            Vec3 from = aim.plus(unit(r).times(2 + 3 * r.nextDouble()));
            triangleRays[i] = new Ray(from, aim.minus(from));
            // Box [−1, 1]³, ray from 4 units away toward a point up to 1.2 from the centre.
            Vec3 o = unit(r).times(4);
            Vec3 t = random(r, 1.2);
            boxRays[i] = new Ray(o, t.minus(o));
        }
        box = new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1), GREY, "box");
        // Shadow tests: points on a floor beside a sphere, light overhead, nothing in between.
        Vec3 f0 = new Vec3(-5, 0, -5);
        Vec3 f1 = new Vec3(5, 0, -5);
        Vec3 f2 = new Vec3(5, 0, 5);
        Vec3 f3 = new Vec3(-5, 0, 5);
        shadowScene = new Group(java.util.List.of(new Triangle(f0, f2, f1, GREY, "a"), new Triangle(f0, f3, f2, GREY, "b"),
                new Sphere(new Vec3(0, 1, 0), 1, GREY, "s")), "scene");
        light = new PointLight(new Vec3(3, 8, 2), Color.WHITE, true, "light");
        for (int i = 0; i < N; i++) {
            shadowPoints[i] = new Vec3(2 + 2 * r.nextDouble(), 0, -4 + 8 * r.nextDouble());
            shadowNormals[i] = new Vec3(0, 1, 0);
        }
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long sphereTextbook() {
        long hits = 0;
        for (int i = 0; i < N; i++) {
            rec.reset();
            hits += SphereMethods.textbook(spheres[i], rec, sphereRays[i]) ? 1 : 0;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long sphereStable() {
        long hits = 0;
        for (int i = 0; i < N; i++) {
            rec.reset();
            hits += SphereMethods.reference(spheres[i], rec, sphereRays[i]) ? 1 : 0;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long triangleLecture() {
        long hits = 0;
        for (int i = 0; i < N; i++) {
            rec.reset();
            hits += TriangleMethods.lecture(triangles[i], rec, triangleRays[i]) ? 1 : 0;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long triangleMollerTrumbore() {
        long hits = 0;
        for (int i = 0; i < N; i++) {
            rec.reset();
            hits += TriangleMethods.mollerTrumbore(triangles[i], rec, triangleRays[i]) ? 1 : 0;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long triangleWatertight() {
        long hits = 0;
        for (int i = 0; i < N; i++) {
            rec.reset();
            hits += TriangleMethods.reference(triangles[i], rec, triangleRays[i]) ? 1 : 0;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long boxNaiveSlabs() {
        long hits = 0;
        for (int i = 0; i < N; i++) {
            rec.reset();
            hits += BoxMethods.naiveSlabs(box, rec, boxRays[i]) ? 1 : 0;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long boxReference() {
        long hits = 0;
        for (int i = 0; i < N; i++) {
            rec.reset();
            hits += BoxMethods.reference(box, rec, boxRays[i]) ? 1 : 0;
        }
        return hits;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long shadowFixedEpsilon() {
        return blocked(ShadowOffsets::fixedEpsilon);
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long shadowSceneGlobal() {
        return blocked(EarlierOffsets::sceneGlobal);
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public long shadowLocalOffset() {
        return blocked(ShadowOffsets::localOffset);
    }

    /** How many of the shadow points the offset method judges shadowed. */
    private long blocked(ShadowOffsets.ShadowTest method) {
        long blocked = 0;
        for (int i = 0; i < N; i++) {
            blocked += method.isShadowed(shadowScene, shadowPoints[i], shadowNormals[i], light, rec) ? 1 : 0;
        }
        return blocked;
    }
}
