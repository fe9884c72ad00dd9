package raylab.grade;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
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

import javax.imageio.ImageIO;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;
import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.Submission;
import raylab.course.TestLauncher;
import raylab.course.TestResult;
import raylab.grade.GradeReport.Kind;
import raylab.render.ImageCompare;

/**
 * The autograder. For each milestone M: the student's file(s) of M only are compiled over the
 * framework and the reference solutions of the other milestones, and M's visible, hidden and
 * data-case tests (the grader's own copies) run on that in a separate JVM with memory and time
 * limits; M's scenes are rendered the same way and compared with their reference images. The
 * list of tests and their points comes from the grader (tests run on the reference); a test
 * scores only when the grader received its pass.
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

    /** Phase times on standard error (environment variable RAYLAB_GRADE_TIMES; measurements only). */
    private static final boolean TIMES = System.getenv("RAYLAB_GRADE_TIMES") != null;

    /** JVM options from an environment variable, split at spaces (measurements only: flags to compare). */
    private static List<String> extraJvmOptions(String variable) {
        String v = System.getenv(variable);
        return v == null || v.isBlank() ? List.of() : List.of(v.trim().split("\\s+"));
    }

    private final Options options;
    private final Consumer<String> log;
    private List<Assignment> allAssignments = List.of();
    /** Text found only in hidden classes: never shown in a visible test's output or message. */
    private java.util.Set<String> hiddenTexts = java.util.Set.of();
    /** Reference PNG bytes by reference path, read before any student code ran (null: none). */
    private final Map<String, byte[]> references = java.util.Collections.synchronizedMap(new java.util.HashMap<>());

    public Grader(Options options, Consumer<String> log) {
        this.options = options;
        this.log = log;
    }

    /** Graded scenes of this grading by scene path: the variants and their references (GradedScenes). */
    private final Map<String, GradedScenes.Graded> graded = new java.util.concurrent.ConcurrentHashMap<>();
    private long seed = GradedScenes.freshSeed();

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
        GradedScenes.validate(root, selected); // a bad variant spec stops the grading before anything runs
        List<String> notes = new ArrayList<>();
        Sandbox sandbox = Sandbox.detect(options.sandboxUser(), options.sandboxMode(), s -> {
            notes.add(s);
            log.accept(s);
        });
        GraderSetup setup = GraderSetup.prepare(root, selected, options.cacheDir().toAbsolutePath(), log);
        notes.addAll(setup.notes);
        if (TIMES) {
            System.err.printf("setup %.1f s%n", (System.nanoTime() - t0) / 1e9);
        }
        // Mode none: children could write the cache; it is checked against this manifest at the end.
        CacheManifest.Guard cacheGuard = sandbox.mode() == Sandbox.Isolation.NONE ? CacheManifest.guard(setup.dir) : null;
        this.allAssignments = all.all();
        this.hiddenTexts = hiddenTexts(setup, all.all());
        // Every reference image is read before any student code runs.
        for (Assignment a : selected) {
            for (Assignment.GradedScene sc : a.scenes()) {
                Path ref = referenceImage(sc);
                references.put(sc.reference(), ref == null ? null : Files.readAllBytes(ref));
            }
        }
        // Variants of the graded scenes. Their references come from the grader's render (the first
        // round of each band traces with the reference only).
        notes.add(GradeReport.SEED_NOTE + seed + " (grade with --seed " + seed + " to grade the same variants again)");
        long v0 = System.nanoTime();
        for (GradedScenes.Graded g : GradedScenes.forGrading(root, selected, seed, false)) {
            graded.put(g.scene().scene(), g);
            if (!g.note().isEmpty()) {
                notes.add(g.note());
            }
        }
        if (TIMES) {
            System.err.printf("variants %.1f s%n", (System.nanoTime() - v0) / 1e9);
        }

        Submission read;
        try {
            read = Submission.read(submission, all.all());
        } catch (IOException e) {
            read = Submission.unreadable(e.getMessage());
            notes.add("the submission could not be read: " + e.getMessage());
        }
        final Submission sub = read;
        List<String> accepted = new ArrayList<>();
        sub.files().keySet().forEach(k -> accepted.add(k + " <- " + sub.sources().get(k)));
        List<String> ignored = new ArrayList<>(sub.ignored());

        // The boxes live next to the cache (same file system: read-only files can be hard-linked),
        // in a folder others may cross but not list.
        Path workParent = options.cacheDir().toAbsolutePath().resolve("work");
        Files.createDirectories(workParent);
        // Without a sandbox the child could walk up from its folder: then the system's temporary folder.
        Path work = sandbox.mode() != Sandbox.Isolation.NONE && traversableByAll(workParent)
                ? Files.createTempDirectory(workParent, "grade")
                : Files.createTempDirectory("raylab-grade");
        Sandbox.workFolder(work);
        Map<String, GradeReport.Milestone> results = new LinkedHashMap<>();
        // Side by side only when each child has its own namespaces: otherwise one milestone's child
        // could see another's (its command line in /proc names its box).
        ExecutorService pool = Executors.newFixedThreadPool(sandbox.mode() == Sandbox.Isolation.NAMESPACE
                ? Math.max(1, options.parallel()) : 1);
        try {
            // The scenes without their reference images: student code cannot copy a reference.
            Path scenesCopy = work.resolve("scenes");
            copyScenes(root.resolve("scenes"), scenesCopy);
            Map<String, Future<GradeReport.Milestone>> futures = new LinkedHashMap<>();
            for (Assignment a : selected) {
                futures.put(a.id(), pool.submit(() -> gradeMilestone(a, sub, setup, work, scenesCopy, sandbox, ignored)));
            }
            for (Assignment a : selected) {
                try {
                    results.put(a.id(), futures.get(a.id()).get());
                } catch (Exception e) {
                    Throwable c = e.getCause() == null ? e : e.getCause();
                    results.put(a.id(), zeroed(a, setup, "the grader could not grade this milestone: " + c));
                }
            }
        } finally {
            pool.shutdownNow();
            JavaBuild.deleteTreeQuietly(work);
            if (cacheGuard != null) {
                cacheGuard.check().ifPresent(notes::add);
            }
        }
        return new GradeReport(List.copyOf(results.values()), accepted, ignored, notes,
                (System.nanoTime() - t0) / 1e9);
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
        return new GradeReport(List.of(), List.of(), List.of(), List.of(GradeReport.FAILED + why), seconds);
    }

    private GradeReport.Milestone gradeMilestone(Assignment a, Submission sub, GraderSetup setup, Path work,
            Path scenesCopy, Sandbox sandbox, List<String> ignored) throws IOException {
        if (setup.broken.containsKey(a.id())) {
            // The course's setup cannot grade this milestone: it fails, the others are graded.
            return new GradeReport.Milestone(a.id(), a.title(), List.of(GradeReport.FAILED + setup.broken.get(a.id())),
                    List.of());
        }
        for (Assignment.GradedScene sc : a.scenes()) {
            GradedScenes.Graded g = graded.get(sc.scene());
            if ((g == null || !g.varied()) && references.get(sc.reference()) == null) {
                // Scored as published without its reference: no point of it could be decided.
                return new GradeReport.Milestone(a.id(), a.title(), List.of(GradeReport.FAILED + "the reference image "
                        + sc.reference() + " of the graded scene " + sc.scene() + " is missing (render it with"
                        + " ./raylab reference " + sc.scene() + ")"), List.of());
            }
        }
        Path mdir = work.resolve(a.id());
        Files.createDirectories(mdir);
        List<String> notes = new ArrayList<>();
        List<String> missing = a.files().stream().map(Assignment.StudentFile::path)
                .filter(p -> !sub.files().containsKey(p)).toList();
        List<String> twice = missing.stream().map(p -> sub.conflicts().get(p)).filter(java.util.Objects::nonNull).toList();
        if (!twice.isEmpty()) {
            return zeroed(a, setup, String.join("; ", twice));
        }
        if (!missing.isEmpty()) {
            String names = String.join(", ", missing.stream().map(p -> p.substring(p.lastIndexOf('/') + 1)).toList());
            String todo = String.join(", ", a.files().stream().flatMap(f -> f.methods().stream()).toList());
            return zeroed(a, setup, "no " + names + " was submitted: write " + todo + " (" + a.folder() + ")");
        }
        // Compile the student's file(s) of this milestone over the framework and the other references.
        Path overlay = mdir.resolve("overlay");
        List<Path> below = new ArrayList<>();
        for (var e : setup.references.entrySet()) {
            if (!e.getKey().equals(a.id())) {
                below.add(e.getValue());
            }
        }
        // References of milestones not selected are still needed by this milestone's code.
        Path otherRefs = mdir.resolve("other-refs");
        below.add(otherRefs);
        copyOtherReferences(a, setup, otherRefs);
        below.add(setup.framework);
        below.addAll(setup.libraries);
        Map<String, String> files = new LinkedHashMap<>();
        for (Assignment.StudentFile f : a.files()) {
            files.put(f.path().substring("src/main/java/".length()), sub.files().get(f.path()));
        }
        long c0 = System.nanoTime();
        JavaBuild.Result compiled = MilestoneBuild.compileOverlay(files, mdir.resolve("src"), below, overlay);
        if (TIMES) {
            System.err.printf("%s compile %.1f s%n", a.id(), (System.nanoTime() - c0) / 1e9);
        }
        // Children reach their boxes through this folder, but nothing else in it.
        Sandbox.workFolder(mdir);
        for (Path p : List.of(mdir.resolve("src"), overlay, otherRefs)) {
            if (Files.isDirectory(p)) {
                Sandbox.privateFolder(p);
            }
        }
        if (!compiled.success()) {
            StringBuilder msg = new StringBuilder("your code does not compile, so this milestone scores 0:");
            for (JavaBuild.Problem p : compiled.errors().stream().limit(10).toList()) {
                String file = p.file() == null ? "" : mdir.resolve("src").relativize(p.file()).toString();
                msg.append("\n  ").append(file.isEmpty() ? "" : "src/main/java/" + file + ":" + p.line() + ": ")
                        .append(p.message());
            }
            Map<String, String> graded = new LinkedHashMap<>();
            files.forEach((k, v) -> graded.put("src/main/java/" + k, v));
            for (String use : raylab.course.GradedBuild.atGrader(graded, sub.framework(), below)) {
                msg.append("\n  ").append(use);
            }
            return zeroed(a, setup, msg.toString());
        }
        List<Path> lower = new ArrayList<>(below);
        lower.add(setup.tests);
        for (String removed : checkOverlay(a, overlay, lower)) {
            notes.add(removed);
            synchronized (ignored) {
                ignored.add(removed);
            }
        }
        List<GradeReport.Test> tests = new ArrayList<>();
        // Tests: the visible ones (and visible data cases) in one JVM, the hidden ones in another,
        // so that nothing the visible JVM prints can hold hidden data.
        List<TestResult> expected = setup.expected.get(a.id());
        Map<String, TestResult> got = new LinkedHashMap<>();
        List<String> classes = setup.testClasses.get(a.id());
        List<String> visibleClasses = classes.stream().filter(c -> kindOf(a, c) == Kind.VISIBLE
                || c.equals(DataCases.visibleClassName(a.id()))).toList();
        List<String> hiddenClasses = classes.stream().filter(c -> !visibleClasses.contains(c)).toList();
        // The grader's process: the stand-ins of M's classes (their graded methods call the student
        // process), the other milestones' references, the framework.
        List<Path> trusted = new ArrayList<>();
        trusted.add(setup.standIns.get(a.id()));
        trusted.addAll(below);
        long t0 = System.nanoTime();
        Renders renders = a.scenes().isEmpty() ? null : new Renders();
        runTests(a, visibleClasses, hiddenClasses, expected, trusted, overlay, setup, mdir, sandbox, got, notes,
                renders, scenesCopy);
        if (TIMES) {
            System.err.printf("%s visible and hidden%s %.1f s%n", a.id(), renders != null && renders.done
                    ? " tests and the scenes" : "", (System.nanoTime() - t0) / 1e9);
        }
        tests.addAll(scoreTests(a, setup, plan(a), expected, got));
        // Scenes.
        long s0 = System.nanoTime();
        tests.addAll(renders != null && renders.done ? scoreScenes(a, renders.images, renders.errors, renders.late,
                renders.references, renders.pixels, renders.timedOut, false, renders.millis, options.sceneLimit().multipliedBy(a.scenes().size()))
                : gradeScenes(a, trusted, overlay, setup, mdir, scenesCopy, sandbox));
        if (TIMES) {
            System.err.printf("%s scenes %.1f s%n", a.id(), (System.nanoTime() - s0) / 1e9);
        }
        return new GradeReport.Milestone(a.id(), a.title(), notes.stream().map(this::withheld).toList(),
                tests.stream().map(this::withheld).toList());
    }

    private static final String WITHHELD = "(withheld: it contains text of the hidden tests)";

    /** A visible test's message and output, unless they contain text of the hidden tests. */
    private GradeReport.Test withheld(GradeReport.Test t) {
        if (!"visible".equals(t.visibility())) {
            return t;
        }
        String m = withheld(t.message());
        String o = withheld(t.output());
        if (m.equals(t.message()) && o.equals(t.output())) {
            return t;
        }
        return new GradeReport.Test(t.milestone(), t.name(), t.kind(), t.maxScore(), t.score(), t.passed(), m, o,
                t.visibility(), t.millis(), t.file(), t.images(), withheld(t.note()));
    }

    private String withheld(String text) {
        if (text == null || text.isEmpty()) {
            return text == null ? "" : text;
        }
        for (String h : hiddenTexts) {
            if (text.contains(h)) {
                return WITHHELD;
            }
        }
        return text;
    }

    /**
     * Text of the hidden classes (hidden tests, hidden data cases, hidden helpers) that no visible
     * class has: their names, and their text constants with a space in them (messages, hints).
     */
    private static java.util.Set<String> hiddenTexts(GraderSetup setup, List<Assignment> all) {
        java.util.Set<String> visibleClasses = new java.util.HashSet<>();
        for (Assignment a : all) {
            a.tests().visible().forEach(v -> visibleClasses.add(GraderSetup.testClassName(v)));
            visibleClasses.add(DataCases.visibleClassName(a.id()));
        }
        java.util.Set<String> hiddenClasses = new java.util.HashSet<>();
        setup.testClasses.values().forEach(l -> l.stream().filter(c -> !visibleClasses.contains(c))
                .forEach(hiddenClasses::add));
        java.util.Set<String> hidden = new java.util.HashSet<>();
        java.util.Set<String> shared = new java.util.HashSet<>();
        try (Stream<Path> s = Files.walk(setup.tests)) {
            for (Path p : (Iterable<Path>) s.filter(f -> f.toString().endsWith(".class"))::iterator) {
                String rel = setup.tests.relativize(p).toString().replace('\\', '/');
                String outer = GraderSetup.outer(rel.substring(0, rel.length() - 6).replace('/', '.'));
                boolean isHidden = hiddenClasses.contains(outer) || outer.startsWith("raylab.hidden.");
                java.util.Set<String> strings = ClassStrings.of(Files.readAllBytes(p));
                if (isHidden) {
                    hidden.addAll(strings);
                    hidden.add(outer);
                    hidden.add(outer.replace('.', '/'));
                } else {
                    shared.addAll(strings);
                }
            }
        } catch (IOException e) {
            return java.util.Set.of();
        }
        java.util.Set<String> out = new java.util.HashSet<>();
        for (String h : hidden) {
            boolean name = h.contains("Hidden") || hiddenClasses.contains(h) || hiddenClasses.contains(h.replace('/', '.'));
            boolean text = h.length() >= 12 && h.indexOf(' ') >= 0 && !h.isBlank();
            if (!shared.contains(h) && (name || text)) {
                out.add(h);
            }
        }
        return out;
    }

    /** Libraries a test JVM needs (JUnit and Jackson); a render JVM takes all but Maven's. */
    private static boolean libraryFor(Path lib, boolean render) {
        String n = lib.getFileName().toString();
        if (n.matches("\\d+-(surefire|common-java5).*")) {
            return false;
        }
        return render || n.matches("\\d+-(junit|opentest4j|apiguardian|jackson).*");
    }

    /**
     * The student process's box: the student's classes of M, the public stubs of the other
     * student files and the public framework (as the starter has it); nothing else (no
     * reference, no test, no grader class).
     */
    private Sandbox.Box studentBox(Assignment a, Path overlay, GraderSetup setup, Path mdir, Sandbox sandbox)
            throws IOException {
        List<String> mine = a.files().stream().map(f -> GraderSetup.classPrefix(f.path())).toList();
        return sandbox.box(mdir, List.of(overlay, setup.publicStubs, setup.publicFramework), (entry, rel) ->
                !entry.equals(setup.publicStubs) || mine.stream().noneMatch(x -> GraderSetup.isClassOf(rel, x)));
    }

    /** How the grader's process starts the student process in {@code box}, with a CPU budget per call. */
    private raylab.boundary.StudentProcess.Config studentConfig(Assignment a, Sandbox.Box box, Path overlay,
            long budgetMillis, int heapMb) throws IOException {
        java.util.Set<String> students = new java.util.TreeSet<>();
        try (Stream<Path> s = Files.walk(overlay)) {
            for (Path p : (Iterable<Path>) s.filter(f -> f.toString().endsWith(".class"))::iterator) {
                String rel = overlay.relativize(p).toString().replace('\\', '/');
                students.add(GraderSetup.outer(rel.substring(0, rel.length() - 6).replace('/', '.')));
            }
        }
        List<String> cmd = new ArrayList<>(box.wrapper());
        // The protocol on file descriptors of its own: the JVM's output and the student's raw
        // writes to 1 and 2 go to the stderr file (StudentServer.CHANNEL_WRAPPER).
        cmd.addAll(raylab.remote.StudentServer.CHANNEL_WRAPPER);
        cmd.addAll(List.of(JavaBuild.javaExecutable(),
                raylab.remote.StudentServer.CHANNEL_JVM_OPTION, "-Xmx" + heapMb + "m",
                "-Xss4m", "-XX:+ExitOnOutOfMemoryError", "-Djava.awt.headless=true",
                "-XX:+DisableAttachMechanism", "-XX:-UsePerfData", "--limit-modules", TestLauncher.CHILD_MODULES,
                "-Dfile.encoding=UTF-8"));
        // C1 only: at 0.5 CPU, C2's compiler threads cost more than its faster code saves,
        // even in a render's hundreds of thousands of calls (grader/README.md).
        cmd.addAll(JavaBuild.QUICK_JVM);
        cmd.addAll(JvmOptions.student(heapMb));
        cmd.addAll(extraJvmOptions("RAYLAB_STUDENT_JVM_OPTS"));
        cmd.addAll(List.of("-cp", String.join(java.io.File.pathSeparator, box.classPath()),
                "raylab.remote.StudentServer", "--channel",
                // Stuck code is named after the watchdog's bound: a call of the reference takes far less.
                raylab.remote.StudentServer.STUCK_AFTER, Long.toString(raylab.course.Watchdog.bound(0).toMillis())));
        for (String c : students) {
            cmd.add("--student");
            cmd.add(c);
        }
        return new raylab.boundary.StudentProcess.Config(cmd, box.run(),
                java.util.Set.copyOf(GraderSetup.servedClasses(a)), budgetMillis, 3);
    }

    /**
     * Runs M's test classes in the grader's process (a JVM of trusted code: tests, stand-ins,
     * references) whose stand-ins call a student process in its box: first the visible classes,
     * to their end, then the hidden ones with a new student process in a new box, so that nothing
     * hidden reaches student code before every visible result is reported. Results go into
     * {@code got}.
     */
    private void runTests(Assignment a, List<String> visibleClasses, List<String> hiddenClasses,
            List<TestResult> allExpected, List<Path> trusted, Path overlay, GraderSetup setup, Path mdir,
            Sandbox sandbox, Map<String, TestResult> got, List<String> notes, Renders renders, Path scenesCopy)
            throws IOException {
        java.util.Set<String> visible = new java.util.HashSet<>(visibleClasses);
        java.util.Set<String> hidden = new java.util.HashSet<>(hiddenClasses);
        List<TestResult> expected = allExpected.stream().filter(e -> visible.contains(GraderSetup.outer(e.className()))
                || hidden.contains(GraderSetup.outer(e.className()))).toList();
        if (expected.isEmpty()) {
            return;
        }
        List<Path> cp = new ArrayList<>();
        cp.add(setup.tests); // the grader's tests first
        for (Path p : trusted) {
            if (!setup.libraries.contains(p) || libraryFor(p, renders != null)) {
                cp.add(p);
            }
        }
        Path dir = Files.createTempDirectory(mdir, "tests");
        List<Sandbox.Box> boxes = new ArrayList<>();
        try {
            List<String> classes = new ArrayList<>();
            for (int g = 0; g < 2; g++) {
                Sandbox.Box box = studentBox(a, overlay, setup, mdir, sandbox);
                boxes.add(box);
                Path config = dir.resolve(g == 0 ? "visible.properties" : "hidden.properties");
                raylab.boundary.Remote.writeConfig(config, studentConfig(a, box, overlay,
                        options.limits().perTestSeconds() * 1000L, options.limits().heapMegabytes()));
                if (g == 0) {
                    classes.addAll(visibleClasses);
                } else {
                    classes.add(TestLauncher.thenBoundary(config));
                    classes.addAll(hiddenClasses);
                }
            }
            // The scenes last, in the same JVM, with a third student process (nothing a test
            // passed to student code reaches a picture).
            List<Path> pngs = new ArrayList<>();
            Duration sceneLimit = options.sceneLimit().multipliedBy(renders == null ? 0 : a.scenes().size());
            List<String> jvm = new ArrayList<>(List.of("-Draylab.boundary=" + dir.resolve("visible.properties")));
            if (renders != null) {
                Sandbox.Box box = studentBox(a, overlay, setup, mdir, sandbox);
                boxes.add(box);
                Path config = dir.resolve("render.properties");
                raylab.boundary.Remote.writeConfig(config, studentConfig(a, box, overlay,
                        options.sceneLimit().toMillis(), options.sceneHeapMb()));
                Path rdir = Files.createDirectory(dir.resolve("render"));
                Path list = rdir.resolve("scenes.txt");
                Files.write(list, sceneArguments(a, rdir, scenesCopy, pngs));
                classes.add(TestLauncher.thenRender(config, list, sceneLimit.toSeconds()));
                // The milestone's reference predicts the student's answers, so that calls go in batches.
                jvm.add("-Draylab.boundary.references=" + setup.references.get(a.id()).toAbsolutePath());
            }
            // One JVM for both groups and the scenes, so the milestone's time limits cover all.
            TestLauncher.Limits l = options.limits();
            TestLauncher.Limits both = new TestLauncher.Limits(Math.max(l.heapMegabytes(),
                    renders == null ? 0 : options.sceneHeapMb()), l.wallClock().multipliedBy(2).plus(sceneLimit)
                    .plusSeconds(renders == null ? 0 : 30), l.perTestSeconds(), l.outputCapBytes());
            jvm.addAll(JvmOptions.trusted(both.heapMegabytes()));
            jvm.addAll(extraJvmOptions("RAYLAB_TRUSTED_JVM_OPTS"));
            TestLauncher.Run o = TestLauncher.runTrusted(cp, setup.tests, classes, both, dir, expected, jvm);
            for (TestResult r : o.results()) {
                got.put(r.id(), r);
            }
            boolean allReported = expected.stream().map(e -> got.get(e.id())).allMatch(r -> r != null
                    && r.status() != TestResult.Status.MISSING && !r.id().equals(o.cutOff()));
            if (renders != null) {
                renders.done = true;
                readRenders(pngs, renders.images, renders.errors, renders.late, renders.references, renders.pixels);
                renders.timedOut = !o.finished() && o.timedOut();
                byte[] millis = readCapped(dir.resolve("render").resolve("millis.txt"), 64);
                try {
                    renders.millis = Long.parseLong(new String(millis == null ? new byte[0] : millis,
                            java.nio.charset.StandardCharsets.US_ASCII).trim()) / a.scenes().size();
                } catch (NumberFormatException e) {
                    renders.millis = 0; // stopped before the renders ended
                }
                Path times = dir.resolve("render").resolve("times.txt");
                if (TIMES && Files.isRegularFile(times)) {
                    System.err.print(Files.readString(times));
                }
            }
            if (!o.finished() && !o.problem().isEmpty() && !allReported) {
                boolean visibleDone = expected.stream().filter(e -> visible.contains(GraderSetup.outer(e.className())))
                        .map(e -> got.get(e.id())).allMatch(r -> r != null && r.status() != TestResult.Status.MISSING
                                && !r.id().equals(o.cutOff()));
                // What went wrong in the hidden run is named on the hidden tests only (their visibility).
                notes.add(visibleDone ? "the hidden tests' run did not finish (see the hidden tests)"
                        : "the test run did not finish: " + o.problem());
            }
        } finally {
            for (Sandbox.Box box : boxes) {
                sandbox.finish(box, null);
            }
            JavaBuild.deleteTreeQuietly(dir);
        }
    }

    /**
     * A variant's reference: rendered with the variant ({@code made}, by the grader's render:
     * the reference's own trace) or, if that render could not make it, rendered here now.
     */
    private byte[] variantReference(GradedScenes.Graded g, byte[] made) {
        if (g.reference() != null) {
            return g.reference();
        }
        if (made != null) {
            return made;
        }
        if (TIMES) {
            System.err.println(g.scene().scene() + ": the variant's reference rendered here");
        }
        try {
            return GradedScenes.renderReference(g.json(), options.root().toAbsolutePath().resolve(g.scene().scene()));
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** What the renders of M's scenes in the grader's test JVM left ({@link #runTests}). */
    private static final class Renders {
        boolean done;
        boolean timedOut;
        long millis;
        final List<byte[]> images = new ArrayList<>();
        final List<String> errors = new ArrayList<>();
        final List<Boolean> late = new ArrayList<>();
        final List<byte[]> references = new ArrayList<>();
        /** Per scene the graded feedback's worst pixels (raylab.inspect.WorstPixels JSON), or null. */
        final List<String> pixels = new ArrayList<>();
    }

    private void copyOtherReferences(Assignment a, GraderSetup setup, Path out) throws IOException {
        Files.createDirectories(out);
        List<Assignment> all = allAssignments;
        List<String> prefixes = new ArrayList<>();
        for (Assignment o : all) {
            if (!o.id().equals(a.id()) && !setup.references.containsKey(o.id())) {
                o.files().forEach(f -> prefixes.add(GraderSetup.classPrefix(f.path())));
            }
        }
        if (prefixes.isEmpty()) {
            return;
        }
        Path code = GraderSetup.codeSource();
        if (Files.isDirectory(code)) {
            try (Stream<Path> s = Files.walk(code)) {
                for (Path p : (Iterable<Path>) s.filter(Files::isRegularFile)::iterator) {
                    String name = code.relativize(p).toString().replace('\\', '/');
                    if (prefixes.stream().anyMatch(x -> GraderSetup.isClassOf(name, x))) {
                        Path t = out.resolve(name);
                        Files.createDirectories(t.getParent());
                        Files.copy(p, t);
                    }
                }
            }
        } else {
            try (var jar = new java.util.jar.JarFile(code.toFile())) {
                for (var e : (Iterable<java.util.jar.JarEntry>) jar.stream()::iterator) {
                    if (prefixes.stream().anyMatch(x -> GraderSetup.isClassOf(e.getName(), x))) {
                        Path t = out.resolve(e.getName());
                        Files.createDirectories(t.getParent());
                        try (var in = jar.getInputStream(e)) {
                            Files.copy(in, t);
                        }
                    }
                }
            }
        }
    }

    /**
     * Removes class files the student's file produced that are not its own classes and would
     * shadow a class of the framework, a library or another milestone.
     */
    private static List<String> checkOverlay(Assignment a, Path overlay, List<Path> below) throws IOException {
        List<String> prefixes = a.files().stream().map(f -> GraderSetup.classPrefix(f.path())).toList();
        List<String> removed = new ArrayList<>();
        List<Path> classFiles;
        try (Stream<Path> s = Files.walk(overlay)) {
            classFiles = s.filter(Files::isRegularFile).toList();
        }
        try (java.net.URLClassLoader lower = new java.net.URLClassLoader(below.stream().map(p -> {
            try {
                return p.toUri().toURL();
            } catch (java.net.MalformedURLException e) {
                throw new IllegalStateException(e);
            }
        }).toArray(java.net.URL[]::new), null)) {
            for (Path p : classFiles) {
                String name = overlay.relativize(p).toString().replace('\\', '/');
                boolean own = prefixes.stream().anyMatch(x -> GraderSetup.isClassOf(name, x));
                String pkg = name.contains("/") ? name.substring(0, name.lastIndexOf('/') + 1) : "";
                boolean samePackage = prefixes.stream().anyMatch(x -> x.startsWith(pkg) && x.indexOf('/', pkg.length()) < 0);
                if (own) {
                    continue;
                }
                if (samePackage && lower.findResource(name) == null && !name.startsWith("java")) {
                    continue; // a helper class of the student's own, shadowing nothing
                }
                Files.delete(p);
                removed.add(name.replace(".class", "").replace('/', '.') + ": a class declared in "
                        + String.join(", ", a.files().stream().map(f -> f.path().substring(f.path().lastIndexOf('/') + 1)).toList())
                        + " that would replace a framework class; ignored");
            }
        }
        return removed;
    }

    /** The milestone's points and test names, as check and the handouts have them. */
    private GradingPlan.Plan plan(Assignment a) throws IOException {
        return GradingPlan.of(options.root().toAbsolutePath(), a);
    }

    /** Visibility and kind of the test class. */
    private static Kind kindOf(Assignment a, String className) {
        String outer = GraderSetup.outer(className);
        if (outer.equals(DataCases.className(a.id())) || outer.equals(DataCases.visibleClassName(a.id()))) {
            return Kind.CASE;
        }
        for (String v : a.tests().visible()) {
            if (GraderSetup.testClassName(v).equals(outer)) {
                return Kind.VISIBLE;
            }
        }
        return Kind.HIDDEN;
    }

    /**
     * Groups results per test method (parameterized invocations together) and scores them: the
     * points and names come from {@link GradingPlan} (display names, shares in whole cents, in
     * the order of the test files), as in {@code raylab check} and the handouts.
     */
    private static List<GradeReport.Test> scoreTests(Assignment a, GraderSetup setup, GradingPlan.Plan plan,
            List<TestResult> expected, Map<String, TestResult> got) {
        Map<String, List<TestResult>> groups = GradingPlan.byMethod(expected);
        Map<String, GradingPlan.Item> planned = new LinkedHashMap<>();
        List<String> order = new ArrayList<>();
        for (GradingPlan.Item i : plan.visible()) {
            planned.put(i.key(), i);
            order.add(i.key());
        }
        for (GradingPlan.Item i : plan.hidden()) {
            planned.put(i.key(), i);
            order.add(i.key());
        }
        // Shares over the groups that exist, in plan order (a test the plan does not know goes last).
        java.util.Comparator<String> byPlan = java.util.Comparator.comparingInt(k -> {
            int i = order.indexOf(k);
            return i < 0 ? Integer.MAX_VALUE : i;
        });
        List<String> keys = new ArrayList<>(groups.keySet());
        keys.sort(byPlan);
        List<String> visibleKeys = keys.stream().filter(k -> kindOf(a, groups.get(k).get(0).className()) == Kind.VISIBLE).toList();
        List<String> hiddenKeys = keys.stream().filter(k -> kindOf(a, groups.get(k).get(0).className()) == Kind.HIDDEN).toList();
        long[] vs = GradingPlan.share(100L * a.tests().visiblePoints(), visibleKeys.size());
        double[] weights = new double[hiddenKeys.size()];
        for (int i = 0; i < weights.length; i++) {
            TestResult t = groups.get(hiddenKeys.get(i)).get(0);
            weights[i] = a.tests().hiddenWeight(GradingPlan.outer(t.className()), t.method());
        }
        long[] hs = GradingPlan.share(100L * a.tests().hiddenPoints(), weights);
        Map<String, DataCases.Case> cases = new LinkedHashMap<>();
        for (DataCases.Case c : setup.cases.getOrDefault(a.id(), List.of())) {
            cases.put(c.method(), c);
        }
        List<GradeReport.Test> out = new ArrayList<>();
        for (String key : keys) {
            List<TestResult> g = groups.get(key);
            TestResult first = g.get(0);
            Kind kind = kindOf(a, first.className());
            double points;
            String visibility;
            GradingPlan.Item item = planned.get(key);
            String name = item != null ? item.name() : first.method();
            if (kind == Kind.VISIBLE) {
                points = vs[visibleKeys.indexOf(key)] / 100.0;
                visibility = "visible";
            } else if (kind == Kind.HIDDEN) {
                points = hs[hiddenKeys.indexOf(key)] / 100.0;
                visibility = a.tests().hiddenVisibility();
            } else {
                DataCases.Case c = cases.get(first.method());
                points = c == null ? 0 : Math.round(c.points() * 100) / 100.0;
                visibility = c == null ? a.tests().hiddenVisibility() : c.visibility();
                name = "data case: " + (c == null ? first.method() : c.name());
            }
            boolean passed = true;
            boolean gradingFailed = false; // the first failure is the grader's, not the student's
            String message = "";
            String output = "";
            long ms = 0;
            String note = "";
            int failedCount = 0;
            for (TestResult e : g) {
                TestResult r = got.get(e.id());
                if (r == null) {
                    r = e.with(TestResult.Status.MISSING, "no result was reported for this test");
                }
                ms += r.millis();
                note = raylab.course.Notes.add(note, r.output());
                if (!r.status().passed()) {
                    failedCount++;
                    if (passed) {
                        gradingFailed = r.gradingFailed();
                        message = gradingFailed ? GradingStatus.message(r.message())
                                : explain(r, g.size() > 1 ? r.displayName() : null);
                        output = r.output() == null ? "" : r.output();
                    }
                    passed = false;
                }
            }
            if (failedCount > 1 && g.size() > 1 && !gradingFailed) {
                message = failedCount + " of " + g.size() + " cases failed; the first: " + message;
            }
            if (kind != Kind.VISIBLE) {
                output = ""; // what hidden tests print stays hidden
            }
            String file = kind == Kind.CASE ? (cases.get(first.method()) == null ? "" : cases.get(first.method()).file())
                    : testFile(a, first.className());
            out.add(new GradeReport.Test(a.id(), name, kind, points, passed ? points : 0, passed,
                    raylab.course.Messages.plain(message), raylab.course.Notes.strip(output), visibility, ms, file, null)
                    .withNote(note));
        }
        return out;
    }

    private static String testFile(Assignment a, String className) {
        String outer = GraderSetup.outer(className);
        for (String f : a.tests().visible()) {
            if (GraderSetup.testClassName(f).equals(outer)) {
                return f;
            }
        }
        for (String f : a.tests().hidden()) {
            if (GraderSetup.testClassName(f).equals(outer)) {
                return f;
            }
        }
        return "";
    }

    private static String simple(String className) {
        return className.substring(className.lastIndexOf('.') + 1);
    }

    private static String explain(TestResult r, String invocation) {
        String base = switch (r.status()) {
            case FAILED -> r.message();
            case TIMED_OUT -> "timed out: " + (r.message() == null || r.message().isBlank()
                    ? "the test took longer than allowed (an endless loop?)" : r.message());
            case CRASHED -> "crashed: " + r.message() + " (System.exit, running out of memory or a JVM crash; "
                    + "tests after it could not run)";
            case MISSING -> "not run: " + r.message() + ". Tests that the grader did not see pass score 0: look for "
                    + "System.exit, an exception while loading your class, an endless loop, or running out of memory";
            case ABORTED -> "aborted: " + r.message();
            case PASSED -> "";
        };
        return invocation == null ? base : "[" + invocation + "] " + base;
    }

    /**
     * The arguments of {@code TrustedRender} for M's scenes (triples SCENE.json OUT.png NAME, the
     * PNGs in {@code dir}, added to {@code pngs}); each variant is written next to its published
     * scene in the grader's copy of {@code scenes/} (relative paths of meshes resolve as before).
     */
    private List<String> sceneArguments(Assignment a, Path dir, Path scenesCopy, List<Path> pngs) throws IOException {
        Path root = options.root().toAbsolutePath();
        List<String> out = new ArrayList<>();
        for (int i = 0; i < a.scenes().size(); i++) {
            Assignment.GradedScene sc = a.scenes().get(i);
            Path scene = scenesCopy.resolve(root.resolve("scenes").relativize(root.resolve(sc.scene())).toString());
            if (graded.containsKey(sc.scene()) && graded.get(sc.scene()).varied()) {
                Path v = scene.resolveSibling("variant-" + a.id() + "-" + i + "-" + scene.getFileName());
                Files.writeString(v, graded.get(sc.scene()).json());
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

    /** What a render left: the PNG and the first line of its error, capped in size, not following links. */
    private static void readRenders(List<Path> pngs, List<byte[]> images, List<String> errors, List<Boolean> late,
            List<byte[]> referencesMade, List<String> pixels) throws IOException {
        for (Path png : pngs) {
            images.add(readCapped(png, 64L << 20));
            referencesMade.add(readCapped(Path.of(png + ".reference.png"), 64L << 20));
            byte[] px = readCapped(Path.of(png + ".pixels.json"), 256 * 1024);
            pixels.add(px == null ? null : new String(px, java.nio.charset.StandardCharsets.UTF_8));
            byte[] err = readCapped(Path.of(png + ".err"), 64 * 1024);
            errors.add(err == null ? null : GraderSetup.firstLine(new String(err,
                    java.nio.charset.StandardCharsets.UTF_8)).replaceFirst("^raylab: ", ""));
            late.add(Files.exists(Path.of(png + ".timeout"), java.nio.file.LinkOption.NOFOLLOW_LINKS));
        }
    }

    /**
     * Renders the milestone's scenes in the grader's process (stand-ins calling the student
     * process in its box; the PNGs are encoded there) and compares each with its reference.
     */
    private List<GradeReport.Test> gradeScenes(Assignment a, List<Path> trusted, Path overlay, GraderSetup setup,
            Path mdir, Path scenesCopy, Sandbox sandbox) throws IOException {
        List<GradeReport.Test> out = new ArrayList<>();
        if (a.scenes().isEmpty()) {
            return out;
        }
        Path root = options.root().toAbsolutePath();
        List<Path> cp = new ArrayList<>();
        for (Path p : trusted) {
            if (!setup.libraries.contains(p) || libraryFor(p, true)) {
                cp.add(p);
            }
        }
        Sandbox.Box box = studentBox(a, overlay, setup, mdir, sandbox);
        Path dir = Files.createTempDirectory(mdir, "render");
        Path config = dir.resolve("student.properties");
        raylab.boundary.Remote.writeConfig(config, studentConfig(a, box, overlay, options.sceneLimit().toMillis(),
                options.sceneHeapMb()));
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
        cmd.addAll(extraJvmOptions("RAYLAB_RENDER_JVM_OPTS"));
        cmd.addAll(List.of(
                // The milestone's reference predicts the student's answers, so that calls go in batches.
                "-Draylab.boundary.references=" + setup.references.get(a.id()).toAbsolutePath(),
                "-cp", String.join(java.io.File.pathSeparator,
                        cp.stream().map(Path::toString).toList()), "raylab.boundary.TrustedRender"));
        List<Path> pngs = new ArrayList<>();
        cmd.addAll(sceneArguments(a, dir, scenesCopy, pngs));
        long t0 = System.nanoTime();
        Duration limit = options.sceneLimit().multipliedBy(a.scenes().size());
        boolean timedOut = false;
        List<byte[]> images = new ArrayList<>();
        List<String> errors = new ArrayList<>();
        List<Boolean> late = new ArrayList<>();
        List<byte[]> referencesMade = new ArrayList<>();
        List<String> pixels = new ArrayList<>();
        Process p = null;
        try {
            ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile())
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(TIMES ? ProcessBuilder.Redirect.INHERIT : ProcessBuilder.Redirect.DISCARD);
            p = pb.start();
            p.getOutputStream().close();
            try {
                if (!p.waitFor(limit.toMillis() * TestLauncher.GUARD_FACTOR, java.util.concurrent.TimeUnit.MILLISECONDS)) {
                    timedOut = true;
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                timedOut = true;
            }
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            try {
                p.waitFor(5, java.util.concurrent.TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            // Read what the child left only once it is gone.
            readRenders(pngs, images, errors, late, referencesMade, pixels);
        } finally {
            if (p != null) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
            }
            sandbox.finish(box, null);
            JavaBuild.deleteTreeQuietly(dir);
        }
        long ms = (System.nanoTime() - t0) / 1_000_000 / a.scenes().size();
        // -XX:+ExitOnOutOfMemoryError ends the JVM with status 3 when the heap runs out.
        boolean outOfMemory = p != null && !timedOut && !p.isAlive() && p.exitValue() == 3;
        return scoreScenes(a, images, errors, late, referencesMade, pixels, timedOut, outOfMemory, ms, limit);
    }

    /**
     * M's scene items: each render compared with its reference ({@code late}: stopped at the time
     * limit; {@code timedOut}: the whole run was).
     */
    private List<GradeReport.Test> scoreScenes(Assignment a, List<byte[]> images, List<String> errors,
            List<Boolean> late, List<byte[]> referencesMade, List<String> pixels, boolean timedOut, boolean outOfMemory, long ms,
            Duration limit) {
        List<GradeReport.Test> out = new ArrayList<>();
        List<String> studentFiles = a.files().stream().map(Assignment.StudentFile::path).toList();
        for (int i = 0; i < a.scenes().size(); i++) {
            Assignment.GradedScene sc = a.scenes().get(i);
            String name = sc.scene();
            GradedScenes.Graded g = graded.get(sc.scene());
            byte[] refBytes = g != null && g.varied() ? variantReference(g, referencesMade.get(i))
                    : references.get(sc.reference());
            byte[] mine = images.get(i);
            String errLine = errors.get(i) == null ? "" : errors.get(i);
            String msg;
            GradeReport.Images shown = null;
            boolean passed = false;
            if (refBytes == null) {
                msg = "grader setup problem: no reference image " + sc.reference();
            } else if (mine == null || errors.get(i) != null) {
                msg = late.get(i) ? "your code used more than " + limit.toSeconds()
                                + " s of CPU time in the renders and was stopped (an endless loop, or far too slow?)"
                        : errLine.startsWith(raylab.course.TestResult.GRADING_FAILED) ? GradingStatus.message(errLine)
                        : !errLine.isEmpty() ? raylab.course.Explain.renderFailure(errLine, studentFiles)
                        : outOfMemory ? "the render ran out of memory (" + options.sceneHeapMb()
                                + " MB): look for something that grows with every ray, such as a list or an array"
                                + " allocated per hit and kept"
                        : timedOut ? GradingStatus.message("the grader's render JVM was stopped by its wall-clock guard"
                                + " before this scene was rendered, although the renders' limit is in the student's CPU"
                                + " time: the machine or the grader was too slow")
                        : "no image was rendered (the render JVM ended early: System.exit or a crash)";
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
                            passed ? "" : PixelFeedback.valid(pixels.get(i)));
                    msg += passed ? "" : PixelFeedback.summaryLine(shown.pixels());
                } catch (IOException | RuntimeException e) {
                    msg = "the rendered image could not be compared: " + e.getMessage();
                    shown = new GradeReport.Images(null, refBytes, null, "");
                }
            }
            out.add(new GradeReport.Test(a.id(), name, Kind.SCENE, sc.points(), passed ? sc.points() : 0, passed, msg,
                    "", "visible", ms, sc.scene(), shown));
        }
        return out;
    }

    /** The bytes of a regular file (not a link), or null when there is none or it is larger than {@code cap}. */
    private static byte[] readCapped(Path f, long cap) {
        try {
            if (!Files.isRegularFile(f, java.nio.file.LinkOption.NOFOLLOW_LINKS) || Files.size(f) > cap) {
                return null;
            }
            return Files.readAllBytes(f);
        } catch (IOException e) {
            return null;
        }
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

    static byte[] png(BufferedImage img) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        ImageIO.write(img, "png", b);
        return b.toByteArray();
    }

    /** Every graded item of a milestone at zero, with one explanation. */
    private GradeReport.Milestone zeroed(Assignment a, GraderSetup setup, String why) throws IOException {
        List<GradeReport.Test> tests = new ArrayList<>();
        for (GradeReport.Test t : scoreTests(a, setup, plan(a), setup.expected.getOrDefault(a.id(), List.of()), Map.of())) {
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
