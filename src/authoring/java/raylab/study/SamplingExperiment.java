package raylab.study;

import java.util.ArrayList;
import java.util.List;

import org.knowm.xchart.XYChart;

import raylab.camera.PerspectiveCamera;
import raylab.light.PointLight;
import raylab.material.BlinnPhong;
import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.render.Image;
import raylab.render.Renderer;
import raylab.scene.Sampler;
import raylab.scene.Scene;
import raylab.surface.Box;
import raylab.surface.Sphere;
import raylab.surface.Triangle;

/** Samples per pixel, random against stratified: error against a high-sample reference, and time. */
final class SamplingExperiment implements Experiment {
    @Override
    public String name() {
        return "sampling";
    }

    @Override
    public String title() {
        return "samples per pixel: random against stratified";
    }

    /** A small region full of edges: a sphere's silhouette and highlight, a box, a hard shadow. */
    static Scene scene(int width, int height) {
        Lambertian floor = new Lambertian(new Color(0.7, 0.7, 0.7), Color.BLACK, "floor");
        BlinnPhong shiny = new BlinnPhong(new Color(0.8, 0.2, 0.1), new Color(0.6, 0.6, 0.6), 60, Color.BLACK, "shiny");
        Lambertian blue = new Lambertian(new Color(0.1, 0.3, 0.8), Color.BLACK, "blue");
        Vec3 f0 = new Vec3(-4, 0, -4);
        Vec3 f1 = new Vec3(4, 0, -4);
        Vec3 f2 = new Vec3(4, 0, 4);
        Vec3 f3 = new Vec3(-4, 0, 4);
        return Scene.builder().size(width, height)
                .camera(new PerspectiveCamera(new Vec3(0, 1.6, 4.5), new Vec3(0, -0.25, -1), new Vec3(0, 1, 0), 40,
                        width, height))
                .background(new Color(0.05, 0.05, 0.1))
                .add(new Triangle(f0, f2, f1, floor, "floor a"))
                .add(new Triangle(f0, f3, f2, floor, "floor b"))
                .add(new Sphere(new Vec3(-0.7, 0.7, 0), 0.7, shiny, "sphere"))
                .add(new Box(new Vec3(0.4, 0, -0.6), new Vec3(1.4, 1.0, 0.4), blue, "box"))
                .add(new PointLight(new Vec3(2.5, 5, 3), new Color(1, 1, 1), true, "light"))
                .build();
    }

    static double rmse(Image a, Image b) {
        double sum = 0;
        for (int y = 0; y < a.height; y++) {
            for (int x = 0; x < a.width; x++) {
                Color p = a.get(x, y);
                Color q = b.get(x, y);
                sum += (p.r - q.r) * (p.r - q.r) + (p.g - q.g) * (p.g - q.g) + (p.b - q.b) * (p.b - q.b);
            }
        }
        return Math.sqrt(sum / (3.0 * a.width * a.height));
    }

    /** The tolerance of the verdict: one 8-bit step, below which an 8-bit image shows no difference. */
    static final double TOLERANCE = 1.0 / 255;

    /**
     * The verdict from the measured numbers: for each sampler, the render time at the first
     * measured spp whose RMSE is within the tolerance (its runs); a sampler that never gets there
     * is not within the tolerance and reports its smallest error.
     */
    static Verdict decide(String[] names, double[][] err, Timing.Stats[][] time) {
        List<Verdict.Option> options = new ArrayList<>();
        for (int s = 0; s < names.length; s++) {
            int reach = -1;
            double best = Double.POSITIVE_INFINITY;
            for (int i = 0; i < err[s].length; i++) {
                best = Math.min(best, err[s][i]);
                if (reach < 0 && err[s][i] <= TOLERANCE) {
                    reach = i;
                }
            }
            int at = reach < 0 ? err[s].length - 1 : reach;
            options.add(new Verdict.Option(names[s], reach < 0 ? best : err[s][reach], time[s][at]));
        }
        return Verdict.decide(options, TOLERANCE);
    }

    @Override
    public void run(Study study) throws Exception {
        int width = study.pick(96, 48);
        int height = study.pick(64, 32);
        int[] spps = study.quick ? new int[] {1, 4, 16, 64} : new int[] {1, 4, 9, 16, 36, 64, 144, 256};
        int referenceSpp = study.pick(1024, 256);
        Scene base = scene(width, height);
        Image reference = new Renderer(base.withSampler(Sampler.STRATIFIED).withSamplesPerPixel(referenceSpp))
                .render(1, null);
        // Warm the JIT on the whole render path before timing anything.
        new Renderer(base.withSamplesPerPixel(16)).render(1, null);

        Sampler[] samplers = {Sampler.RANDOM, Sampler.STRATIFIED};
        String[] names = {"random", "stratified"};
        double[] x = new double[spps.length];
        double[][] err = new double[2][spps.length];
        long[][] tests = new long[2][spps.length];
        Timing.Stats[][] time = new Timing.Stats[2][spps.length];
        for (int i = 0; i < spps.length; i++) {
            x[i] = spps[i];
            Image[] last = new Image[2];
            Renderer[] renderers = new Renderer[2];
            Runnable[] tasks = new Runnable[2];
            for (int s = 0; s < 2; s++) {
                int sampler = s;
                renderers[s] = new Renderer(base.withSampler(samplers[s]).withSamplesPerPixel(spps[i]));
                tasks[s] = () -> last[sampler] = renderers[sampler].render(1, null);
            }
            Timing.Stats[] t = study.timing.secondsInterleaved(study.quick ? 0 : 1, study.quick || spps[i] >= 64 ? 3 : 5, tasks);
            for (int s = 0; s < 2; s++) {
                time[s][i] = t[s];
                err[s][i] = rmse(last[s], reference);
                tests[s][i] = renderers[s].stats().intersectionTests;
            }
        }

        List<Plots.Curve> curves = new ArrayList<>();
        for (int s = 0; s < 2; s++) {
            List<Plots.FrontPoint> pts = new ArrayList<>();
            for (int i = 0; i < spps.length; i++) {
                pts.add(new Plots.FrontPoint(time[s][i], err[s][i]));
            }
            curves.add(new Plots.Curve(names[s], pts));
        }
        XYChart front = Plots.front("Sampling: error against render time", "render time (s), 1 thread (median; bar: quartiles)",
                "RMSE (linear radiance)", true, true, 1e-6, curves);
        Plots.guide(front, "one 8-bit step (1/255)", new double[] {time[0][0].min(), time[1][spps.length - 1].max()},
                new double[] {TOLERANCE, TOLERANCE});
        Plots.save(front, study.out, "sampling-front.png");

        XYChart e = Plots.xy("Error against samples per pixel", "samples per pixel (eye rays per pixel)",
                "RMSE (linear radiance)", true, true);
        Plots.line(e, "random", x, err[0], 0);
        Plots.line(e, "stratified", x, err[1], 1);
        double[] half = new double[spps.length];
        double[] threeQuarter = new double[spps.length];
        for (int i = 0; i < spps.length; i++) {
            half[i] = err[0][0] * Math.pow(x[i], -0.5);
            threeQuarter[i] = err[1][0] * Math.pow(x[i], -0.75);
        }
        Plots.guide(e, "slope −1/2", x, half);
        Plots.guide(e, "slope −3/4", x, threeQuarter);
        Plots.save(e, study.out, "sampling-error.png");

        double slopeRandom = slope(x, err[0]);
        double slopeStrat = slope(x, err[1]);
        int last = spps.length - 1;
        double sppMatch = sppForError(x, err[1], err[0][last]);
        double stratStep = sppForError(x, err[1], TOLERANCE);
        double randomStep = sppForError(x, err[0], TOLERANCE);
        Timing.Ratio perSample = Timing.ratio(time[1][last], time[0][last]);

        Report r = study.report;
        r.section("Samples per pixel: random against stratified");
        r.plot("sampling-front.png", "RMSE against render time; dashed: the front");
        r.paragraph(String.format("A %d×%d image with edges everywhere (a sphere's silhouette and highlight, a box, a hard"
                + " shadow on a floor), rendered with 1 to %d samples per pixel, each sampler. Error: RMSE over all"
                + " pixels and channels, in linear radiance, against a %d-sample stratified reference of the same"
                + " region. Time: whole render, 1 thread, the two samplers and the calibration loop in turns (%s runs;"
                + " bars: fastest to slowest run). Load-independent cost: samples (eye rays) per pixel, and the"
                + " intersection tests the renderer counted.", width, height, spps[last], referenceSpp,
                study.quick ? "3" : "a warm-up round, then 5 (3 from 64 spp on)"));
        r.plot("sampling-error.png", "RMSE against samples per pixel, log-log: the same comparison in operations (eye rays per pixel), which load does not change");
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"spp", "RMSE random", "RMSE stratified", "time random (s)", "time stratified (s)",
            "stratified / random time", "intersection tests random", "intersection tests stratified"});
        for (int i = 0; i < spps.length; i++) {
            rows.add(new String[] {String.valueOf(spps[i]), String.format("%.5f", err[0][i]), String.format("%.5f", err[1][i]),
                time[0][i].format("%.3f"), time[1][i].format("%.3f"), Timing.ratio(time[1][i], time[0][i]).format(),
                String.format("%,d", tests[0][i]), String.format("%,d", tests[1][i])});
        }
        r.table(rows);
        r.paragraph(String.format("Fitted slopes of log RMSE against log spp (from 4 spp on): random %.2f (theory −0.5),"
                + " stratified %.2f (theory −0.75 for images whose error comes from edges). At 1 spp both samplers"
                + " trace the pixel centre, so their errors agree. Both do the same work per sample (one eye ray and"
                + " two random numbers: the intersection counts agree to %.1f%%); at %d spp stratified took %s random's"
                + " time. Stratified reaches random's %d-spp error with about %s spp. The reference has error of its own"
                + " (about that of the stratified curve extended to %d spp), which the last points include.",
                slopeRandom, slopeStrat, 100 * Math.abs(tests[1][last] / (double) tests[0][last] - 1), spps[last],
                perSample.format(), spps[last], formatSpp(sppMatch), referenceSpp));

        Verdict v = decide(names, err, time);
        r.conclude(String.format("**Sampling: %s.** %s The error drops below one 8-bit step with stratified sampling at %s,"
                + " with random sampling at %s; past that mark, more samples change little that an 8-bit image can show.",
                v.headline(), v.reason("smallest RMSE", d -> String.format("%.4f", d), "RMSE ≤ 1/255, one 8-bit step",
                        "render time at the first spp within it"),
                sppText(stratStep, spps[last]), sppText(randomStep, spps[last])));
    }

    /** "about 26 spp", or "more than 64 spp (not reached in this run)". */
    static String sppText(double spp, int largest) {
        return Double.isNaN(spp) ? "more than " + largest + " spp (not reached in this run)" : String.format("about %.0f spp", spp);
    }

    static String formatSpp(double spp) {
        if (Double.isNaN(spp)) {
            return "(not reached in this run)";
        }
        return String.format("%.0f", spp);
    }

    /** Least-squares slope of log y against log x, from x ≥ 4 on. */
    static double slope(double[] x, double[] y) {
        double sx = 0;
        double sy = 0;
        double sxx = 0;
        double sxy = 0;
        int n = 0;
        for (int i = 0; i < x.length; i++) {
            if (x[i] >= 4 && y[i] > 0) {
                double lx = Math.log(x[i]);
                double ly = Math.log(y[i]);
                sx += lx;
                sy += ly;
                sxx += lx * lx;
                sxy += lx * ly;
                n++;
            }
        }
        return n < 2 ? Double.NaN : (n * sxy - sx * sy) / (n * sxx - sx * sx);
    }

    /** Where the (decreasing) error curve first reaches target, interpolated in log-log; NaN if never. */
    static double sppForError(double[] x, double[] err, double target) {
        if (err[0] <= target) {
            return x[0];
        }
        for (int i = 1; i < x.length; i++) {
            if (err[i] <= target) {
                double f = (Math.log(target) - Math.log(err[i - 1])) / (Math.log(err[i]) - Math.log(err[i - 1]));
                return Math.exp(Math.log(x[i - 1]) + f * (Math.log(x[i]) - Math.log(x[i - 1])));
            }
        }
        return Double.NaN;
    }
}
