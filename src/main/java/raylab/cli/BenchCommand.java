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

    @Option(names = "--threads", description = "Render threads (default: all cores, ${DEFAULT-VALUE}).")
    int threads = Runtime.getRuntime().availableProcessors();

    @Override
    public Integer call() throws Exception {
        if (runs < 1 || warmup < 0 || threads < 1) {
            throw UserError.badInput("--runs and --threads must be at least 1, --warmup at least 0");
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
        out.printf("runs: %d timed after %d warm-up, %d thread%s%n%n", runs, warmup, threads, threads == 1 ? "" : "s");
        out.println("| scene | size | primitives | median render time | min - max | rays per second | load (cold, meshes and their BVH) | scene BVH build |");
        out.println("|---|---|---:|---:|---:|---:|---:|---:|");
        for (int i = 0; i < loaded.size(); i++) {
            Scene s = loaded.get(i);
            double[] seconds = new double[runs];
            long rays = 0;
            long build = 0;
            for (int r = 0; r < warmup + runs; r++) {
                Renderer renderer = new Renderer(s, new RenderPlan(s), Mode.FULL);
                renderer.render(threads, null);
                if (r >= warmup) {
                    RenderStats st = renderer.stats();
                    seconds[r - warmup] = renderer.renderNanos() / 1e9;
                    rays = st.eyeRays + st.shadowRays;
                    build = renderer.buildNanos();
                }
            }
            double[] sorted = seconds.clone();
            Arrays.sort(sorted);
            double median = runs % 2 == 1 ? sorted[runs / 2] : (sorted[runs / 2 - 1] + sorted[runs / 2]) / 2;
            out.printf("| %s | %dx%d | %,d | %.3f s | %.3f - %.3f s | %,.0f | %.0f ms | %.1f ms |%n", scenes.get(i),
                    s.width, s.height, s.primitiveCount(), median, sorted[0], sorted[runs - 1], rays / median,
                    loadNanos.get(i) / 1e6, build / 1e6);
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
        out.printf("mesh: %s, %,d triangles, %,d BVH nodes, %s kernel; parse %.0f ms, build %.0f ms%n", obj,
                mesh.primitiveCount(), mesh.nodeCount(), mesh.usesPackedKernel() ? "packed" : "Triangle.intersect",
                (t1 - t0) / 1e6, (t2 - t1) / 1e6);
        out.printf("rays: %dx%d pixel centres (harness camera), %d thread%s, %d warm-up + %d timed passes each%n", w, h,
                threads, threads == 1 ? "" : "s", warmup, runs);
        out.flush();
        for (int r = 0; r < warmup; r++) {
            bench.run(threads, true);
        }
        double[] primary = new double[runs];
        double[] withShadows = new double[runs];
        MeshBench.Pass p = null;
        MeshBench.Pass ps = null;
        for (int r = 0; r < runs; r++) {
            p = bench.run(threads, false);
            ps = bench.run(threads, true);
            primary[r] = p.mraysPerSecond();
            withShadows[r] = ps.mraysPerSecond();
        }
        Arrays.sort(primary);
        Arrays.sort(withShadows);
        out.printf("{\"triangles\":%d,\"threads\":%d,\"build_ms\":%.1f,\"primary_mrays_s\":%.2f,"
                + "\"primary_plus_shadow_mrays_s\":%.2f,\"primary_median\":%.2f,\"primary_min\":%.2f,"
                + "\"shadow_median\":%.2f,\"hits\":%d,\"occluded\":%d}%n",
                mesh.primitiveCount(), threads, (t2 - t1) / 1e6, primary[runs - 1], withShadows[runs - 1],
                median(primary), primary[0], median(withShadows), p.hits(), ps.occluded());
        out.flush();
        return Main.OK;
    }

    private static double median(double[] sorted) {
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }
}
