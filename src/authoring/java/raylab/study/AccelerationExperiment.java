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

    /** The verdict at one triangle count: both must give the linear group's answers (tolerance 0); cost per ray. */
    static Verdict decide(double mismatchPercent, Timing.Stats linear, Timing.Stats bvh) {
        return Verdict.decide(List.of(new Verdict.Option("the linear group", 0, linear),
                new Verdict.Option("the BVH", mismatchPercent, bvh)), 0);
    }

    /**
     * The count from which the BVH is recommended at every larger count measured (-1: not at the
     * largest), from the per-count verdicts.
     */
    static int crossover(int[] counts, Verdict[] perCount) {
        int from = -1;
        for (int i = counts.length - 1; i >= 0 && "the BVH".equals(perCount[i].recommended()); i--) {
            from = counts[i];
        }
        return from;
    }

    /** The counts whose verdict is too close to call, as "8, 16". */
    static String tooClose(int[] counts, Verdict[] perCount) {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < counts.length; i++) {
            if (perCount[i].kind == Verdict.Kind.TOO_CLOSE) {
                out.add(String.format("%,d", counts[i]));
            }
        }
        return String.join(", ", out);
    }

    /** The bold headline of the conclusion, from the per-count verdicts. */
    static String headline(int[] counts, Verdict[] perCount) {
        int from = crossover(counts, perCount);
        if (from < 0) {
            return "the BVH is not recommended at any count measured";
        }
        return from == counts[0] ? "use the BVH for any scene measured" : String.format("use the BVH from %,d primitives on", from);
    }

    @Override
    public void run(Study study) throws Exception {
        int[] counts = study.quick ? new int[] {1, 4, 16, 64, 1000, 10000}
                : new int[] {1, 2, 4, 8, 16, 32, 64, 100, 300, 1000, 3000, 10000, 30000, 100000, 300000, 1000000};
        double[] x = new double[counts.length];
        Timing.Stats[] linear = new Timing.Stats[counts.length];
        Timing.Stats[] bvh = new Timing.Stats[counts.length];
        Timing.Stats[] build = new Timing.Stats[counts.length];
        double[] testsLinear = new double[counts.length];
        double[] testsBvh = new double[counts.length];
        double[] mismatch = new double[counts.length];
        Verdict[] verdicts = new Verdict[counts.length];
        int[] linearRays = new int[counts.length];
        Timing slow = study.quick ? study.timing : new Timing(0.1, 0.02, 9);
        // The quick run's usual warm-up (0.05 s) left the BVH's code still being recompiled during
        // its timed runs at small counts (runs at two speeds, and the crossover moved between two
        // runs a minute apart); a longer one costs about 2 s in all.
        Timing small = study.quick ? new Timing(0.25, 0.002, 15) : study.timing;
        for (int i = 0; i < counts.length; i++) {
            int n = counts[i];
            x[i] = n;
            List<Triangle> tris = triangles(n, Study.SEED + n);
            Bvh[] tree = new Bvh[1];
            int buildRuns = n >= 100000 ? 2 : 5;
            build[i] = study.timing.seconds(n >= 30000 ? 0 : 1, study.quick ? 3 : buildRuns, () -> tree[0] = new Bvh(tris, "bvh"));
            Group group = new Group(tris, "group");
            IntersectionRecord rec = new IntersectionRecord();
            Ray[] many = rays(1024, Study.SEED);
            // The linear group at 10^5 and more triangles: fewer rays, so a run stays short.
            linearRays[i] = (int) Math.max(8, Math.min(1024, 4_000_000L / n));
            Ray[] few = java.util.Arrays.copyOf(many, linearRays[i]);
            // Same answers? The closest t of every ray, both ways; and the tests each does per ray.
            IntersectionRecord a = new IntersectionRecord();
            IntersectionRecord b = new IntersectionRecord();
            int differ = 0;
            for (Ray ray : few) {
                a.reset();
                b.reset();
                group.intersect(a, ray);
                tree[0].intersect(b, ray);
                if (a.hasHit() != b.hasHit() || a.hasHit() && a.t != b.t) {
                    differ++;
                }
            }
            testsLinear[i] = a.tests / (double) few.length;
            testsBvh[i] = b.tests / (double) few.length;
            mismatch[i] = 100.0 * differ / few.length;
            Timing t = n >= 30000 ? slow : small;
            Timing.Stats[] both = t.nanosPerOpInterleaved(new Timing.Work[] {
                reps -> trace(group, few, rec, reps), reps -> trace(tree[0], many, rec, reps)},
                new long[] {few.length, many.length});
            linear[i] = both[0];
            bvh[i] = both[1];
            verdicts[i] = decide(mismatch[i], linear[i], bvh[i]);
            study.log(String.format("bvh: n=%d linear %.0f ns/ray, BVH %.0f ns/ray, build %.4f s", n,
                    linear[i].median(), bvh[i].median(), build[i].median()));
        }

        List<Plots.FrontPoint> lp = new ArrayList<>();
        List<Plots.FrontPoint> bp = new ArrayList<>();
        for (int i = 0; i < counts.length; i++) {
            lp.add(new Plots.FrontPoint(linear[i], mismatch[i]));
            bp.add(new Plots.FrontPoint(bvh[i], mismatch[i]));
        }
        XYChart front = Plots.front("Acceleration: error against time per ray",
                "time per ray (ns, log; bar: quartiles), one point per triangle count", "wrong closest hits (% of rays)",
                true, false, 0, List.of(new Plots.Curve("linear group", lp), new Plots.Curve("BVH (SAH, 12 bins)", bp)));
        Plots.save(front, study.out, "bvh-front.png");

        XYChart c = Plots.xy("Time per ray against triangle count", "triangles", "time per ray (ns)", true, true);
        Plots.timed(c, "linear group", x, linear, 0);
        Plots.timed(c, "BVH (SAH, 12 bins)", x, bvh, 1);
        Plots.save(c, study.out, "bvh-time-per-ray.png");
        XYChart ops = Plots.xy("Intersection tests per ray against triangle count", "triangles",
                "ray–triangle tests per ray", true, true);
        Plots.line(ops, "linear group", x, testsLinear, 0);
        Plots.line(ops, "BVH (SAH, 12 bins)", x, testsBvh, 1);
        Plots.save(ops, study.out, "bvh-tests-per-ray.png");
        XYChart b = Plots.xy("BVH build time against triangle count", "triangles", "build time (s)", true, true);
        Plots.timed(b, "BVH build", x, build, 1);
        Plots.save(b, study.out, "bvh-build-time.png");

        int last = counts.length - 1;
        Timing.Ratio speedup = Timing.ratio(linear[last], bvh[last]);
        double breakEvenRays = build[last].median() * 1e9 / (linear[last].median() - bvh[last].median());
        double slopeLinear = SamplingExperiment.slope(x, values(linear));
        double slopeBvh = SamplingExperiment.slope(x, values(bvh));
        int from = crossover(counts, verdicts);
        String close = tooClose(counts, verdicts);

        Report r = study.report;
        r.section("A linear group against the bounding volume hierarchy");
        r.plot("bvh-front.png", "error against time per ray, one point per triangle count: both structures give the linear"
                + " group's closest hit on every ray checked, so the front is decided by time alone");
        r.paragraph(String.format("n random triangles (seeded) in the unit cube, each about 1/∛n across; closest-hit rays"
                + " from a sphere around the cube toward random points inside it. Both structures must give the same"
                + " closest hit: the error axis of the front is the share of rays whose closest t differs from the"
                + " linear group's (it was %s), so the front is decided by time. Time per ray: the two structures and the"
                + " calibration loop in turns, median of the runs, bars from fastest to slowest run. The linear group gets"
                + " fewer rays at large n (%d at n = %,d) so that each run stays short; every count is measured, nothing"
                + " is extrapolated. Load-independent cost: ray–triangle tests per ray, as counted by the structures."
                + " Build time: the BVH constructor (SAH over 12 bins, leaves of up to 4), median of 2–5 builds.",
                TriangleExperiment.max(mismatch) == 0 ? "0 at every count" : String.format("at most %.2f%%", TriangleExperiment.max(mismatch)),
                linearRays[last], counts[last]));
        r.plot("bvh-time-per-ray.png", "time per ray against triangle count, log-log");
        r.plot("bvh-tests-per-ray.png", "intersection tests per ray against triangle count, log-log");
        r.plot("bvh-build-time.png", "BVH build time against triangle count, log-log");
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"triangles", "linear (ns/ray)", "BVH (ns/ray)", "linear / BVH time (95% interval)",
            "tests/ray linear", "tests/ray BVH", "verdict", "BVH build (ms)"});
        for (int i = 0; i < counts.length; i++) {
            Verdict v = verdicts[i];
            rows.add(new String[] {String.format("%,d", counts[i]), linear[i].format("%,.0f"), bvh[i].format("%,.0f"),
                Timing.ratio(linear[i], bvh[i]).format(), String.format("%,.1f", testsLinear[i]), String.format("%,.1f", testsBvh[i]),
                v.recommended() != null ? v.recommended() : Verdict.TOO_CLOSE, build[i].scaled(1000).format("%,.3f")});
        }
        r.table(rows);
        r.paragraph(String.format("Fitted over the counts from 4 on, the linear group's time per ray grows as n^%.2f,"
                + " the BVH's as n^%.2f. The renderer switches to a BVH from %d primitives"
                + " (RenderPlan.ACCELERATION_THRESHOLD).", slopeLinear, slopeBvh, RenderPlan.ACCELERATION_THRESHOLD));

        r.conclude(String.format("**Acceleration: %s.** Applying the rule at each count, the BVH is recommended at every"
                + " count from %s on%s (the renderer switches at %d); at %,d triangles the linear group takes %s the BVH's"
                + " time per ray (%,.0f ns against %,.0f ns) and %,.0f times its ray–triangle tests. The linear cost grows"
                + " as n^%.2f, the BVH's as n^%.2f. Its build (%.2f s at %,d) pays for itself after about %,.0f rays, %s"
                + " one 640×480 image.",
                headline(counts, verdicts), from < 0 ? "(none)" : String.format("%,d", from),
                close.isEmpty() ? "" : "; at " + close + " triangles the costs are " + Verdict.TOO_CLOSE,
                RenderPlan.ACCELERATION_THRESHOLD, counts[last], speedup.format(), linear[last].median(), bvh[last].median(),
                testsLinear[last] / testsBvh[last], slopeLinear, slopeBvh, build[last].median(), counts[last],
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
