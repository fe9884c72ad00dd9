package raylab.boundary;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import raylab.math.Color;
import raylab.ray.IntersectionRecord;
import raylab.render.Image;
import raylab.render.Mode;
import raylab.render.PngFiles;
import raylab.render.RenderPlan;
import raylab.render.RenderStats;
import raylab.render.Renderer;
import raylab.render.Shader;
import raylab.scene.Scene;
import raylab.scene.SceneLoader;

/**
 * Renders scenes in the grader's process (with stand-ins whose graded methods run in the student
 * process): arguments are triples SCENE.json OUT.png NAME; for each scene the error line, if
 * any, goes to OUT.png.err. Pixel by pixel as the renderer does, so a student exception names
 * its pixel; the PNG is encoded here, never in the student's process.
 */
public final class TrustedRender {
    private TrustedRender() {
    }

    /**
     * Rows per band of a batched render: a band's calls wait for the student's answers in memory,
     * and at 2 rows they are a few megabytes, which die young (8 rows took the trusted JVM's
     * collections from 0.7 to 1.7 s in a grading at 0.5 CPU).
     */
    static final int BAND_ROWS = 2;

    /** Renders one scene: the same pixels as {@link Renderer#render}. */
    public static Image render(Scene scene, String name) {
        return render(scene, name, null);
    }

    /**
     * Renders one scene, batching the student calls through {@code spec} if it is not null (the
     * same pixels, bit for bit, as one call at a time: {@link Speculation}).
     */
    public static Image render(Scene scene, String name, Speculation spec) {
        return render(scene, name, spec, null, new int[1]);
    }

    /**
     * As {@link #render(Scene, String, Speculation)}, also setting in {@code reference} (if not
     * null) each pixel traced with predictions only: the first round of a band uses no answer of
     * the student's, so that trace is the reference solution's (the milestone's reference and the
     * trusted framework). {@code set[0]} counts the pixels of {@code reference} set: all of them
     * unless a prediction failed (then the reference must be rendered apart).
     */
    public static Image render(Scene scene, String name, Speculation spec, Image reference, int[] set) {
        Renderer r = new Renderer(scene, new RenderPlan(scene), Mode.FULL);
        Shader shader = new Shader(scene, r.root(), r.plan(), Mode.FULL);
        Image image = new Image(scene.width, scene.height);
        IntersectionRecord rec = new IntersectionRecord();
        RenderStats stats = new RenderStats();
        if (spec == null) {
            for (int y = 0; y < scene.height; y++) {
                checkTime();
                for (int x = 0; x < scene.width; x++) {
                    image.set(x, y, pixel(r, shader, rec, stats, x, y, name));
                }
            }
            return image;
        }
        // The reference image's traces have a shader and a record of their own: the state the
        // reference leaves in them (a shadow ray's scratch record) never reaches a sent call.
        Shader referenceShader = new Shader(scene, r.root(), r.plan(), Mode.FULL);
        Remote.speculate(spec);
        try {
            for (int y0 = 0; y0 < scene.height; y0 += BAND_ROWS) {
                checkTime();
                set[0] += band(r, shader, rec, stats, image, y0, Math.min(scene.height, y0 + BAND_ROWS), name, spec,
                        reference, referenceShader);
            }
        } finally {
            Remote.speculate(null);
        }
        return image;
    }

    private static void checkTime() {
        if (timeUp()) {
            throw new OutOfTime();
        }
    }

    /** Whether the renders' time limit has passed. */
    private static boolean timeUp() {
        return timed && (budget < 0 || Remote.process().studentCpuNanos() - cpuAtStart > budget);
    }

    private static Color pixel(Renderer r, Shader shader, IntersectionRecord rec, RenderStats stats, int x, int y,
            String name) {
        try {
            return r.pixel(x, y, shader, rec, stats);
        } catch (StudentException e) {
            throw e.in("while tracing pixel (" + x + ", " + y + ") of " + name);
        }
    }

    /**
     * Rows y0 to y1 in rounds: each open pixel traced with the answers known and neutral guesses
     * for the rest (never the reference's answers: {@link Speculation}), then the guesses checked
     * against the student's answers in one frame, until every pixel's trace rests on the
     * student's answers only. Failures are thrown in the order of the pixels, as a render one
     * call at a time would meet them. Before the rounds, every pixel is traced by the milestone's
     * reference alone into {@code reference} (if not null), with {@code referenceShader}; a pixel
     * whose trace there called no stand-in is done with that colour ({@link Speculation#frameworkOnly}).
     * Returns how many pixels of the reference image were set.
     */
    private static int band(Renderer r, Shader shader, IntersectionRecord rec, RenderStats stats, Image image,
            int y0, int y1, String name, Speculation spec, Image reference, Shader referenceShader) {
        int w = image.width;
        int n = w * (y1 - y0);
        Color[] colors = new Color[n];
        Throwable[] failures = new Throwable[n];
        boolean[] done = new boolean[n];
        boolean[] oneAtATime = new boolean[n];
        Speculation.Pixel[] traces = new Speculation.Pixel[n];
        int open = n;
        int set = 0;
        if (reference != null) {
            // The reference image: every pixel traced once by the milestone's reference here,
            // before any call of the band is sent; nothing of these traces leaves this JVM.
            // A pixel whose trace called no stand-in is the trusted framework's alone: the rounds
            // would trace it to the same colour, sending nothing, so it is done here.
            IntersectionRecord referenceRec = new IntersectionRecord();
            for (int i = 0; i < n; i++) {
                Speculation.Pixel p = spec.beginReference();
                try {
                    Color c = r.pixel(i % w, y0 + i / w, referenceShader, referenceRec, stats);
                    reference.set(i % w, y0 + i / w, c);
                    set++;
                    if (spec.frameworkOnly(p)) {
                        colors[i] = c;
                        done[i] = true;
                        open--;
                    }
                } catch (Speculation.Unpredictable | RuntimeException | StackOverflowError e) {
                    // Left out: the grader renders the reference itself.
                } finally {
                    spec.end();
                }
            }
        }
        for (int round = 0; open > 0 && round < Speculation.MAX_ROUNDS; round++) {
            for (int i = 0; i < n; i++) {
                if (done[i] || oneAtATime[i]) {
                    continue;
                }
                traces[i] = spec.begin();
                colors[i] = null;
                failures[i] = null;
                try {
                    colors[i] = r.pixel(i % w, y0 + i / w, shader, rec, stats);
                } catch (Speculation.Unpredictable e) {
                    oneAtATime[i] = true;
                    open--;
                } catch (RuntimeException | StackOverflowError e) {
                    failures[i] = e;
                } finally {
                    spec.end();
                }
            }
            spec.send();
            for (int i = 0; i < n; i++) {
                if (!done[i] && !oneAtATime[i]) {
                    if (traces[i].exact()) {
                        done[i] = true;
                        open--;
                    } else {
                        spec.keep(traces[i]);
                    }
                }
            }
        }
        for (int i = 0; i < n; i++) {
            int x = i % w;
            int y = y0 + i / w;
            if (!done[i]) {
                Color[] c = new Color[1];
                spec.oneAtATime(() -> c[0] = pixel(r, shader, rec, stats, x, y, name));
                image.set(x, y, c[0]);
                continue;
            }
            if (failures[i] instanceof StudentException e) {
                throw e.in("while tracing pixel (" + x + ", " + y + ") of " + name);
            }
            if (failures[i] instanceof RuntimeException e) {
                throw e;
            }
            if (failures[i] instanceof Error e) {
                throw e;
            }
            image.set(x, y, colors[i]);
        }
        spec.clear();
        return set;
    }

    /** Thrown through a render when the renders' time is up ({@link #renderAll}'s CPU budget is spent). */
    static final class OutOfTime extends RuntimeException {
        private static final long serialVersionUID = 1L;

        OutOfTime() {
            super("out of time", null, false, false);
        }
    }

    /**
     * The renders' time limit, if {@link #timed}: the student processes' CPU time from
     * {@link #cpuAtStart} on (never the grader's, never time spent waiting for a CPU), checked
     * between bands and before every frame sent within a band.
     */
    private static long budget;
    private static long cpuAtStart;
    private static boolean timed;

    /**
     * The error line of a scene whose render ended with {@code t}, and beside {@code out} the
     * marker ({@link GradingFailure#RENDER_MARKER}) when that is the grading's failure: a
     * {@link GradingFailure}, or this JVM's own memory or stack running out (a
     * {@link VirtualMachineError}: it runs no code of the student's, whose running out of memory in
     * the student process is a {@link StudentException}).
     */
    static String failure(Throwable t, Path out) throws java.io.IOException {
        if (t instanceof StudentException || t instanceof StudentTimeout) {
            return t.getMessage();
        }
        if (t instanceof GradingFailure || t instanceof VirtualMachineError) {
            Files.writeString(Path.of(out + GradingFailure.RENDER_MARKER), "", StandardCharsets.UTF_8);
            return t instanceof GradingFailure ? t.getMessage() : "the grader's render JVM: " + t;
        }
        return t.toString();
    }

    /**
     * Renders the scenes of {@code args} (triples SCENE.json OUT.png NAME) one after the other with
     * this JVM's student process, batched by the milestone's reference named in the system
     * property {@code raylab.boundary.references} if it is set. A scene that fails leaves
     * {@code OUT.png.err} (its first line says why); once the student's code has used
     * {@code cpuBudgetNanos} of CPU time from now on (the renders' limit; {@link Long#MAX_VALUE}:
     * none), the scene being rendered and those after it leave {@code OUT.png.timeout} instead.
     * A batched render also leaves the reference solution's image, {@code OUT.png.reference.png},
     * when its first rounds traced every pixel. Timings go to {@code times} when
     * RAYLAB_GRADE_TIMES is set.
     */
    public static void renderAll(java.util.List<String> args, long cpuBudgetNanos, java.io.PrintStream times)
            throws java.io.IOException {
        timed = cpuBudgetNanos != Long.MAX_VALUE;
        budget = cpuBudgetNanos;
        if (timed && budget >= 0) {
            cpuAtStart = Remote.process().studentCpuNanos();
            Remote.process().beforeEachFrame(TrustedRender::checkTime);
        }
        List<Runnable> later = new ArrayList<>();
        for (int i = 0; i + 2 < args.size(); i += 3) {
            Path out = Path.of(args.get(i + 1));
            String err = null;
            try {
                checkTime();
                Scene scene = SceneLoader.load(Path.of(args.get(i)));
                String refs = System.getProperty("raylab.boundary.references");
                Speculation spec = refs == null || refs.isEmpty() ? null
                        : new Speculation(Remote.process(), Path.of(refs));
                long c0 = ProcessHandle.current().info().totalCpuDuration().map(java.time.Duration::toNanos).orElse(0L);
                long w0 = System.nanoTime();
                long s0 = spec == null ? 0 : StudentProcess.cpuNanosOf(Remote.process());
                long l0 = spec == null ? 0 : Remote.process().liveCallbacks();
                long d0 = spec == null ? 0 : Remote.process().deferredQuestions();
                long b0 = spec == null ? 0 : Remote.process().multiBytes();
                Image reference = spec == null ? null : new Image(scene.width, scene.height);
                int[] set = new int[1];
                Image image = render(scene, args.get(i + 2), spec, reference, set);
                PngFiles.write(image.toBufferedImage(), out);
                if (reference != null && set[0] == scene.width * scene.height) {
                    PngFiles.write(reference.toBufferedImage(), Path.of(out + ".reference.png"));
                    // After every scene is rendered, so that the feedback cannot change a score;
                    // only for images that differ (else it has nothing to trace, and no process is started).
                    if (raylab.inspect.WorstPixels.anyDiffers(image, reference)) {
                        Path feedback = Path.of(out + ".pixels.json");
                        later.add(() -> pixelFeedback(scene, image, reference, spec, feedback));
                    }
                }
                if (Boolean.getBoolean("raylab.boundary.raw")) {
                    writeRaw(image, Path.of(out + ".raw")); // every channel's bits, for tests
                }
                if (spec != null && System.getenv("RAYLAB_GRADE_TIMES") != null) {
                    times.printf("%s: %s, live callbacks %d, questions sent back %d, %.1f MB in frames; wall %.2f s,"
                            + " grader process CPU %.2f s, student CPU %.2f s%n",
                            args.get(i + 2), spec.counts(), Remote.process().liveCallbacks() - l0,
                            Remote.process().deferredQuestions() - d0, (Remote.process().multiBytes() - b0) / 1e6,
                            (System.nanoTime() - w0) / 1e9,
                            (ProcessHandle.current().info().totalCpuDuration().map(java.time.Duration::toNanos).orElse(0L) - c0) / 1e9,
                            (StudentProcess.cpuNanosOf(Remote.process()) - s0) / 1e9);
                }
            } catch (OutOfTime e) {
                Files.deleteIfExists(out);
                Files.writeString(Path.of(out + ".timeout"), "", StandardCharsets.UTF_8);
                continue;
            } catch (Throwable t) {
                err = failure(t, out);
            }
            if (err != null) {
                Files.deleteIfExists(out);
                Files.writeString(Path.of(out + ".err"), err.length() > 2000 ? err.substring(0, 2000) : err,
                        StandardCharsets.UTF_8);
            }
        }
        if (!later.isEmpty()) {
            // The feedback chooses its pixels by comparing with the reference image: it runs after
            // every graded image is final, with a student process of its own, so that nothing it
            // sends reaches the process whose answers were graded (grader/README.md, "What crosses
            // the boundary").
            String config = System.getProperty("raylab.boundary");
            if (config == null) {
                later.clear();
            } else {
                try {
                    Remote.switchTo(Path.of(config));
                    cpuAtStart = Remote.process().studentCpuNanos();
                    budget = Math.min(budget, FEEDBACK_NANOS);
                    Remote.process().beforeEachFrame(TrustedRender::checkTime);
                } catch (RuntimeException e) {
                    later.clear(); // no process for the feedback: no feedback, the grades stand
                }
            }
        }
        for (Runnable r : later) {
            r.run();
        }
    }

    /** The most student CPU time the graded feedback's traces may take, for all scenes. */
    private static final long FEEDBACK_NANOS = 10_000_000_000L;

    /**
     * The graded feedback of a scene that differs (issue 40): its worst pixels traced both ways, the
     * reference's tree by the milestone's reference alone ({@link Speculation#beginReference}: nothing noted or sent),
     * the student's through the process boundary one call at a time (in the feedback's own student
     * process, {@link #renderAll}), written as
     * {@link raylab.inspect.WorstPixels} JSON. Nothing is written when the images agree, when the
     * renders' time is up, or when anything goes wrong: the feedback never costs a grade.
     */
    static void pixelFeedback(Scene scene, Image image, Image reference, Speculation spec, Path file) {
        if (timeUp()) {
            return;
        }
        raylab.inspect.Tracer tracer;
        try {
            tracer = new raylab.inspect.Tracer(scene);
        } catch (RuntimeException | StackOverflowError e) {
            return;
        }
        try {
            spec.clear();
            var result = raylab.inspect.WorstPixels.find(image, reference, (x, y) -> {
                if (timeUp()) {
                    return null;
                }
                raylab.inspect.RayTree ref;
                Remote.speculate(spec);
                spec.beginReference();
                try {
                    ref = tracer.trace(x, y);
                } catch (Speculation.Unpredictable | RuntimeException | StackOverflowError e) {
                    return null;
                } finally {
                    spec.end();
                    Remote.speculate(null);
                }
                // The student's tree through this JVM's student process, one call at a time.
                try {
                    return new raylab.inspect.RayTree[] {tracer.trace(x, y), ref};
                } catch (RuntimeException | StackOverflowError e) {
                    return null;
                }
            }, scene);
            if (result.isPresent()) {
                raylab.inspect.WorstPixels.write(result.get(), file);
            }
        } catch (Throwable e) {
            try {
                Files.deleteIfExists(file);
            } catch (java.io.IOException ignored) {
                // nothing more to do: no feedback
            }
        } finally {
            Remote.speculate(null);
        }
    }

    private static void writeRaw(Image image, Path file) throws java.io.IOException {
        java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate(24 * image.width * image.height);
        for (int y = 0; y < image.height; y++) {
            for (int x = 0; x < image.width; x++) {
                Color c = image.get(x, y);
                b.putDouble(c.r).putDouble(c.g).putDouble(c.b);
            }
        }
        Files.write(file, b.array());
    }

    public static void main(String[] args) throws Exception {
        // -Draylab.boundary.renderSeconds=S: the renders' limit, S s of the student's CPU time (the grader's
        // render JVM of a milestone without tests); without it, none.
        long seconds = Long.getLong("raylab.boundary.renderSeconds", -1);
        renderAll(java.util.Arrays.asList(args), seconds < 0 ? Long.MAX_VALUE : seconds * 1_000_000_000L, System.err);
        if (Boolean.getBoolean("raylab.boundary.exit")) {
            System.exit(0); // shutdown hooks run (a profiler's dump on exit; measurements only)
        }
        Runtime.getRuntime().halt(0);
    }
}
