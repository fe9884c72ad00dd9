package raylab.grade;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.jar.JarOutputStream;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.tools.Diagnostic;
import javax.tools.JavaFileObject;

import com.fasterxml.jackson.core.type.TypeReference;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import raylab.course.Assignment;
import raylab.course.JavaBuild;
import raylab.course.SourceRoots;
import raylab.course.TestLauncher;
import raylab.course.TestResult;

/**
 * What the grader builds once and caches (under {@code target/grader-cache/<key>} of the project
 * root): the framework classes without any student file's reference solution and without
 * instructor-only packages ({@code framework.jar}); each milestone's reference classes
 * ({@code ref/<id>/}); the grader's tests compiled from its own copies (visible tests, hidden
 * tests, generated data-case tests: {@code tests/}); and the list of tests each milestone must
 * report, found by running them on the reference ({@code expected.json}).
 *
 * <p>One job: the grader's build and its cache, whose parts share one cache key and one manifest.
 */
final class GraderSetup {
    private static final ObjectMapper JSON = new ObjectMapper();
    /** Instructor-only packages kept out of the student's child JVM. */
    static final List<String> PRIVATE_PACKAGES = List.of("raylab/grade/", "raylab/numerics/", "raylab/study/");
    /**
     * The packages of the build's tools inside the shaded jar, the jars {@link #toolOfTheBuild}
     * leaves out of a test run's cache: the study's charts and their PDF and logging libraries, the
     * benchmarks'. No trusted JVM and no student process loads them; in framework.jar they were
     * half of what every grading hashes ({@link CacheManifest#verify}) and every JVM's jar index.
     */
    static final List<String> TOOL_PACKAGES = List.of("org/apache/pdfbox/", "org/apache/fontbox/",
            "org/apache/commons/logging/", "org/knowm/xchart/", "de/rototor/", "de/erichseifert/", "com/madgag/",
            "org/openjdk/jmh/", "joptsimple/", "org/apache/commons/math3/", "org/pitest/", "org/slf4j/");

    final Path dir;
    final Path framework;
    final Path tests;
    final List<Path> libraries;
    final Map<String, Path> references = new LinkedHashMap<>();
    /**
     * The public classes of every student file (the starter's stubs, compiled): with
     * {@link #framework} the public framework the student process gets.
     */
    final Path publicStubs;
    /**
     * The framework as the starter ships it: {@link #framework}'s classes without those the
     * release leaves out of the starter ({@code assignments/release.json} "exclude").
     */
    final Path publicFramework;
    /** Per milestone: its stand-in classes for the grader's process ({@link raylab.boundary.StandIns}). */
    final Map<String, Path> standIns = new LinkedHashMap<>();
    /** Per milestone: the test classes (outer names) that belong to it. */
    final Map<String, List<String>> testClasses = new LinkedHashMap<>();
    /** Per milestone: the tests found by running them on the reference. */
    final Map<String, List<TestResult>> expected = new LinkedHashMap<>();
    /** Per milestone: its data cases. */
    final Map<String, List<DataCases.Case>> cases = new LinkedHashMap<>();
    final List<String> notes = new ArrayList<>();
    /**
     * Milestones the course's setup cannot grade, with the cause (a test that fails on the
     * reference solution): their gradings fail ({@link GradeReport#failed}); never a test left out.
     */
    final Map<String, String> broken = new java.util.LinkedHashMap<>();

    private GraderSetup(Path dir, List<Path> libraries) {
        this.dir = dir;
        this.framework = dir.resolve("framework.jar");
        this.tests = dir.resolve("tests");
        this.publicStubs = dir.resolve("public");
        this.publicFramework = dir.resolve("public-framework.jar");
        this.libraries = libraries;
    }

    /** This JVM's class path as absolute paths (children run in other directories). */
    static List<Path> ownClassPath() {
        return JavaBuild.ownClassPath().stream().map(p -> p.toAbsolutePath().normalize()).toList();
    }

    /**
     * Whether {@code p} is a jar of the build's own tools, which no trusted JVM loads: Maven's
     * test runner, the fuzzer, the architecture tests, the study's charts and their PDF and
     * logging libraries. On a test run's class path (the grader graded in Maven's test JVM) they
     * are most of its megabytes, which every grading would hash ({@link CacheManifest#verify})
     * and every seeded copy of the cache would copy. Folders and every other jar are kept: an
     * instructor's classes before the jar ({@code target/incremental}) go wherever raylab's go.
     */
    static boolean toolOfTheBuild(Path p) {
        return p.getFileName().toString().matches("(surefire|common-java5|jazzer|archunit|slf4j|xchart"
                + "|VectorGraphics2D|graphics2d|pdfbox|fontbox|commons-logging|animated-gif-lib|jmh|jopt-simple"
                + "|commons-math3|pitest)[-.].*\\.jar");
    }

    /** The class path entry holding raylab's own classes (a directory or the shaded jar). */
    static Path codeSource() throws IOException {
        for (Path p : GraderSetup.ownClassPath()) {
            if (Files.isDirectory(p) ? Files.exists(p.resolve("raylab/cli/Main.class")) : hasEntry(p, "raylab/cli/Main.class")) {
                return p;
            }
        }
        throw new IOException("cannot find raylab's own classes on the class path");
    }

    private static boolean hasEntry(Path jar, String name) {
        if (!Files.isRegularFile(jar)) {
            return false;
        }
        try (JarFile j = new JarFile(jar.toFile())) {
            return j.getEntry(name) != null;
        } catch (IOException e) {
            return false;
        }
    }

    /** Class-file name prefixes of a student file: "raylab/surface/Sphere". */
    static String classPrefix(String studentPath) {
        String s = studentPath.startsWith("src/main/java/") ? studentPath.substring("src/main/java/".length()) : studentPath;
        return s.substring(0, s.length() - ".java".length());
    }

    static boolean isClassOf(String entry, String prefix) {
        return entry.equals(prefix + ".class") || (entry.startsWith(prefix + "$") && entry.endsWith(".class"));
    }

    /** Class name of a test file path (relative to the project root). */
    static String testClassName(String path) {
        String s = path;
        for (String root : List.of("src/test/java/", "grader/tests/")) {
            if (s.startsWith(root)) {
                s = s.substring(root.length());
            }
        }
        return s.substring(0, s.length() - ".java".length()).replace('/', '.');
    }

    /**
     * Builds (or reuses from the cache) everything the grader needs for these milestones. A
     * selection of some of the course's milestones (or of all in another order) uses the whole
     * course's build when the cache holds it already (it holds every milestone's classes, tests
     * and expected results), instead of building one of its own: one build serves every selection.
     */
    static GraderSetup prepare(Path root, List<Assignment> milestones, Path cacheRoot, java.util.function.Consumer<String> log)
            throws IOException {
        List<Assignment> course = Assignments0.all(root);
        List<String> courseIds = course.stream().map(Assignment::id).toList();
        List<String> ids = milestones.stream().map(Assignment::id).toList();
        // Some of the course's milestones, or all of them in another order (the build's key is the list).
        if (!ids.equals(courseIds) && courseIds.containsAll(ids)) {
            GraderSetup whole = prepare(root, course, cacheRoot, log, false);
            if (whole != null) {
                return whole.restrictedTo(milestones);
            }
        }
        return prepare(root, milestones, cacheRoot, log, true);
    }

    /**
     * This build for some of its milestones: their references, stand-ins, data cases, expected
     * tests and problems; the test classes of every milestone stay listed (which of the cached
     * classes are hidden, as in a grading of the whole course).
     */
    private GraderSetup restrictedTo(List<Assignment> milestones) throws IOException {
        GraderSetup s = new GraderSetup(dir, libraries);
        s.testClasses.putAll(testClasses);
        for (Assignment a : milestones) {
            s.cases.put(a.id(), cases.get(a.id()));
            s.references.put(a.id(), references.get(a.id()));
            s.standIns.put(a.id(), standIns.get(a.id()));
        }
        s.readExpected(dir.resolve("expected.json"), milestones);
        return s;
    }

    /** As above for exactly these milestones; without {@code build}, null where the cache does not hold them. */
    private static GraderSetup prepare(Path root, List<Assignment> milestones, Path cacheRoot,
            java.util.function.Consumer<String> log, boolean build) throws IOException {
        Path code = codeSource();
        List<Path> libs = new ArrayList<>();
        for (Path p : GraderSetup.ownClassPath()) {
            if (!p.equals(code) && !p.getFileName().toString().equals("test-classes") && !toolOfTheBuild(p)) {
                libs.add(p.toAbsolutePath());
            }
        }
        Map<String, List<DataCases.Case>> cases = new LinkedHashMap<>();
        List<Path> testSources = new ArrayList<>();
        Map<String, List<String>> classesOf = new LinkedHashMap<>();
        for (Assignment a : milestones) {
            List<String> cls = new ArrayList<>();
            for (String t : concat(a.tests().visible(), a.tests().hidden())) {
                Path f = root.resolve(t);
                if (!Files.isRegularFile(f)) {
                    throw new IOException(a.folder() + "/assignment.json lists the test file " + t
                            + ", which does not exist (grader setup problem)");
                }
                testSources.add(f);
                cls.add(testClassName(t));
            }
            List<DataCases.Case> cs = DataCases.load(root, a);
            cases.put(a.id(), cs);
            if (cs.stream().anyMatch(DataCases::visible)) {
                cls.add(DataCases.visibleClassName(a.id()));
            }
            if (cs.stream().anyMatch(c -> !DataCases.visible(c))) {
                cls.add(DataCases.className(a.id()));
            }
            classesOf.put(a.id(), cls);
        }
        // The cache key: everything the cached results depend on.
        MessageDigest md = sha256();
        md.update(code.toAbsolutePath().toString().getBytes(StandardCharsets.UTF_8));
        md.update(digestOf(code).getBytes(StandardCharsets.UTF_8));
        for (Path p : libs) {
            md.update(p.toString().getBytes(StandardCharsets.UTF_8));
        }
        List<Path> hashed = new ArrayList<>(testSources);
        hashed.addAll(JavaBuild.sourcesUnder(root.resolve("grader/tests")));
        hashed.addAll(JavaBuild.sourcesUnder(root.resolve("src/test/java/raylab/testing")));
        for (Path p : hashed) {
            md.update(p.toString().getBytes(StandardCharsets.UTF_8));
            md.update(Files.readAllBytes(p));
        }
        for (Assignment a : milestones) {
            md.update(a.toString().getBytes(StandardCharsets.UTF_8));
            for (DataCases.Case c : cases.get(a.id())) {
                md.update(c.toString().getBytes(StandardCharsets.UTF_8));
            }
        }
        String key = HexFormat.of().formatHex(md.digest()).substring(0, 20);
        Path dir = cacheRoot.resolve(key);
        List<Path> cachedLibs = new ArrayList<>();
        for (int i = 0; i < libs.size(); i++) {
            cachedLibs.add(dir.resolve("lib").resolve(i + "-" + libs.get(i).getFileName()));
        }
        GraderSetup s = new GraderSetup(dir, cachedLibs);
        s.cases.putAll(cases);
        s.testClasses.putAll(classesOf);
        for (Assignment a : milestones) {
            s.references.put(a.id(), dir.resolve("ref").resolve(a.id()));
            s.standIns.put(a.id(), dir.resolve("standins").resolve(a.id()));
        }
        Path expectedFile = dir.resolve("expected.json");
        if (CacheManifest.usable(dir, log)) { // verified against its hash manifest, else deleted and rebuilt
            s.readExpected(expectedFile, milestones);
            return s;
        }
        if (!build) {
            return null;
        }
        log.accept("grader: building the grader's classes and listing the tests on the reference (cached in "
                + dir + ")");
        Files.createDirectories(cacheRoot);
        Path tmp = Files.createTempDirectory(cacheRoot, key + ".tmp");
        GraderSetup t = new GraderSetup(tmp, libs);
        t.cases.putAll(cases);
        t.testClasses.putAll(classesOf);
        List<String> studentPrefixes = new ArrayList<>();
        for (Assignment a : Assignments0.all(root)) {
            for (Assignment.StudentFile f : a.files()) {
                studentPrefixes.add(classPrefix(f.path()));
            }
        }
        writeFramework(code, t.framework, studentPrefixes);
        // Libraries are copied next to it: the sandbox user cannot read a home directory's ~/.m2.
        Files.createDirectories(tmp.resolve("lib"));
        for (int i = 0; i < libs.size(); i++) {
            Path from = libs.get(i);
            Path to = tmp.resolve("lib").resolve(i + "-" + from.getFileName());
            if (Files.isDirectory(from)) {
                try (Stream<Path> w = Files.walk(from)) {
                    for (Path p : (Iterable<Path>) w::iterator) {
                        Path q = to.resolve(from.relativize(p).toString());
                        if (Files.isDirectory(p)) {
                            Files.createDirectories(q);
                        } else {
                            Files.copy(p, q);
                        }
                    }
                }
            } else if (Files.isRegularFile(from)) {
                Files.copy(from, to);
            }
        }
        for (Assignment a : milestones) {
            List<String> prefixes = a.files().stream().map(f -> classPrefix(f.path())).toList();
            copyClasses(code, tmp.resolve("ref").resolve(a.id()), prefixes);
        }
        writeBoundaryClasses(root, milestones, t, libs);
        // Compile the grader's tests: generated case classes, hidden and visible tests, with
        // their helpers found on the source path.
        Path gen = tmp.resolve("generated");
        for (Assignment a : milestones) {
            for (boolean visible : new boolean[] {true, false}) {
                List<DataCases.Case> part = cases.get(a.id()).stream().filter(c -> DataCases.visible(c) == visible).toList();
                if (part.isEmpty()) {
                    continue;
                }
                String cls = visible ? DataCases.visibleClassName(a.id()) : DataCases.className(a.id());
                Path f = gen.resolve(cls.replace('.', '/') + ".java");
                Files.createDirectories(f.getParent());
                Files.writeString(f, DataCases.testSource(cls, a.id(), part));
                testSources.add(f);
            }
        }
        // The student-facing assertion helpers are compiled here too, so that a copy compiled
        // elsewhere (target/test-classes) is never needed at run time.
        for (Path helper : JavaBuild.sourcesUnder(root.resolve("src/test/java/raylab/testing"))) {
            if (!testSources.contains(helper)) {
                testSources.add(helper);
            }
        }
        List<Path> sourcePath = Stream.of(root.resolve("src/test/java"), root.resolve("grader/tests"), gen)
                .filter(Files::isDirectory).toList();
        compileWithSourcePath(testSources, sourcePath, GraderSetup.ownClassPath(), t.tests);
        // List the tests by running them on the reference (trusted code): dynamic and
        // parameterized tests appear only when run.
        Path work = Files.createTempDirectory(tmp, "run");
        List<Path> cp = new ArrayList<>();
        cp.add(t.tests);
        cp.addAll(GraderSetup.ownClassPath());
        List<String> all = classesOf.values().stream().flatMap(List::stream).toList();
        TestLauncher.Run o = TestLauncher.run(cp, t.tests, List.of(), all,
                new TestLauncher.Limits(1024, Duration.ofMinutes(10), 120, 4096), work, List.of());
        if (!o.finished()) {
            throw new IOException("running the tests on the reference failed: " + o.problem());
        }
        Map<String, List<TestResult>> exp = new LinkedHashMap<>();
        for (Assignment a : milestones) {
            List<String> mine = classesOf.get(a.id());
            exp.put(a.id(), o.results().stream()
                    .filter(r -> mine.contains(outer(r.className()))).toList());
        }
        JSON.writerWithDefaultPrettyPrinter().writeValue(tmp.resolve("expected.json").toFile(), exp);
        JavaBuild.deleteTreeQuietly(work);
        CacheManifest.write(tmp);
        // Files readable (children get hard links to them), the folder itself private: only the
        // grader can reach the cache; children get their own copies or links in their box.
        Sandbox.readableByAll(tmp);
        Sandbox.privateFolder(tmp);
        try {
            Files.move(tmp, dir, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException e) {
            // another grading built it at the same time: use theirs
            JavaBuild.deleteTreeQuietly(tmp);
        }
        s.readExpected(expectedFile, milestones);
        return s;
    }

    /**
     * The public stubs of every student file (the starter's text, compiled) and, per milestone,
     * the stand-ins of its classes: the public source with each graded method forwarding to the
     * student process.
     */
    private static void writeBoundaryClasses(Path root, List<Assignment> milestones, GraderSetup t, List<Path> libs)
            throws IOException {
        Map<String, String> stubs = new LinkedHashMap<>();
        for (Assignment a : Assignments0.all(root)) {
            for (Assignment.StudentFile f : a.files()) {
                Path src = root.resolve(f.path());
                stubs.put(classPrefix(f.path()) + ".java", raylab.course.SolutionRegions.toStudent(
                        src.getFileName().toString(), Files.readString(src), java.util.Set.of()));
            }
        }
        List<Path> below = new ArrayList<>();
        below.add(t.framework);
        below.addAll(libs);
        raylab.boundary.StandIns.compile(stubs, below, t.publicStubs);
        // The public framework: what the release puts in the starter, no more: the classes of the
        // lab and the tools (docs/architecture.md), never the grader's, authoring's or the mesh engine's.
        java.util.Set<String> shipped = new java.util.TreeSet<>(SourceRoots.classesUnder(root, SourceRoots.LAB));
        java.util.Set<String> tools = SourceRoots.classesUnder(root, SourceRoots.TOOLS);
        if (tools.isEmpty()) {
            throw new IOException(root.resolve(SourceRoots.TOOLS) + ": missing (the grader builds the public framework"
                    + " from the lab's and the tools' sources)");
        }
        shipped.addAll(tools);
        // One jar file, so that a student box links it instead of copying thousands of files.
        try (JarFile jar = new JarFile(t.framework.toFile());
                var out = new java.util.jar.JarOutputStream(Files.newOutputStream(t.publicFramework))) {
            List<JarEntry> kept = jar.stream().filter(en -> {
                String n = en.getName();
                return !(en.isDirectory() || n.startsWith("META-INF/") && !n.startsWith(ServiceFiles.FOLDER)
                        || n.startsWith("raylab/") && n.endsWith(".class") && !SourceRoots.compiledFrom(n, shipped));
            }).toList();
            java.util.Set<String> names = kept.stream().map(JarEntry::getName).collect(Collectors.toSet());
            for (JarEntry en : kept) {
                try (var in = jar.getInputStream(en)) {
                    putEntry(out, en.getName(), in.readAllBytes(), names);
                }
            }
        }
        List<Path> withStubs = new ArrayList<>(below);
        withStubs.add(0, t.publicStubs);
        for (Assignment a : milestones) {
            Map<String, String> fw = new LinkedHashMap<>();
            for (Assignment.StudentFile f : a.files()) {
                String rel = classPrefix(f.path()) + ".java";
                String fq = classPrefix(f.path()).replace('/', '.');
                java.util.Set<String> names = new java.util.LinkedHashSet<>();
                for (String m : f.methods()) {
                    names.add(m.substring(m.lastIndexOf('.') + 1));
                }
                fw.put(rel, raylab.boundary.StandIns.forwarding(stubs.get(rel), fq, names));
            }
            raylab.boundary.StandIns.compile(fw, withStubs, t.dir.resolve("standins").resolve(a.id()));
        }
    }

    /** The class names a milestone's student files define as the grader knows them ("raylab.surface.Sphere"). */
    static List<String> servedClasses(Assignment a) {
        return a.files().stream().map(f -> classPrefix(f.path()).replace('/', '.')).toList();
    }

    private void readExpected(Path file, List<Assignment> milestones) throws IOException {
        Map<String, List<TestResult>> exp = JSON.readValue(file.toFile(),
                new TypeReference<Map<String, List<TestResult>>>() { });
        for (Assignment a : milestones) {
            List<TestResult> list = exp.getOrDefault(a.id(), List.of());
            List<TestResult> good = new ArrayList<>();
            for (TestResult r : list) {
                if (r.status().passed()) {
                    good.add(r);
                } else if (!broken.containsKey(a.id())) {
                    // Left out, the test's points would go to the others or vanish: a wrong grade.
                    broken.put(a.id(), "the test " + r.className() + "." + r.method() + " of milestone " + a.id()
                            + " fails on the reference solution (" + firstLine(r.message())
                            + "): fix the test or the reference, then grade again");
                }
            }
            expected.put(a.id(), good);
        }
    }

    static String outer(String className) {
        int k = className.indexOf('$');
        return k < 0 ? className : className.substring(0, k);
    }

    static String firstLine(String s) {
        if (s == null) {
            return "";
        }
        int k = s.indexOf('\n');
        return k < 0 ? s : s.substring(0, k);
    }

    private static List<String> concat(List<String> a, List<String> b) {
        List<String> out = new ArrayList<>(a);
        out.addAll(b);
        return out;
    }

    private static boolean excluded(String entry, List<String> studentPrefixes) {
        for (String p : PRIVATE_PACKAGES) {
            if (entry.startsWith(p)) {
                return true;
            }
        }
        String unversioned = entry.replaceFirst("^META-INF/versions/\\d+/", "");
        for (String p : TOOL_PACKAGES) {
            if (unversioned.startsWith(p)) {
                return true;
            }
        }
        for (String p : studentPrefixes) {
            if (isClassOf(entry, p)) {
                return true;
            }
        }
        return false;
    }

    /** framework.jar: raylab's classes (and, from the shaded jar, its libraries) minus the excluded. */
    private static void writeFramework(Path code, Path out, List<String> studentPrefixes) throws IOException {
        try (OutputStream fo = Files.newOutputStream(out); JarOutputStream jar = new JarOutputStream(fo)) {
            jar.setLevel(1);
            if (Files.isDirectory(code)) {
                List<Path> files;
                try (Stream<Path> s = Files.walk(code)) {
                    files = s.filter(Files::isRegularFile).sorted().toList();
                }
                Map<String, Path> kept = new LinkedHashMap<>();
                for (Path p : files) {
                    String name = code.relativize(p).toString().replace(File.separatorChar, '/');
                    if (!excluded(name, studentPrefixes)) {
                        kept.put(name, p);
                    }
                }
                for (Map.Entry<String, Path> e : kept.entrySet()) {
                    putEntry(jar, e.getKey(), Files.readAllBytes(e.getValue()), kept.keySet());
                }
            } else {
                try (JarFile in = new JarFile(code.toFile())) {
                    List<JarEntry> kept = in.stream().filter(e -> !e.isDirectory() && !excluded(e.getName(), studentPrefixes)
                            && !e.getName().equals("META-INF/MANIFEST.MF")).toList();
                    java.util.Set<String> names = kept.stream().map(JarEntry::getName).collect(Collectors.toSet());
                    for (JarEntry e : kept) {
                        try (InputStream is = in.getInputStream(e)) {
                            putEntry(jar, e.getName(), is.readAllBytes(), names);
                        }
                    }
                }
            }
        }
    }

    /**
     * Writes one entry of a jar that holds the entries {@code names}; a services file lists only
     * the raylab providers among them ({@link ServiceFiles}), and is left out when none is.
     */
    private static void putEntry(JarOutputStream jar, String name, byte[] bytes, java.util.Set<String> names)
            throws IOException {
        if (name.startsWith(ServiceFiles.FOLDER)) {
            String kept = ServiceFiles.keep(new String(bytes, StandardCharsets.UTF_8),
                    c -> !c.startsWith("raylab.") || names.contains(ServiceFiles.classFile(c)));
            if (kept == null) {
                return;
            }
            bytes = kept.getBytes(StandardCharsets.UTF_8);
        }
        jar.putNextEntry(new JarEntry(name));
        jar.write(bytes);
        jar.closeEntry();
    }

    private static void copyClasses(Path code, Path out, List<String> prefixes) throws IOException {
        Files.createDirectories(out);
        if (Files.isDirectory(code)) {
            try (Stream<Path> s = Files.walk(code)) {
                for (Path p : (Iterable<Path>) s.filter(Files::isRegularFile)::iterator) {
                    String name = code.relativize(p).toString().replace(File.separatorChar, '/');
                    if (prefixes.stream().anyMatch(x -> isClassOf(name, x))) {
                        Path t = out.resolve(name);
                        Files.createDirectories(t.getParent());
                        Files.copy(p, t);
                    }
                }
            }
        } else {
            try (JarFile in = new JarFile(code.toFile())) {
                for (JarEntry e : (Iterable<JarEntry>) in.stream()::iterator) {
                    if (prefixes.stream().anyMatch(x -> isClassOf(e.getName(), x))) {
                        Path t = out.resolve(e.getName());
                        Files.createDirectories(t.getParent());
                        try (InputStream is = in.getInputStream(e)) {
                            Files.copy(is, t);
                        }
                    }
                }
            }
        }
    }

    /** Compiles sources, generating classes for the helpers they use from the source path. */
    static void compileWithSourcePath(List<Path> sources, List<Path> sourcePath, List<Path> classPath, Path out)
            throws IOException {
        List<Diagnostic<? extends JavaFileObject>> errors = JavaBuild.javac(sources, classPath, out,
                List.of("-implicit:class", "-sourcepath", JavaBuild.pathOf(sourcePath))).stream()
                .filter(d -> d.getKind() == Diagnostic.Kind.ERROR).toList();
        if (!errors.isEmpty()) {
            String errs = errors.stream().limit(5).map(d -> (d.getSource() == null ? "" : d.getSource().getName() + ":"
                    + d.getLineNumber() + ": ") + d.getMessage(Locale.ROOT).split("\n")[0]).collect(Collectors.joining("; "));
            throw new IOException("the grader's tests do not compile (grader setup problem): " + errs);
        }
    }

    private static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A digest of raylab's own classes (size and time of each class file or of the jar). */
    static String digestOf(Path code) throws IOException {
        if (!Files.isDirectory(code)) {
            return Files.size(code) + ":" + Files.getLastModifiedTime(code).toMillis();
        }
        MessageDigest md = sha256();
        try (Stream<Path> s = Files.walk(code)) {
            for (Path p : (Iterable<Path>) s.filter(Files::isRegularFile).sorted()::iterator) {
                md.update((p + ":" + Files.size(p) + ":" + Files.getLastModifiedTime(p).toMillis())
                        .getBytes(StandardCharsets.UTF_8));
            }
        }
        return HexFormat.of().formatHex(md.digest());
    }


    /** Small indirection so tests can run on a subset: all assignments of the root. */
    static final class Assignments0 {
        static List<Assignment> all(Path root) throws IOException {
            return raylab.course.Assignments.load(root).all();
        }
    }
}
