package raylab.course;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Collectors;

import javax.lang.model.element.Element;
import javax.lang.model.element.ElementKind;
import javax.lang.model.element.ExecutableElement;
import javax.lang.model.element.Modifier;
import javax.lang.model.element.PackageElement;
import javax.lang.model.element.TypeElement;
import javax.lang.model.util.Elements;
import javax.lang.model.util.Types;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.SimpleJavaFileObject;
import javax.tools.StandardJavaFileManager;

import com.sun.source.tree.CompilationUnitTree;
import com.sun.source.tree.Tree;
import com.sun.source.util.JavacTask;
import com.sun.source.util.TreePath;
import com.sun.source.util.TreePathScanner;
import com.sun.source.util.Trees;

/**
 * (Shared: {@code check}, {@code submit-check} and the grader say the same with it; it ships in
 * the starter.) The graded files are built by the grader against its own, original framework,
 * never against the student's edited copy. This class finds what would build here and not there:
 * the framework files a student changed (against the release's manifest, {@value #MANIFEST}: each
 * framework file's SHA-256 and the members of every released class), and each symbol a graded
 * file uses that exists only in the student's changed or added framework files, in one sentence:
 * "Sphere uses Vec3.lengthCubed, which you added to Vec3.java; the grader uses the original Vec3:
 * this will not compile there".
 */
public final class GradedBuild {
    /** The manifest the release writes into the starter. */
    public static final String MANIFEST = "assignments/framework.manifest";
    private static final String SOURCES = "src/main/java/";
    /** The trees that name a symbol the graded file uses. */
    private static final Set<Tree.Kind> USES = Set.of(Tree.Kind.IDENTIFIER, Tree.Kind.MEMBER_SELECT,
            Tree.Kind.MEMBER_REFERENCE, Tree.Kind.NEW_CLASS);

    private GradedBuild() {
    }

    /** The released framework: file to SHA-256 (framework files only) and every released member's signature. */
    public record Manifest(SortedMap<String, String> hashes, Set<String> api) {
        /** The released type names (top-level and nested), from the member list. */
        public Set<String> types() {
            return api.stream().filter(s -> !s.contains("#")).collect(Collectors.toSet());
        }
    }

    /** What the student's project has that the grader's framework has not. */
    public record Drift(List<String> changedFiles, List<String> addedFiles, List<String> uses) {
        /** True when nothing differs. */
        public boolean none() {
            return changedFiles.isEmpty() && addedFiles.isEmpty() && uses.isEmpty();
        }

        /** The same with these uses too (the graded files' uses of what another graded file of the student's has). */
        public Drift with(List<String> more) {
            List<String> all = new ArrayList<>(uses);
            more.stream().filter(u -> !all.contains(u)).forEach(all::add);
            return new Drift(changedFiles, addedFiles, all);
        }

        /** One line each: the uses first (they cost the milestone), then the files. */
        public List<String> lines() {
            List<String> out = new ArrayList<>(uses);
            for (String f : changedFiles) {
                out.add("you changed " + f + ": the grader uses the original, so your change does not count there");
            }
            for (String f : addedFiles) {
                out.add("you added " + f + ": the grader does not have it");
            }
            return out;
        }
    }

    // ---------------------------------------------------------------- the manifest

    /** The manifest's text for the released files (path to bytes) given the compiled classes on {@code classPath}. */
    public static String manifestText(SortedMap<String, byte[]> released, Set<String> studentFiles, List<Path> classPath)
            throws IOException {
        StringBuilder b = new StringBuilder();
        b.append("# The released framework, written by `raylab release`: do not edit. `./raylab check` and\n")
                .append("# `./raylab submit-check` compare your project with it: the grader builds your graded files\n")
                .append("# against these original files, never against your copy.\n");
        List<String> classes = new ArrayList<>();
        for (var e : released.entrySet()) {
            String rel = e.getKey();
            boolean toolsJar = rel.startsWith("lib/") && rel.endsWith(".jar"); // the tools, as the starter has them
            if (!toolsJar && (!rel.startsWith(SOURCES) || !rel.endsWith(".java"))) {
                continue;
            }
            if (!toolsJar) {
                classes.add(className(rel));
            }
            if (!studentFiles.contains(rel)) {
                b.append("sha256 ").append(sha256(e.getValue())).append(' ').append(rel).append('\n');
            }
        }
        for (String s : api(classes, classPath)) {
            b.append("api ").append(s).append('\n');
        }
        return b.toString();
    }

    /** Reads the manifest of the project at {@code root}, or null when it has none (the instructor's tree). */
    public static Manifest manifest(Path root) throws IOException {
        Path f = root.resolve(MANIFEST);
        if (!Files.isRegularFile(f)) {
            return null;
        }
        SortedMap<String, String> hashes = new TreeMap<>();
        Set<String> api = new TreeSet<>();
        for (String line : Files.readAllLines(f, StandardCharsets.UTF_8)) {
            if (line.startsWith("sha256 ")) {
                String[] p = line.split(" ", 3);
                hashes.put(p[2], p[1]);
            } else if (line.startsWith("api ")) {
                api.add(line.substring(4));
            }
        }
        return new Manifest(hashes, api);
    }

    static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    static String className(String rel) {
        return rel.substring(SOURCES.length(), rel.length() - ".java".length()).replace('/', '.');
    }

    /** Every non-private member (and nested type) of the given classes, as {@link #signature} gives it. */
    static Set<String> api(List<String> classes, List<Path> classPath) throws IOException {
        Set<String> out = new TreeSet<>();
        JavaCompiler javac = JavaBuild.compiler();
        try (StandardJavaFileManager files = javac.getStandardFileManager(null, Locale.ROOT, StandardCharsets.UTF_8)) {
            JavacTask task = (JavacTask) javac.getTask(new StringWriter(), files, null, options(classPath), null,
                    List.of(source("Empty.java", "class Empty {}")));
            task.analyze();
            Elements elements = task.getElements();
            Types types = task.getTypes();
            for (String c : classes) {
                TypeElement t = elements.getTypeElement(c);
                if (t != null) {
                    members(t, elements, types, out);
                }
            }
        }
        return out;
    }

    private static void members(TypeElement t, Elements elements, Types types, Set<String> out) {
        out.add(elements.getBinaryName(t).toString());
        for (Element m : t.getEnclosedElements()) {
            if (m.getModifiers().contains(Modifier.PRIVATE)) {
                continue;
            }
            if (m instanceof TypeElement nested) {
                members(nested, elements, types, out);
            } else {
                out.add(signature(m, elements, types));
            }
        }
    }

    /** "raylab.math.Vec3#dot(raylab.math.Vec3)", "raylab.math.Vec3#x", "raylab.scene.Scene$Light" (a type). */
    static String signature(Element m, Elements elements, Types types) {
        if (m instanceof TypeElement t) {
            return elements.getBinaryName(t).toString();
        }
        String owner = elements.getBinaryName((TypeElement) m.getEnclosingElement()).toString();
        if (m instanceof ExecutableElement x) {
            return owner + "#" + x.getSimpleName() + "(" + x.getParameters().stream()
                    .map(p -> types.erasure(p.asType()).toString()).collect(Collectors.joining(",")) + ")";
        }
        return owner + "#" + m.getSimpleName();
    }

    // ---------------------------------------------------------------- the student's project

    /** The framework files of the project that differ from the manifest, and the ones added. */
    public static Drift files(Path root, Manifest m, Set<String> studentFiles) throws IOException {
        List<String> changed = new ArrayList<>();
        for (var e : m.hashes().entrySet()) {
            Path p = root.resolve(e.getKey());
            if (!Files.isRegularFile(p) || !sha256(Files.readAllBytes(p)).equals(e.getValue())) {
                changed.add(e.getKey());
            }
        }
        List<String> added = new ArrayList<>();
        Set<String> released = new LinkedHashSet<>(m.hashes().keySet());
        released.addAll(studentFiles);
        for (Path p : JavaBuild.sourcesUnder(root.resolve(SOURCES))) {
            String rel = root.relativize(p).toString().replace('\\', '/');
            if (!released.contains(rel)) {
                added.add(rel);
            }
        }
        return new Drift(changed, added, List.of());
    }

    /**
     * Everything the grader would build differently for the project at {@code root}: its changed
     * and added framework files and the graded files' uses of what only they have. {@code graded}
     * maps each graded file's path (src/main/java/...) to the text to check: the project's own or
     * a submission's. Null when the project has no manifest.
     */
    public static Drift check(Path root, Map<String, String> graded, Set<String> studentFiles, List<Path> classPath)
            throws IOException {
        Manifest m = manifest(root);
        if (m == null) {
            return null;
        }
        Drift d = files(root, m, studentFiles);
        if (d.changedFiles().isEmpty() && d.addedFiles().isEmpty()) {
            return d;
        }
        Map<String, String> own = new LinkedHashMap<>();
        for (String f : d.changedFiles()) {
            if (Files.isRegularFile(root.resolve(f))) {
                own.put(f, Files.readString(root.resolve(f), StandardCharsets.UTF_8));
            }
        }
        for (String f : d.addedFiles()) {
            own.put(f, Files.readString(root.resolve(f), StandardCharsets.UTF_8));
        }
        List<String> uses = uses(graded, own, classPath, m.api(), d.addedFiles());
        return new Drift(d.changedFiles(), d.addedFiles(), uses);
    }

    /**
     * The grader's side, after the graded files failed to compile against its framework on
     * {@code classPath}: the uses of what only the submission's own framework files ({@code own},
     * ignored for grading) have, in the same sentences as {@link #check}.
     */
    public static List<String> atGrader(Map<String, String> graded, Map<String, String> own, List<Path> classPath)
            throws IOException {
        if (own.isEmpty()) {
            return List.of();
        }
        List<String> classes = own.keySet().stream().map(GradedBuild::classNameOf).toList();
        Set<String> original = api(classes, classPath);
        List<String> added = own.keySet().stream().filter(f -> !original.contains(classNameOf(f))).toList();
        return uses(graded, own, classPath, original, added);
    }

    /**
     * The graded files' uses of members that only the student's framework files {@code own} have:
     * the graded and own files are compiled together against {@code classPath}, and each symbol
     * the graded files use that is declared in one of {@code own}'s classes and not in
     * {@code original} (signatures as {@link #signature} gives them) is one sentence. Empty if they
     * do not compile together (javac's errors say more then).
     */
    public static List<String> uses(Map<String, String> graded, Map<String, String> own, List<Path> classPath,
            Set<String> original, List<String> addedFiles) throws IOException {
        return usesIn(graded, own, classPath, original, (user, what, owner, file) -> sentence(user, what, owner, file,
                addedFiles.contains(file)));
    }

    /** The sentence for {@code user} (Sphere) using {@code what} (Vec3.lengthCubed) of {@code owner} in the student's {@code file}. */
    private interface Sentence {
        String of(String user, String what, String owner, String file);
    }

    private static List<String> usesIn(Map<String, String> graded, Map<String, String> own, List<Path> classPath,
            Set<String> original, Sentence sentence) throws IOException {
        Map<String, String> ownByClass = new LinkedHashMap<>();
        own.keySet().forEach(f -> ownByClass.put(classNameOf(f), f));
        JavaCompiler javac = JavaBuild.compiler();
        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        Set<String> out = new LinkedHashSet<>();
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, Locale.ROOT,
                StandardCharsets.UTF_8)) {
            List<JavaFileObject> units = new ArrayList<>();
            graded.forEach((k, v) -> units.add(source(k, v)));
            own.forEach((k, v) -> units.add(source(k, v)));
            JavacTask task = (JavacTask) javac.getTask(new StringWriter(), files, diagnostics, options(classPath), null,
                    units);
            Iterable<? extends CompilationUnitTree> trees = task.parse();
            task.analyze();
            if (diagnostics.getDiagnostics().stream().anyMatch(d -> d.getKind() == Diagnostic.Kind.ERROR)) {
                return List.of();
            }
            Trees t = Trees.instance(task);
            Elements elements = task.getElements();
            Types types = task.getTypes();
            // Every top-level class of the student's own files, a second one of a file included.
            for (CompilationUnitTree unit : trees) {
                String unitPath = unit.getSourceFile().getName();
                own.keySet().stream().filter(unitPath::endsWith).findFirst().ifPresent(f -> {
                    for (Tree decl : unit.getTypeDecls()) {
                        Element e = t.getElement(new TreePath(new TreePath(unit), decl));
                        if (e instanceof TypeElement te) {
                            ownByClass.putIfAbsent(te.getQualifiedName().toString(), f);
                        }
                    }
                });
            }
            for (CompilationUnitTree unit : trees) {
                String unitPath = unit.getSourceFile().getName();
                if (graded.keySet().stream().noneMatch(g -> unitPath.endsWith(g))) {
                    continue;
                }
                String user = unitPath.substring(unitPath.lastIndexOf('/') + 1).replace(".java", "");
                new TreePathScanner<Void, Void>() {
                    @Override
                    public Void scan(Tree tree, Void v) {
                        if (tree != null && USES.contains(tree.getKind())) {
                            used(new TreePath(getCurrentPath(), tree));
                        }
                        return super.scan(tree, v);
                    }

                    private void used(TreePath at) {
                        Element e = t.getElement(at);
                        if (e == null || e.getKind() == ElementKind.PACKAGE || e.getKind() == ElementKind.LOCAL_VARIABLE
                                || e.getKind() == ElementKind.PARAMETER) {
                            return;
                        }
                        TypeElement top = topLevel(e);
                        String file = top == null ? null : ownByClass.get(top.getQualifiedName().toString());
                        if (file != null && !original.contains(signature(e, elements, types))) {
                            out.add(sentence.of(user, what(e), top.getSimpleName().toString(), file));
                        }
                    }
                }.scan(new TreePath(unit), null);
            }
        }
        return List.copyOf(out);
    }

    /**
     * The one sentence for a graded file ({@code user}, e.g. Sphere) using {@code what} (e.g.
     * Vec3.lengthCubed) that only the student's {@code file} of class {@code owner} has: the same in
     * {@code check}, {@code submit-check} and the grader's report.
     */
    public static String sentence(String user, String what, String owner, String file, boolean addedFile) {
        String fileName = file.substring(file.lastIndexOf('/') + 1);
        return addedFile
                ? user + " uses " + what + ", which is in " + fileName + ", a file you added; the grader does not have it:"
                        + " this will not compile there"
                : user + " uses " + what + ", which you added to " + fileName + "; the grader uses the original " + owner
                        + ": this will not compile there";
    }

    /** What a use names: "Vec3.lengthCubed", "new Roots(double, double)", "Roots". */
    private static String what(Element e) {
        if (e instanceof TypeElement te) {
            return te.getSimpleName().toString();
        } else if (e instanceof ExecutableElement x && e.getKind() == ElementKind.CONSTRUCTOR) {
            return "new " + e.getEnclosingElement().getSimpleName() + "(" + x.getParameters().stream()
                    .map(p -> p.asType().toString().replaceAll("[a-z0-9_]+\\.", "")).collect(Collectors.joining(", "))
                    + ")";
        }
        return e.getEnclosingElement().getSimpleName() + "." + e.getSimpleName();
    }

    // ---------------------------------------------------------------- the graded files of other milestones

    /**
     * The one sentence for a graded file ({@code user}, e.g. Box) using {@code what} (e.g.
     * Sphere.later) that the student added to the graded file {@code file} of another milestone:
     * the same in {@code check}, {@code submit-check} and the grader's report.
     */
    public static String acrossSentence(String user, String what, String owner, String file) {
        String fileName = file.substring(file.lastIndexOf('/') + 1);
        return user + " uses " + what + ", which you added to " + fileName + "; the grader compiles " + user
                + ".java with its own " + fileName + ", not yours (each milestone is graded on its own): this will not"
                + " compile there; put what " + user + " needs in " + user + ".java";
    }

    /**
     * Each milestone's graded files' uses of what the student added to a graded file of another
     * milestone (a helper in Sphere.java that Box.java calls): the grader compiles a milestone's
     * files with its own copies of the other milestones' classes, never the student's, so such a
     * use compiles in the student's project and not at the grader. {@code graded}: the files to
     * check, by path; {@code all}: every graded file of the project or the submission, by path;
     * {@code milestoneOf}: each graded file's milestone. Only another file whose class a file names
     * is compiled with it; none when they do not compile together (javac's errors say more then),
     * or when the project has no manifest.
     */
    public static List<String> acrossMilestones(Path root, Map<String, String> graded, Map<String, String> all,
            Map<String, String> milestoneOf, List<Path> classPath) throws IOException {
        Manifest m = manifest(root);
        return m == null ? List.of() : acrossMilestones(graded, all, milestoneOf, classPath, m.api());
    }

    /**
     * The grader's side of {@link #acrossMilestones}, after one milestone's files ({@code graded})
     * did not compile against {@code classPath}, which holds the grader's own classes of the other
     * milestones: the uses of what the submission's other graded files ({@code all}) have and those
     * classes have not.
     */
    public static List<String> acrossAtGrader(Map<String, String> graded, Map<String, String> all,
            Map<String, String> milestoneOf, List<Path> classPath) throws IOException {
        List<String> classes = all.keySet().stream().filter(f -> !graded.containsKey(f)).map(GradedBuild::classNameOf)
                .toList();
        return acrossMilestones(graded, all, milestoneOf, classPath, api(classes, classPath));
    }

    private static List<String> acrossMilestones(Map<String, String> graded, Map<String, String> all,
            Map<String, String> milestoneOf, List<Path> classPath, Set<String> original) throws IOException {
        Map<String, Map<String, String>> byMilestone = new LinkedHashMap<>();
        graded.forEach((f, text) -> byMilestone.computeIfAbsent(milestoneOf.getOrDefault(f, f), k -> new LinkedHashMap<>())
                .put(f, text));
        List<String> out = new ArrayList<>();
        for (var e : byMilestone.entrySet()) {
            Map<String, String> named = new LinkedHashMap<>();
            all.forEach((f, text) -> {
                boolean other = !e.getKey().equals(milestoneOf.getOrDefault(f, f));
                if (other && text != null && typesDeclared(text).stream().anyMatch(type -> e.getValue().values().stream()
                        .anyMatch(t -> t != null && java.util.regex.Pattern.compile("\\b" + java.util.regex.Pattern.quote(type)
                                + "\\b").matcher(t).find()))) {
                    named.put(f, text);
                }
            });
            if (!named.isEmpty()) {
                out.addAll(usesIn(e.getValue(), named, classPath, original, GradedBuild::acrossSentence));
            }
        }
        return out;
    }

    private static TypeElement topLevel(Element e) {
        Element c = e;
        while (c != null && !(c.getEnclosingElement() instanceof PackageElement)) {
            c = c.getEnclosingElement();
        }
        return c instanceof TypeElement t ? t : null;
    }

    /**
     * The names of the types a source declares, nested ones and a few capitalised words of its
     * comments too ("class Sphere", "record Roots"; a type named in lower case is missed): only to
     * choose which other files to compile with a file that names one, so more is harmless.
     */
    static Set<String> typesDeclared(String text) {
        Set<String> out = new LinkedHashSet<>();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\b(?:class|interface|enum|record)\\s+([A-Z][\\w$]*)")
                .matcher(text);
        while (m.find()) {
            out.add(m.group(1));
        }
        return out;
    }

    /** The class a source declares, from its path: .../raylab/math/Vec3.java is raylab.math.Vec3. */
    static String classNameOf(String path) {
        String p = path.replace('\\', '/');
        int k = p.indexOf(SOURCES);
        p = k >= 0 ? p.substring(k + SOURCES.length()) : p;
        return p.replaceFirst("\\.java$", "").replace('/', '.');
    }


    private static List<String> options(List<Path> classPath) {
        return List.of("--release", "17", "-encoding", "UTF-8", "-nowarn", "-proc:none", "-classpath",
                JavaBuild.pathOf(classPath));
    }

    private static JavaFileObject source(String name, String text) {
        return new SimpleJavaFileObject(java.net.URI.create("string:///" + name.replace('\\', '/')),
                JavaFileObject.Kind.SOURCE) {
            @Override
            public CharSequence getCharContent(boolean ignoreEncodingErrors) {
                return text;
            }
        };
    }
}
