package raylab.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import raylab.bench.MachineInfo;
import raylab.bench.MeshBench;
import raylab.bench.PairedRatio;
import raylab.render.RenderPlan;
import raylab.render.RenderStats;
import raylab.render.Renderer;
import raylab.render.Mode;
import raylab.scene.ObjLoader;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;
import raylab.surface.Mesh;

/**
 * {@code raylab bench SCENE.json...}: renders each scene several times after warm-up runs and
 * reports the median wall time and rays per second, stamped with machine, JVM and date.
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = {"Measure render time and rays per second.",
            "Warm-up runs, then timed runs; prints a Markdown table of median wall time (min-max) and rays per second, with machine, JVM and date.",
            "With --obj MESH.obj: the Embree harness's rays on one mesh (primary, then primary + shadow), as one JSON line."})
public final class BenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "SCENE.json", arity = "0..*", description = "Scenes to render.")
    List<Path> scenes = new ArrayList<>();

    /** Seed of the bootstrap resampling, so the same runs always give the same interval. */
    private static final long SEED = 20261201L;

    @Option(names = "--obj", paramLabel = "MESH.obj",
            description = {"Instead of scenes: trace the rays of the shared Embree harness (../shared/bench/embree) on this mesh,",
                "primary rays only, then primary plus one shadow ray per hit; prints Mrays/s (best and median of --runs)."})
    Path obj;

    @Option(names = "--size", paramLabel = "WxH", description = "Image size for --obj (default: ${DEFAULT-VALUE}).")
    String size = "1024x768";

    @Option(names = "--runs", description = "Timed runs per scene (default: ${DEFAULT-VALUE}).")
    int runs = 5;

    @Option(names = "--warmup", description = "Untimed warm-up runs per scene (default: ${DEFAULT-VALUE}).")
    int warmup = 2;

    @Option(names = "--threads", split = ",", paramLabel = "N[,N...]",
            description = {"Render threads (default: all cores, ${DEFAULT-VALUE}).",
                "Several counts (such as 1,2) are timed in turns, run by run, and each is compared with the first:",
                "speed-up as the median of the paired run ratios with a bootstrap 95%% interval."})
    List<Integer> threadCounts = new ArrayList<>(List.of(Runtime.getRuntime().availableProcessors()));

    @Override
    public Integer call() throws Exception {
        if (runs < 1 || warmup < 0 || threadCounts.isEmpty() || threadCounts.stream().anyMatch(t -> t == null || t < 1 || t > 1024)) {
            throw UserError.badInput("--runs and --threads must be at least 1 (--threads at most 1024), --warmup at least 0");
        }
        if (threadCounts.size() > 1 && runs < 3) {
            throw UserError.badInput("comparing thread counts needs --runs 3 or more");
        }
        PrintWriter out = spec.commandLine().getOut();
        if (obj != null) {
            return meshBench(out);
        }
        if (scenes.isEmpty()) {
            throw UserError.badInput("give SCENE.json files to render, or --obj MESH.obj");
        }
        List<Scene> loaded = new ArrayList<>();
        List<Long> loadNanos = new ArrayList<>();
        for (Path p : scenes) {
            long t0 = System.nanoTime();
            loaded.add(SceneLoader.load(p));
            loadNanos.add(System.nanoTime() - t0);
        }
        out.println("machine: " + MachineInfo.current().oneLine());
        out.printf("runs: %d timed after %d warm-up, threads %s%s%n%n", runs, warmup, counts(),
                threadCounts.size() > 1 ? ", thread counts in turns run by run" : "");
        out.println("| scene | size | primitives | threads | median render time | min - max | rays per second | speed-up over "
                + threadCounts.get(0) + " thread" + (threadCounts.get(0) == 1 ? "" : "s")
                + " (95% interval) | load (cold, meshes and their BVH) | scene BVH build |");
        out.println("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|");
        int k = threadCounts.size();
        for (int i = 0; i < loaded.size(); i++) {
            Scene s = loaded.get(i);
            double[][] seconds = new double[k][runs];
            long rays = 0;
            long build = 0;
            for (int r = 0; r < warmup + runs; r++) {
                for (int c = 0; c < k; c++) {
                    Renderer renderer = new Renderer(s, new RenderPlan(s), Mode.FULL);
                    renderer.render(threadCounts.get(c), null);
                    if (r >= warmup) {
                        RenderStats st = renderer.stats();
                        seconds[c][r - warmup] = renderer.renderNanos() / 1e9;
                        rays = st.eyeRays + st.shadowRays;
                        build = renderer.buildNanos();
                    }
                }
            }
            for (int c = 0; c < k; c++) {
                double[] sorted = seconds[c].clone();
                Arrays.sort(sorted);
                double median = median(sorted);
                out.printf("| %s | %dx%d | %,d | %d | %.3f s | %.3f - %.3f s | %,.0f | %s | %.0f ms | %.1f ms |%n",
                        scenes.get(i), s.width, s.height, s.primitiveCount(), threadCounts.get(c), median, sorted[0],
                        sorted[runs - 1], rays / median, c == 0 ? "" : speedUp(seconds[0], seconds[c]),
                        loadNanos.get(i) / 1e6, build / 1e6);
            }
            out.flush();
        }
        return Main.OK;
    }

    private Integer meshBench(PrintWriter out) throws Exception {
        String[] wh = size.split("x", -1);
        int w;
        int h;
        try {
            w = Integer.parseInt(wh[0]);
            h = wh.length == 2 ? Integer.parseInt(wh[1]) : -1;
        } catch (NumberFormatException e) {
            w = -1;
            h = -1;
        }
        if (wh.length != 2 || w < 1 || h < 1 || (long) w * h > 100_000_000L) {
            throw UserError.badInput("--size must be WIDTHxHEIGHT, such as 1024x768, got '" + size + "'");
        }
        long t0 = System.nanoTime();
        ObjLoader.Indexed read;
        try {
            read = ObjLoader.read(obj, obj.toString());
        } catch (ObjLoader.ObjException e) {
            throw UserError.badInput(e.getMessage());
        }
        long t1 = System.nanoTime();
        Mesh mesh = new Mesh(read.triangleVertices(), MeshBench.GREY, obj.getFileName().toString());
        long t2 = System.nanoTime();
        read = null;
        MeshBench bench = new MeshBench(mesh, w, h);
        out.println("machine: " + MachineInfo.current().oneLine());
        out.printf("mesh: %s, %,d triangles, %,d BVH nodes, %s; parse %.0f ms, build %.0f ms%n", obj,
                mesh.primitiveCount(), mesh.nodeCount(), mesh.kernel(),
                (t1 - t0) / 1e6, (t2 - t1) / 1e6);
        out.printf("rays: %dx%d pixel centres (harness camera), threads %s, %d warm-up + %d timed passes each%s%n", w, h,
                counts(), warmup, runs, threadCounts.size() > 1 ? ", thread counts in turns pass by pass" : "");
        out.flush();
        int k = threadCounts.size();
        // Warm-up passes as the timed ones (primary, then with shadows): a JIT that saw only one
        // kind compiles the other's branch as a trap, and the first timed pass of it deoptimizes.
        for (int r = 0; r < warmup; r++) {
            for (int t : threadCounts) {
                bench.run(t, false);
                bench.run(t, true);
            }
        }
        double[][] primary = new double[k][runs];
        double[][] withShadows = new double[k][runs];
        double[][] primaryCpu = new double[k][runs];
        double[][] withShadowsCpu = new double[k][runs];
        MeshBench.Pass p = null;
        MeshBench.Pass ps = null;
        for (int r = 0; r < runs; r++) {
            for (int c = 0; c < k; c++) {
                p = bench.run(threadCounts.get(c), false);
                ps = bench.run(threadCounts.get(c), true);
                primary[c][r] = p.mraysPerSecond();
                withShadows[c][r] = ps.mraysPerSecond();
                primaryCpu[c][r] = p.mraysPerCpuSecond();
                withShadowsCpu[c][r] = ps.mraysPerCpuSecond();
            }
        }
        for (int c = 0; c < k; c++) {
            double[] sp = primary[c].clone();
            double[] ss = withShadows[c].clone();
            Arrays.sort(sp);
            Arrays.sort(ss);
            double[] cp = primaryCpu[c].clone();
            double[] cs = withShadowsCpu[c].clone();
            Arrays.sort(cp);
            Arrays.sort(cs);
            String scaling = String.format(",\"cpu_primary_median\":%.2f,\"cpu_primary_min\":%.2f,\"cpu_primary_max\":%.2f,"
                    + "\"cpu_shadow_median\":%.2f,\"cpu_shadow_min\":%.2f,\"cpu_shadow_max\":%.2f", median(cp), cp[0],
                    cp[runs - 1], median(cs), cs[0], cs[runs - 1]);
            if (c > 0) {
                // Throughputs: the speed-up is the ratio of c's rate to the first count's, pass by pass.
                double[] ratio = PairedRatio.of(primary[c], primary[0], SEED);
                scaling += String.format(",\"speedup_over_%d_threads\":%.2f,\"speedup_low\":%.2f,\"speedup_high\":%.2f",
                        threadCounts.get(0), ratio[0], ratio[1], ratio[2]);
            }
            out.printf("{\"triangles\":%d,\"threads\":%d,\"build_ms\":%.1f,\"primary_mrays_s\":%.2f,"
                    + "\"primary_plus_shadow_mrays_s\":%.2f,\"primary_median\":%.2f,\"primary_min\":%.2f,"
                    + "\"shadow_median\":%.2f,\"hits\":%d,\"occluded\":%d%s}%n",
                    mesh.primitiveCount(), threadCounts.get(c), (t2 - t1) / 1e6, sp[runs - 1], ss[runs - 1], median(sp),
                    sp[0], median(ss), p.hits(), ps.occluded(), scaling);
        }
        out.flush();
        return Main.OK;
    }

    private String counts() {
        return threadCounts.stream().map(String::valueOf).collect(java.util.stream.Collectors.joining(","));
    }

    /** "1.93× (1.85–1.98)": how much faster than the first count, from the paired run times. */
    private static String speedUp(double[] first, double[] other) {
        double[] r = PairedRatio.of(first, other, SEED);
        return String.format("%.2f× (%.2f–%.2f)", r[0], r[1], r[2]);
    }

    private static double median(double[] sorted) {
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }
}
