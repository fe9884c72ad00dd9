package raylab.study;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.function.UnaryOperator;

import org.knowm.xchart.XYChart;

import raylab.light.PointLight;
import raylab.material.Lambertian;
import raylab.math.BoundingBox;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.numerics.ShadowOffsets;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Group;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * Shadow-ray offsets: none, three fixed ε, an offset from |x| alone, the scene-global offset
 * (the reference before) and the local offset from a per-hit error bound (the reference). The
 * scene has a fine detail: a 4 × 4 leaf 0.005 above a 20 × 20 ground through the coordinate
 * origin, a sphere, a light above; it is rotated, scaled by 10⁻⁴ to 10⁶, moved up to 10⁷ away, and
 * in one setting joined by one small sphere 10¹² away. Acne: points that see the light judged
 * shadowed; leaks: points under the leaf judged lit.
 *
 * <p>One experiment: its scene, its settings and its tally read together as the study's figure.
 */
final class ShadowExperiment implements Experiment {
    static final String[] METHODS = {"no offset", "fixed ε = 10⁻⁹", "fixed ε = 10⁻⁶", "fixed ε = 10⁻³",
        "offset ∝ ‖x‖ only", "scene-global offset", "local offset (reference)"};
    static final int GLOBAL = 5;
    static final int LOCAL = 6;
    static final Lambertian GREY = new Lambertian(new Color(0.7, 0.7, 0.7), Color.BLACK, "grey");
    static final double GAP = 0.005;
    static final Vec3 LIGHT = new Vec3(4.5, 30, 4.5);
    static final Vec3 SPHERE = new Vec3(-5, 2, -5);

    @Override
    public String name() {
        return "shadows";
    }

    @Override
    public String title() {
        return "shadow-ray offsets: scale, translation, a leaf above the ground, an object far away";
    }

    static boolean shadowed(int method, Surface scene, Vec3 x, Vec3 n, PointLight light, IntersectionRecord scratch) {
        switch (method) {
            case 0:
                return ShadowOffsets.none(scene, x, n, light, scratch);
            case 1:
                return FixedOffset.isShadowed(1e-9, scene, x, n, light, scratch);
            case 2:
                return ShadowOffsets.fixedEpsilon(scene, x, n, light, scratch);
            case 3:
                return FixedOffset.isShadowed(1e-3, scene, x, n, light, scratch);
            case 4:
                return EarlierOffsets.hitPointScaled(scene, x, n, light, scratch);
            case 5:
                return EarlierOffsets.sceneGlobal(scene, x, n, light, scratch);
            default:
                return ShadowOffsets.localOffset(scene, x, n, light, scratch);
        }
    }

    /** A surface that counts the shadow rays cast at it (any-hit queries), around another. */
    static final class Counting extends Surface {
        final Surface inner;
        long rays;

        Counting(Surface inner) {
            super(null, inner.name());
            this.inner = inner;
        }

        @Override
        public boolean intersect(IntersectionRecord rec, Ray ray) {
            return inner.intersect(rec, ray);
        }

        @Override
        public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
            rays++;
            return inner.intersectsAny(ray, scratch);
        }

        @Override
        public BoundingBox boundingBox() {
            return inner.boundingBox();
        }
    }

    /** The shading points of one setting: point, normal facing the eye, and whether the point truly sees the light. */
    static final class Points {
        final Counting scene;
        final PointLight light;
        final List<Vec3> x = new ArrayList<>();
        final List<Vec3> n = new ArrayList<>();
        final List<Boolean> lit = new ArrayList<>();

        Points(double s, double translation, double far, int perKind, long seed) {
            SplittableRandom rnd = new SplittableRandom(seed);
            Vec3[] rot = rotation(rnd);
            Vec3 shift = SphereExperiment.unit(rnd).times(translation);
            UnaryOperator<Vec3> m = v -> apply(rot, v).times(s).plus(shift);
            List<Surface> all = new ArrayList<>();
            Vec3 ga = m.apply(new Vec3(-10, 0, -10));
            Vec3 gb = m.apply(new Vec3(10, 0, -10));
            Vec3 gc = m.apply(new Vec3(10, 0, 10));
            Vec3 gd = m.apply(new Vec3(-10, 0, 10));
            all.add(new Triangle(ga, gc, gb, GREY, "ground"));
            all.add(new Triangle(ga, gd, gc, GREY, "ground"));
            all.add(new Sphere(m.apply(SPHERE), 2 * s, GREY, "sphere"));
            Vec3 la = m.apply(new Vec3(2, GAP, 2));
            Vec3 lb = m.apply(new Vec3(6, GAP, 2));
            Vec3 lc = m.apply(new Vec3(6, GAP, 6));
            Vec3 ld = m.apply(new Vec3(2, GAP, 6));
            all.add(new Triangle(la, lb, lc, GREY, "leaf"));
            all.add(new Triangle(la, lc, ld, GREY, "leaf"));
            if (far > 0) {
                all.add(new Sphere(SphereExperiment.unit(rnd).times(far), 1, GREY, "far"));
            }
            scene = new Counting(new Group(all, "scene"));
            light = new PointLight(m.apply(LIGHT), Color.WHITE, true, "light");
            Vec3 highEye = m.apply(new Vec3(3, 12, 25));
            Vec3 lowEye = m.apply(new Vec3(0, GAP / 2, 0.3));
            IntersectionRecord hit = new IntersectionRecord();
            // Points that see the light: on the ground clear of the blockers (a third of them within
            // 5·10⁻⁴ of the coordinate origin, where the ground's large vertices dominate the
            // rounding), and on the sphere's lit side.
            for (int k = 0; k < perKind; k++) {
                int kind = rnd.nextInt(3);
                Vec3 target;
                Vec3 eye = highEye;
                if (kind == 0) {
                    target = new Vec3(rnd.nextDouble(-10, 10), 0, rnd.nextDouble(-10, 10));
                } else if (kind == 1) {
                    target = new Vec3(rnd.nextDouble(-5e-4, 5e-4), 0, rnd.nextDouble(-5e-4, 5e-4));
                } else {
                    Vec3 dir = SphereExperiment.unit(rnd);
                    dir = new Vec3(dir.x, Math.abs(dir.y) + 0.2, dir.z).normalize();
                    target = SPHERE.plus(dir.times(2));
                    eye = m.apply(SPHERE.plus(dir.times(10)));
                    if (LIGHT.minus(target).normalize().dot(dir) < 0.01) {
                        continue;
                    }
                }
                if (kind < 2 && !clearOfBlockers(target)) {
                    continue;
                }
                add(hit, new Ray(eye, m.apply(target).minus(eye)), kind < 2 ? "ground" : "sphere", true);
            }
            // Points under the leaf, seen from an eye just above the ground: in its shadow.
            for (int k = 0; k < perKind; k++) {
                Vec3 target = new Vec3(rnd.nextDouble(2.5, 5.5), 0, rnd.nextDouble(2.5, 5.5));
                double f = GAP / LIGHT.y;
                double cx = target.x + f * (LIGHT.x - target.x);
                double cz = target.z + f * (LIGHT.z - target.z);
                if (cx > 2.2 && cx < 5.8 && cz > 2.2 && cz < 5.8) {
                    add(hit, new Ray(lowEye, m.apply(target).minus(lowEye)), "ground", false);
                }
            }
        }

        private void add(IntersectionRecord hit, Ray ray, String expected, boolean seesLight) {
            hit.reset();
            if (!scene.intersect(hit, ray) || !hit.surface.name().equals(expected)) {
                return; // the eye ray was stopped by another surface first
            }
            Vec3 normal = hit.normal.dot(ray.d) > 0 ? hit.normal.negate() : hit.normal;
            if (normal.dot(light.position.minus(hit.point)) <= 0) {
                return; // the shader traces no shadow ray toward a light behind the surface
            }
            x.add(hit.point);
            n.add(normal);
            lit.add(seesLight);
        }
    }

    /** The segment from ground point g (unscaled) to the light passes the leaf and the sphere with room to spare. */
    static boolean clearOfBlockers(Vec3 g) {
        double f = GAP / LIGHT.y;
        double cx = g.x + f * (LIGHT.x - g.x);
        double cz = g.z + f * (LIGHT.z - g.z);
        if (cx > 1.5 && cx < 6.5 && cz > 1.5 && cz < 6.5) {
            return false;
        }
        Vec3 dd = LIGHT.minus(g);
        double t = Math.max(0, Math.min(1, SPHERE.minus(g).dot(dd) / dd.dot(dd)));
        return g.plus(dd.times(t)).minus(SPHERE).length() > 2.2;
    }

    /** A seeded random rotation (rows of the matrix), from a random unit quaternion. */
    static Vec3[] rotation(SplittableRandom r) {
        double a = r.nextGaussian();
        double b = r.nextGaussian();
        double c = r.nextGaussian();
        double d = r.nextGaussian();
        double len = Math.sqrt(a * a + b * b + c * c + d * d);
        a /= len;
        b /= len;
        c /= len;
        d /= len;
        return new Vec3[] {
            new Vec3(a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c)),
            new Vec3(2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b)),
            new Vec3(2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d)};
    }

    static Vec3 apply(Vec3[] rot, Vec3 v) {
        return new Vec3(rot[0].dot(v), rot[1].dot(v), rot[2].dot(v));
    }

    /** One setting of the experiment. */
    record Setting(double scale, double translation, double far) {
        String label() {
            return String.format("s = 1e%d, T = %s%s", Math.round(Math.log10(scale)),
                    translation == 0 ? "0" : String.format("1e%d", Math.round(Math.log10(translation))),
                    far > 0 ? String.format(", + object 1e%d away", Math.round(Math.log10(far))) : "");
        }
    }

    static long loop(int method, Points pts, Vec3[] xs, Vec3[] ns, IntersectionRecord scratch, int reps) {
        long blocked = 0;
        for (int k = 0; k < reps; k++) {
            for (int i = 0; i < xs.length; i++) {
                if (shadowed(method, pts.scene, xs[i], ns[i], pts.light, scratch)) {
                    blocked++;
                }
            }
        }
        return blocked;
    }

    /** The verdict: tolerance 0 (no acne and no leak in any setting); cost per shadow test. */
    static Verdict decide(String[] names, double[] worstPercent, Timing.Stats[] cost) {
        List<Verdict.Option> options = new ArrayList<>();
        for (int m = 0; m < names.length; m++) {
            options.add(new Verdict.Option(names[m], worstPercent[m], cost[m]));
        }
        return Verdict.decide(options, 0);
    }

    @Override
    public void run(Study study) throws Exception {
        double[] scales = study.quick ? new double[] {1e-4, 1, 1e6} : new double[] {1e-4, 1e-2, 1, 1e2, 1e4, 1e6};
        double[] translations = {0, 1e7};
        int perKind = study.pick(400, 150);
        List<Setting> settings = new ArrayList<>();
        for (double s : scales) {
            for (double t : translations) {
                settings.add(new Setting(s, t, 0));
            }
        }
        settings.add(new Setting(1, 0, 1e12));
        int nm = METHODS.length;
        int ns = settings.size();
        double[][] acne = new double[nm][ns];
        double[][] leaks = new double[nm][ns];
        int[] litCases = new int[ns];
        int[] darkCases = new int[ns];
        IntersectionRecord scratch = new IntersectionRecord();
        for (int k = 0; k < ns; k++) {
            Setting st = settings.get(k);
            Points pts = new Points(st.scale(), st.translation(), st.far(), perKind, Study.SEED + 17L * k);
            int[] acneCount = new int[nm];
            int[] leakCount = new int[nm];
            for (int i = 0; i < pts.x.size(); i++) {
                boolean seesLight = pts.lit.get(i);
                if (seesLight) {
                    litCases[k]++;
                } else {
                    darkCases[k]++;
                }
                for (int m = 0; m < nm; m++) {
                    boolean sh = shadowed(m, pts.scene, pts.x.get(i), pts.n.get(i), pts.light, scratch);
                    if (seesLight && sh) {
                        acneCount[m]++;
                    } else if (!seesLight && !sh) {
                        leakCount[m]++;
                    }
                }
            }
            for (int m = 0; m < nm; m++) {
                acne[m][k] = 100.0 * acneCount[m] / Math.max(1, litCases[k]);
                leaks[m][k] = 100.0 * leakCount[m] / Math.max(1, darkCases[k]);
            }
        }
        // Cost: every point of the unit-scale setting (near the origin, no far object), each method.
        Points unit = new Points(1, 0, 0, perKind, Study.SEED);
        Vec3[] xs = unit.x.toArray(new Vec3[0]);
        Vec3[] nrm = unit.n.toArray(new Vec3[0]);
        double[] raysPerTest = new double[nm];
        double[] raysPerTestFar = new double[nm];
        Points bigGround = new Points(1e6, 0, 0, perKind, Study.SEED + 3);
        for (int m = 0; m < nm; m++) {
            unit.scene.rays = 0;
            loop(m, unit, xs, nrm, scratch, 1);
            raysPerTest[m] = unit.scene.rays / (double) xs.length;
            bigGround.scene.rays = 0;
            loop(m, bigGround, bigGround.x.toArray(new Vec3[0]), bigGround.n.toArray(new Vec3[0]), scratch, 1);
            raysPerTestFar[m] = bigGround.scene.rays / (double) bigGround.x.size();
        }
        Timing.Work[] works = new Timing.Work[nm];
        for (int m = 0; m < nm; m++) {
            int method = m;
            works[m] = reps -> loop(method, unit, xs, nrm, scratch, reps);
        }
        Timing.Stats[] cost = study.timing.nanosPerOpInterleaved(works, xs.length);

        double[] worst = new double[nm];
        List<Plots.Curve> curves = new ArrayList<>();
        for (int m = 0; m < nm; m++) {
            worst[m] = Math.max(TriangleExperiment.max(acne[m]), TriangleExperiment.max(leaks[m]));
            curves.add(new Plots.Curve(METHODS[m], List.of(new Plots.FrontPoint(cost[m], worst[m]))));
        }
        Plots.save(Plots.front("Shadow rays: wrong answers against cost", "ns per shadow test (median; bar: quartiles)",
                "worst acne or leak rate over the settings (%)", false, true, 1e-2, curves), study.out, "shadow-front.png");

        // Acne and leaks against scale: the worst over the translations (and, at scale 1, the far object).
        double[] sx = scales.clone();
        XYChart l = Plots.xy(960, "Light leaks under the leaf against scene scale", "scene scale s",
                "points under the leaf judged lit (%), worst over T", true, false);
        XYChart a = Plots.xy(960, "Shadow acne against scene scale (offset methods)", "scene scale s",
                "points that see the light judged shadowed (%), worst over T", true, false);
        for (int m = 0; m < nm; m++) {
            double[] ya = new double[scales.length];
            double[] yl = new double[scales.length];
            for (int k = 0; k < ns; k++) {
                Setting st = settings.get(k);
                if (st.far() > 0) {
                    continue;
                }
                int i = java.util.Arrays.binarySearch(scales, st.scale());
                ya[i] = Math.max(ya[i], acne[m][k]);
                yl[i] = Math.max(yl[i], leaks[m][k]);
            }
            if (m > 0) {
                Plots.line(a, METHODS[m], sx, ya, m);
            }
            Plots.line(l, METHODS[m], sx, yl, m);
        }
        for (XYChart c : List.of(a, l)) {
            Plots.legendRight(c);
            c.getStyler().setXAxisDecimalPattern("0E0");
        }
        Plots.save(a, study.out, "shadow-acne.png");
        Plots.save(l, study.out, "shadow-leaks.png");

        Report r = study.report;
        r.section("Shadow-ray offsets: fixed, scene-global and local");
        r.plot("shadow-front.png", "worst acne or leak rate against cost per shadow test; 0 is drawn at 10⁻² %; dashed: the front");
        r.paragraph(String.format("The scene has a fine detail next to large things: a 20 × 20 ground of two triangles through"
                + " the coordinate origin, a sphere of radius 2, a 4 × 4 leaf %.3f above the ground and a light 30 above."
                + " It is rotated at random (seeded), scaled by s and moved by T; one setting adds a sphere of radius 1"
                + " at 10¹² from the origin, which makes the scene's bounding box huge. Points that see the light: on"
                + " the ground clear of every blocker (a third within 5·10⁻⁴ s of the coordinate origin, where the"
                + " ground's vertices are much larger than the point) and on the sphere's lit side. Points in shadow:"
                + " on the ground under the leaf, seen from an eye just above the ground. All points come from eye rays"
                + " intersected with the reference methods, so their rounding error is real; up to %d of each kind per"
                + " setting. Acne: a point that sees the light judged shadowed. Leak: a point under the leaf judged lit."
                + " Cost: nanoseconds per shadow test at s = 1, T = 0 (%,d points), all methods and the calibration loop"
                + " in turns.", GAP, perKind, xs.length));
        r.plot("shadow-acne.png", "acne rate against scene scale");
        r.paragraph(String.format("Not plotted: with no offset at all, %.0f%% to %.0f%% of the points that see the light have"
                + " acne in every setting.", ShadowExperiment.min(acne[0]), TriangleExperiment.max(acne[0])));
        r.plot("shadow-leaks.png", "leak rate against scene scale");
        List<String[]> rows = new ArrayList<>();
        String[] head = new String[2 + nm];
        head[0] = "setting";
        head[1] = "points (see light / in shadow)";
        for (int m = 0; m < nm; m++) {
            head[2 + m] = "acne % / leaks %, " + METHODS[m];
        }
        rows.add(head);
        for (int k = 0; k < ns; k++) {
            String[] row = new String[head.length];
            row[0] = settings.get(k).label();
            row[1] = litCases[k] + " / " + darkCases[k];
            for (int m = 0; m < nm; m++) {
                row[2 + m] = String.format("%.1f / %.1f", acne[m][k], leaks[m][k]);
            }
            rows.add(row);
        }
        r.table(rows);
        List<String[]> costRows = new ArrayList<>();
        costRows.add(new String[] {"method", "ns per shadow test (median, min–max)", "cost / fixed ε = 10⁻⁶ (95% interval)",
            "shadow rays per test, s = 1", "shadow rays per test, s = 10⁶ (huge ground)"});
        for (int m = 0; m < nm; m++) {
            costRows.add(new String[] {METHODS[m], cost[m].format("%.1f"), Timing.ratio(cost[m], cost[2]).format(),
                String.format("%.3f", raysPerTest[m]), String.format("%.3f", raysPerTestFar[m])});
        }
        r.table(costRows);
        int farSetting = ns - 1;
        r.paragraph(String.format("The local offset (Shadows.isShadowed) starts the shadow ray γ(8)·16·max|x_i| off the"
                + " surface; when the ray then meets a surface within that surface's own rounding error of x (x small on"
                + " a large triangle), it starts again beyond that surface's bound: the shadow-ray count above shows how"
                + " often (%.3f rays per test at s = 1, %.3f where the ground is 2·10⁷ across). With one object 10¹²"
                + " away, the scene-global offset grows to about 2^-46·10¹² ≈ %.3f, above the leaf: it leaked at %.1f%% of"
                + " the points under the leaf, the local offset at %.1f%%.",
                raysPerTest[LOCAL], raysPerTestFar[LOCAL], 0x1p-46 * 1e12, leaks[GLOBAL][farSetting], leaks[LOCAL][farSetting]));

        Verdict v = decide(METHODS, worst, cost);
        StringBuilder bands = new StringBuilder();
        for (int m = 1; m < nm; m++) {
            if (worst[m] > 0) {
                bands.append(METHODS[m]).append(": worst in ").append(worstSetting(settings, acne[m], leaks[m])).append("; ");
            }
        }
        r.conclude(String.format("**Shadow rays: %s.** %s Where the others fail: %s.",
                v.headline(), v.reason("worst acne or leak rate", d -> String.format("%.1f%%", d),
                        "no acne and no leak in any setting", "time per shadow test"),
                bands.toString().replaceAll("; $", "")));
    }

    /** "s = ..., T = ... (acne 12.0%, leaks 0.0%)": the setting with the highest acne or leak rate. */
    static String worstSetting(List<Setting> settings, double[] acne, double[] leaks) {
        int best = 0;
        for (int k = 1; k < settings.size(); k++) {
            if (Math.max(acne[k], leaks[k]) > Math.max(acne[best], leaks[best])) {
                best = k;
            }
        }
        return String.format("%s (acne %.1f%%, leaks %.1f%%)", settings.get(best).label(), acne[best], leaks[best]);
    }

    static double min(double[] v) {
        double m = Double.POSITIVE_INFINITY;
        for (double x : v) {
            m = Math.min(m, x);
        }
        return m;
    }
}
