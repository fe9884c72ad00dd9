package raylab.grade;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;

import raylab.boundary.GradingFailure;
import raylab.course.Assignment;
import raylab.course.JavaBuild;
import raylab.course.TestLauncher;
import raylab.grade.GradeReport.Kind;
import raylab.render.ImageCompare;

/**
 * A milestone's graded scenes: rendered by {@code TrustedRender} in the grader's process (the
 * stand-ins call the student process in its box; the PNGs are encoded there), then each render
 * compared with its reference or its variant's reference. The renders run at the end of the
 * milestone's test JVM ({@link MilestoneTests}) or, when that JVM had no tests to run, in a render
 * JVM of their own ({@link #renderAlone}).
 */
final class SceneGrading {
    private SceneGrading() {
    }

    /**
     * What the render of one scene left.
     *
     * @param image         the student's PNG (null: none)
     * @param error         the first line of its error (null: none)
     * @param late          stopped at the renders' time limit
     * @param gradingFailed its error is the grader's, not the student's code's ({@link GradingFailure#RENDER_MARKER})
     * @param referenceMade the variant's reference image the render made with it (null: none)
     * @param pixels        the graded feedback's worst pixels (raylab.inspect.WorstPixels JSON), or null
     */
    record Render(byte[] image, String error, boolean late, boolean gradingFailed, byte[] referenceMade,
            String pixels) {
    }

    /**
     * What the renders of M's scenes left.
     *
     * @param scenes      per scene in the milestone's order
     * @param timedOut    the JVM that rendered them was stopped by its wall-clock guard
     * @param outOfMemory the render JVM ran out of memory
     * @param millis      the time of one scene
     * @param ended       how the JVM that rendered them ended early and what it said (its exit status,
     *                    the first line of its standard error), for the course staff; "" when it did not
     */
    record Renders(List<Render> scenes, boolean timedOut, boolean outOfMemory, long millis, String ended) {
    }

    /**
     * The arguments of {@code TrustedRender} for M's scenes (triples SCENE.json OUT.png NAME, the
     * PNGs in {@code dir}, added to {@code pngs}); each variant is written next to its published
     * scene in the grader's copy of {@code scenes/} (relative paths of meshes resolve as before).
     */
    static List<String> arguments(GradingRun run, Assignment a, Path dir, List<Path> pngs) throws IOException {
        Path root = run.root();
        List<String> out = new ArrayList<>();
        for (int i = 0; i < a.scenes().size(); i++) {
            Assignment.GradedScene sc = a.scenes().get(i);
            Path scene = run.scenesCopy().resolve(root.resolve("scenes").relativize(root.resolve(sc.scene())).toString());
            GradedScenes.Graded g = run.graded().get(sc.scene());
            if (g != null && g.varied()) {
                Path v = scene.resolveSibling("variant-" + a.id() + "-" + i + "-" + scene.getFileName());
                Files.writeString(v, g.json());
                scene = v;
            }
            Path png = dir.resolve("scene" + i + ".png");
            out.add(scene.toString());
            out.add(png.toString());
            out.add(sc.scene());
            pngs.add(png);
        }
        return out;
    }

    /** What each render left: the PNG and the first line of its error, capped in size, not following links. */
    static List<Render> read(List<Path> pngs) {
        List<Render> out = new ArrayList<>();
        for (Path png : pngs) {
            byte[] px = readCapped(Path.of(png + ".pixels.json"), 256 * 1024);
            byte[] err = readCapped(Path.of(png + ".err"), 64 * 1024);
            out.add(new Render(readCapped(png, 64L << 20),
                    err == null ? null : GraderSetup.firstLine(new String(err, StandardCharsets.UTF_8))
                            .replaceFirst("^raylab: ", ""),
                    Files.exists(Path.of(png + ".timeout"), LinkOption.NOFOLLOW_LINKS),
                    Files.exists(Path.of(png + GradingFailure.RENDER_MARKER), LinkOption.NOFOLLOW_LINKS),
                    readCapped(Path.of(png + ".reference.png"), 64L << 20),
                    px == null ? null : new String(px, StandardCharsets.UTF_8)));
        }
        return out;
    }

    /**
     * Renders the milestone's scenes in a render JVM of their own (stand-ins calling a student
     * process in its box) and compares each with its reference.
     */
    static List<GradeReport.Test> renderAlone(GradingRun run, GradingRun.Milestone m) throws IOException {
        Assignment a = m.a();
        if (a.scenes().isEmpty()) {
            return new ArrayList<>();
        }
        Grader.Options options = run.options();
        List<Path> cp = run.trustedClassPath(m.trusted(), true);
        Sandbox.Box box = run.studentBox(a, m.overlay(), m.dir());
        Path dir = Files.createTempDirectory(m.dir(), "render");
        Path config = dir.resolve("student.properties");
        raylab.boundary.Remote.writeConfig(config, run.studentConfig(a, box, m.overlay(),
                options.sceneLimit().toMillis(), options.sceneHeapMb()));
        List<String> cmd = new ArrayList<>(List.of(JavaBuild.javaExecutable(),
                "-Xmx" + options.sceneHeapMb() + "m", "-XX:+ExitOnOutOfMemoryError", "-Djava.awt.headless=true",
                // Grader code only: every module (--limit-modules would turn class data sharing off).
                "-XX:+DisableAttachMechanism", "-XX:-UsePerfData",
                "-Draylab.boundary=" + config,
                // The renders' limit in the student's CPU time; this JVM's wall clock below is only a guard.
                "-Draylab.boundary.renderSeconds=" + options.sceneLimit().multipliedBy(a.scenes().size()).toSeconds()));
        // Quick to start: C1 only (a render of seconds pays C2's compile time back rarely).
        cmd.addAll(JavaBuild.QUICK_JVM);
        cmd.addAll(JvmOptions.trusted(options.sceneHeapMb()));
        cmd.addAll(GradingRun.extraJvmOptions("RAYLAB_RENDER_JVM_OPTS"));
        cmd.addAll(List.of(
                // The milestone's reference predicts the student's answers, so that calls go in batches.
                "-Draylab.boundary.references=" + run.setup().references.get(a.id()).toAbsolutePath(),
                "-cp", String.join(java.io.File.pathSeparator,
                        cp.stream().map(Path::toString).toList()), "raylab.boundary.TrustedRender"));
        List<Path> pngs = new ArrayList<>();
        cmd.addAll(arguments(run, a, dir, pngs));
        long t0 = System.nanoTime();
        Duration limit = options.sceneLimit().multipliedBy(a.scenes().size());
        boolean timedOut = false;
        List<Render> renders;
        Process p = null;
        // The render JVM's standard error is the JVM's and the grader's own (the student's code runs
        // in its student process): its first line names why it did not start or ended early.
        Path err = dir.resolve("render-jvm.err");
        String said = "";
        try {
            ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile())
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                    .redirectError(GradingRun.TIMES ? ProcessBuilder.Redirect.INHERIT : ProcessBuilder.Redirect.to(err.toFile()));
            p = pb.start();
            p.getOutputStream().close();
            try {
                if (!p.waitFor(limit.toMillis() * TestLauncher.GUARD_FACTOR, TimeUnit.MILLISECONDS)) {
                    timedOut = true;
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                timedOut = true;
            }
            JavaBuild.stop(p);
            // Read what the child left only once it is gone.
            renders = read(pngs);
            said = firstLineOf(err);
        } finally {
            if (p != null) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
            }
            run.sandbox().finish(box, null);
            JavaBuild.deleteTreeQuietly(dir);
        }
        long ms = (System.nanoTime() - t0) / 1_000_000 / a.scenes().size();
        // -XX:+ExitOnOutOfMemoryError ends the JVM with status 3 when the heap runs out.
        boolean outOfMemory = p != null && !timedOut && !p.isAlive() && p.exitValue() == 3;
        String ended = p == null || timedOut || p.isAlive() || p.exitValue() == 0 ? ""
                : "exit status " + p.exitValue() + (said.isEmpty() ? "" : "; it said: " + said);
        return score(run, a, new Renders(renders, timedOut, outOfMemory, ms, ended), limit);
    }

    /** The first non-blank line of the first 8 KB of {@code f}, control characters dropped; "" if none. */
    static String firstLineOf(Path f) {
        byte[] head = new byte[8192];
        int n = 0;
        try (java.io.InputStream in = Files.newInputStream(f, LinkOption.NOFOLLOW_LINKS)) {
            n = in.readNBytes(head, 0, head.length);
        } catch (IOException e) {
            return "";
        }
        for (String line : new String(head, 0, n, StandardCharsets.UTF_8).split("[\\r\\n]+")) {
            String clean = line.replaceAll("\\p{Cntrl}", "").strip();
            if (!clean.isEmpty()) {
                return clean.length() > 300 ? clean.substring(0, 300) : clean;
            }
        }
        return "";
    }

    /**
     * Whether a scene without an image is the grading's failure: its render marked its error so
     * ({@link GradingFailure#RENDER_MARKER}), or it has no error at all and was not stopped at the
     * renders' limit, so the render JVM did not finish it. That JVM runs no code of the student's
     * (the student's runs in its student process, whose failures are errors): its crash, its
     * memory and its wall-clock guard are the grading's, not the student's.
     */
    static boolean gradingsFailure(Render r) {
        return !r.late() && (r.gradingFailed() || r.error() == null || r.error().isEmpty());
    }

    /**
     * M's scene items: each render compared with its reference ({@link Render#late}: stopped at
     * the time limit; {@link Renders#timedOut}: the whole run was).
     */
    static List<GradeReport.Test> score(GradingRun run, Assignment a, Renders renders, Duration limit) {
        List<GradeReport.Test> out = new ArrayList<>();
        List<String> studentFiles = a.files().stream().map(Assignment.StudentFile::path).toList();
        for (int i = 0; i < a.scenes().size(); i++) {
            Assignment.GradedScene sc = a.scenes().get(i);
            Render r = renders.scenes().get(i);
            GradedScenes.Graded g = run.graded().get(sc.scene());
            byte[] refBytes = g != null && g.varied() ? variantReference(run, g, r.referenceMade())
                    : run.references().get(sc.reference());
            byte[] mine = r.image();
            String errLine = r.error() == null ? "" : r.error();
            String msg;
            GradeReport.Images shown = null;
            boolean passed = false;
            GradingStatus status = GradingStatus.GRADED;
            if (refBytes == null) {
                msg = "grader setup problem: no reference image " + sc.reference();
            } else if (mine == null || r.error() != null) {
                if (gradingsFailure(r)) {
                    status = GradingStatus.GRADING_FAILED;
                }
                msg = r.late() ? "your code used more than " + limit.toSeconds()
                                + " s of CPU time in the renders and was stopped (an endless loop, or far too slow?)"
                        : r.gradingFailed() ? GradingStatus.message(errLine)
                        : !errLine.isEmpty() ? raylab.course.Explain.renderFailure(errLine, studentFiles)
                        : renders.outOfMemory() ? GradingStatus.message("the grader's render JVM ran out of its memory ("
                                + run.options().sceneHeapMb() + " MB) before this scene was rendered: the student's code"
                                + " runs in a process of its own, whose memory is its own")
                        : renders.timedOut() ? GradingStatus.message("the grader's render JVM was stopped by its wall-clock"
                                + " guard before this scene was rendered, although the renders' limit is in the student's"
                                + " CPU time: the machine or the grader was too slow")
                        : GradingStatus.message("the grader's JVM that renders the scenes ended early, before this scene"
                                + " was rendered, and it runs no code of the student's: "
                                + (renders.ended().isEmpty() ? "a crash, or the machine's memory" : renders.ended()));
                shown = new GradeReport.Images(null, refBytes, null, "");
            } else {
                try {
                    BufferedImage img = ImageIO.read(new java.io.ByteArrayInputStream(mine));
                    BufferedImage ref = ImageIO.read(new java.io.ByteArrayInputStream(refBytes));
                    if (img == null) {
                        throw new IOException("not a PNG image");
                    }
                    ImageCompare.Result c = ImageCompare.compare(img, ref);
                    passed = c.matches(sc.tolerance());
                    String metric = c.summary() + "; allowed: " + String.format(java.util.Locale.ROOT, "%.3f%%",
                            100 * sc.tolerance());
                    msg = passed ? "" : "the image differs from the reference: " + metric
                            + " (your render, the reference and the difference are shown side by side)";
                    shown = new GradeReport.Images(mine, refBytes, png(c.diff()), metric,
                            passed ? "" : PixelFeedback.valid(r.pixels()));
                    msg += passed ? "" : PixelFeedback.summaryLine(shown.pixels());
                } catch (IOException | RuntimeException e) {
                    msg = "the rendered image could not be compared: " + e.getMessage();
                    shown = new GradeReport.Images(null, refBytes, null, "");
                }
            }
            out.add(new GradeReport.Test(a.id(), sc.scene(), Kind.SCENE, sc.points(), passed ? sc.points() : 0, passed,
                    msg, "", "visible", renders.millis(), sc.scene(), shown, "", status));
        }
        return out;
    }

    /**
     * A variant's reference: rendered with the variant ({@code made}, by the grader's render:
     * the reference's own trace) or, if that render could not make it, rendered here now.
     */
    private static byte[] variantReference(GradingRun run, GradedScenes.Graded g, byte[] made) {
        if (g.reference() != null) {
            return g.reference();
        }
        if (made != null) {
            return made;
        }
        if (GradingRun.TIMES) {
            System.err.println(g.scene().scene() + ": the variant's reference rendered here");
        }
        try {
            return GradedScenes.renderReference(g.json(), run.root().resolve(g.scene().scene()));
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** The bytes of a regular file (not a link), or null when there is none or it is larger than {@code cap}. */
    static byte[] readCapped(Path f, long cap) {
        try {
            if (!Files.isRegularFile(f, LinkOption.NOFOLLOW_LINKS) || Files.size(f) > cap) {
                return null;
            }
            return Files.readAllBytes(f);
        } catch (IOException e) {
            return null;
        }
    }

    static byte[] png(BufferedImage img) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        ImageIO.write(img, "png", b);
        return b.toByteArray();
    }
}
