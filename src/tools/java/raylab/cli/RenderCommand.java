package raylab.cli;

import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import raylab.render.Image;
import raylab.render.ImageCompare;
import raylab.render.Mode;
import raylab.render.PngFiles;
import raylab.render.RenderPlan;
import raylab.render.RenderStats;
import raylab.render.Renderer;
import raylab.scene.Display;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;
import raylab.course.Watchdog;

/** {@code raylab render SCENE.json}: renders a scene, prints the plan and the counters. */
@Command(name = "render", mixinStandardHelpOptions = true,
        description = {"Render a scene to a PNG image.",
            "Prints the plan (which effects the scene needs) and counters (rays, tests, time)."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:rendered (and matched the reference, with --compare)",
            "1:the image differs from the reference, or a file could not be written",
            "2:bad scene or option", "3:the scene needs a milestone that is not implemented yet"})
public final class RenderCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "SCENE.json", description = "The scene file.")
    Path scenePath;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT.png",
            description = "Where to write the image (default: out/<scene name>.png).")
    Path output;

    @Option(names = "--threads", paramLabel = "N", description = "Render threads (default: all cores, ${DEFAULT-VALUE}).")
    int threads = Runtime.getRuntime().availableProcessors();

    @Option(names = "--spp", paramLabel = "N", description = "Samples per pixel, overriding the scene's.")
    Integer spp;

    @Option(names = "--mode", paramLabel = "MODE",
            description = "What to draw: ${COMPLETION-CANDIDATES} (default: ${DEFAULT-VALUE}).")
    Mode mode = Mode.FULL;

    @Option(names = "--compare", paramLabel = "REF.png",
            description = "Compare with a reference image: print the error and write a diff heatmap.")
    Path reference;

    @Option(names = "--diff", paramLabel = "DIFF.png",
            description = "Where to write the diff heatmap (default: OUT.diff.png).")
    Path diffPath;

    @Option(names = "--tolerance", paramLabel = "FRACTION",
            description = "With --compare: the fraction of pixels allowed to differ (default: the scene's grading"
                    + " tolerance in assignments/*/assignment.json, else " + DEFAULT_TOLERANCE + ").")
    Double tolerance;

    /** The tolerance of a scene that no milestone grades. */
    static final double DEFAULT_TOLERANCE = 0.001;

    @Option(names = "--brute-force",
            description = "Render without any shortcut of the plan: every effect on, a shadow ray toward every light"
                    + " at every lit point, a linear group instead of a BVH (the image must be the same).")
    boolean bruteForce;

    @Option(names = {"-q", "--quiet"}, description = "Print only errors and the comparison result.")
    boolean quiet;

    @Option(names = "--watch", description = "Run again after every save of one of your files (clearing the screen"
            + " each time, also after a save of the scene; the image in out/ stays fresh); Ctrl-C stops.")
    boolean watch;

    @Override
    public Integer call() throws Exception {
        if (watch) {
            return Watch.again(spec, List.of(scenePath.toAbsolutePath()));
        }
        PrintWriter out = spec.commandLine().getOut();
        if (threads < 1) {
            throw UserError.badInput("--threads must be at least 1, got " + threads);
        }
        if (spp != null && (spp < 1 || spp > 4096)) {
            throw UserError.badInput("--spp must be between 1 and 4096, got " + spp);
        }
        String toleranceSource = "";
        if (tolerance == null) {
            var graded = raylab.course.GradingPlan.gradedScene(Path.of("").toAbsolutePath(), scenePath);
            tolerance = graded.map(g -> g.tolerance()).orElse(DEFAULT_TOLERANCE);
            toleranceSource = graded.isPresent() ? " (the grading tolerance of " + graded.get().scene() + ")" : "";
        }
        if (!(tolerance >= 0 && tolerance <= 1)) {
            throw UserError.badInput("--tolerance must be a fraction between 0 and 1, got " + tolerance);
        }
        BufferedImage ref = null;
        if (reference != null) {
            ref = PngFiles.read(reference); // fail before rendering if the reference is unusable
        }
        Path target = output != null ? output : defaultOutput(scenePath, mode);
        Path diff = ref == null ? null : diffPath != null ? diffPath : sibling(target, ".diff.png");
        // Fail before any work if an image could not be written: a directory, a device or a link
        // in its place, a missing or read-only folder (only the default out/ is created).
        try {
            PngFiles.checkTarget(target, output == null);
            if (diff != null) {
                PngFiles.checkTarget(diff, output == null && diffPath == null);
            }
        } catch (PngFiles.OutputException e) {
            throw UserError.badInput((output == null ? "" : "-o ") + e.getMessage());
        }
        long t0 = System.nanoTime();
        Scene scene = SceneLoader.load(scenePath);
        if (spp != null) {
            scene = scene.withSamplesPerPixel(spp);
        }
        long loadNanos = System.nanoTime() - t0;
        String memory = Image.memoryProblem(scene.width, scene.height, Image.availableHeap());
        if (memory != null) {
            throw UserError.badInput(Display.path(scenePath) + ": " + memory);
        }

        RenderPlan plan = bruteForce ? RenderPlan.bruteForce(scene) : new RenderPlan(scene);
        Renderer renderer = new Renderer(scene, plan, mode);
        if (!quiet) {
            out.printf("raylab render %s -> %s (%dx%d, %s, %d thread%s)%n", Display.path(scenePath),
                    Display.path(target),
                    scene.width, scene.height, mode.name().toLowerCase(), threads, threads == 1 ? "" : "s");
            out.println(bruteForce ? "plan (brute force):" : "plan:");
            plan.describe().forEach(out::println);
            out.flush();
        }
        Image image;
        // Stuck student code is named, and the command ends, when no tile finishes within the bound.
        String context = " while rendering " + Display.path(scenePath);
        try (Progress progress = Progress.start(scene, Renderer.TILE);
                Watchdog watchdog = Watchdog.start(Watchdog.bound(0),
                        StudentFault.studentFiles(Path.of("").toAbsolutePath()),
                        stuck -> StudentFault.stuck(spec.commandLine().getErr(), stuck + context))) {
            image = renderer.render(threads, tile -> {
                watchdog.progress();
                progress.tileDone(tile);
            });
        } catch (RuntimeException | StackOverflowError e) {
            if (e instanceof UserError) {
                throw e;
            }
            throw studentsOrRethrow(e, renderer, scene, mode, scenePath);
        }
        long t1 = System.nanoTime();
        BufferedImage picture = image.toBufferedImage();
        image = null; // the linear picture is no longer needed: its memory may go while encoding
        PngFiles.write(picture, target);
        long writeNanos = System.nanoTime() - t1;
        if (!quiet) {
            printCounters(out, renderer, loadNanos, writeNanos);
        }
        if (ref == null) {
            return Main.OK;
        }
        ImageCompare.Result result = ImageCompare.compare(picture, ref);
        PngFiles.write(result.diff(), diff);
        boolean match = result.matches(tolerance);
        out.printf("compare with %s: %s: %s%n  diff heatmap: %s%n  tolerance: %s%s%n", Display.path(reference),
                match ? "MATCH" : "DIFFERS", result.summary(), Display.path(diff),
                String.format(java.util.Locale.ROOT, "%.3f%%", 100 * tolerance), toleranceSource);
        return match ? Main.OK : Main.FAILED;
    }

    /**
     * An exception from the student's code as a one-line user error naming the first pixel (in
     * scan order) where it happens; any other exception as it is.
     */
    static RuntimeException studentsOrRethrow(Throwable e, Renderer renderer, Scene scene, Mode mode, Path scenePath) {
        List<String> files = StudentFault.studentFiles(Path.of("").toAbsolutePath());
        if (!StudentFault.isStudents(e, files)) {
            if (e instanceof RuntimeException re) {
                throw re;
            }
            throw (Error) e;
        }
        int[] at = failingPixel(renderer, scene, mode, e.getClass(), 10_000_000_000L);
        String context = (at == null ? "while rendering " : "while tracing pixel (" + at[0] + ", " + at[1] + ") of ")
                + Display.path(scenePath);
        return new UserError(StudentFault.describe(e, files, context).orElseThrow()
                + (at == null ? "" : "; ./raylab trace " + Display.path(scenePath) + " --pixel " + at[0] + " " + at[1]
                        + " shows that ray"), Main.FAILED);
    }

    /** The first pixel, row by row, whose colour throws {@code type}, or null (none within the time budget). */
    static int[] failingPixel(Renderer renderer, Scene scene, Mode mode, Class<?> type, long budgetNanos) {
        long start = System.nanoTime();
        raylab.render.Shader shader = new raylab.render.Shader(scene, renderer.root(), renderer.plan(), mode);
        raylab.ray.IntersectionRecord rec = new raylab.ray.IntersectionRecord();
        RenderStats stats = new RenderStats();
        for (int y = 0; y < scene.height; y++) {
            for (int x = 0; x < scene.width; x++) {
                try {
                    renderer.pixel(x, y, shader, rec, stats);
                } catch (RuntimeException | StackOverflowError again) {
                    if (again.getClass() == type) {
                        return new int[] {x, y};
                    }
                }
            }
            if (System.nanoTime() - start > budgetNanos) {
                return null;
            }
        }
        return null;
    }

    private static void printCounters(PrintWriter out, Renderer r, long loadNanos, long writeNanos) {
        RenderStats s = r.stats();
        double seconds = r.renderNanos() / 1e9;
        out.println("counters:");
        out.printf("  %-22s %,d%n", "eye rays", s.eyeRays);
        out.printf("  %-22s %,d (%,d blocked)%n", "shadow rays", s.shadowRays, s.shadowRaysBlocked);
        out.printf("  %-22s %,d%n", "intersection tests", s.intersectionTests);
        out.printf("  %-22s %,d%n", "specular evaluations", s.specularEvaluations);
        out.printf("  %-22s %,.0f%n", "rays per second", (s.eyeRays + s.shadowRays) / Math.max(seconds, 1e-9));
        if (s.nonFinitePixels > 0) {
            out.printf("  %-22s %,d (drawn magenta)%n", "NaN/infinite pixels", s.nonFinitePixels);
        }
        out.printf("time: load %s, build %s, render %s, write %s%n", ms(loadNanos), ms(r.buildNanos()),
                ms(r.renderNanos()), ms(writeNanos));
    }

    static String ms(long nanos) {
        return String.format("%.1f ms", nanos / 1e6);
    }

    /** out/NAME.png, or out/NAME-MODE.png for a debug mode. */
    static Path defaultOutput(Path scene, Mode mode) {
        String name = scene.getFileName().toString().replaceFirst("\\.json$", "");
        return Path.of("out", mode == Mode.FULL ? name + ".png" : name + "-" + mode.name().toLowerCase() + ".png");
    }

    static Path sibling(Path file, String suffix) {
        String name = file.getFileName().toString().replaceFirst("\\.png$", "");
        Path parent = file.toAbsolutePath().getParent();
        return parent.resolve(name + suffix);
    }
}
