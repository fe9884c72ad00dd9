package raylab.study;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.knowm.xchart.XYChart;

import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.render.RenderPlan;
import raylab.surface.Bvh;
import raylab.surface.Group;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/** A linear group against the bounding volume hierarchy: time per ray and build time against triangle count. */
final class AccelerationExperiment implements Experiment {
    @Override
    public String name() {
        return "bvh";
    }

    @Override
    public String title() {
        return "linear group against BVH, 1 to 10^6 triangles";
    }

    /** n random triangles in the unit cube, each about 1/∛n across (seeded). */
    static List<Triangle> triangles(int n, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Lambertian m = new Lambertian(Color.WHITE, Color.BLACK, "grey");
        double size = 1.0 / Math.cbrt(n);
        List<Triangle> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            Vec3 c = new Vec3(random.nextDouble(), random.nextDouble(), random.nextDouble());
            out.add(new Triangle(jitter(c, size, random), jitter(c, size, random), jitter(c, size, random), m, "t"));
        }
        return out;
    }

    private static Vec3 jitter(Vec3 c, double size, SplittableRandom r) {
        return new Vec3(c.x + size * (r.nextDouble() - 0.5), c.y + size * (r.nextDouble() - 0.5),
                c.z + size * (r.nextDouble() - 0.5));
    }

    /** Rays from a sphere of radius 3 around the cube's centre toward random points in the cube. */
    static Ray[] rays(int count, long seed) {
        SplittableRandom random = new SplittableRandom(seed);
        Vec3 centre = new Vec3(0.5, 0.5, 0.5);
        Ray[] out = new Ray[count];
        for (int i = 0; i < count; i++) {
            double z = 2 * random.nextDouble() - 1;
            double phi = 2 * Math.PI * random.nextDouble();
            double s = Math.sqrt(1 - z * z);
            Vec3 p = centre.plus(new Vec3(s * Math.cos(phi), s * Math.sin(phi), z).times(3));
            Vec3 target = new Vec3(random.nextDouble(), random.nextDouble(), random.nextDouble());
            out[i] = new Ray(p, target.minus(p));
        }
        return out;
    }

    static long trace(Surface root, Ray[] rays, IntersectionRecord rec, int reps) {
        long hits = 0;
        for (int k = 0; k < reps; k++) {
            for (Ray ray : rays) {
                rec.reset();
                if (root.intersect(rec, ray)) {
                    hits++;
                }
            }
        }
        return hits;
    }

    @Override
    public void run(Study study) throws Exception {
        int[] counts = study.quick ? new int[] {1, 4, 16, 64, 100, 1000, 10000}
                : new int[] {1, 2, 4, 8, 16, 32, 64, 100, 300, 1000, 3000, 10000, 30000, 100000, 300000, 1000000};
        double[] x = new double[counts.length];
        Timing.Stats[] linear = new Timing.Stats[counts.length];
        Timing.Stats[] bvh = new Timing.Stats[counts.length];
        Timing.Stats[] build = new Timing.Stats[counts.length];
        int[] linearRays = new int[counts.length];
        Timing slow = study.quick ? study.timing : new Timing(0.2, 0.02, 7);
        for (int i = 0; i < counts.length; i++) {
            int n = counts[i];
            x[i] = n;
            List<Triangle> tris = triangles(n, Study.SEED + n);
            int buildRuns = n >= 100000 ? 3 : 5;
            Bvh[] tree = new Bvh[1];
            build[i] = study.timing.seconds(n >= 300000 ? 0 : 2, study.quick ? 3 : buildRuns, () -> tree[0] = new Bvh(tris, "bvh"));
            Group group = new Group(tris, "group");
            IntersectionRecord rec = new IntersectionRecord();
            Ray[] many = rays(1024, Study.SEED);
            // The linear group at 10^5 and more triangles: fewer rays, so a run stays short.
            linearRays[i] = (int) Math.max(8, Math.min(1024, 4_000_000L / n));
            Ray[] few = java.util.Arrays.copyOf(many, linearRays[i]);
            Timing t = n >= 30000 ? slow : study.timing;
            linear[i] = t.nanosPerOp(reps -> trace(group, few, rec, reps), few.length);
            bvh[i] = study.timing.nanosPerOp(reps -> trace(tree[0], many, rec, reps), many.length);
            study.log(String.format("bvh: n=%d linear %.0f ns/ray, BVH %.0f ns/ray, build %.4f s", n,
                    linear[i].median(), bvh[i].median(), build[i].median()));
        }

        XYChart c = Plots.xy("Time per ray against triangle count", "triangles", "time per ray (ns)", true, true);
        Plots.timed(c, "linear group", x, linear, 0);
        Plots.timed(c, "BVH (SAH, 12 bins)", x, bvh, 1);
        Plots.save(c, study.out, "bvh-time-per-ray.png");
        XYChart b = Plots.xy("BVH build time against triangle count", "triangles", "build time (s)", true, true);
        Timing.Stats[] buildPositive = new Timing.Stats[counts.length];
        for (int i = 0; i < counts.length; i++) {
            Timing.Stats s = build[i];
            buildPositive[i] = s;
        }
        Plots.timed(b, "BVH build", x, buildPositive, 1);
        Plots.save(b, study.out, "bvh-build-time.png");

        // The count from which the BVH is faster at every larger count measured.
        int crossover = -1;
        for (int i = counts.length - 1; i >= 0 && bvh[i].median() < linear[i].median(); i--) {
            crossover = counts[i];
        }
        int last = counts.length - 1;
        double speedup = linear[last].median() / bvh[last].median();
        double breakEvenRays = build[last].median() * 1e9 / (linear[last].median() - bvh[last].median());
        double slopeLinear = SamplingExperiment.slope(x, values(linear));
        double slopeBvh = SamplingExperiment.slope(x, values(bvh));

        Report r = study.report;
        r.section("A linear group against the bounding volume hierarchy");
        r.paragraph(String.format("n random triangles (seeded) in the unit cube, each about 1/∛n across; closest-hit rays"
                + " from a sphere around the cube toward random points inside it. Time per ray: median of the"
                + " runs, bars from fastest to slowest run. The linear group gets fewer rays at large n (%d at"
                + " n = %,d) so that each run stays short; every count is measured, nothing is extrapolated."
                + " Build time: the BVH constructor (SAH over 12 bins, leaves of up to 4), %s.",
                linearRays[last], counts[last], "median of 3–5 builds"));
        r.plot("bvh-time-per-ray.png", "time per ray against triangle count, log-log");
        r.plot("bvh-build-time.png", "BVH build time against triangle count, log-log");
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"triangles", "linear (ns/ray)", "BVH (ns/ray)", "speed-up", "BVH build (ms)"});
        for (int i = 0; i < counts.length; i++) {
            rows.add(new String[] {String.format("%,d", counts[i]), linear[i].format("%,.0f"), bvh[i].format("%,.0f"),
                String.format("%.1f×", linear[i].median() / bvh[i].median()), build[i].scaled(1000).format("%,.3f")});
        }
        r.table(rows);
        r.paragraph(String.format("Fitted over the counts from 4 on, the linear group's time per ray grows as n^%.2f,"
                + " the BVH's as n^%.2f. The renderer switches to a BVH from %d primitives"
                + " (RenderPlan.ACCELERATION_THRESHOLD); in this measurement the BVH is faster at every count from %s"
                + " triangles on.", slopeLinear, slopeBvh, RenderPlan.ACCELERATION_THRESHOLD,
                crossover < 0 ? "(never)" : String.valueOf(crossover)));

        r.conclude(String.format("**Acceleration: use the BVH%s.** It is faster at every count from %s triangles on"
                + " (the renderer switches at %d); at %,d triangles it is %.0f× faster per ray (%,.0f ns against"
                + " %,.0f ns). The linear cost grows as n^%.2f, the BVH's as n^%.2f. Its build (%.2f s at %,d)"
                + " pays for itself after about %,.0f rays, %s one 640×480 image.",
                crossover < 0 ? " only where measured faster" : crossover <= 1 ? " for any scene" : " from " + crossover + " primitives on",
                crossover < 0 ? "(never)" : String.valueOf(crossover), RenderPlan.ACCELERATION_THRESHOLD, counts[last],
                speedup, bvh[last].median(), linear[last].median(), slopeLinear, slopeBvh, build[last].median(), counts[last],
                breakEvenRays, breakEvenRays < 640 * 480 ? "less than" : "more than"));
    }

    static double[] values(Timing.Stats[] s) {
        double[] v = new double[s.length];
        for (int i = 0; i < s.length; i++) {
            v[i] = s[i].median();
        }
        return v;
    }
}
