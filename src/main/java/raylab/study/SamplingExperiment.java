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

    @Override
    public void run(Study study) throws Exception {
        int width = study.pick(96, 48);
        int height = study.pick(64, 32);
        int[] spps = study.quick ? new int[] {1, 4, 16} : new int[] {1, 4, 9, 16, 36, 64, 144, 256};
        int referenceSpp = study.pick(1024, 64);
        Scene base = scene(width, height);
        Image reference = new Renderer(base.withSampler(Sampler.STRATIFIED).withSamplesPerPixel(referenceSpp))
                .render(1, null);
        // Warm the JIT on the whole render path before timing anything.
        new Renderer(base.withSamplesPerPixel(16)).render(1, null);

        Sampler[] samplers = {Sampler.RANDOM, Sampler.STRATIFIED};
        double[] x = new double[spps.length];
        double[][] err = new double[2][spps.length];
        Timing.Stats[][] time = new Timing.Stats[2][spps.length];
        for (int i = 0; i < spps.length; i++) {
            x[i] = spps[i];
            for (int s = 0; s < 2; s++) {
                Scene scene = base.withSampler(samplers[s]).withSamplesPerPixel(spps[i]);
                Image[] last = new Image[1];
                int runs = study.quick ? 2 : 5;
                time[s][i] = study.timing.seconds(study.quick ? 0 : 1, runs, () -> last[0] = new Renderer(scene).render(1, null));
                err[s][i] = rmse(last[0], reference);
            }
        }

        XYChart e = Plots.xy("Error against samples per pixel", "samples per pixel",
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

        XYChart t = Plots.xy("Render time against samples per pixel", "samples per pixel", "render time (s)", true, true);
        Plots.timed(t, "random", x, time[0], 0);
        Plots.timed(t, "stratified", x, time[1], 1);
        Plots.save(t, study.out, "sampling-time.png");

        XYChart et = Plots.xy("Error against render time", "render time (s)", "RMSE (linear radiance)", true, true);
        for (int s = 0; s < 2; s++) {
            double[] tx = new double[spps.length];
            for (int i = 0; i < spps.length; i++) {
                tx[i] = time[s][i].median();
            }
            Plots.line(et, samplers[s].name().toLowerCase(), tx, err[s], s);
        }
        Plots.save(et, study.out, "sampling-error-vs-time.png");

        double slopeRandom = slope(x, err[0]);
        double slopeStrat = slope(x, err[1]);
        // The spp at which stratified sampling matches random sampling's error at its largest spp.
        int last = spps.length - 1;
        double sppMatch = sppForError(x, err[1], err[0][last]);
        double step = 1.0 / 255;
        double stratStep = sppForError(x, err[1], step);
        double randomStep = sppForError(x, err[0], step);

        Report r = study.report;
        r.section("Samples per pixel: random against stratified");
        r.paragraph(String.format("A %d×%d image with edges everywhere (a sphere's silhouette and highlight, a box, a hard"
                + " shadow on a floor), rendered with 1 to %d samples per pixel, each sampler. Error: RMSE over all"
                + " pixels and channels, in linear radiance, against a %d-sample stratified reference of the same"
                + " region. Time: whole render, 1 thread (%s).", width, height, spps[last], referenceSpp,
                study.quick ? "median of 2 runs; bars: fastest to slowest run" : "median of 5 runs after a warm-up render; bars: fastest to slowest run"));
        r.plot("sampling-error.png", "RMSE against samples per pixel, log-log");
        r.plot("sampling-time.png", "render time against samples per pixel");
        r.plot("sampling-error-vs-time.png", "RMSE against render time");
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"spp", "RMSE random", "RMSE stratified", "time random (s)", "time stratified (s)"});
        for (int i = 0; i < spps.length; i++) {
            rows.add(new String[] {String.valueOf(spps[i]), String.format("%.5f", err[0][i]), String.format("%.5f", err[1][i]),
                time[0][i].format("%.3f"), time[1][i].format("%.3f")});
        }
        r.table(rows);
        r.paragraph(String.format("Fitted slopes of log RMSE against log spp (from 4 spp on): random %.2f (theory −0.5),"
                + " stratified %.2f (theory −0.75 for images whose error comes from edges). At 1 spp both samplers"
                + " trace the pixel centre, so their errors agree. Both do the same work per sample (one eye ray and"
                + " two random numbers); at %d spp stratified took %.2f× random's time. The reference has error of"
                + " its own (about that of the stratified curve extended to %d spp), which the last points include.",
                slopeRandom, slopeStrat, spps[last], time[1][last].median() / time[0][last].median(), referenceSpp));

        r.conclude(String.format("**Sampling: use stratified.** It does the same work per sample as random and its"
                + " error falls faster (slope %.2f against %.2f on log-log axes): it reaches random's %d-spp"
                + " error with about %s spp. Time grows linearly with spp (%.3f s at 1 spp, %.3f s at %d spp here)."
                + " The error drops below one 8-bit step (1/255) at about %s spp stratified, %s spp random: past"
                + " that mark, more samples change little that an 8-bit image can show.", slopeStrat, slopeRandom, spps[last],
                formatSpp(sppMatch), time[1][0].median(), time[1][last].median(), spps[last],
                formatSpp(stratStep), formatSpp(randomStep)));
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
