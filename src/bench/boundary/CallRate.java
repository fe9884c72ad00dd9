import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.nio.file.Path;

import raylab.boundary.Batches;
import raylab.boundary.StudentJvm;
import raylab.boundary.StudentProcess;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Sphere;

/**
 * Calls per second across the process boundary: Sphere.intersect of the reference (on
 * target/classes) called one at a time and in MULTI frames of 256 (a 16x16 tile) and 4096, and the same
 * calls in this JVM. Usage: java -cp target/classes src/bench/boundary/CallRate.java [ROUNDS]
 * Prints thread CPU time of this JVM too (the machine may be loaded: compare in turns).
 */
public class CallRate {
    public static void main(String[] args) throws Exception {
        int rounds = args.length > 0 ? Integer.parseInt(args[0]) : 5;
        String cp = System.getProperty("java.class.path");
        List<Path> dirs = new ArrayList<>();
        for (String e : cp.split(java.io.File.pathSeparator)) {
            dirs.add(Path.of(e).toAbsolutePath());
        }
        try (StudentProcess p = new StudentProcess(new StudentProcess.Config(
                StudentJvm.javaCommand(dirs, 128, List.of()), null, Set.of("raylab.surface.Sphere"), 60_000, 1))) {
            Sphere s = new Sphere(new Vec3(0, 0, 3), 1, null, "ball");
            java.util.Random rnd = new java.util.Random(1);
            int n = 20_000;
            Ray[] rays = new Ray[n];
            for (int i = 0; i < n; i++) {
                rays[i] = new Ray(new Vec3(0, 0, 0), new Vec3(rnd.nextGaussian() * 0.3, rnd.nextGaussian() * 0.3, 1));
            }
            var bean = java.lang.management.ManagementFactory.getThreadMXBean();
            for (int r = 0; r < rounds; r++) {
                long c0 = bean.getCurrentThreadCpuTime();
                long t0 = System.nanoTime();
                long s0 = StudentProcess.cpuNanosOf(p);
                for (int i = 0; i < n; i++) {
                    p.call("raylab.surface.Sphere", "intersect", s, new IntersectionRecord(), rays[i]);
                }
                long t1 = System.nanoTime();
                long c1 = bean.getCurrentThreadCpuTime();
                long s1 = StudentProcess.cpuNanosOf(p);
                multi(p, s, rays, 256);
                long t2 = System.nanoTime();
                long c2 = bean.getCurrentThreadCpuTime();
                long s2 = StudentProcess.cpuNanosOf(p);
                multi(p, s, rays, 4096);
                long t2m = System.nanoTime();
                long c2m = bean.getCurrentThreadCpuTime();
                long s2m = StudentProcess.cpuNanosOf(p);
                System.out.printf("round %d: multi by 4096 %,.0f calls/s (grader %.2f us, student %.2f us)%n", r,
                        n / ((t2m - t2) / 1e9), (c2m - c2) / 1e3 / n, (s2m - s2) / 1e3 / n);
                t2 = System.nanoTime();
                for (int i = 0; i < n; i++) {
                    s.intersect(new IntersectionRecord(), rays[i]);
                }
                long t3 = System.nanoTime();
                System.out.printf("round %d: sync %,.0f calls/s (grader CPU %.1f us/call, student CPU %.1f us/call);"
                        + " multi by 256 %,.0f calls/s (grader %.2f us, student %.2f us); in-process %,.0f calls/s%n", r,
                        n / ((t1 - t0) / 1e9), (c1 - c0) / 1e3 / n, (s1 - s0) / 1e3 / n,
                        n / ((t2 - t1) / 1e9), (c2 - c1) / 1e3 / n, (s2 - s1) / 1e3 / n, n / ((t3 - t2) / 1e9));
            }
        }
    }

    /** All rays as MULTI frames of {@code size} calls each. */
    private static void multi(StudentProcess p, Sphere s, Ray[] rays, int size) {
        for (int i = 0; i < rays.length; i += size) {
            List<Batches.Call> batch = new ArrayList<>();
            for (int k = i; k < Math.min(rays.length, i + size); k++) {
                batch.add(new Batches.Call("raylab.surface.Sphere", "intersect", s,
                        new Object[] {new IntersectionRecord(), rays[k]}, List.of()));
            }
            p.multi(batch);
        }
    }
}
