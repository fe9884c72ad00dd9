package raylab.course.release;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.stream.Stream;

import com.fasterxml.jackson.core.util.DefaultIndenter;
import com.fasterxml.jackson.core.util.DefaultPrettyPrinter;
import com.fasterxml.jackson.core.util.Separators;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;
import raylab.course.JavaBuild;
import raylab.course.SolutionRegions;
import raylab.grade.ServiceFiles;

/**
 * Cuts the student starter from the instructor's tree: the files {@code assignments/release.json}
 * selects, with every solution region replaced by its stub, the hidden test lists removed from
 * the assignment descriptions, and a README generated from {@code assignments/STARTER-README.md}.
 * The same tree gives the same bytes on every run (files are walked in sorted order and nothing
 * but the solution regions and the hidden lists is changed).
 */
public final class Release {
    /** What was written. */
    public record Written(Path out, int files, List<String> milestones, List<String> stubbedFiles) {
    }

    /** The starter in memory: relative path ('/'-separated) to content, sorted. */
    public record Tree(SortedMap<String, byte[]> files, Set<String> executable, List<String> stubbedFiles,
            List<String> milestones) {
    }

    private Release() {
    }

    /** Computes the starter's files without writing anything. */
    public static Tree build(Path root) throws IOException {
        ReleaseSpec spec = ReleaseSpec.load(root);
        Assignments assignments = Assignments.load(root);
        Set<String> visibleTests = new HashSet<>();
        for (Assignment a : assignments.all()) {
            for (String v : a.tests().visible()) {
                visibleTests.add(v);
                if (!Files.isRegularFile(root.resolve(v))) {
                    throw new IOException(a.folder() + "/assignment.json: visible test " + v + " does not exist");
                }
            }
        }
        SortedMap<String, byte[]> out = new TreeMap<>();
        // The tools as a jar with its sources (docs/architecture.md); the lab comes as source below.
        ToolsJar.Built tools = ToolsJar.build(root);
        out.putAll(tools.files());
        List<String> stubbed = new ArrayList<>();
        boolean anyVisibleCase = false;
        for (String rel : projectFiles(root)) {
            boolean wanted = ReleaseSpec.matchesAny(spec.include(), rel) || visibleTests.contains(rel);
            if (!wanted || ReleaseSpec.matchesAny(spec.exclude(), rel) || ReleaseSpec.matchesAny(spec.never(), rel)) {
                continue;
            }
            if (rel.equals("README.md")) {
                continue; // generated below
            }
            byte[] bytes = Files.readAllBytes(root.resolve(rel));
            Assignment owner = null;
            if (rel.matches("assignments/[^/]+/(assignment\\.json|README\\.md)")) {
                String folder = rel.substring(0, rel.lastIndexOf('/'));
                for (Assignment a : assignments.all()) {
                    if (a.folder().toString().replace('\\', '/').equals(folder)) {
                        owner = a;
                    }
                }
            }
            if (owner != null && rel.endsWith("/assignment.json")) {
                List<GradingPlan.CaseInfo> cases = GradingPlan.cases(root, owner);
                double hiddenCasePoints = cases.stream().filter(c -> !c.visibility().equals("visible"))
                        .mapToDouble(GradingPlan.CaseInfo::points).sum();
                List<String> visibleFiles = new ArrayList<>();
                for (String caseFile : owner.cases()) {
                    String path = owner.folder().toString().replace('\\', '/') + "/" + caseFile;
                    byte[] visible = visibleCases(root.resolve(path));
                    if (visible != null) {
                        visibleFiles.add(caseFile);
                        out.put(path, visible);
                        anyVisibleCase = true;
                    }
                }
                bytes = withoutHiddenTests(rel, bytes, hiddenCasePoints, visibleFiles);
            } else if (owner != null && rel.endsWith("/README.md")) {
                // The grading table and the total: from assignment.json, never by hand.
                String text = new String(bytes, StandardCharsets.UTF_8);
                bytes = HandoutTable.update(text, GradingPlan.of(root, owner)).getBytes(StandardCharsets.UTF_8);
            } else if (rel.equals("pom.xml")) {
                bytes = starterPom(new String(bytes, StandardCharsets.UTF_8), tools.version())
                        .getBytes(StandardCharsets.UTF_8);
            } else if (rel.equals(SCENE_SCHEMA)) {
                // Surface types registered on the class path (raylab.scene.SurfaceType) join the schema.
                bytes = raylab.scene.SurfaceTypes.schemaWithExtensions(new String(bytes, StandardCharsets.UTF_8))
                        .getBytes(StandardCharsets.UTF_8);
            } else if (rel.endsWith(".java")) {
                String text = new String(bytes, StandardCharsets.UTF_8);
                if (SolutionRegions.hasRegions(text) || assignments.ownerOf(rel).isPresent()) {
                    text = stub(rel, text, assignments);
                    bytes = text.getBytes(StandardCharsets.UTF_8);
                    stubbed.add(rel);
                }
            }
            out.put(rel, bytes);
        }
        for (Assignment a : assignments.all()) {
            for (Assignment.StudentFile f : a.files()) {
                if (!out.containsKey(f.path())) {
                    throw new IOException(a.folder() + "/assignment.json: student file " + f.path()
                            + " is not in the starter (missing, or left out by " + ReleaseSpec.FILE + ")");
                }
            }
        }
        // A services file lists only the providers the starter has: the instructor's (commands, the
        // packed mesh engine, the boundary hooks) would stop ServiceLoader, and so every command.
        for (String rel : List.copyOf(out.keySet())) {
            if (rel.startsWith(ServiceFiles.SOURCE_FOLDER)) {
                String kept = ServiceFiles.keep(new String(out.get(rel), StandardCharsets.UTF_8), c -> ships(out, c));
                if (kept == null) {
                    out.remove(rel);
                } else {
                    out.put(rel, kept.getBytes(StandardCharsets.UTF_8));
                }
            }
        }
        if (anyVisibleCase) {
            // Visible data cases run in ./raylab check, with the grader's case checker.
            out.put(CASE_CHECK_STARTER, Files.readAllBytes(root.resolve(CASE_CHECK)));
        }
        // The released framework's hashes and members: check and submit-check name what the grader will not have.
        Set<String> studentFiles = new HashSet<>();
        assignments.all().forEach(a -> a.files().forEach(f -> studentFiles.add(f.path())));
        out.put(raylab.course.GradedBuild.MANIFEST, raylab.course.GradedBuild.manifestText(out, studentFiles,
                raylab.course.JavaBuild.ownClassPath()).getBytes(StandardCharsets.UTF_8));
        // What raylab inspect and check compare a student's ray trees with: data, made by the reference.
        ReferenceTraces.add(root, out);
        out.put("README.md", StarterReadme.render(root, spec.readmeTemplate(), assignments)
                .getBytes(StandardCharsets.UTF_8));
        Set<String> exec = new HashSet<>();
        for (String e : spec.executable()) {
            if (out.containsKey(e)) {
                exec.add(e);
            }
        }
        return new Tree(out, Set.copyOf(exec), List.copyOf(stubbed), assignments.ids());
    }

    /** Whether the starter (its files by relative path) has the source of a class of src/main/java. */
    static boolean ships(Map<String, byte[]> starter, String className) {
        return starter.containsKey("src/main/java/" + ServiceFiles.sourceFile(className));
    }

    /**
     * The starter's pom.xml: the instructor's without its {@code course} and {@code mesh-engine}
     * profiles (the other modules' source roots) and its {@code mutation} profile (which names every hidden test class and the
     * grader's folder), each with the comment before it, and with the tools jar's version.
     */
    static String starterPom(String pom, String toolsVersion) {
        String out = withoutProfile(withoutProfile(withoutProfile(pom, "course"), "mesh-engine"), "mutation");
        return out.replaceFirst("<raylab\\.tools\\.version>[^<]*</raylab\\.tools\\.version>",
                "<raylab.tools.version>" + toolsVersion + "</raylab.tools.version>");
    }

    /** {@code pom} without the profile of that id and the comment right before it. */
    static String withoutProfile(String pom, String id) {
        int at = pom.indexOf("<id>" + id + "</id>");
        if (at < 0) {
            return pom;
        }
        int start = pom.lastIndexOf("<profile>", at);
        int end = pom.indexOf("</profile>", at);
        if (start < 0 || end < 0) {
            return pom;
        }
        end += "</profile>".length();
        int comment = pom.lastIndexOf("<!--", start);
        if (comment >= 0 && pom.indexOf("-->", comment) < start
                && pom.substring(pom.indexOf("-->", comment) + 3, start).isBlank()) {
            start = comment;
        }
        int lineStart = pom.lastIndexOf('\n', start) + 1;
        if (pom.substring(lineStart, start).isBlank()) {
            start = lineStart;
        }
        if (end < pom.length() && pom.charAt(end) == '\n') {
            end++;
        }
        return pom.substring(0, start) + pom.substring(end);
    }

    /** The scene format's JSON Schema. */
    static final String SCENE_SCHEMA = "scenes/scene.schema.json";

    /** The grader's data-case checker, and where the starter gets a copy when some case is visible. */
    static final String CASE_CHECK = "grader/tests/raylab/cases/CaseCheck.java";
    static final String CASE_CHECK_STARTER = "src/test/java/raylab/cases/CaseCheck.java";

    /** A case file with only its visible cases, in one fixed layout; null when none is visible. */
    static byte[] visibleCases(Path file) throws IOException {
        ObjectMapper json = new ObjectMapper();
        JsonNode n = json.readTree(file.toFile());
        com.fasterxml.jackson.databind.node.ArrayNode keep = json.createArrayNode();
        for (JsonNode c : n.isArray() ? n : List.of(n)) {
            if ("visible".equals(c.path("visibility").asText())) {
                keep.add(c);
            }
        }
        if (keep.isEmpty()) {
            return null;
        }
        return (json.writerWithDefaultPrettyPrinter().writeValueAsString(keep) + "\n").getBytes(StandardCharsets.UTF_8);
    }

    /** The student's version of a file with solution regions; checks that they belong to its milestone. */
    static String stub(String rel, String text, Assignments assignments) throws IOException {
        var owner = assignments.ownerOf(rel);
        List<SolutionRegions.Region> regions;
        try {
            regions = SolutionRegions.parse(rel, text);
        } catch (IllegalArgumentException e) {
            throw new IOException(e.getMessage());
        }
        if (owner.isEmpty()) {
            throw new IOException(rel + ":" + regions.get(0).beginLine() + ": solution region of milestone '"
                    + regions.get(0).milestone() + "' in a file that no assignment.json lists as a student file");
        }
        String id = owner.get().id();
        if (regions.isEmpty()) {
            throw new IOException(rel + ": listed as a student file of milestone '" + id
                    + "' but has no solution region (the student would get the solution)");
        }
        for (SolutionRegions.Region r : regions) {
            if (!r.milestone().equals(id)) {
                throw new IOException(rel + ":" + r.beginLine() + ": solution region of milestone '" + r.milestone()
                        + "' in a file of milestone '" + id + "' (each milestone's work lives in its own files)");
            }
        }
        if (regions.stream().noneMatch(r -> r.stubLine() > 0)) {
            throw new IOException(rel + ": no region of milestone '" + id + "' has a // STUB part, so nothing"
                    + " would tell the student what to write");
        }
        return SolutionRegions.toStudent(rel, text, Set.of());
    }

    /**
     * An assignment.json without what the grader keeps private, written in one fixed layout: the
     * tests.hidden list and the scenes' variant specs go, and the data-driven cases go with their points counted as hidden
     * points (the case files are grader data and are not shipped).
     */
    static byte[] withoutHiddenTests(String rel, byte[] bytes, double casePoints) throws IOException {
        return withoutHiddenTests(rel, bytes, casePoints, List.of());
    }

    /**
     * As above, keeping the case files that hold visible cases (written with only those cases)
     * and counting the hidden cases' points as hidden points.
     */
    static byte[] withoutHiddenTests(String rel, byte[] bytes, double casePoints, List<String> visibleCaseFiles)
            throws IOException {
        ObjectMapper json = new ObjectMapper();
        JsonNode node = json.readTree(bytes);
        if (!(node instanceof ObjectNode obj)) {
            throw new IOException(rel + ": not a JSON object");
        }
        if (obj.get("tests") instanceof ObjectNode tests) {
            tests.remove("hidden");
            tests.remove("hiddenWeights"); // names the hidden classes
            if (casePoints > 0) {
                double hidden = tests.path("hiddenPoints").asDouble(0) + casePoints;
                if (hidden != Math.rint(hidden)) {
                    throw new IOException(rel + ": the cases' points must add up to whole points, got " + casePoints);
                }
                tests.put("hiddenPoints", (long) hidden);
            }
        }
        obj.remove("cases");
        // How the grader varies the graded scenes is grader data too.
        for (JsonNode sc : obj.path("scenes")) {
            if (sc instanceof ObjectNode o) {
                o.remove("variant");
            }
        }
        if (!visibleCaseFiles.isEmpty()) {
            com.fasterxml.jackson.databind.node.ArrayNode c = obj.putArray("cases");
            visibleCaseFiles.forEach(c::add);
        }
        DefaultPrettyPrinter pretty = new DefaultPrettyPrinter()
                .withSeparators(Separators.createDefaultInstance()
                        .withObjectFieldValueSpacing(Separators.Spacing.AFTER))
                .withObjectIndenter(new DefaultIndenter("  ", "\n"))
                .withArrayIndenter(new DefaultIndenter("  ", "\n"));
        String text = json.writer(pretty).writeValueAsString(obj);
        return (text + "\n").getBytes(StandardCharsets.UTF_8);
    }

    /** Every regular file of the project, relative and '/'-separated, sorted; .git and build output skipped. */
    static List<String> projectFiles(Path root) throws IOException {
        List<String> out = new ArrayList<>();
        Files.walkFileTree(root, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) {
                String rel = rel(root, dir);
                if (rel.equals(".git") || rel.equals("target") || rel.equals("out")) {
                    return FileVisitResult.SKIP_SUBTREE;
                }
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) {
                if (attrs.isRegularFile()) {
                    out.add(rel(root, file));
                }
                return FileVisitResult.CONTINUE;
            }
        });
        out.sort(null);
        return out;
    }

    static String rel(Path root, Path p) {
        return root.relativize(p).toString().replace('\\', '/');
    }

    /**
     * Writes the starter to {@code out}: first into a temporary sibling folder, then moved into
     * place, so a failed run leaves no half-written starter. A non-empty {@code out} is refused
     * unless {@code force}.
     */
    public static Written write(Path root, Path out, boolean force) throws IOException {
        Path absRoot = root.toAbsolutePath().normalize();
        Path target = out.toAbsolutePath().normalize();
        if (absRoot.startsWith(target)) {
            throw new IOException(out + ": the starter cannot be written over the project itself");
        }
        if (Files.exists(target)) {
            if (!Files.isDirectory(target)) {
                throw new IOException(out + ": exists and is not a folder");
            }
            boolean empty;
            try (Stream<Path> s = Files.list(target)) {
                empty = s.findAny().isEmpty();
            }
            if (!empty && !force) {
                throw new IOException(out + ": not empty (use --force to replace it)");
            }
            if (Files.exists(target.resolve(ReleaseSpec.FILE))) {
                throw new IOException(out + ": looks like an instructor tree (it has " + ReleaseSpec.FILE
                        + "); refusing to replace it");
            }
        }
        Tree tree = build(absRoot);
        Path parent = target.getParent();
        Files.createDirectories(parent);
        Path partial = parent.resolve("." + target.getFileName() + ".partial-" + ProcessHandle.current().pid());
        JavaBuild.deleteTree(partial);
        try {
            for (Map.Entry<String, byte[]> e : tree.files().entrySet()) {
                Path f = partial.resolve(e.getKey());
                Files.createDirectories(f.getParent());
                Files.write(f, e.getValue());
                setMode(f, tree.executable().contains(e.getKey()));
            }
            JavaBuild.deleteTree(target);
            try {
                Files.move(partial, target, StandardCopyOption.ATOMIC_MOVE);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(partial, target);
            }
        } finally {
            JavaBuild.deleteTree(partial);
        }
        return new Written(target, tree.files().size(), tree.milestones(), tree.stubbedFiles());
    }

    private static void setMode(Path f, boolean executable) throws IOException {
        PosixFileAttributeView posix = Files.getFileAttributeView(f, PosixFileAttributeView.class);
        if (posix != null) {
            posix.setPermissions(PosixFilePermissions.fromString(executable ? "rwxr-xr-x" : "rw-r--r--"));
        } else {
            f.toFile().setExecutable(executable, false);
        }
    }
}
