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
import raylab.render.RenderPlan;
import raylab.render.RenderStats;
import raylab.render.Renderer;
import raylab.render.Mode;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;

/**
 * {@code raylab bench SCENE.json...}: renders each scene several times after warm-up runs and
 * reports the median wall time and rays per second, stamped with machine, JVM and date.
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = {"Measure render time and rays per second.",
            "Warm-up runs, then timed runs; prints a Markdown table of median wall time (min-max) and rays per second, with machine, JVM and date."})
public final class BenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(paramLabel = "SCENE.json", arity = "1..*", description = "Scenes to render.")
    List<Path> scenes;

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
}
