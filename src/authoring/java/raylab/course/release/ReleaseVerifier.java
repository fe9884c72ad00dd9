package raylab.course.release;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermission;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.MilestoneCheck;
import raylab.course.SolutionRegions;
import raylab.course.TestLauncher;
import raylab.course.TestResult;
import raylab.grade.ServiceFiles;
import raylab.render.ImageCompare;
import raylab.render.PngFiles;

/**
 * Checks a written starter against the instructor's tree, and reports one line per check:
 * <ul>
 * <li>contents: no solution text or marker, nothing instructor-only or hidden, descriptions
 * readable;</li>
 * <li>the starter's main code and visible tests compile (against the libraries only);</li>
 * <li>no reference method body is anywhere in the starter, under any name ({@link SolutionLeaks});</li>
 * <li>on the stubs every milestone's visible tests fail with "not implemented yet"; with only the
 * milestones it requires put back they still fail, naming the milestone;</li>
 * <li>with the milestone's solution (and those it requires) put back its tests pass, while the
 * tests of every other milestone still fail, and its scenes render and match their references;
 * without its solution its first scene stops with exit status 3 naming it;</li>
 * <li>optionally, the README's commands in a copy of the starter: {@code ./mvnw package},
 * {@code ./raylab --help}, {@code ./raylab render scenes/sphere.json}, {@code ./raylab check}.</li>
 * </ul>
 * Child JVMs run at most two at a time.
 *
 * <p>One job: the release's checks, each a short method, run in the order of the list above.
 */
public final class ReleaseVerifier {
    /** Message of {@link raylab.course.NotImplemented}, which every stubbed test must show. */
    static final String NOT_IMPLEMENTED = "is not implemented yet";

    /** What to verify. */
    public record Options(boolean buildCheck, int parallel) {
        public static final Options DEFAULT = new Options(true, 2);
    }

    /** One verified property: a name, whether it holds, and the details. */
    public record Check(String name, boolean passed, String detail) {
        static Check of(String name, List<String> problems, String okDetail) {
            return problems.isEmpty() ? new Check(name, true, okDetail)
                    : new Check(name, false, summarize(problems));
        }

        @Override
        public String toString() {
            return (passed ? "PASS " : "FAIL ") + name + (detail.isEmpty() ? "" : ": " + detail);
        }
    }

    /** All checks, in a fixed order. */
    public record Report(List<Check> checks, long millis) {
        public boolean passed() {
            return checks.stream().allMatch(Check::passed);
        }

        public long failures() {
            return checks.stream().filter(c -> !c.passed()).count();
        }
    }

    private final Path root;
    private final Path starter;
    private final Path work;
    private final Options options;
    private final Assignments assignments;
    private final List<Path> libraries;
    /** The libraries without the tools jar: what the lab's sources compile against. */
    private final List<Path> labLibraries;
    private final Map<String, CompletableFuture<Path>> overlays = new ConcurrentHashMap<>();
    private Path mainClasses;
    private Path testClasses;
    private List<TestResult> expected;
    private Map<String, String> milestoneOfClass;

    private ReleaseVerifier(Path root, Path starter, Path work, Options options) throws IOException {
        this.root = root.toAbsolutePath().normalize();
        this.starter = starter.toAbsolutePath().normalize();
        this.work = work.toAbsolutePath().normalize();
        this.options = options;
        this.assignments = Assignments.load(this.root);
        // The libraries and the starter's tools jar, as the starter's pom.xml gives them to its tests.
        List<Path> libs = new ArrayList<>(libraries());
        Path tools = toolsJar(this.starter);
        if (tools != null) {
            libs.add(tools);
        }
        this.libraries = List.copyOf(libs);
        this.labLibraries = tools == null ? this.libraries : libraries();
    }

    /** Verifies {@code starter} (written from {@code root}), using {@code work} for build output. */
    public static Report verify(Path root, Path starter, Path work, Options options) throws IOException {
        long t0 = System.nanoTime();
        Files.createDirectories(work);
        ReleaseVerifier v = new ReleaseVerifier(root, starter, work, options);
        List<Check> checks = v.run();
        return new Report(checks, (System.nanoTime() - t0) / 1_000_000);
    }

    private List<Check> run() throws IOException {
        List<Check> checks = new ArrayList<>(contents());
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, options.parallel()), r -> {
            Thread t = new Thread(r, "release-verify");
            t.setDaemon(true);
            return t;
        });
        try {
            Future<List<Check>> build = options.buildCheck() ? pool.submit(() -> new BuildCheck(starter, work).run())
                    : null;
            List<Check> compiled = compile();
            checks.addAll(compiled);
            if (compiled.stream().allMatch(Check::passed)) {
                checks.add(noSolutionLeak());
                checks.add(discover());
                if (checks.get(checks.size() - 1).passed()) {
                    List<Future<List<Check>>> jobs = new ArrayList<>();
                    jobs.add(pool.submit(this::stubsOnly));
                    for (Assignment a : assignments.all()) {
                        for (Callable<List<Check>> job : milestoneJobs(a)) {
                            jobs.add(pool.submit(job));
                        }
                    }
                    for (Future<List<Check>> j : jobs) {
                        checks.addAll(get(j, "milestone checks"));
                    }
                }
            }
            if (build != null) {
                checks.addAll(get(build, "README commands"));
            }
        } finally {
            pool.shutdownNow();
        }
        return checks;
    }

    /**
     * Lines of the starter's files that name a hidden test class, or the grader's folder
     * ({@code grader/}): "FILE:LINE names ...".
     */
    static List<String> namesHidden(Path starter, List<String> files, Set<String> hiddenClasses) throws IOException {
        List<String> named = new ArrayList<>();
        for (String rel : files) {
            String text = new String(Files.readAllBytes(starter.resolve(rel)), StandardCharsets.ISO_8859_1);
            String[] lines = text.split("\n", -1);
            for (int i = 0; i < lines.length; i++) {
                for (String h : hiddenClasses) {
                    if (lines[i].contains(h)) {
                        named.add(rel + ":" + (i + 1) + " names the hidden test " + h);
                    }
                }
                if (lines[i].contains("grader/")) {
                    named.add(rel + ":" + (i + 1) + " names the grader's folder (" + abbreviate(lines[i].trim(), 40) + ")");
                }
            }
        }
        return named;
    }

    /** A page of the project's docs named by its path, as comments and handouts name them. */
    private static final Pattern DOC_PATH = Pattern.compile("(?<![\\w/.-])(docs/[\\w./-]*\\.md)");
    /** A Markdown link to a Markdown file of the project (no scheme, relative to the linking file). */
    private static final Pattern MD_LINK = Pattern.compile("\\]\\(([^)#:\\s]+\\.md)(#[^)]*)?\\)");
    /** The starter's text files, by name: the rest (images, jars) names no page. */
    private static final Pattern TEXT_FILE = Pattern.compile(".*\\.(java|md|xml|json|txt|properties|cmd|sh)|raylab|mvnw");

    /**
     * Lines of the starter's text files ({@code texts}: path to content) that name a page of
     * {@code docs/} the starter does not have, or link from a Markdown file to one it does not
     * have: "FILE:LINE names docs/X.md, which the starter does not have". A student who follows
     * such a pointer finds nothing (the instructor's pages, such as the numerics notes, stay out).
     */
    static List<String> unshippedDocs(Map<String, String> texts) {
        List<String> out = new ArrayList<>();
        for (Map.Entry<String, String> e : new java.util.TreeMap<>(texts).entrySet()) {
            String rel = e.getKey();
            String[] lines = e.getValue().split("\n", -1);
            for (int i = 0; i < lines.length; i++) {
                Matcher m = DOC_PATH.matcher(lines[i]);
                while (m.find()) {
                    if (!texts.containsKey(m.group(1))) {
                        out.add(rel + ":" + (i + 1) + " names " + m.group(1) + ", which the starter does not have");
                    }
                }
                if (!rel.endsWith(".md")) {
                    continue;
                }
                Matcher l = MD_LINK.matcher(lines[i]);
                while (l.find()) {
                    Path parent = Path.of(rel).getParent();
                    String target = (parent == null ? Path.of(l.group(1)) : parent.resolve(l.group(1))).normalize()
                            .toString().replace('\\', '/');
                    if (!texts.containsKey(target)) {
                        out.add(rel + ":" + (i + 1) + " links to " + target + ", which the starter does not have");
                    }
                }
            }
        }
        return out;
    }

    /** {@link #unshippedDocs(Map)} of the text files among {@code files} (path to bytes, as {@link Release#build} makes them). */
    static List<String> unshippedDocsOf(Map<String, byte[]> files) {
        Map<String, String> texts = new HashMap<>();
        files.forEach((rel, bytes) -> {
            if (TEXT_FILE.matcher(rel.substring(rel.lastIndexOf('/') + 1)).matches()) {
                texts.put(rel, new String(bytes, StandardCharsets.UTF_8));
            }
        });
        return unshippedDocs(texts);
    }

    /** {@link #unshippedDocsOf} the starter written in {@code starter}. */
    static List<String> unshippedDocs(Path starter, List<String> files) throws IOException {
        Map<String, byte[]> bytes = new HashMap<>();
        for (String rel : files) {
            bytes.put(rel, Files.readAllBytes(starter.resolve(rel)));
        }
        return unshippedDocsOf(bytes);
    }

    /**
     * Providers that a services file of the starter lists and whose source the starter lacks
     * ({@code ServiceLoader} would stop every command there): "FILE:LINE lists NAME, ...".
     */
    static List<String> unshippedProviders(Path starter, List<String> files) throws IOException {
        Set<String> have = new HashSet<>(files);
        List<String> out = new ArrayList<>();
        for (String rel : files) {
            if (rel.startsWith(ServiceFiles.SOURCE_FOLDER)) {
                String[] lines = Files.readString(starter.resolve(rel)).split("\n", -1);
                for (int i = 0; i < lines.length; i++) {
                    for (String c : ServiceFiles.providers(lines[i])) {
                        if (!have.contains("src/main/java/" + ServiceFiles.sourceFile(c))) {
                            out.add(rel + ":" + (i + 1) + " lists " + c + ", which the starter does not have");
                        }
                    }
                }
            }
        }
        return out;
    }

    private static List<Check> get(Future<List<Check>> f, String what) {
        try {
            return f.get();
        } catch (ExecutionException e) {
            Throwable c = e.getCause();
            return List.of(new Check(what, false, "could not run: " + c.getClass().getSimpleName() + ": "
                    + firstLine(c.getMessage())));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return List.of(new Check(what, false, "interrupted"));
        }
    }

    // ---------------------------------------------------------------- contents

    private List<Check> contents() throws IOException {
        List<Check> out = new ArrayList<>();
        ReleaseSpec spec = ReleaseSpec.load(root);
        List<String> files = Release.projectFiles(starter);

        List<String> solutionText = new ArrayList<>();
        List<String> stubMarkers = new ArrayList<>();
        Pattern stub = Pattern.compile("^\\s*// STUB\\s*$");
        for (String rel : files) {
            String text = new String(Files.readAllBytes(starter.resolve(rel)), StandardCharsets.ISO_8859_1);
            String[] lines = text.split("\n", -1);
            for (int i = 0; i < lines.length; i++) {
                if (lines[i].contains("SOLUTION")) {
                    solutionText.add(rel + ":" + (i + 1));
                }
                if (stub.matcher(lines[i]).matches()) {
                    stubMarkers.add(rel + ":" + (i + 1));
                }
            }
        }
        out.add(Check.of("no \"SOLUTION\" text in any file", solutionText, files.size() + " files"));
        out.add(Check.of("no // STUB marker", stubMarkers, ""));

        List<String> leaked = new ArrayList<>();
        int regions = 0;
        int distinctive = 0;
        for (String rel : Release.projectFiles(root)) {
            if (!rel.endsWith(".java") || !rel.startsWith("src/")) {
                continue;
            }
            String text = Files.readString(root.resolve(rel), StandardCharsets.UTF_8);
            if (!SolutionRegions.hasRegions(text)) {
                continue;
            }
            Path inStarter = starter.resolve(rel);
            if (!Files.isRegularFile(inStarter)) {
                continue; // instructor-only file: "nothing private" below covers it
            }
            Set<String> starterLines = Files.readAllLines(inStarter, StandardCharsets.UTF_8).stream()
                    .map(String::trim).collect(Collectors.toSet());
            List<SolutionRegions.Region> rs = SolutionRegions.parse(rel, text);
            regions += rs.size();
            String[] lines = text.split("\n", -1);
            Set<Integer> inside = new HashSet<>();
            for (SolutionRegions.Region r : rs) {
                for (int k = r.beginLine(); k <= r.endLine(); k++) {
                    inside.add(k);
                }
            }
            Set<String> outside = new HashSet<>();
            for (int k = 1; k <= lines.length; k++) {
                if (!inside.contains(k)) {
                    outside.add(lines[k - 1].trim());
                }
            }
            for (SolutionRegions.Region r : rs) {
                for (int j = 0; j < r.solution().size(); j++) {
                    String s = r.solution().get(j).trim();
                    if (s.length() < 12 || outside.contains(s)) {
                        continue;
                    }
                    distinctive++;
                    if (starterLines.contains(s)) {
                        leaked.add(rel + ":" + (r.beginLine() + 1 + j) + " (" + abbreviate(s, 40) + ")");
                    }
                }
            }
        }
        out.add(Check.of("no solution line in the starter", leaked,
                distinctive + " distinctive lines of " + regions + " regions checked"));

        List<String> privateFiles = new ArrayList<>();
        Set<String> hiddenNames = new HashSet<>();
        Set<String> hiddenPaths = new HashSet<>();
        for (Assignment a : assignments.all()) {
            for (String h : a.tests().hidden()) {
                hiddenPaths.add(h);
                hiddenNames.add(h.substring(h.lastIndexOf('/') + 1));
            }
        }
        for (String rel : files) {
            String name = rel.substring(rel.lastIndexOf('/') + 1);
            if (ReleaseSpec.matchesAny(spec.never(), rel) || ReleaseSpec.matchesAny(spec.exclude(), rel)) {
                privateFiles.add(rel);
            } else if (hiddenPaths.contains(rel) || hiddenNames.contains(name)) {
                privateFiles.add(rel + " (hidden test)");
            }
        }
        out.add(Check.of("nothing instructor-only or hidden", privateFiles, hiddenPaths.size() + " hidden tests absent"));

        // No file of the starter names a hidden test, and none but the framework's sources the
        // grader's folder (the mutation profile of the instructor's pom.xml named every hidden test
        // class and grader/tests).
        Set<String> hiddenClasses = new HashSet<>();
        hiddenNames.forEach(n -> hiddenClasses.add(n.endsWith(".java") ? n.substring(0, n.length() - 5) : n));
        out.add(Check.of("no file names a hidden test or grader/", namesHidden(starter, files, hiddenClasses),
                hiddenClasses.size() + " hidden test names looked for"));

        out.add(Check.of("services files list only the starter's classes", unshippedProviders(starter, files), ""));
        out.add(Check.of("every page of docs/ that a file names or links is in the starter", unshippedDocs(starter, files),
                ""));
        List<String> fences = new ArrayList<>();
        for (String rel : files) {
            if (rel.endsWith(".md")) {
                fences.addAll(MarkdownFences.unclosed(rel, Files.readString(starter.resolve(rel))));
            }
        }
        out.add(Check.of("every Markdown page of the starter closes its code blocks", fences, ""));

        List<String> desc = new ArrayList<>();
        try {
            Assignments s = Assignments.load(starter);
            if (!s.ids().equals(assignments.ids())) {
                desc.add("milestones " + s.ids() + " instead of " + assignments.ids());
            }
            for (Assignment a : s.all()) {
                if (!a.tests().hidden().isEmpty()) {
                    desc.add(a.folder() + "/assignment.json still lists hidden tests");
                }
                for (String v : a.tests().visible()) {
                    if (!Files.isRegularFile(starter.resolve(v))) {
                        desc.add("visible test " + v + " missing");
                    }
                }
                for (Assignment.GradedScene g : a.scenes()) {
                    for (String f : List.of(g.scene(), g.reference())) {
                        if (!Files.isRegularFile(starter.resolve(f))) {
                            desc.add(a.id() + ": " + f + " missing");
                        }
                    }
                }
            }
        } catch (IOException e) {
            desc.add(firstLine(e.getMessage()));
        }
        out.add(Check.of("assignment descriptions readable, without hidden tests, their files present", desc,
                assignments.ids().size() + " milestones"));
        out.add(Check.of("reference ray traces of the published scenes match their reference images",
                ReferenceTraces.problems(starter, files), ReferenceTraces.published(files).size() + " scenes"));

        List<String> tables = new ArrayList<>();
        for (Assignment a : assignments.all()) {
            Path handout = starter.resolve(a.folder().toString()).resolve("README.md");
            if (Files.isRegularFile(handout)) {
                String text = Files.readString(handout, StandardCharsets.UTF_8);
                if (!text.equals(HandoutTable.update(text, raylab.course.GradingPlan.of(root, a)))) {
                    tables.add(a.folder() + "/README.md");
                }
            }
        }
        out.add(Check.of("handout grading tables and totals agree with assignment.json", tables,
                assignments.ids().size() + " handouts"));

        List<String> readme = new ArrayList<>();
        Path readmeFile = starter.resolve("README.md");
        if (!Files.isRegularFile(readmeFile)) {
            readme.add("README.md missing");
        } else {
            Matcher m = Pattern.compile("\\]\\(([^)#\\s]+)\\)").matcher(Files.readString(readmeFile));
            while (m.find()) {
                String link = m.group(1);
                if (!link.contains("://") && !Files.exists(starter.resolve(link))) {
                    readme.add("README.md links to " + link + ", which is not in the starter");
                }
            }
        }
        out.add(Check.of("README says how to submit, and ./raylab submit-check is in the starter",
                submitProblems(starter), ""));
        List<String> modes = new ArrayList<>();
        for (String rel : files) {
            PosixFileAttributeView v = Files.getFileAttributeView(starter.resolve(rel), PosixFileAttributeView.class);
            if (v != null) {
                boolean x = v.readAttributes().permissions().contains(PosixFilePermission.OWNER_EXECUTE);
                if (x != spec.executable().contains(rel)) {
                    modes.add(rel + (x ? " is executable" : " is not executable"));
                }
            }
        }
        readme.addAll(modes);
        out.add(Check.of("README links resolve, only " + spec.executable() + " executable", readme, ""));
        return out;
    }

    /**
     * What is missing for a student to submit: the README's "## Submitting" section naming
     * submit-check, a part for each platform, and the command's sources (the command and the
     * grader's intake it reads submissions with) in the starter.
     */
    static List<String> submitProblems(Path starter) throws IOException {
        List<String> problems = new ArrayList<>();
        Path readme = starter.resolve("README.md");
        String text = Files.isRegularFile(readme) ? Files.readString(readme, StandardCharsets.UTF_8) : "";
        int at = text.indexOf("\n## Submitting\n");
        if (at < 0) {
            problems.add("README.md has no \"## Submitting\" section");
        } else {
            int end = text.indexOf("\n## ", at + 1);
            String section = end < 0 ? text.substring(at) : text.substring(at, end);
            if (!section.contains("./raylab submit-check")) {
                problems.add("README.md's Submitting section does not name ./raylab submit-check");
            }
            for (String platform : List.of("### Gradescope", "### PrairieLearn", "### Classroom 50")) {
                if (!section.contains("\n" + platform)) {
                    problems.add("README.md's Submitting section has no part \"" + platform + "\"");
                }
            }
        }
        Path jar = toolsJar(starter);
        Set<String> entries = new HashSet<>();
        if (jar == null) {
            problems.add("the starter has no tools jar (" + ToolsJar.REPOSITORY + "/.../" + ToolsJar.ARTIFACT + "-*.jar)");
        } else {
            try (java.util.jar.JarFile j = new java.util.jar.JarFile(jar.toFile())) {
                j.stream().forEach(e -> entries.add(e.getName()));
            }
        }
        for (String c : SUBMIT_CLASSES) {
            if (jar != null && !entries.contains(c.replace('.', '/') + ".class")) {
                problems.add(c + " is not in the starter's tools jar (./raylab submit-check needs it)");
            }
        }
        return problems;
    }

    /** The classes ./raylab submit-check runs in the starter: the command and the grader's intake. */
    static final List<String> SUBMIT_CLASSES = List.of("raylab.cli.SubmitCheckCommand", "raylab.course.Submission",
            "raylab.course.PackageScanner");

    /** The starter's tools jar (not its sources jar), or null when there is none. */
    static Path toolsJar(Path starter) throws IOException {
        Path lib = starter.resolve(ToolsJar.REPOSITORY);
        if (!Files.isDirectory(lib)) {
            return null;
        }
        try (var s = Files.walk(lib)) {
            return s.filter(p -> {
                String n = p.getFileName().toString();
                return n.startsWith(ToolsJar.ARTIFACT + "-") && n.endsWith(".jar") && !n.endsWith("-sources.jar");
            }).sorted().findFirst().orElse(null);
        }
    }

    // ---------------------------------------------------------------- compile and discover

    private List<Check> compile() throws IOException {
        List<Check> out = new ArrayList<>();
        mainClasses = work.resolve("starter-main");
        testClasses = work.resolve("starter-tests");
        JavaBuild.deleteTree(mainClasses);
        JavaBuild.deleteTree(testClasses);
        // The lab alone, without the tools jar: the starter's sources use nothing of the tools.
        List<Path> mainSources = JavaBuild.sourcesUnder(starter.resolve("src/main/java"));
        JavaBuild.Result m = JavaBuild.compile(mainSources, labLibraries, mainClasses);
        out.add(compiled("the starter's src/main/java compiles", m, mainSources.size()));
        if (!m.success()) {
            return out;
        }
        // The visible tests' helpers use the tools (raylab.course.Notes), as the starter's pom.xml gives them.
        List<Path> testSources = JavaBuild.sourcesUnder(starter.resolve("src/test/java"));
        JavaBuild.Result t = JavaBuild.compile(testSources, cp(mainClasses), testClasses);
        out.add(compiled("the starter's visible tests compile", t, testSources.size()));
        return out;
    }

    /** No reference method body anywhere in the starter, by bytecode or by source ({@link SolutionLeaks}). */
    private Check noSolutionLeak() {
        String name = "no reference method body in the starter (normalized bytecode and source tokens)";
        try {
            List<SolutionLeaks.Leak> leaks = SolutionLeaks.find(root, starter, assignments, mainClasses,
                    List.of(mainClasses, testClasses), libraries, work.resolve("leaks"));
            return Check.of(name, leaks.stream().map(Object::toString).toList(), "");
        } catch (IOException | RuntimeException e) {
            return new Check(name, false, "could not check: " + firstLine(e.getMessage()));
        }
    }

    private Check compiled(String name, JavaBuild.Result r, int files) {
        if (r.success()) {
            return new Check(name, true, files + " files");
        }
        return new Check(name, false, summarize(r.errors().stream().map(p -> {
            String f = p.file() == null ? "" : starter.relativize(p.file().toAbsolutePath()).toString() + ":" + p.line() + ": ";
            return f + p.message();
        }).toList()));
    }

    private Check discover() throws IOException {
        milestoneOfClass = new HashMap<>();
        for (Assignment a : assignments.all()) {
            for (String v : a.tests().visible()) {
                milestoneOfClass.put(MilestoneCheck.className(v), a.id());
            }
        }
        expected = TestLauncher.discover(cp(mainClasses, testClasses), testClasses, List.of(), List.of(), work);
        Map<String, Integer> counts = new LinkedHashMap<>();
        List<String> problems = new ArrayList<>();
        for (String id : assignments.ids()) {
            counts.put(id, 0);
        }
        for (List<TestResult> g : raylab.course.GradingPlan.byMethod(expected).values()) {
            TestResult r = g.get(0);
            String id = milestoneOf(r);
            if (id == null) {
                problems.add(r.className() + " is a test of no milestone");
            }
        }
        // Counted as everywhere else: one test per test method, from the test files.
        for (Assignment a : assignments.all()) {
            int n = 0;
            for (String v : a.tests().visible()) {
                if (Files.isRegularFile(starter.resolve(v))) {
                    n += raylab.course.GradingPlan.testMethods(starter.resolve(v), raylab.course.GradingPlan.className(v)).size();
                }
            }
            counts.put(a.id(), n);
        }
        counts.forEach((id, n) -> {
            if (n == 0) {
                problems.add("milestone " + id + " has no visible test");
            }
        });
        String detail = counts.entrySet().stream().map(e -> e.getKey() + " " + e.getValue())
                .collect(Collectors.joining(", "));
        return Check.of("visible tests found (" + detail + ")", problems, "");
    }

    private String milestoneOf(TestResult r) {
        String c = r.className();
        int dollar = c.indexOf('$');
        return milestoneOfClass.get(dollar < 0 ? c : c.substring(0, dollar));
    }

    // ---------------------------------------------------------------- milestone checks

    private List<Check> stubsOnly() throws IOException {
        List<TestResult> results = runTests(null, "stubs");
        List<Check> out = new ArrayList<>();
        for (String id : assignments.ids()) {
            List<TestResult> mine = of(results, id);
            List<String> problems = new ArrayList<>();
            for (TestResult r : mine) {
                if (r.status().passed()) {
                    problems.add(name(r) + " passes on the stubs");
                } else if (!r.message().contains(NOT_IMPLEMENTED)) {
                    problems.add(name(r) + " fails without saying what is not implemented: "
                            + abbreviate(r.message(), 100));
                }
            }
            out.add(Check.of(id + ": on the stubs its " + mine.size() + " visible tests fail with \"not implemented\"",
                    problems, ""));
        }
        return out;
    }

    /**
     * The checks of one milestone, as separate jobs (tests, each scene, the scene without the
     * solution) so that two workers stay busy; results keep this order.
     */
    private List<Callable<List<Check>>> milestoneJobs(Assignment a) {
        List<Callable<List<Check>>> jobs = new ArrayList<>();
        Set<String> with = new TreeSet<>(a.requires());
        with.add(a.id());
        jobs.add(() -> milestoneTests(a, with));
        for (Assignment.GradedScene g : a.scenes()) {
            jobs.add(() -> List.of(render(a, g, with)));
        }
        if (!a.scenes().isEmpty()) {
            jobs.add(() -> List.of(renderWithout(a)));
        }
        return jobs;
    }

    private List<Check> milestoneTests(Assignment a, Set<String> with) throws IOException {
        List<Check> out = new ArrayList<>();
        String label = a.id() + (a.requires().isEmpty() ? "" : " (with " + String.join(", ", a.requires()) + ")");
        Path overlay = overlay(with);
        List<TestResult> results = runTests(overlay, "with-" + a.id());
        List<TestResult> mine = of(results, a.id());
        List<String> failing = mine.stream().filter(r -> !r.status().passed())
                .map(r -> name(r) + ": " + abbreviate(r.message(), 100)).toList();
        out.add(Check.of(label + ": solution put back, its " + mine.size() + " visible tests pass", failing, ""));
        List<String> others = new ArrayList<>();
        int otherCount = 0;
        for (String id : assignments.ids()) {
            if (with.contains(id)) {
                continue;
            }
            for (TestResult r : of(results, id)) {
                otherCount++;
                if (r.status().passed()) {
                    others.add(name(r) + " (" + id + ") passes");
                }
            }
        }
        if (otherCount > 0) {
            out.add(Check.of(label + ": the other milestones' " + otherCount + " tests still fail", others, ""));
        }
        if (!a.requires().isEmpty()) {
            List<TestResult> req = of(runTests(overlay(new TreeSet<>(a.requires())), "without-" + a.id()), a.id());
            List<String> problems = new ArrayList<>();
            for (TestResult r : req) {
                if (r.status().passed()) {
                    problems.add(name(r) + " passes without " + a.id() + "'s code");
                } else if (!r.message().contains("'" + a.id() + "' " + NOT_IMPLEMENTED)) {
                    problems.add(name(r) + " does not name milestone " + a.id() + ": "
                            + abbreviate(r.message(), 100));
                }
            }
            out.add(Check.of(a.id() + ": with only " + String.join(", ", a.requires())
                    + " put back, its tests fail naming '" + a.id() + "'", problems, ""));
        }
        return out;
    }

    /** The milestone's first scene, with only the milestones it requires put back: exit 3 naming it. */
    private Check renderWithout(Assignment a) throws IOException {
        Path without = a.requires().isEmpty() ? null : overlay(new TreeSet<>(a.requires()));
        String scene = a.scenes().get(0).scene();
        Path png = work.resolve("renders/without-" + a.id() + "-" + baseName(scene) + ".png");
        Files.createDirectories(png.getParent());
        MilestoneBuild.RenderOutcome o = MilestoneBuild.renderInChild(
                cp(without, mainClasses), starter.resolve(scene), png, Duration.ofSeconds(120), 512, work);
        boolean ok = o.exitStatus() == 3 && o.message().contains("'" + a.id() + "'");
        return new Check(a.id() + ": without its solution, " + scene + " stops naming '" + a.id() + "'", ok,
                "exit " + o.exitStatus() + ", \"" + abbreviate(o.message(), 120) + "\"");
    }

    private Check render(Assignment a, Assignment.GradedScene g, Set<String> with) throws IOException {
        Path overlay = overlay(with);
        String name = a.id() + ": " + g.scene() + " renders and matches " + g.reference();
        Path png = work.resolve("renders/" + a.id() + "-" + baseName(g.scene()) + ".png");
        Files.createDirectories(png.getParent());
        MilestoneBuild.RenderOutcome o = MilestoneBuild.renderInChild(cp(overlay, mainClasses),
                starter.resolve(g.scene()), png, Duration.ofSeconds(120), 1024, work);
        if (o.exitStatus() != 0) {
            return new Check(name, false, "render exit " + o.exitStatus() + ": " + abbreviate(o.message(), 160));
        }
        Path ref = starter.resolve(g.reference());
        if (!Files.isRegularFile(ref)) {
            return new Check(name, false, g.reference() + " is missing");
        }
        try {
            ImageCompare.Result r = ImageCompare.compare(PngFiles.read(png), PngFiles.read(ref));
            return new Check(name, r.matches(g.tolerance()), r.summary() + ", tolerance "
                    + String.format("%.3f%%", 100 * g.tolerance()));
        } catch (IllegalArgumentException e) {
            return new Check(name, false, e.getMessage());
        }
    }

    /** The classes of the given milestones' files with their solutions, compiled over the stubs (null if that fails). */
    private Path overlay(Set<String> milestones) throws IOException {
        String key = String.join("+", new TreeSet<>(milestones));
        CompletableFuture<Path> mine = new CompletableFuture<>();
        CompletableFuture<Path> f = overlays.putIfAbsent(key, mine);
        if (f == null) {
            try {
                mine.complete(compileOverlay(milestones, key));
            } catch (IOException | RuntimeException e) {
                mine.completeExceptionally(e);
            }
            f = mine;
        }
        try {
            return f.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted");
        } catch (ExecutionException e) {
            throw e.getCause() instanceof IOException io ? io : new IOException(e.getCause());
        }
    }

    private Path compileOverlay(Set<String> milestones, String key) throws IOException {
        Map<String, String> files = new LinkedHashMap<>();
        for (String id : milestones) {
            Assignment a = assignments.byId(id).orElseThrow();
            for (Assignment.StudentFile f : a.files()) {
                files.put(f.path(), MilestoneBuild.withSolutions(root.resolve(f.path()), f.path(), milestones));
            }
        }
        Path dir = work.resolve("overlay").resolve(key);
        JavaBuild.deleteTree(dir);
        JavaBuild.Result r = MilestoneBuild.compileOverlay(files, dir.resolve("src"), cp(mainClasses),
                dir.resolve("classes"));
        if (!r.success()) {
            throw new IOException("the solutions of " + key + " do not compile over the stubs: "
                    + summarize(r.errors().stream().map(Object::toString).toList()));
        }
        return dir.resolve("classes");
    }

    private List<TestResult> runTests(Path overlay, String what) throws IOException {
        Path dir = work.resolve("runs").resolve(what);
        Files.createDirectories(dir);
        TestLauncher.Run o = TestLauncher.run(cp(overlay, mainClasses, testClasses), testClasses, List.of(),
                List.of(), TestLauncher.Limits.DEFAULT, dir, expected);
        return o.results();
    }

    private List<TestResult> of(List<TestResult> results, String milestone) {
        return results.stream().filter(r -> milestone.equals(milestoneOf(r))).toList();
    }

    private static String name(TestResult r) {
        String c = r.className();
        return c.substring(c.lastIndexOf('.') + 1) + "." + r.method()
                + (r.displayName().equals(r.method() + "()") || r.displayName().equals(r.method()) ? ""
                        : " [" + abbreviate(r.displayName(), 40) + "]");
    }

    // ---------------------------------------------------------------- helpers

    /** The given class folders first, then the libraries. */
    private List<Path> cp(Path... first) {
        List<Path> out = new ArrayList<>();
        for (Path p : first) {
            if (p != null) {
                out.add(p);
            }
        }
        out.addAll(libraries);
        return out;
    }

    /**
     * This JVM's class path without its class folders: the libraries (when raylab runs from its
     * shaded jar, that jar, whose raylab classes come after the starter's on every class path).
     */
    static List<Path> libraries() {
        List<Path> out = new ArrayList<>();
        for (Path p : JavaBuild.ownClassPath()) {
            if (!Files.isDirectory(p)) {
                out.add(p);
            }
        }
        return out;
    }

    static String baseName(String path) {
        String n = path.substring(path.lastIndexOf('/') + 1);
        return n.replaceFirst("\\.json$", "");
    }

    static String summarize(List<String> problems) {
        int show = Math.min(problems.size(), 5);
        String s = String.join("; ", problems.subList(0, show));
        return problems.size() > show ? s + "; and " + (problems.size() - show) + " more" : s;
    }

    static String abbreviate(String s, int n) {
        String one = firstLine(s);
        return one.length() <= n ? one : one.substring(0, n - 3) + "...";
    }

    static String firstLine(String s) {
        if (s == null) {
            return "";
        }
        int nl = s.indexOf('\n');
        return (nl < 0 ? s : s.substring(0, nl)).strip();
    }
}
