package raylab.study;

import java.util.ArrayList;
import java.util.List;

import org.knowm.xchart.XYChart;

import raylab.camera.PerspectiveCamera;
import raylab.light.PointLight;
import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.numerics.ShadowOffsets;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.render.Shader;
import raylab.surface.Group;
import raylab.surface.Sphere;
import raylab.surface.Surface;
import raylab.surface.Triangle;

/**
 * Shadow-ray offsets: no offset, a fixed epsilon, an offset scaled by the hit point, and the
 * scale-aware reference. A lit sphere on a floor, the whole scene scaled by 10⁻⁴ to 10⁸; for
 * every eye-ray hit, each method decides whether the point is shadowed, and the answer is
 * compared with the exact one worked out from the geometry.
 */
final class ShadowExperiment implements Experiment {
    static final String[] METHODS = {"no offset", "fixed ε = 10⁻⁹", "fixed ε = 10⁻⁶", "fixed ε = 10⁻³",
        "offset ∝ |x| (hit point only)", "scale-aware (reference)"};
    static final int FIXED = 2;
    static final int REFERENCE = 5;

    @Override
    public String name() {
        return "shadows";
    }

    @Override
    public String title() {
        return "shadow-ray offsets against scene scale";
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
                return ShadowOffsets.hitPointScaled(scene, x, n, light, scratch);
            default:
                return ShadowOffsets.scaleAware(scene, x, n, light, scratch);
        }
    }

    /** Shading points of one scale: the hit point, the normal facing the viewer, and the exact answer. */
    static final class Points {
        final Group scene;
        final PointLight light;
        final List<Vec3> x = new ArrayList<>();
        final List<Vec3> n = new ArrayList<>();
        /** +1 exactly lit, −1 exactly shadowed (by the sphere, with a margin). */
        final List<Integer> exact = new ArrayList<>();

        Points(double s, int width, int height) {
            Lambertian grey = new Lambertian(new Color(0.7, 0.7, 0.7), Color.BLACK, "grey");
            Vec3 f0 = new Vec3(-5, 0, -5).times(s);
            Vec3 f1 = new Vec3(5, 0, -5).times(s);
            Vec3 f2 = new Vec3(5, 0, 5).times(s);
            Vec3 f3 = new Vec3(-5, 0, 5).times(s);
            Vec3 centre = new Vec3(0, 1, 0).times(s);
            double r = s;
            Sphere sphere = new Sphere(centre, r, grey, "sphere");
            scene = new Group(List.of(new Triangle(f0, f2, f1, grey, "floor a"), new Triangle(f0, f3, f2, grey, "floor b"), sphere), "scene");
            light = new PointLight(new Vec3(3, 8, 2).times(s), Color.WHITE, true, "light");
            PerspectiveCamera camera = new PerspectiveCamera(new Vec3(0, 3, 8).times(s), new Vec3(0, -0.35, -1),
                    new Vec3(0, 1, 0), 50, width, height);
            IntersectionRecord rec = new IntersectionRecord();
            Vec3 lightUnit = light.position.times(1 / s);
            for (int iy = 0; iy < height; iy++) {
                for (int ix = 0; ix < width; ix++) {
                    Ray ray = camera.rayThroughPixelCenter(ix, iy);
                    rec.reset();
                    if (!scene.intersect(rec, ray)) {
                        continue;
                    }
                    Vec3 normal = Shader.facing(rec.normal, ray.d);
                    Vec3 toLight = light.position.minus(rec.point);
                    if (normal.dot(toLight) <= 0) {
                        continue; // the shader traces no shadow ray for a light behind the surface
                    }
                    // The exact answer, in unit-scale coordinates, with margins for the points
                    // whose answer rounding may legitimately change.
                    Vec3 xu = rec.point.times(1 / s);
                    int answer;
                    if (rec.surface == sphere) {
                        Vec3 nu = xu.minus(new Vec3(0, 1, 0)).normalize();
                        if (nu.dot(lightUnit.minus(xu).normalize()) < 1e-3) {
                            continue;
                        }
                        answer = 1;
                    } else {
                        double dist = segmentDistance(new Vec3(0, 1, 0), xu, lightUnit);
                        if (Math.abs(dist - 1) < 1e-3) {
                            continue;
                        }
                        answer = dist > 1 ? 1 : -1;
                    }
                    x.add(rec.point);
                    n.add(normal);
                    exact.add(answer);
                }
            }
        }
    }

    /** Distance from c to the segment a–b. */
    static double segmentDistance(Vec3 c, Vec3 a, Vec3 b) {
        Vec3 ab = b.minus(a);
        double t = Math.max(0, Math.min(1, c.minus(a).dot(ab) / ab.dot(ab)));
        return a.plus(ab.times(t)).minus(c).length();
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

    @Override
    public void run(Study study) throws Exception {
        int width = study.pick(160, 64);
        int height = study.pick(120, 48);
        int lo = -4;
        int hi = 12;
        int step = study.quick ? 4 : 1;
        int count = (hi - lo) / step + 1;
        double[] x = new double[count];
        double[][] acne = new double[METHODS.length][count];
        double[][] leaks = new double[METHODS.length][count];
        IntersectionRecord scratch = new IntersectionRecord();
        for (int k = 0; k < count; k++) {
            double s = Math.pow(10, lo + k * step);
            x[k] = s;
            Points pts = new Points(s, width, height);
            int lit = 0;
            int dark = 0;
            int[] acneCount = new int[METHODS.length];
            int[] leakCount = new int[METHODS.length];
            for (int i = 0; i < pts.x.size(); i++) {
                boolean exactLit = pts.exact.get(i) > 0;
                if (exactLit) {
                    lit++;
                } else {
                    dark++;
                }
                for (int m = 0; m < METHODS.length; m++) {
                    boolean sh = shadowed(m, pts.scene, pts.x.get(i), pts.n.get(i), pts.light, scratch);
                    if (exactLit && sh) {
                        acneCount[m]++;
                    } else if (!exactLit && !sh) {
                        leakCount[m]++;
                    }
                }
            }
            for (int m = 0; m < METHODS.length; m++) {
                acne[m][k] = 100.0 * acneCount[m] / Math.max(1, lit);
                leaks[m][k] = 100.0 * leakCount[m] / Math.max(1, dark);
            }
        }
        // Cost: every shading point at scale 1, each method.
        Points unit = new Points(1, width, height);
        Vec3[] xs = unit.x.toArray(new Vec3[0]);
        Vec3[] ns = unit.n.toArray(new Vec3[0]);
        Timing.Work[] works = new Timing.Work[METHODS.length];
        for (int m = 0; m < METHODS.length; m++) {
            int method = m;
            works[m] = reps -> loop(method, unit, xs, ns, scratch, reps);
        }
        Timing.Stats[] cost = study.timing.nanosPerOpInterleaved(works, xs.length);

        XYChart l = Plots.xy(960, "Light leaks against scene scale", "scene scale (sphere radius)", "shadowed points judged lit (%)", true, false);
        XYChart a = Plots.xy(960, "Shadow acne against scene scale (offset methods)", "scene scale (sphere radius)", "lit points judged shadowed (%)", true, false);
        // No offset (acne on about every second to every lit point at every scale) would flatten
        // the others against the axis; it is in the table.
        for (int m = 0; m < METHODS.length; m++) {
            if (m > 0) {
                Plots.line(a, METHODS[m], x, acne[m], m);
            }
            Plots.line(l, METHODS[m], x, leaks[m], m);
        }
        for (XYChart c : List.of(a, l)) {
            Plots.legendRight(c);
            c.getStyler().setXAxisDecimalPattern("0E0");
        }
        Plots.save(a, study.out, "shadow-acne.png");
        Plots.save(l, study.out, "shadow-leaks.png");

        Report r = study.report;
        r.section("Shadow-ray offsets: fixed epsilon against scale-aware");
        r.paragraph(String.format("A sphere (radius s) resting on a floor of two triangles (10 s across), a point light above,"
                + " the camera looking down; the whole scene scaled by s = 10^%d to 10^%d. Each pixel's eye ray is"
                + " intersected with the reference methods; at each hit that faces the light, every offset method"
                + " (raylab.numerics.ShadowOffsets) decides whether the point is shadowed. The exact answer comes from"
                + " the geometry: a sphere point facing the light is lit (the floor is below it); a floor point is"
                + " shadowed exactly when the segment to the light passes within one radius of the sphere's centre."
                + " Points within 0.1%% of either boundary are left out. Acne: lit points judged shadowed. Leaks:"
                + " shadowed points judged lit. Cost: nanoseconds per shadow test (origin offset and any-hit query"
                + " against the 3 surfaces) over the %,d shading points of the unit-scale scene.", lo, hi, xs.length));
        r.plot("shadow-acne.png", "fraction of acne points against scene scale");
        r.paragraph(String.format("Not plotted: with no offset at all, %.0f%% to %.0f%% of lit points have acne at every scale.",
                min(acne[0]), TriangleExperiment.max(acne[0])));
        r.plot("shadow-leaks.png", "fraction of leaking points against scene scale");
        r.paragraph("Leaks: a floor point in the sphere's shadow whose origin is lifted above the sphere's top (an"
                + " offset larger than the sphere's diameter) sees the light. An origin pushed into the sphere does not"
                + " leak: the shadow ray still meets the sphere on its way out.");
        List<String[]> rows = new ArrayList<>();
        int nm = METHODS.length;
        String[] head = new String[1 + 2 * nm];
        head[0] = "scale";
        for (int m = 0; m < METHODS.length; m++) {
            head[1 + m] = "acne % " + METHODS[m];
            head[1 + nm + m] = "leaks % " + METHODS[m];
        }
        rows.add(head);
        for (int k = 0; k < count; k++) {
            String[] row = new String[head.length];
            row[0] = String.format("1e%d", lo + k * step);
            for (int m = 0; m < METHODS.length; m++) {
                row[1 + m] = String.format("%.1f", acne[m][k]);
                row[1 + nm + m] = String.format("%.1f", leaks[m][k]);
            }
            rows.add(row);
        }
        r.table(rows);
        List<String[]> costRows = new ArrayList<>();
        costRows.add(new String[] {"method", "ns per shadow test (median, min–max)"});
        for (int m = 0; m < METHODS.length; m++) {
            costRows.add(new String[] {METHODS[m], cost[m].format("%.1f")});
        }
        r.table(costRows);

        StringBuilder fixed = new StringBuilder();
        for (int m = 1; m <= 3; m++) {
            double acneFrom = firstScale(x, acne[m], true);
            double leaksUpTo = firstScale(x, leaks[m], false);
            fixed.append(METHODS[m]).append(": ")
                    .append(!Double.isNaN(acneFrom) ? "acne from scale " + formatScale(acneFrom) + " up"
                            : TriangleExperiment.max(acne[m]) > 0 ? "acne only at scale " + scalesWith(x, acne[m]) : "no acne")
                    .append(", ")
                    .append(Double.isNaN(leaksUpTo) ? "no leaks" : "leaks at scale " + formatScale(leaksUpTo) + " and below")
                    .append("; ");
        }
        r.conclude(String.format("**Shadow rays: offset the origin by an amount that scales with the scene.** With no offset,"
                + " about %.0f%% of lit points (median over scales) are speckled with acne at every scale. Every fixed ε"
                + " works only over a band of scene sizes (%s). The scale-aware offset (Shadows.isShadowed) had at most"
                + " %.1f%% acne and %.1f%% leaks from 10^%d to 10^%d. It costs %.1f ns per shadow test against %.1f ns"
                + " for the fixed ε = 10⁻⁶ (%+.0f%%).",
                median(acne[0]), fixed.toString().replaceAll("; $", ""), TriangleExperiment.max(acne[REFERENCE]),
                TriangleExperiment.max(leaks[REFERENCE]), lo, hi, cost[REFERENCE].median(), cost[FIXED].median(),
                100 * (cost[REFERENCE].median() / cost[FIXED].median() - 1)));
    }

    /**
     * up: the smallest scale from which the rate is non-zero at every larger scale measured;
     * down: the largest scale up to which it is non-zero at every smaller scale. NaN if none.
     */
    static double firstScale(double[] x, double[] rate, boolean up) {
        double found = Double.NaN;
        if (up) {
            for (int k = x.length - 1; k >= 0 && rate[k] > 0; k--) {
                found = x[k];
            }
        } else {
            for (int k = 0; k < x.length && rate[k] > 0; k++) {
                found = x[k];
            }
        }
        return found;
    }

    static String scalesWith(double[] x, double[] rate) {
        List<String> out = new ArrayList<>();
        for (int k = 0; k < x.length; k++) {
            if (rate[k] > 0) {
                out.add(formatScale(x[k]));
            }
        }
        return String.join(", ", out);
    }

    static String formatScale(double s) {
        return Double.isNaN(s) ? "never in range" : String.format("10^%d", Math.round(Math.log10(s)));
    }

    static double min(double[] v) {
        double m = Double.POSITIVE_INFINITY;
        for (double x : v) {
            m = Math.min(m, x);
        }
        return m;
    }

    static double median(double[] v) {
        return Timing.Stats.of(v).median();
    }
}
