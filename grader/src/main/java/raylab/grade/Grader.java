package raylab.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Consumer;
import java.util.stream.Stream;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;
import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.Submission;
import raylab.course.TestLauncher;
import raylab.course.TestResult;
import raylab.grade.GradeReport.Kind;

/**
 * The autograder, as the list of its steps. For a grading: the milestones, the grader's setup,
 * the reference images (read before any student code runs), the scene variants, the submission,
 * then each milestone side by side. For each milestone M: the student's file(s) of M only are
 * compiled over the framework and the reference solutions of the other milestones; M's visible,
 * hidden and data-case tests (the grader's own copies) run on that with memory and time limits
 * ({@link MilestoneTests}); M's scenes are rendered the same way and compared with their reference
 * images ({@link SceneGrading}). The list of tests and their points comes from the grader (tests
 * run on the reference); a test scores only when the grader received its pass.
 */
public final class Grader {
    /**
     * Grading options.
     *
     * @param root        the instructor's project root (assignments/, tests, scenes)
     * @param milestones  milestone ids to grade (empty: all)
     * @param limits      limits of each test JVM
     * @param sceneLimit  time limit of one scene render
     * @param sceneHeapMb heap of a render JVM
     * @param cacheDir    where built grader classes are cached
     * @param sandboxUser unprivileged user for student code when root (null: default, "": none)
     * @param parallel    milestones graded at the same time
     */
    public record Options(Path root, List<String> milestones, TestLauncher.Limits limits, Duration sceneLimit,
            int sceneHeapMb, Path cacheDir, String sandboxUser, int parallel, Sandbox.Isolation sandboxMode) {
        public Options(Path root, List<String> milestones, TestLauncher.Limits limits, Duration sceneLimit,
                int sceneHeapMb, Path cacheDir, String sandboxUser, int parallel) {
            this(root, milestones, limits, sceneLimit, sceneHeapMb, cacheDir, sandboxUser, parallel, Sandbox.Isolation.AUTO);
        }

        public Options withSandboxMode(Sandbox.Isolation m) {
            return new Options(root, milestones, limits, sceneLimit, sceneHeapMb, cacheDir, sandboxUser, parallel,
                    m == null ? Sandbox.Isolation.AUTO : m);
        }

        public static Options defaults(Path root) {
            return new Options(root, List.of(), new TestLauncher.Limits(512, Duration.ofSeconds(120), 10, 16 * 1024),
                    Duration.ofSeconds(60), 512, root.resolve("target/grader-cache"), null,
                    Math.max(1, Math.min(2, Runtime.getRuntime().availableProcessors())));
        }

        public Options withMilestones(List<String> m) {
            return new Options(root, m, limits, sceneLimit, sceneHeapMb, cacheDir, sandboxUser, parallel, sandboxMode);
        }

        public Options withLimits(TestLauncher.Limits l, Duration scene) {
            return new Options(root, milestones, l, scene, sceneHeapMb, cacheDir, sandboxUser, parallel, sandboxMode);
        }

        public Options withSandboxUser(String u) {
            return new Options(root, milestones, limits, sceneLimit, sceneHeapMb, cacheDir, u, parallel, sandboxMode);
        }

        public Options withCache(Path c) {
            return new Options(root, milestones, limits, sceneLimit, sceneHeapMb, c, sandboxUser, parallel, sandboxMode);
        }
    }

    private final Options options;
    private final Consumer<String> log;
    private long seed = GradedScenes.freshSeed();

    public Grader(Options options, Consumer<String> log) {
        this.options = options;
        this.log = log;
    }

    /** The seed of the graded scenes' variants (default: drawn fresh). */
    public Grader seed(long s) {
        this.seed = s;
        return this;
    }

    /**
     * Grades a submission (directory or zip). Never throws for a bad submission: problems become
     * zero scores with explanations. Throws IOException only when the grader itself cannot work
     * (the caller still writes a results file, see {@link #failed}).
     */
    public GradeReport grade(Path submission) throws IOException {
        long t0 = System.nanoTime();
        Path root = options.root().toAbsolutePath();
        Assignments all = Assignments.load(root);
        List<Assignment> selected = selected(all);
        GradedScenes.validate(root, selected); // a bad variant spec stops the grading before anything runs
        // Every general note for the course staff; those a student may read also in forStudents.
        List<String> notes = new ArrayList<>();
        List<String> forStudents = new ArrayList<>();
        Consumer<String> studentNote = n -> {
            notes.add(n);
            forStudents.add(n);
        };
        Sandbox sandbox = Sandbox.detect(options.sandboxUser(), options.sandboxMode(), s -> {
            notes.add(s);
            log.accept(s);
        });
        GraderSetup setup = GraderSetup.prepare(root, selected, options.cacheDir().toAbsolutePath(), log);
        notes.addAll(setup.notes);
        phase("setup", t0);
        // Mode none: children could write the cache; it is checked against this manifest at the end.
        CacheManifest.Guard cacheGuard = sandbox.mode() == Sandbox.Isolation.NONE ? CacheManifest.guard(setup.dir) : null;
        HiddenText hidden = HiddenText.of(setup, all.all());
        Map<String, byte[]> references = references(selected);
        Map<String, GradedScenes.Graded> graded = variants(root, selected, notes);
        Submission sub = submission(submission, all, studentNote);
        List<String> accepted = new ArrayList<>();
        sub.files().keySet().forEach(k -> accepted.add(k + " <- " + sub.sources().get(k)));
        List<String> ignored = new ArrayList<>(sub.ignored());
        Path work = workFolder(sandbox);
        Map<String, GradeReport.Milestone> results;
        try {
            // The scenes without their reference images: student code cannot copy a reference.
            Path scenesCopy = work.resolve("scenes");
            copyScenes(root.resolve("scenes"), scenesCopy);
            GradingRun run = new GradingRun(options, setup, sandbox, work, scenesCopy, all.all(), graded, references);
            results = gradeMilestones(run, selected, sub, ignored, hidden);
        } finally {
            JavaBuild.deleteTreeQuietly(work);
            if (cacheGuard != null) {
                cacheGuard.check().ifPresent(studentNote);
            }
        }
        return new GradeReport(List.copyOf(results.values()), accepted, ignored, notes, forStudents,
                (System.nanoTime() - t0) / 1e9, null);
    }

    /** The milestones to grade (all when the options name none); a name that is none is an error. */
    private List<Assignment> selected(Assignments all) throws IOException {
        List<Assignment> selected = new ArrayList<>();
        for (Assignment a : all.all()) {
            if (options.milestones().isEmpty() || options.milestones().contains(a.id())) {
                selected.add(a);
            }
        }
        for (String m : options.milestones()) {
            if (all.byId(m).isEmpty()) {
                throw new IOException("no milestone '" + m + "' (milestones: " + String.join(", ", all.ids()) + ")");
            }
        }
        return selected;
    }

    /** Every reference image of the selected milestones' scenes, read before any student code runs (null: none). */
    private Map<String, byte[]> references(List<Assignment> selected) throws IOException {
        Map<String, byte[]> references = java.util.Collections.synchronizedMap(new java.util.HashMap<>());
        for (Assignment a : selected) {
            for (Assignment.GradedScene sc : a.scenes()) {
                Path ref = referenceImage(sc);
                references.put(sc.reference(), ref == null ? null : Files.readAllBytes(ref));
            }
        }
        return references;
    }

    /**
     * Variants of the graded scenes, by scene path. Their references come from the grader's
     * render (the first round of each band traces with the reference only).
     */
    private Map<String, GradedScenes.Graded> variants(Path root, List<Assignment> selected, List<String> notes)
            throws IOException {
        notes.add(GradeReport.SEED_NOTE + seed + " (grade with --seed " + seed + " to grade the same variants again)");
        long v0 = System.nanoTime();
        Map<String, GradedScenes.Graded> graded = new java.util.concurrent.ConcurrentHashMap<>();
        for (GradedScenes.Graded g : GradedScenes.forGrading(root, selected, seed, false)) {
            graded.put(g.scene().scene(), g);
            if (!g.note().isEmpty()) {
                notes.add(g.note());
            }
        }
        phase("variants", v0);
        return graded;
    }

    /** The submission's files; one that cannot be read is graded as empty, and the notes say why. */
    private static Submission submission(Path submission, Assignments all, Consumer<String> studentNote) {
        try {
            return Submission.read(submission, all.all());
        } catch (IOException e) {
            studentNote.accept("the submission could not be read: " + e.getMessage());
            return Submission.unreadable(e.getMessage());
        }
    }

    /**
     * The grading's work folder. The boxes live next to the cache (same file system: read-only
     * files can be hard-linked), in a folder others may cross but not list; without a sandbox the
     * child could walk up from its folder: then the system's temporary folder.
     */
    private Path workFolder(Sandbox sandbox) throws IOException {
        Path workParent = options.cacheDir().toAbsolutePath().resolve("work");
        Files.createDirectories(workParent);
        Path work = sandbox.mode() != Sandbox.Isolation.NONE && traversableByAll(workParent)
                ? Files.createTempDirectory(workParent, "grade")
                : Files.createTempDirectory("raylab-grade");
        Sandbox.workFolder(work);
        return work;
    }

    /**
     * Grades the milestones, side by side only when each child has its own namespaces: otherwise
     * one milestone's child could see another's (its command line in /proc names its box).
     */
    private Map<String, GradeReport.Milestone> gradeMilestones(GradingRun run, List<Assignment> selected,
            Submission sub, List<String> ignored, HiddenText hidden) throws IOException {
        Map<String, GradeReport.Milestone> results = new LinkedHashMap<>();
        ExecutorService pool = Executors.newFixedThreadPool(run.sandbox().mode() == Sandbox.Isolation.NAMESPACE
                ? Math.max(1, options.parallel()) : 1);
        try {
            Map<String, Future<GradeReport.Milestone>> futures = new LinkedHashMap<>();
            for (Assignment a : selected) {
                futures.put(a.id(), pool.submit(() -> gradeMilestone(run, a, sub, ignored, hidden)));
            }
            for (Assignment a : selected) {
                try {
                    results.put(a.id(), futures.get(a.id()).get());
                } catch (Exception e) {
                    Throwable c = e.getCause() == null ? e : e.getCause();
                    results.put(a.id(), zeroed(a, run.setup(), "the grader could not grade this milestone: " + c));
                }
            }
        } finally {
            pool.shutdownNow();
        }
        return results;
    }

    private static boolean traversableByAll(Path dir) {
        try {
            for (Path p = dir.toAbsolutePath(); p != null; p = p.getParent()) {
                if (!Files.getPosixFilePermissions(p).contains(java.nio.file.attribute.PosixFilePermission.OTHERS_EXECUTE)) {
                    return false;
                }
            }
            return true;
        } catch (IOException | UnsupportedOperationException e) {
            return true;
        }
    }

    private static void copyScenes(Path from, Path to) throws IOException {
        try (Stream<Path> s = Files.walk(from)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                Path rel = from.relativize(p);
                if (rel.toString().equals("reference") || rel.startsWith("reference")) {
                    continue;
                }
                Path t = to.resolve(rel.toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(t);
                } else if (Files.isRegularFile(p)) {
                    Files.copy(p, t);
                    // Readable by the sandboxed renderer whatever the instructor's file mode was
                    // (a scene written through a temporary file is 0600).
                    try {
                        Files.setPosixFilePermissions(t, java.nio.file.attribute.PosixFilePermissions.fromString("rw-r--r--"));
                    } catch (UnsupportedOperationException e) {
                        // not a POSIX file system: nothing to widen
                    }
                }
            }
        }
    }

    /** A report for a submission that does not exist: nothing to grade, score 0, and why. */
    public static GradeReport nothingSubmitted(String why, double seconds) {
        return new GradeReport(List.of(), List.of(), List.of(), List.of("nothing was graded: " + why), seconds);
    }

    /**
     * A report for a grading that could not run at all: no points decided ({@link GradeReport#failed}),
     * the reason for the course staff only.
     */
    public static GradeReport failed(String why, double seconds) {
        return new GradeReport(List.of(), List.of(), List.of(), List.of(GradeReport.FAILED + why), List.of(),
                seconds, why);
    }

    /**
     * One milestone's steps: whether the course can grade it, whether the submission has its
     * files, their compilation, its tests, its scenes; what a visible item shows withheld when it
     * holds text of the hidden tests.
     */
    private GradeReport.Milestone gradeMilestone(GradingRun run, Assignment a, Submission sub, List<String> ignored,
            HiddenText hidden) throws IOException {
        GraderSetup setup = run.setup();
        String cannot = cannotGrade(run, a);
        if (cannot != null) {
            // The course's setup cannot grade this milestone: it fails, the others are graded.
            return new GradeReport.Milestone(a.id(), a.title(), List.of(GradeReport.FAILED + cannot), List.of(),
                    cannot);
        }
        String absent = absentFiles(a, sub);
        if (absent != null) {
            return zeroed(a, setup, absent);
        }
        Path mdir = run.work().resolve(a.id());
        Files.createDirectories(mdir);
        StudentCompile.Compiled compiled = StudentCompile.compile(run, a, sub, mdir);
        if (compiled.errors() != null) {
            return zeroed(a, setup, compiled.errors());
        }
        List<String> notes = new ArrayList<>();
        List<Path> lower = new ArrayList<>(compiled.below());
        lower.add(setup.tests);
        for (String removed : StudentCompile.removeShadowing(a, compiled.overlay(), lower)) {
            notes.add(removed);
            synchronized (ignored) {
                ignored.add(removed);
            }
        }
        // The grader's process: the stand-ins of M's classes (their graded methods call the student
        // process), the other milestones' references, the framework.
        List<Path> trusted = new ArrayList<>();
        trusted.add(setup.standIns.get(a.id()));
        trusted.addAll(compiled.below());
        GradingRun.Milestone m = new GradingRun.Milestone(a, mdir, compiled.overlay(), trusted);
        // Tests: the visible ones (and visible data cases) in one JVM, the hidden ones in another,
        // so that nothing the visible JVM prints can hold hidden data.
        List<TestResult> expected = setup.expected.get(a.id());
        List<String> visibleClasses = MilestoneTests.visibleClasses(a, setup);
        List<String> hiddenClasses = setup.testClasses.get(a.id()).stream().filter(c -> !visibleClasses.contains(c))
                .toList();
        long t0 = System.nanoTime();
        MilestoneTests.Ran ran = MilestoneTests.run(run, m, visibleClasses, hiddenClasses, expected,
                !a.scenes().isEmpty());
        phase(a.id() + " visible and hidden" + (ran.renders() != null ? " tests and the scenes" : ""), t0);
        notes.addAll(ran.notes());
        List<GradeReport.Test> tests = new ArrayList<>(MilestoneTests.score(a, setup, plan(a), expected, ran.got()));
        long s0 = System.nanoTime();
        tests.addAll(ran.renders() != null
                ? SceneGrading.score(run, a, ran.renders(), options.sceneLimit().multipliedBy(a.scenes().size()))
                : SceneGrading.renderAlone(run, m));
        phase(a.id() + " scenes", s0);
        return new GradeReport.Milestone(a.id(), a.title(), notes.stream().map(hidden::withheld).toList(),
                tests.stream().map(hidden::withheld).toList());
    }

    /** Why the course's setup cannot grade milestone {@code a}, or null when it can. */
    private static String cannotGrade(GradingRun run, Assignment a) {
        if (run.setup().broken.containsKey(a.id())) {
            return run.setup().broken.get(a.id());
        }
        for (Assignment.GradedScene sc : a.scenes()) {
            GradedScenes.Graded g = run.graded().get(sc.scene());
            if ((g == null || !g.varied()) && run.references().get(sc.reference()) == null) {
                // Scored as published without its reference: no point of it could be decided.
                return "the reference image " + sc.reference() + " of the graded scene " + sc.scene()
                        + " is missing (render it with ./raylab reference " + sc.scene() + ")";
            }
        }
        return null;
    }

    /** Why the submission lacks the milestone's files (submitted twice, or not at all), or null when it has them. */
    private static String absentFiles(Assignment a, Submission sub) {
        List<String> missing = a.files().stream().map(Assignment.StudentFile::path)
                .filter(p -> !sub.files().containsKey(p)).toList();
        List<String> twice = missing.stream().map(p -> sub.conflicts().get(p)).filter(java.util.Objects::nonNull).toList();
        if (!twice.isEmpty()) {
            return String.join("; ", twice);
        }
        if (!missing.isEmpty()) {
            String names = String.join(", ", missing.stream().map(p -> p.substring(p.lastIndexOf('/') + 1)).toList());
            String todo = String.join(", ", a.files().stream().flatMap(f -> f.methods().stream()).toList());
            return "no " + names + " was submitted: write " + todo + " (" + a.folder() + ")";
        }
        return null;
    }

    /** A phase's time on standard error (RAYLAB_GRADE_TIMES). */
    static void phase(String what, long startNanos) {
        if (GradingRun.TIMES) {
            System.err.printf("%s %.1f s%n", what, (System.nanoTime() - startNanos) / 1e9);
        }
    }

    /** The milestone's points and test names, as check and the handouts have them. */
    private GradingPlan.Plan plan(Assignment a) throws IOException {
        return GradingPlan.of(options.root().toAbsolutePath(), a);
    }

    /** The reference PNG, rendered with the reference solution (trusted) if it is not there yet. */
    private Path referenceImage(Assignment.GradedScene sc) throws IOException {
        Path root = options.root().toAbsolutePath();
        Path ref = root.resolve(sc.reference());
        if (Files.isRegularFile(ref)) {
            return ref;
        }
        Path cached = options.cacheDir().toAbsolutePath().resolve("references").resolve(sc.reference());
        synchronized (Grader.class) {
            if (!Files.isRegularFile(cached)) {
                log.accept("grader: " + sc.reference() + " is missing; rendering it with the reference solution"
                        + " (make it with ./raylab reference " + sc.scene() + ")");
                Files.createDirectories(cached.getParent());
                Path tmp = Files.createTempDirectory(cached.getParent(), "ref");
                Path out = tmp.resolve("ref.png");
                MilestoneBuild.RenderOutcome o = MilestoneBuild.renderInChild(GraderSetup.ownClassPath(),
                        root.resolve(sc.scene()), out, Duration.ofMinutes(5), 1024, tmp);
                if (o.exitStatus() != 0 || !Files.isRegularFile(out)) {
                    JavaBuild.deleteTreeQuietly(tmp);
                    return null;
                }
                Files.move(out, cached, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
                JavaBuild.deleteTreeQuietly(tmp);
            }
        }
        return cached;
    }

    /** Every graded item of a milestone at zero, with one explanation. */
    private GradeReport.Milestone zeroed(Assignment a, GraderSetup setup, String why) throws IOException {
        List<GradeReport.Test> tests = new ArrayList<>();
        for (GradeReport.Test t : MilestoneTests.score(a, setup, plan(a), setup.expected.getOrDefault(a.id(), List.of()), Map.of())) {
            tests.add(new GradeReport.Test(t.milestone(), t.name(), t.kind(), t.maxScore(), 0, false, why, "",
                    t.visibility(), 0, t.file(), null));
        }
        for (Assignment.GradedScene sc : a.scenes()) {
            tests.add(new GradeReport.Test(a.id(), sc.scene(), Kind.SCENE,
                    sc.points(), 0, false, why, "", "visible", 0, sc.scene(), null));
        }
        return new GradeReport.Milestone(a.id(), a.title(), List.of(why), tests);
    }
}
