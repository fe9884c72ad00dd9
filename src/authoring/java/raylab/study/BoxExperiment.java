package raylab.study;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.knowm.xchart.CategoryChart;

import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.numerics.BoxMethods;
import raylab.numerics.Oracle;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Box;

/**
 * Another accuracy knob: the box's slab test as written in the lecture (no care for a zero
 * direction component) against the reference. Rays in general position, rays running in a face's
 * plane, rays running along an edge.
 */
final class BoxExperiment implements Experiment {
    static final String[] METHODS = {"naive slabs", "reference slabs"};
    static final String[] KINDS = {"random rays", "rays in a face's plane", "rays along an edge"};

    @Override
    public String name() {
        return "box";
    }

    @Override
    public String title() {
        return "box: naive slabs against the reference";
    }

    static boolean intersect(int method, Box box, IntersectionRecord rec, Ray ray) {
        return method == 0 ? BoxMethods.naiveSlabs(box, rec, ray) : BoxMethods.reference(box, rec, ray);
    }

    /** A ray of the given kind toward the box [−1, 1]³ (from outside). */
    static Ray ray(int kind, SplittableRandom r) {
        double[] p = new double[3];
        double[] d = new double[3];
        int along = r.nextInt(3);
        for (int axis = 0; axis < 3; axis++) {
            p[axis] = 4 * r.nextDouble() - 2;
            d[axis] = 2 * r.nextDouble() - 1;
        }
        if (kind == 0) {
            Vec3 origin = SphereExperiment.unit(r).times(4);
            Vec3 target = new Vec3(2.4 * r.nextDouble() - 1.2, 2.4 * r.nextDouble() - 1.2, 2.4 * r.nextDouble() - 1.2);
            return new Ray(origin, target.minus(origin));
        }
        // The ray starts outside along one axis and travels along it; the other coordinates are
        // fixed: on a face's plane (kind 1: one of them), or on an edge (kind 2: both).
        p[along] = r.nextBoolean() ? -3 : 3;
        d[along] = -Math.signum(p[along]);
        int u = (along + 1) % 3;
        int v = (along + 2) % 3;
        p[u] = r.nextBoolean() ? -1 : 1;
        d[u] = 0;
        if (kind == 2) {
            p[v] = r.nextBoolean() ? -1 : 1;
            d[v] = 0;
        } else {
            p[v] = 2.4 * r.nextDouble() - 1.2;
            d[v] = 0;
        }
        return new Ray(new Vec3(p[0], p[1], p[2]), new Vec3(d[0], d[1], d[2]));
    }

    static long loop(int method, Box box, Ray[] rays, IntersectionRecord rec, int reps) {
        long hits = 0;
        for (int k = 0; k < reps; k++) {
            if (method == 0) {
                for (Ray ray : rays) {
                    rec.reset();
                    hits += BoxMethods.naiveSlabs(box, rec, ray) ? 1 : 0;
                }
            } else {
                for (Ray ray : rays) {
                    rec.reset();
                    hits += BoxMethods.reference(box, rec, ray) ? 1 : 0;
                }
            }
        }
        return hits;
    }

    @Override
    public void run(Study study) throws Exception {
        int perKind = study.pick(20000, 2000);
        Box box = new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1), new Lambertian(Color.WHITE, Color.BLACK, "grey"), "box");
        SplittableRandom r = new SplittableRandom(Study.SEED + 5);
        IntersectionRecord rec = new IntersectionRecord();
        double[][] wrong = new double[2][3];
        for (int kind = 0; kind < 3; kind++) {
            int[] count = new int[2];
            for (int i = 0; i < perKind; i++) {
                Ray ray = ray(kind, r);
                boolean exact = Oracle.box(box.min, box.max, ray.p, ray.d, ray.tMin, ray.tMax).hit;
                for (int m = 0; m < 2; m++) {
                    rec.reset();
                    if (intersect(m, box, rec, ray) != exact) {
                        count[m]++;
                    }
                }
            }
            for (int m = 0; m < 2; m++) {
                wrong[m][kind] = 100.0 * count[m] / perKind;
            }
        }
        Ray[] rays = new Ray[4096];
        SplittableRandom rc = new SplittableRandom(Study.SEED + 6);
        for (int i = 0; i < rays.length; i++) {
            rays[i] = ray(0, rc);
        }
        Timing.Work[] works = new Timing.Work[2];
        for (int m = 0; m < 2; m++) {
            int method = m;
            works[m] = reps -> loop(method, box, rays, rec, reps);
        }
        Timing.Stats[] cost = study.timing.nanosPerOpInterleaved(works, rays.length);
        double[] worst = new double[2];
        List<Plots.Curve> curves = new ArrayList<>();
        for (int m = 0; m < 2; m++) {
            worst[m] = TriangleExperiment.max(wrong[m]);
            curves.add(new Plots.Curve(METHODS[m], List.of(new Plots.FrontPoint(cost[m], worst[m]))));
        }
        Plots.save(Plots.front("Box: wrong answers against cost", "ns per ray–box test (median; bar: quartiles)",
                "wrong hit/miss (% of rays, worst kind)", false, true, 1e-3, curves), study.out, "box-front.png");

        CategoryChart chart = Plots.bars("Box: wrong hit/miss answers", "rays", "wrong hit/miss (% of rays)");
        for (int m = 0; m < 2; m++) {
            List<Double> ys = new ArrayList<>();
            for (double w : wrong[m]) {
                ys.add(w);
            }
            Plots.bars(chart, METHODS[m] + (TriangleExperiment.max(wrong[m]) == 0 ? " (0 everywhere)" : ""), List.of(KINDS), ys);
        }
        Plots.save(chart, study.out, "box-wrong.png");

        Report rep = study.report;
        rep.section("Another knob: the box's slab test");
        rep.plot("box-front.png", "wrong answers against cost per test; 0 is drawn at 10⁻³ %; dashed: the front");
        rep.paragraph(String.format("The box [−1, 1]³; %,d rays of each kind: in general position (from 4 units away toward"
                + " points up to 1.2 from the centre), in the plane of a face (travelling along one axis, with one other"
                + " coordinate exactly on a face's plane and a zero direction component there), and along an edge (two"
                + " coordinates on face planes). The exact answer is the oracle's (raylab.numerics.Oracle.box: a ray on the"
                + " boundary of the closed box hits it). Methods: BoxMethods.naiveSlabs (the lecture's slabs as written:"
                + " 0/0 = NaN when the origin lies on a slab plane and the direction is zero along it) and Box.intersect.",
                perKind));
        rep.plot("box-wrong.png", "wrong hit/miss answers by kind of ray");
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"method", "wrong % " + KINDS[0], "wrong % " + KINDS[1], "wrong % " + KINDS[2], "ns per intersection",
            "cost / naive's (95% interval)"});
        for (int m = 0; m < 2; m++) {
            rows.add(new String[] {METHODS[m], String.format("%.2f", wrong[m][0]), String.format("%.2f", wrong[m][1]),
                String.format("%.2f", wrong[m][2]), cost[m].format("%.1f"), Timing.ratio(cost[m], cost[0]).format()});
        }
        rep.table(rows);
        Verdict v = decide(METHODS, worst, cost);
        rep.paragraph("Both methods do one ray–box test per ray: the front is drawn in nanoseconds only.");
        rep.conclude(String.format("**Box: %s.** %s By kind of ray, the naive slabs were wrong for %.2f%% in general"
                + " position, %.2f%% in a face's plane and %.2f%% along an edge; the reference for %.2f%%, %.2f%% and"
                + " %.2f%%. Axis-aligned rays along faces are common in test scenes and orthographic views.",
                v.headline(), v.reason("worst wrong %", d -> String.format("%.2f%%", d),
                        "no wrong hit/miss answer for any kind of ray", "time per test"),
                wrong[0][0], wrong[0][1], wrong[0][2], wrong[1][0], wrong[1][1], wrong[1][2]));
    }

    /** The verdict: tolerance 0 wrong answers (worst kind of ray); cost per test. */
    static Verdict decide(String[] names, double[] worstPercent, Timing.Stats[] cost) {
        List<Verdict.Option> options = new ArrayList<>();
        for (int m = 0; m < names.length; m++) {
            options.add(new Verdict.Option(names[m], worstPercent[m], cost[m]));
        }
        return Verdict.decide(options, 0);
    }
}
