package raylab.course;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * What {@code raylab check} does, for the student's tree and the instructor's alike: compiles the
 * visible tests of the chosen milestones against the running raylab, runs them in a child JVM,
 * renders each milestone's scenes in a child JVM and compares them with their references, and
 * says for each milestone what to look at next.
 *
 * <p>One command's pipeline (compile, tests, renders, the next step), the student's side of what the
 * grader does in separate classes, kept whole so that the starter ships it as one file.
 */
public final class MilestoneCheck {
    /** Folder of the assertion helpers the visible tests share. */
    public static final String HELPERS = "src/test/java/raylab/testing";

    /** How a scene came out. */
    public enum SceneStatus {
        MATCH, DIFFERS, NOT_IMPLEMENTED, ERROR
    }

    /** One scene: its file, what happened, and the line that says so. */
    public record SceneOutcome(Assignment.GradedScene scene, SceneStatus status, String message) {
        public boolean matches() {
            return status == SceneStatus.MATCH;
        }
    }

    /**
     * One milestone: its test results (or why they could not run) and its scenes.
     *
     * @param problem a compile error or a failed run, empty if the tests ran
     */
    public record Outcome(Assignment assignment, List<TestResult> tests, String problem, List<SceneOutcome> scenes,
            GradingPlan.Plan plan) {
        /** Without a plan: tests in the order given. */
        public Outcome(Assignment assignment, List<TestResult> tests, String problem, List<SceneOutcome> scenes) {
            this(assignment, tests, problem, scenes, null);
        }

        /** One row of the points table: a visible test (all its invocations), a visible data case or a scene. */
        public record Row(GradingPlan.Item item, boolean passed, boolean ran, String message) {
        }

        /**
         * Everything the student can run locally, in the order the handout teaches (the test
         * file's order, then data cases, then scenes), with the points the autograder gives.
         */
        public List<Row> rows() {
            List<Row> out = new ArrayList<>();
            if (plan == null) {
                return out;
            }
            Map<String, List<TestResult>> groups = GradingPlan.byMethod(tests);
            for (GradingPlan.Item i : plan.visible()) {
                switch (i.kind()) {
                    case TEST, CASE -> {
                        List<TestResult> g = groups.get(i.kind() == GradingPlan.Kind.TEST ? i.key()
                                : GradingPlan.casesClassName(assignment.id()) + "#" + i.key());
                        if (g == null) {
                            out.add(new Row(i, false, false, problem.isEmpty() ? "did not run" : problem));
                        } else {
                            TestResult bad = g.stream().filter(t -> !t.status().passed()).findFirst().orElse(null);
                            long failed = g.stream().filter(t -> !t.status().passed()).count();
                            String msg = bad == null ? "" : (g.size() > 1 ? (failed > 1 ? failed + " of " + g.size()
                                    + " invocations failed; the first, " : "") + "[" + bad.displayName() + "] " : "")
                                    + (bad.message() == null ? "" : bad.message());
                            out.add(new Row(i, bad == null, true, msg));
                        }
                    }
                    case SCENE -> {
                        SceneOutcome so = scenes.stream().filter(x -> x.scene().scene().equals(i.key())).findFirst()
                                .orElse(null);
                        out.add(new Row(i, so != null && so.matches(), so != null, so == null ? "not rendered" : so.message()));
                    }
                    default -> {
                    }
                }
            }
            return out;
        }

        /** Points earned locally, in cents. */
        public long earnedCents() {
            return rows().stream().filter(Row::passed).mapToLong(r -> r.item().cents()).sum();
        }

        /** Tests (and data cases) counted the one way: a test method with all its invocations is one test. */
        public long testsPassed() {
            if (plan != null) {
                return rows().stream().filter(r -> r.item().kind() != GradingPlan.Kind.SCENE && r.passed()).count();
            }
            return tests.stream().filter(t -> t.status().passed()).count();
        }

        public long testCount() {
            if (plan != null) {
                return rows().stream().filter(r -> r.item().kind() != GradingPlan.Kind.SCENE).count();
            }
            return tests.size();
        }

        public long scenesMatching() {
            return scenes.stream().filter(SceneOutcome::matches).count();
        }

        public boolean done() {
            return problem.isEmpty() && !tests.isEmpty() && testsPassed() == testCount()
                    && scenesMatching() == scenes.size();
        }

        /** The failing tests, in handout order when there is a plan. */
        private List<TestResult> failingInOrder() {
            List<TestResult> failing = new ArrayList<>();
            if (plan != null) {
                Map<String, List<TestResult>> groups = GradingPlan.byMethod(tests);
                for (Row r : rows()) {
                    if (r.item().kind() != GradingPlan.Kind.SCENE && !r.passed() && r.ran()) {
                        List<TestResult> g = groups.get(r.item().kind() == GradingPlan.Kind.TEST ? r.item().key()
                                : GradingPlan.casesClassName(assignment.id()) + "#" + r.item().key());
                        g.stream().filter(t -> !t.status().passed()).findFirst().ifPresent(failing::add);
                    }
                }
                for (TestResult t : tests) {
                    if (!t.status().passed() && !failing.contains(t) && failing.stream().noneMatch(
                            f -> f.className().equals(t.className()) && f.method().equals(t.method()))) {
                        failing.add(t);
                    }
                }
                return failing;
            }
            return tests.stream().filter(t -> !t.status().passed()).toList();
        }

        /** The name a test has in the handout (its display name, or the case's name). */
        public String nameOf(TestResult t) {
            if (plan != null) {
                for (GradingPlan.Item i : plan.visible()) {
                    if (i.key().equals(GradingPlan.outer(t.className()) + "#" + t.method())
                            || (i.kind() == GradingPlan.Kind.CASE && i.key().equals(t.method()))) {
                        return i.kind() == GradingPlan.Kind.CASE ? "data case \"" + i.name() + "\"" : "\"" + i.name() + "\"";
                    }
                }
            }
            return simpleName(t.className()) + "." + t.method();
        }

        /** What to look at next, in one short line. */
        public String nextStep() {
            String id = assignment.id();
            if (!problem.isEmpty()) {
                return problem;
            }
            if (tests.isEmpty()) {
                return "no visible tests found for " + id;
            }
            List<TestResult> failing = failingInOrder();
            for (TestResult t : failing) {
                String missing = missingMilestone(t.message());
                if (missing != null) {
                    return missingStep(id, missing, t.message());
                }
            }
            for (TestResult t : failing) {
                if (t.message() != null && t.message().contains(STUCK)) { // the loop first: it hides the rest
                    return "fix " + nameOf(t) + ": " + oneLine(t.message(), 90);
                }
            }
            for (TestResult t : failing) {
                return "fix " + nameOf(t) + ": " + oneLine(t.message(), 90);
            }
            for (SceneOutcome s : scenes) {
                if (s.status() == SceneStatus.NOT_IMPLEMENTED) {
                    String missing = missingMilestone(s.message());
                    return missing == null ? s.message() : missingStep(id, missing, s.message());
                }
            }
            for (SceneOutcome s : scenes) {
                if (!s.matches()) {
                    if (s.status() == SceneStatus.DIFFERS) {
                        String name = baseName(s.scene().scene());
                        return "./raylab render " + s.scene().scene() + " --compare " + s.scene().reference()
                                + ", then look at out/" + name + ".diff.png";
                    }
                    return s.scene().scene() + ": " + oneLine(s.message(), 90);
                }
            }
            return "done";
        }

        private String missingStep(String id, String missing, String message) {
            Matcher m = WRITE.matcher(message);
            String method = m.find() ? m.group(1) : null;
            if (missing.equals(id)) {
                return "implement " + (method != null ? method : "the methods of " + assignment.folder() + "/README.md");
            }
            return "first finish milestone " + missing + (method != null ? " (" + method + ")" : "");
        }
    }

    private static final Pattern MISSING = Pattern.compile("milestone '([a-z0-9-]+)' is not implemented yet");
    private static final Pattern WRITE = Pattern.compile("not implemented yet: write ([A-Za-z0-9_.]+)");

    private MilestoneCheck() {
    }

    /** The milestone a NotImplemented message names, or null. */
    static String missingMilestone(String message) {
        if (message == null) {
            return null;
        }
        Matcher m = MISSING.matcher(message);
        return m.find() ? m.group(1) : null;
    }

    /**
     * Checks the given milestones of the project at {@code root}, writing build output under
     * {@code root/target/check} and renders under {@code root/out}.
     */
    public static List<Outcome> run(Path root, List<Assignment> selected, int threads, Consumer<String> progress)
            throws IOException {
        return run(root, selected, threads, progress, List.of());
    }

    /**
     * As {@link #run(Path, List, int, Consumer)}, with {@code first} put before raylab's own
     * classes (a test puts a student's compiled file there).
     */
    public static List<Outcome> run(Path root, List<Assignment> selected, int threads, Consumer<String> progress,
            List<Path> first) throws IOException {
        return run(root, selected, threads, progress, first, true);
    }

    /**
     * As {@link #run(Path, List, int, Consumer, List)}; without {@code renderScenes} only the
     * visible tests and data cases run (each outcome's scene list is then empty).
     */
    public static List<Outcome> run(Path root, List<Assignment> selected, int threads, Consumer<String> progress,
            List<Path> first, boolean renderScenes) throws IOException {
        // One check at a time per project: each begins by clearing target/check/run, where another
        // check's test JVM may be working (check --watch beside a check, or submit-check).
        Path work = root.resolve("target/check");
        Files.createDirectories(work);
        synchronized (CHECK_LOCK) {
            try (java.nio.channels.FileChannel f = java.nio.channels.FileChannel.open(work.resolve(".lock"),
                    java.nio.file.StandardOpenOption.CREATE, java.nio.file.StandardOpenOption.WRITE)) {
                java.nio.channels.FileLock lock = f.tryLock();
                if (lock == null) {
                    progress.accept("waiting for another check of this project to finish ...");
                    lock = f.lock();
                }
                try {
                    return runLocked(root, work, selected, threads, progress, first, renderScenes);
                } finally {
                    lock.release();
                }
            }
        }
    }

    /** Held by the check of this JVM that holds target/check's file lock. */
    private static final Object CHECK_LOCK = new Object();

    private static List<Outcome> runLocked(Path root, Path work, List<Assignment> selected, int threads,
            Consumer<String> progress, List<Path> first, boolean renderScenes) throws IOException {
        List<Path> own = new ArrayList<>(first);
        own.addAll(JavaBuild.ownClassPath());
        Path helpers = work.resolve("helpers");
        // Compiled tests are kept while their sources and the built classes stay the same (BuildCache).
        JavaBuild.deleteTree(work.resolve("run"));
        progress.accept("compiling the visible tests ...");
        JavaBuild.Result h = BuildCache.compile(JavaBuild.sourcesUnder(root.resolve(HELPERS)), own, helpers);
        String helperProblem = h.success() ? "" : "the test helpers do not compile: " + first(root, h);

        Map<String, String> problems = new LinkedHashMap<>();
        Map<String, String> milestoneOfClass = new LinkedHashMap<>();
        List<Path> testDirs = new ArrayList<>();
        for (Assignment a : selected) {
            if (!helperProblem.isEmpty()) {
                problems.put(a.id(), helperProblem);
                continue;
            }
            List<Path> sources = new ArrayList<>();
            for (String v : a.tests().visible()) {
                Path p = root.resolve(v);
                if (!Files.isRegularFile(p)) {
                    problems.put(a.id(), "visible test " + v + " is missing");
                }
                sources.add(p);
            }
            if (problems.containsKey(a.id())) {
                continue;
            }
            // Visible data cases run as one generated test class, as the grader runs them.
            List<GradingPlan.CaseInfo> cases = GradingPlan.cases(root, a).stream()
                    .filter(c -> c.visibility().equals("visible")).toList();
            if (!cases.isEmpty()) {
                Path checker = caseChecker(root);
                if (checker == null) {
                    problems.put(a.id(), "the data cases need src/test/java/raylab/cases/CaseCheck.java, which is missing");
                    continue;
                }
                Path gen = work.resolve("generated").resolve(a.id()).resolve(
                        GradingPlan.casesClassName(a.id()).replace('.', '/') + ".java");
                Files.createDirectories(gen.getParent());
                String text = GradingPlan.casesTestSource(a.id(), cases);
                if (!Files.isRegularFile(gen) || !Files.readString(gen, StandardCharsets.UTF_8).equals(text)) {
                    Files.writeString(gen, text, StandardCharsets.UTF_8); // unchanged: its compiled class is kept
                }
                sources.add(gen);
                sources.add(checker);
                milestoneOfClass.put(GradingPlan.casesClassName(a.id()), a.id());
            }
            Path out = work.resolve("tests").resolve(a.id());
            List<Path> cp = new ArrayList<>(List.of(helpers));
            cp.addAll(own);
            JavaBuild.Result r = BuildCache.compile(sources, cp, out);
            if (!r.success()) {
                problems.put(a.id(), "fix the compile error: " + first(root, r));
                continue;
            }
            testDirs.add(out);
            for (String v : a.tests().visible()) {
                milestoneOfClass.put(className(v), a.id());
            }
        }

        // The scenes render in child JVMs of their own while the tests run: on two cores the
        // renders and the tests overlap instead of taking turns.
        java.util.concurrent.ExecutorService renders = java.util.concurrent.Executors.newFixedThreadPool(
                Math.max(1, Math.min(2, Runtime.getRuntime().availableProcessors())), r -> {
                    Thread t = new Thread(r, "check-render");
                    t.setDaemon(true);
                    return t;
                });
        Map<Assignment.GradedScene, java.util.concurrent.Future<SceneOutcome>> rendered = new LinkedHashMap<>();
        for (Assignment a : selected) {
            List<String> files = a.files().stream().map(Assignment.StudentFile::path).toList();
            // After a scene stuck in the student's code, the milestone's scenes not started yet are
            // not rendered (they would most likely be stuck in the same loop, each for the bound).
            java.util.concurrent.atomic.AtomicReference<String> stuck = new java.util.concurrent.atomic.AtomicReference<>();
            for (Assignment.GradedScene g : renderScenes ? a.scenes() : List.<Assignment.GradedScene>of()) {
                progress.accept("rendering " + g.scene() + " ...");
                rendered.put(g, renders.submit(() -> {
                    String before = stuck.get();
                    if (before != null) {
                        return new SceneOutcome(g, SceneStatus.ERROR, "not rendered: " + before
                                + ": fix that, then check again");
                    }
                    SceneOutcome o = render(root, g, own, threads, files);
                    if (o.status() == SceneStatus.ERROR && o.message().contains(STUCK)) {
                        stuck.compareAndSet(null, g.scene() + " was stuck (" + o.message() + ")");
                    }
                    return o;
                }));
            }
        }
        renders.shutdown();

        Map<String, List<TestResult>> results = new LinkedHashMap<>();
        if (!milestoneOfClass.isEmpty()) {
            progress.accept("running the tests ...");
            List<Path> cp = new ArrayList<>(testDirs);
            cp.add(helpers);
            cp.addAll(own);
            List<String> classes = new ArrayList<>(milestoneOfClass.keySet());
            Path runDir = work.resolve("run");
            Files.createDirectories(runDir);
            List<Path> compiled = new ArrayList<>(testDirs);
            compiled.add(helpers);
            List<TestResult> expected = BuildCache.discover(cp, classes, runDir, compiled, work.resolve("discovered.json"));
            List<String> run = new ArrayList<>(classes);
            run.add(TestLauncher.watchdog()); // stuck code is named, and the other test classes go on
            TestLauncher.Run o = TestLauncher.run(cp, null, List.of(), run, TestLauncher.Limits.DEFAULT,
                    runDir, expected);
            for (TestResult t : o.results()) {
                String c = t.className();
                int dollar = c.indexOf('$');
                String id = milestoneOfClass.get(dollar < 0 ? c : c.substring(0, dollar));
                if (id != null) {
                    results.computeIfAbsent(id, k -> new ArrayList<>()).add(t);
                }
            }
        }

        List<Outcome> out = new ArrayList<>();
        for (Assignment a : selected) {
            List<SceneOutcome> scenes = new ArrayList<>();
            for (Assignment.GradedScene g : renderScenes ? a.scenes() : List.<Assignment.GradedScene>of()) {
                scenes.add(finished(g, rendered.get(g)));
            }
            out.add(new Outcome(a, results.getOrDefault(a.id(), List.of()), problems.getOrDefault(a.id(), ""),
                    scenes, GradingPlan.of(root, a)));
        }
        return out;
    }

    /** What the watchdog's sentence ends with (raylab.course.Watchdog). */
    static final String STUCK = "without returning: an endless loop?";

    /** The outcome of a render started in the background. */
    private static SceneOutcome finished(Assignment.GradedScene g, java.util.concurrent.Future<SceneOutcome> f)
            throws IOException {
        try {
            return f.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new SceneOutcome(g, SceneStatus.ERROR, "interrupted");
        } catch (java.util.concurrent.ExecutionException e) {
            if (e.getCause() instanceof IOException io) {
                throw io;
            }
            throw new IllegalStateException(e.getCause());
        }
    }

    /**
     * The data-case checker: shipped in the starter under src/test/java; in the instructor's tree,
     * the copy in a top-level folder's {@code tests} (beside the other tests that are not shipped).
     */
    static Path caseChecker(Path root) {
        String checker = "raylab/cases/CaseCheck.java";
        if (Files.isRegularFile(root.resolve("src/test/java").resolve(checker))) {
            return root.resolve("src/test/java").resolve(checker);
        }
        try (java.util.stream.Stream<Path> top = Files.list(root)) {
            return top.map(d -> d.resolve("tests").resolve(checker)).filter(Files::isRegularFile).sorted()
                    .findFirst().orElse(null);
        } catch (IOException e) {
            return null;
        }
    }

    /** Renders a scene with {@code raylab render --compare} in a child JVM (so a stuck render can be stopped). */
    static SceneOutcome render(Path root, Assignment.GradedScene g, List<Path> classPath, int threads)
            throws IOException {
        return render(root, g, classPath, threads, List.of());
    }

    static SceneOutcome render(Path root, Assignment.GradedScene g, List<Path> classPath, int threads,
            List<String> studentFiles) throws IOException {
        String java = JavaBuild.javaExecutable();
        Path png = root.resolve("out").resolve(baseName(g.scene()) + ".png");
        Files.createDirectories(png.getParent()); // render -o refuses a missing folder
        List<String> cmd = new ArrayList<>(List.of(java, "-Xmx1g", "-XX:+ExitOnOutOfMemoryError", "-Djava.awt.headless=true"));
        // a short run: the quick JIT alone and one GC thread cost less CPU than the full JIT
        cmd.addAll(JavaBuild.QUICK_JVM);
        cmd.addAll(List.of("-cp",
                String.join(File.pathSeparator, classPath.stream().map(Path::toString).toList()),
                "raylab.cli.Main", "render", root.resolve(g.scene()).toString(), "-o", png.toString(),
                "--compare", root.resolve(g.reference()).toString(), "--tolerance", Double.toString(g.tolerance()),
                "--quiet", "--threads", Integer.toString(threads)));
        Path log = Files.createTempFile("raylab-check", ".log");
        try {
            Process p = new ProcessBuilder(cmd).directory(root.toFile()).redirectErrorStream(true)
                    .redirectOutput(log.toFile()).start();
            p.getOutputStream().close();
            if (!p.waitFor(300, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                p.waitFor(5, TimeUnit.SECONDS);
                return new SceneOutcome(g, SceneStatus.ERROR, "the render did not finish within 300 s (an endless loop?)");
            }
            String text = Files.readString(log, StandardCharsets.UTF_8).strip();
            String last = "";
            for (String line : text.split("\n")) {
                if (line.startsWith("raylab: ") || line.startsWith("compare with ")) {
                    last = line.startsWith("raylab: ") ? line.substring(8) : line.replaceFirst("^compare with \\S+: ", "");
                }
            }
            SceneStatus s = switch (p.exitValue()) {
                case 0 -> SceneStatus.MATCH;
                case 3 -> last.contains("not implemented") ? SceneStatus.NOT_IMPLEMENTED : SceneStatus.ERROR;
                case 1 -> last.startsWith("DIFFERS") ? SceneStatus.DIFFERS : SceneStatus.ERROR;
                default -> SceneStatus.ERROR;
            };
            if (p.exitValue() == 3 && last.isEmpty()) {
                return new SceneOutcome(g, SceneStatus.ERROR, "the render ran out of memory (1 GB): look for something"
                        + " that grows with every ray, such as a list or an array allocated per hit and kept");
            }
            return new SceneOutcome(g, s, last.isEmpty() ? "exit status " + p.exitValue()
                    : s == SceneStatus.ERROR ? Explain.renderFailure(last, studentFiles) : last);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return new SceneOutcome(g, SceneStatus.ERROR, "interrupted");
        } finally {
            Files.deleteIfExists(log);
        }
    }

    /** The test class of a source path such as src/test/java/raylab/surface/SphereTest.java. */
    public static String className(String sourcePath) {
        String p = sourcePath.replace('\\', '/');
        int k = p.indexOf("src/test/java/");
        if (k >= 0) {
            p = p.substring(k + "src/test/java/".length());
        }
        return p.replaceFirst("\\.java$", "").replace('/', '.');
    }

    static String baseName(String path) {
        String n = path.substring(path.replace('\\', '/').lastIndexOf('/') + 1);
        return n.replaceFirst("\\.json$", "");
    }

    static String simpleName(String className) {
        return className.substring(className.lastIndexOf('.') + 1);
    }

    public static String oneLine(String s, int n) {
        if (s == null) {
            return "";
        }
        String t = s.strip();
        int nl = t.indexOf('\n');
        if (nl >= 0) {
            t = t.substring(0, nl).strip();
        }
        if (t.length() <= n) {
            return t;
        }
        // Cut between words, never inside one ("C..."), unless a word is longer than half the line.
        int cut = t.lastIndexOf(' ', n - 4);
        return (cut > n / 2 ? t.substring(0, cut) : t.substring(0, n - 4)) + " ...";
    }

    private static String first(Path root, JavaBuild.Result r) {
        if (r.errors().isEmpty()) {
            return "javac failed";
        }
        JavaBuild.Problem p = r.errors().get(0);
        String where = p.file() == null ? "" : rel(root, p.file()) + ":" + p.line() + ": ";
        return where + p.message() + (r.errors().size() > 1 ? " (and " + (r.errors().size() - 1) + " more)" : "");
    }

    private static String rel(Path root, Path file) {
        Path a = root.toAbsolutePath().normalize();
        Path f = file.toAbsolutePath().normalize();
        return f.startsWith(a) ? a.relativize(f).toString().replace('\\', '/') : f.toString();
    }
}
