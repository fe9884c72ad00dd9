package raylab.study;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import raylab.math.Color;
import raylab.ray.IntersectionRecord;
import raylab.render.Mode;
import raylab.render.RenderPlan;
import raylab.render.RenderStats;
import raylab.render.Renderer;
import raylab.render.Shader;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;

/**
 * What the render plan saves: every bundled scene rendered as planned and by brute force (every
 * effect the scene allows switched on, a linear group instead of any BVH), on the same pixels;
 * the images must be identical, and the time, shadow rays and intersection tests are compared.
 */
final class PlanExperiment implements Experiment {
    static final String[] MODES = {"the plan", "brute force"};

    @Override
    public String name() {
        return "plan";
    }

    @Override
    public String title() {
        return "what the render plan saves on the bundled scenes";
    }

    /** The brute-force renderer of a scene: {@link RenderPlan#bruteForce}, every shortcut of the plan off. */
    static Renderer bruteForce(Scene scene) {
        return new Renderer(scene, RenderPlan.bruteForce(scene), Mode.FULL);
    }

    /** count pixels spread evenly over the image (a Fibonacci lattice: row by row, golden-ratio steps across). */
    static int[][] pixels(int width, int height, int count) {
        int n = Math.max(1, Math.min(count, width * height));
        int[][] out = new int[n][2];
        double phi = (Math.sqrt(5) - 1) / 2;
        for (int i = 0; i < n; i++) {
            out[i][0] = (int) Math.min(width - 1, Math.floor(((i * phi) % 1.0) * width));
            out[i][1] = (int) Math.min(height - 1, Math.floor((i + 0.5) / n * height));
        }
        return out;
    }

    /** Renders the given pixels; returns their colours, adds to stats. */
    static Color[] render(Renderer r, int[][] pixels, RenderStats stats) {
        Shader shader = new Shader(r.scene(), r.root(), r.plan(), Mode.FULL);
        IntersectionRecord rec = new IntersectionRecord();
        Color[] out = new Color[pixels.length];
        for (int i = 0; i < pixels.length; i++) {
            out[i] = r.pixel(pixels[i][0], pixels[i][1], shader, rec, stats);
        }
        return out;
    }

    /** The verdict for one scene: both must give the same image (tolerance 0 differing pixels); time per image. */
    static Verdict decide(double differingPercent, Timing.Stats planned, Timing.Stats brute) {
        return Verdict.decide(List.of(new Verdict.Option(MODES[0], differingPercent, planned),
                new Verdict.Option(MODES[1], 0, brute)), 0);
    }

    /** A scene where the plan changes nothing that is counted: no time difference can be real. */
    static final String SAME_WORK = "same work";

    /**
     * The table's verdict for one scene. When the plan and brute force give the same image and
     * count the same work (shadow rays and intersection tests), there is nothing for the plan to
     * save, and any difference in time is the machine's: {@link #SAME_WORK}, whatever the clock
     * says (one scene in twenty would otherwise pass a 95% interval by chance). Otherwise the
     * rule ({@link #decide}) on time.
     */
    static String sceneVerdict(double differingPercent, long shadowPlanned, long shadowBrute, long testsPlanned,
            long testsBrute, Timing.Stats planned, Timing.Stats brute) {
        if (differingPercent == 0 && shadowPlanned == shadowBrute && testsPlanned == testsBrute) {
            return SAME_WORK;
        }
        Verdict v = decide(differingPercent, planned, brute);
        return v.recommended() != null ? v.recommended() : v.kind == Verdict.Kind.TOO_CLOSE ? Verdict.TOO_CLOSE : "images differ";
    }

    @Override
    public void run(Study study) throws Exception {
        Report r = study.report;
        r.section("What the render plan saves");
        Path dir = Path.of("scenes");
        List<Path> files = new ArrayList<>();
        if (Files.isDirectory(dir)) {
            try (Stream<Path> s = Files.list(dir)) {
                s.filter(p -> p.getFileName().toString().endsWith(".json") && !p.getFileName().toString().contains("schema"))
                        .sorted().forEach(files::add);
            }
        }
        if (files.isEmpty()) {
            r.paragraph("No bundled scenes found (run the study from the repository's root, where scenes/ is).");
            r.conclude("**Render plan: not measured.** The bundled scenes were not found in ./scenes.");
            return;
        }
        // Pixels per scene: as many as the brute force renders in about this many seconds (a probe
        // of 64 pixels tells), at most every pixel of a 4 × 4 grid; so that the slowest scene
        // (a mesh traced without any hierarchy) stays affordable.
        double budget = study.quick ? 0.06 : 0.15;
        int runs = study.pick(9, 7);
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"scene", "pixels traced (of)", "differing pixels", "time as planned (ms, traced pixels)", "time brute force (ms)",
            "brute / planned time (95% interval)", "shadow rays planned / brute", "intersection tests planned / brute",
            "verdict"});
        List<Plots.FrontPoint> planned = new ArrayList<>();
        List<Plots.FrontPoint> brute = new ArrayList<>();
        long shadowPlanned = 0;
        long shadowBrute = 0;
        long testsPlanned = 0;
        long testsBrute = 0;
        int identical = 0;
        int planWins = 0;
        List<String> close = new ArrayList<>();
        List<String> same = new ArrayList<>();
        List<Double> logRatios = new ArrayList<>();
        for (Path file : files) {
            Scene scene = SceneLoader.load(file);
            Renderer p = new Renderer(scene);
            Renderer b = bruteForce(scene);
            int[][] probe = pixels(scene.width, scene.height, 64);
            render(b, probe, new RenderStats());
            long t0 = System.nanoTime();
            render(b, probe, new RenderStats());
            double perPixel = (System.nanoTime() - t0) / 1e9 / probe.length;
            int count = (int) Math.max(64, Math.min(scene.width * scene.height / 16, budget / Math.max(1e-9, perPixel)));
            int[][] px = pixels(scene.width, scene.height, count);
            RenderStats sp = new RenderStats();
            RenderStats sb = new RenderStats();
            Color[] ip = render(p, px, sp);
            Color[] ib = render(b, px, sb);
            int differ = 0;
            for (int i = 0; i < ip.length; i++) {
                if (ip[i].r != ib[i].r || ip[i].g != ib[i].g || ip[i].b != ib[i].b) {
                    differ++;
                }
            }
            identical += differ == 0 ? 1 : 0;
            Timing.Stats[] t = study.timing.secondsInterleaved(1, runs,
                    () -> render(p, px, new RenderStats()), () -> render(b, px, new RenderStats()));
            double pct = 100.0 * differ / ip.length;
            String verdict = sceneVerdict(pct, sp.shadowRays, sb.shadowRays, sp.intersectionTests, sb.intersectionTests,
                    t[0], t[1]);
            if (MODES[0].equals(verdict)) {
                planWins++;
            } else if (verdict.equals(SAME_WORK)) {
                same.add(file.getFileName().toString());
            } else if (verdict.equals(Verdict.TOO_CLOSE)) {
                close.add(file.getFileName().toString());
            }
            Timing.Ratio ratio = Timing.ratio(t[1], t[0]);
            logRatios.add(Math.log(ratio.value()));
            planned.add(new Plots.FrontPoint(t[0].scaled(1000), pct));
            brute.add(new Plots.FrontPoint(t[1].scaled(1000), 0));
            shadowPlanned += sp.shadowRays;
            shadowBrute += sb.shadowRays;
            testsPlanned += sp.intersectionTests;
            testsBrute += sb.intersectionTests;
            rows.add(new String[] {file.getFileName().toString(),
                String.format("%,d (%,d)", ip.length, scene.width * scene.height), String.valueOf(differ),
                t[0].scaled(1000).format("%.1f"), t[1].scaled(1000).format("%.1f"), ratio.format(),
                String.format("%,d / %,d", sp.shadowRays, sb.shadowRays),
                String.format("%,d / %,d", sp.intersectionTests, sb.intersectionTests),
                verdict});
            study.log(String.format("plan: %s planned %.1f ms, brute force %.1f ms, %d pixels differ", file.getFileName(),
                    1000 * t[0].median(), 1000 * t[1].median(), differ));
        }
        Plots.save(Plots.front("Render plan: differing pixels against time", "time for the traced pixels (ms, log; bar: quartiles)",
                "pixels differing from the brute-force image (%)", true, false, 0,
                List.of(new Plots.Curve("as planned (one point per scene)", planned, false),
                        new Plots.Curve("brute force (one point per scene)", brute, false))),
                study.out, "plan-front.png");
        r.plot("plan-front.png", "differing pixels against time, one point per scene and mode; dashed: the front");
        r.paragraph(String.format("Each bundled scene (scenes/*.json) is rendered twice on the same pixels (spread evenly"
                + " over the image; as many as brute force renders in about %.2f s, at most one in 16, so that it stays"
                + " affordable): as planned (RenderPlan: BVH from %d"
                + " primitives, shadow rays only where something can block, specular and ambient terms only where they"
                + " add something) and by brute force (RenderPlan.bruteForce, as `raylab render --brute-force`: the light"
                + " loop at every lit point, specular and ambient terms always, a shadow ray toward every light that casts"
                + " shadows, a linear group of every primitive with meshes split into triangles). The two must give the"
                + " same colour, bit for bit, at every traced pixel. Time: both in turns with the calibration loop, %d"
                + " runs after a warm-up. Load-independent costs: shadow rays and ray–primitive intersection tests. Where both"
                + " modes count the same of each and give the same image, the plan has nothing to save and the verdict is"
                + " \"" + SAME_WORK + "\" whatever the clock says: the rule on time is applied only where the plan changes"
                + " the counted work (with fourteen scenes and 95%% intervals, one would otherwise pass by chance now and"
                + " then).",
                budget, RenderPlan.ACCELERATION_THRESHOLD, runs));
        r.table(rows);
        double geo = 0;
        for (double lr : logRatios) {
            geo += lr / logRatios.size();
        }
        Verdict overall = Verdict.decide(List.of(
                new Verdict.Option(MODES[0], identical == files.size() ? 0 : 1, Timing.Stats.exact(testsPlanned)),
                new Verdict.Option(MODES[1], 0, Timing.Stats.exact(testsBrute))), 0);
        r.conclude(String.format("**Render plan: %s.** The planned and brute-force images were identical in %d of %d bundled"
                + " scenes; by the rule, the plan is recommended on time in %d of them%s%s. Over all scenes the plan cast"
                + " %,d shadow rays where brute force cast %,d, and ran %,d intersection tests against %,d (%.1f%%); brute"
                + " force took %.2f× the planned time (geometric mean over the scenes).",
                overall.headline(), identical, files.size(), planWins,
                same.isEmpty() ? "" : "; " + same.size() + " did the same counted work both ways (the same shadow rays and"
                        + " intersection tests, so no time difference between them can be the plan's: " + String.join(", ", same) + ")",
                close.isEmpty() ? "" : "; " + Verdict.TOO_CLOSE + " for " + String.join(", ", close),
                shadowPlanned, shadowBrute, testsPlanned, testsBrute, 100.0 * testsPlanned / Math.max(1, testsBrute),
                Math.exp(geo)));
    }
}
