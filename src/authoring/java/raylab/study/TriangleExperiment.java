package raylab.study;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.knowm.xchart.CategoryChart;

import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.numerics.TriangleMethods;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Triangle;

/**
 * Triangle: the lecture's method against Möller–Trumbore against the watertight test. Rays
 * through a shared edge or a shared vertex must hit at least one of the triangles that share it;
 * a ray that hits none has gone through a crack.
 */
final class TriangleExperiment implements Experiment {
    static final String[] METHODS = {"lecture (plane + edge tests)", "Möller–Trumbore", "watertight (reference)"};
    static final String[] SHORT = {"lecture", "Möller–Trumbore", "watertight"};
    static final Lambertian GREY = new Lambertian(Color.WHITE, Color.BLACK, "grey");

    @Override
    public String name() {
        return "triangle";
    }

    @Override
    public String title() {
        return "triangle: lecture against Möller–Trumbore against watertight";
    }

    static boolean intersect(int method, Triangle t, IntersectionRecord rec, Ray ray) {
        switch (method) {
            case 0:
                return TriangleMethods.lecture(t, rec, ray);
            case 1:
                return TriangleMethods.mollerTrumbore(t, rec, ray);
            default:
                return TriangleMethods.reference(t, rec, ray);
        }
    }

    static Vec3 random(SplittableRandom r, double scale) {
        return new Vec3(scale * (2 * r.nextDouble() - 1), scale * (2 * r.nextDouble() - 1), scale * (2 * r.nextDouble() - 1));
    }

    /** A ray from a random origin 2 to 5 units away through the given target point. */
    static Ray rayThrough(Vec3 target, SplittableRandom r) {
        Vec3 dir = SphereExperiment.unit(r);
        Vec3 p = target.plus(dir.times(2 + 3 * r.nextDouble()));
        return new Ray(p, target.minus(p));
    }

    /** Counts rays that hit none of the triangles sharing the point they aim at, per method. */
    static long[] cracks(boolean vertex, double offset, int rays, long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        long[] misses = new long[3];
        IntersectionRecord rec = new IntersectionRecord();
        Triangle[] tris = new Triangle[vertex ? 6 : 2];
        for (int i = 0; i < rays; i++) {
            Vec3 o = random(r, offset);
            Vec3 target;
            // The shared edge or vertex lies in a (nearly: up to rounding) flat patch of mesh, so that
            // every ray through it crosses the patch; rays closer than about 6 degrees to the patch's
            // plane are not used.
            Vec3 e1 = SphereExperiment.unit(r);
            Vec3 e2 = e1.cross(SphereExperiment.unit(r)).normalize();
            Vec3 normal = e1.cross(e2);
            if (vertex) {
                // A fan of 6 triangles around v, ring points at uneven radii and angles.
                Vec3 v = o.plus(random(r, 0.5));
                Vec3[] ring = new Vec3[6];
                double phase = r.nextDouble();
                for (int j = 0; j < 6; j++) {
                    double a = 2 * Math.PI * (j + phase + 0.3 * r.nextDouble()) / 6;
                    double rad = 0.5 + r.nextDouble();
                    ring[j] = v.plus(e1.times(rad * Math.cos(a))).plus(e2.times(rad * Math.sin(a)));
                }
                for (int j = 0; j < 6; j++) {
                    tris[j] = new Triangle(v, ring[j], ring[(j + 1) % 6], GREY, "fan");
                }
                target = v;
            } else {
                // Two triangles a, b, c and c, b, d sharing the edge b–c, d across the edge from a.
                Vec3 b = o.plus(e1.times(r.nextDouble() - 0.5)).plus(e2.times(r.nextDouble() - 0.5));
                Vec3 c = b.plus(e1.times(0.5 + r.nextDouble()));
                Vec3 a = b.plus(e1.times(r.nextDouble())).plus(e2.times(0.3 + r.nextDouble()));
                Vec3 d = b.plus(e1.times(r.nextDouble())).minus(e2.times(0.3 + r.nextDouble()));
                tris[0] = new Triangle(a, b, c, GREY, "left");
                tris[1] = new Triangle(c, b, d, GREY, "right");
                double s = r.nextDouble();
                target = b.plus(c.minus(b).times(s));
            }
            Ray ray = rayThrough(target, r);
            while (Math.abs(ray.d.normalize().dot(normal)) < 0.1) {
                ray = rayThrough(target, r);
            }
            for (int m = 0; m < 3; m++) {
                boolean any = false;
                for (Triangle t : tris) {
                    rec.reset();
                    any |= intersect(m, t, rec, ray);
                }
                if (!any) {
                    misses[m]++;
                }
            }
        }
        return misses;
    }

    static long loop(int method, Triangle[] tris, Ray[] rays, IntersectionRecord rec, int reps) {
        long hits = 0;
        for (int k = 0; k < reps; k++) {
            switch (method) {
                case 0:
                    for (int i = 0; i < rays.length; i++) {
                        rec.reset();
                        hits += TriangleMethods.lecture(tris[i], rec, rays[i]) ? 1 : 0;
                    }
                    break;
                case 1:
                    for (int i = 0; i < rays.length; i++) {
                        rec.reset();
                        hits += TriangleMethods.mollerTrumbore(tris[i], rec, rays[i]) ? 1 : 0;
                    }
                    break;
                default:
                    for (int i = 0; i < rays.length; i++) {
                        rec.reset();
                        hits += TriangleMethods.reference(tris[i], rec, rays[i]) ? 1 : 0;
                    }
            }
        }
        return hits;
    }

    @Override
    public void run(Study study) throws Exception {
        int rays = study.pick(1_000_000, 40_000);
        double[] offsets = {1, 1000};
        String[] offsetNames = {"near the origin", "10³ away"};
        List<String> labels = new ArrayList<>();
        List<String> categories = new ArrayList<>();
        double[][] perMillion = new double[3][4];
        int col = 0;
        for (int o = 0; o < offsets.length; o++) {
            for (int kind = 0; kind < 2; kind++) {
                long[] misses = cracks(kind == 1, offsets[o], rays, Study.SEED + 31 * o + kind);
                categories.add((kind == 1 ? "vertex rays, " : "edge rays, ") + offsetNames[o]);
                labels.add((kind == 1 ? "vertex, " : "edge, ") + (o == 0 ? "near 0" : "10³ away"));
                for (int m = 0; m < 3; m++) {
                    perMillion[m][col] = misses[m] * 1e6 / rays;
                }
                col++;
            }
        }
        // Cost: random triangles and random rays aimed near them (about half hit).
        SplittableRandom r = new SplittableRandom(Study.SEED + 7);
        Triangle[] tris = new Triangle[4096];
        Ray[] rs = new Ray[tris.length];
        for (int i = 0; i < tris.length; i++) {
            Vec3 a = random(r, 1);
            Vec3 b = random(r, 1);
            Vec3 c = random(r, 1);
            tris[i] = new Triangle(a, b, c, GREY, "t");
            Vec3 centroid = a.plus(b).plus(c).times(1.0 / 3);
            rs[i] = rayThrough(centroid.plus(random(r, 0.6)), r);
        }
        IntersectionRecord rec = new IntersectionRecord();
        Timing.Work[] works = new Timing.Work[3];
        for (int m = 0; m < 3; m++) {
            int method = m;
            works[m] = reps -> loop(method, tris, rs, rec, reps);
        }
        Timing.Stats[] cost = study.timing.nanosPerOpInterleaved(works, rs.length);
        double[] worst = new double[3];
        List<Plots.Curve> curves = new ArrayList<>();
        for (int m = 0; m < 3; m++) {
            worst[m] = max(perMillion[m]);
            curves.add(new Plots.Curve(SHORT[m], List.of(new Plots.FrontPoint(cost[m], worst[m]))));
        }
        Plots.save(Plots.front("Triangle: cracks against cost", "ns per ray–triangle test (median; bar: quartiles)",
                "cracks: misses per 10⁶ rays (worst kind)", false, true, 0.1, curves),
                study.out, "triangle-front.png");

        CategoryChart chart = Plots.bars("Triangle: rays through shared edges and vertices that hit nothing",
                "rays", "misses per million rays");
        for (int m = 0; m < 3; m++) {
            List<Double> ys = new ArrayList<>();
            for (double v : perMillion[m]) {
                ys.add(v);
            }
            Plots.bars(chart, SHORT[m] + (max(perMillion[m]) == 0 ? " (0 everywhere)" : ""), labels, ys);
        }
        Plots.save(chart, study.out, "triangle-cracks.png");

        Report rep = study.report;
        rep.section("Triangle: lecture against Möller–Trumbore against watertight");
        rep.plot("triangle-front.png", "cracks against cost per test; 0 is drawn at 0.1 per million; dashed: the front");
        rep.paragraph(String.format("Edge rays: two triangles share the edge b–c (random, in one plane up to rounding, about 1 unit across), and the ray"
                + " passes from a random origin 2 to 5 units away through the point b + s(c − b), s uniform in [0, 1]."
                + " Vertex rays: a flat fan of 6 triangles around v, ray through v. Rays within about 6° of the plane are not used. In exact arithmetic every such ray hits at"
                + " least one triangle; a ray for which all report a miss has slipped through a crack. %,d rays of each"
                + " kind, with the geometry near the coordinate origin and translated 10³ away. Cost: %d random triangles,"
                + " rays aimed near their centroids (about half hit), nanoseconds per ray–triangle test.", rays, tris.length));
        rep.plot("triangle-cracks.png", "misses per million edge and vertex rays");
        List<String[]> rows = new ArrayList<>();
        String[] head = new String[2 + categories.size()];
        head[0] = "method";
        for (int c = 0; c < categories.size(); c++) {
            head[1 + c] = "misses/10⁶, " + categories.get(c);
        }
        head[head.length - 1] = "ns per intersection";
        head = java.util.Arrays.copyOf(head, head.length + 1);
        head[head.length - 1] = "cost / Möller–Trumbore's (95% interval)";
        rows.add(head);
        for (int m = 0; m < 3; m++) {
            String[] row = new String[head.length];
            row[0] = METHODS[m];
            for (int c = 0; c < categories.size(); c++) {
                row[1 + c] = String.format("%,.0f", perMillion[m][c]);
            }
            row[row.length - 2] = cost[m].format("%.1f");
            row[row.length - 1] = Timing.ratio(cost[m], cost[1]).format();
            rows.add(row);
        }
        rep.table(rows);

        Verdict v = decide(SHORT, worst, cost);
        rep.paragraph("Every method does one ray–triangle test per ray: the front is drawn in nanoseconds only.");
        rep.conclude(String.format("**Triangle (meshes): %s.** %s For a lone triangle, with no shared edges to leak"
                + " through, the cheapest test is the one to use: here %s.",
                v.headline(), v.reason("worst misses per million", d -> String.format("%,.0f", d),
                        "no ray through a shared edge or vertex lost", "time per test"),
                cheapest(SHORT, cost)));
    }

    /** The verdict: tolerance 0 cracks (worst kind of ray); cost per test. */
    static Verdict decide(String[] names, double[] worstPerMillion, Timing.Stats[] cost) {
        List<Verdict.Option> options = new ArrayList<>();
        for (int m = 0; m < names.length; m++) {
            options.add(new Verdict.Option(names[m], worstPerMillion[m], cost[m]));
        }
        return Verdict.decide(options, 0);
    }

    /** The cheapest method, or "too close to call" when the two cheapest cannot be told apart. */
    static String cheapest(String[] names, Timing.Stats[] cost) {
        List<Verdict.Option> options = new ArrayList<>();
        for (int m = 0; m < names.length; m++) {
            options.add(new Verdict.Option(names[m], 0, cost[m]));
        }
        Verdict v = Verdict.decide(options, 0);
        return v.kind == Verdict.Kind.CHEAPEST ? v.winner.name() + " (" + v.ratio.format() + " of " + v.other.name() + "'s time)"
                : Verdict.TOO_CLOSE + " between " + v.winner.name() + " and " + v.other.name() + " (" + v.ratio.format() + ")";
    }

    static double max(double[] v) {
        double m = 0;
        for (double x : v) {
            m = Math.max(m, x);
        }
        return m;
    }
}
