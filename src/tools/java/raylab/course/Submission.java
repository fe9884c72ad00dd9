package raylab.course;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;


/**
 * (Shared intake: the grader reads a submission with it and {@code raylab submit-check} shows the
 * student beforehand what the grader will take; it ships in the starter, raylab.grade does not.)
 *
 * The files of a student's submission that the grader will use: only the files the assignments
 * let students edit, found by their path in the release's layout or, for a flat upload, by file
 * name; with the right package declaration. Everything else is listed as ignored with the reason.
 * A graded file found twice is taken from the copy at the release's path
 * ({@code src/main/java/raylab/...}, possibly under one folder); with no single such copy, neither
 * is graded and {@link #conflicts()} says why: a stale backup never wins by its place in a zip.
 */
public final class Submission {
    /** Largest student file read, in bytes. */
    public static final long MAX_FILE = 1 << 20;
    /** Largest number of entries looked at in a directory or zip. */
    public static final int MAX_ENTRIES = 20_000;
    /** Largest total of uncompressed bytes read from a zip. */
    public static final long MAX_ZIP_BYTES = 64L << 20;

    private final Map<String, String> files;
    private final Map<String, String> sources;
    private final List<String> ignored;
    private final Map<String, String> conflicts;
    private final Map<String, List<String>> duplicates = new LinkedHashMap<>();
    private final Map<String, String> framework = new LinkedHashMap<>();

    private Submission(Map<String, String> files, Map<String, String> sources, List<String> ignored,
            Map<String, String> conflicts) {
        this.files = files;
        this.conflicts = conflicts.entrySet().stream().collect(java.util.stream.Collectors.toMap(Map.Entry::getKey,
                x -> raylab.scene.Display.escape(x.getValue()), (x, y) -> x, LinkedHashMap::new));
        // Paths in a zip may hold line breaks and other control characters: shown escaped.
        Map<String, String> shown = new LinkedHashMap<>();
        sources.forEach((k, v) -> shown.put(k, raylab.scene.Display.escape(v)));
        this.sources = shown;
        this.ignored = ignored.stream().map(raylab.scene.Display::escape).toList();
    }

    /** Accepted files: assignment path (e.g. src/main/java/raylab/surface/Sphere.java) to text. */
    public Map<String, String> files() {
        return files;
    }

    /** Where each accepted file came from in the submission. */
    public Map<String, String> sources() {
        return sources;
    }

    /** Files not used, each "path: reason". */
    public List<String> ignored() {
        return ignored;
    }

    /**
     * Graded files found more than once with no single copy at the release's path: assignment path
     * to the reason neither copy is graded (such a file is not in {@link #files()}).
     */
    public Map<String, String> conflicts() {
        return conflicts;
    }

    /** Graded files found more than once (taken or not): assignment path to every copy's path, escaped. */
    public Map<String, List<String>> duplicates() {
        return duplicates;
    }

    /**
     * Framework sources of the student's own in the submission (never graded): the path they
     * would have in the project (src/main/java/raylab/math/Vec3.java) to their text.
     */
    public Map<String, String> framework() {
        return framework;
    }

    /** An empty submission with one explanation (for an unreadable input). */
    public static Submission unreadable(String why) {
        return new Submission(Map.of(), Map.of(), List.of(why), Map.of());
    }

    private record Entry(String path, byte[] bytes, long size) {
    }

    /** Reads a directory or a zip file. */
    public static Submission read(Path input, List<Assignment> assignments) throws IOException {
        List<Entry> entries = new ArrayList<>();
        List<String> ignored = new ArrayList<>();
        if (Files.isDirectory(input)) {
            try (Stream<Path> walk = Files.walk(input)) {
                for (Path p : (Iterable<Path>) walk.limit(MAX_ENTRIES)::iterator) {
                    String rel = input.relativize(p).toString().replace('\\', '/');
                    if (Files.isSymbolicLink(p)) {
                        ignored.add(rel + ": a symbolic link (not followed)");
                    } else if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                        long size = Files.size(p);
                        boolean wanted = rel.endsWith(".java") && size <= MAX_FILE;
                        entries.add(new Entry(rel, wanted ? Files.readAllBytes(p) : null, size));
                    }
                }
            }
        } else if (Files.isRegularFile(input)) {
            try (ZipFile zip = new ZipFile(input.toFile())) {
                long total = 0;
                int n = 0;
                for (ZipEntry e : java.util.Collections.list(zip.entries())) {
                    if (++n > MAX_ENTRIES) {
                        ignored.add("(more than " + MAX_ENTRIES + " entries in the zip: the rest were not read)");
                        break;
                    }
                    if (e.isDirectory()) {
                        continue;
                    }
                    String rel = e.getName().replace('\\', '/');
                    while (rel.startsWith("/")) {
                        rel = rel.substring(1);
                    }
                    if (rel.startsWith("__MACOSX/") || rel.contains("/._") || rel.startsWith("._")) {
                        continue;
                    }
                    byte[] bytes = null;
                    if (rel.endsWith(".java")) {
                        try (InputStream in = zip.getInputStream(e)) {
                            bytes = in.readNBytes((int) MAX_FILE + 1);
                        }
                        total += bytes.length;
                        if (bytes.length > MAX_FILE || total > MAX_ZIP_BYTES) {
                            ignored.add(rel + ": larger than " + MAX_FILE + " bytes");
                            continue;
                        }
                    }
                    entries.add(new Entry(rel, bytes, bytes == null ? Math.max(0, e.getSize()) : bytes.length));
                }
            } catch (java.util.zip.ZipException e) {
                throw new IOException(input + ": not a readable zip file (" + e.getMessage() + ")");
            }
        } else {
            throw new IOException(input + ": no such file or directory");
        }
        return select(entries, assignments, ignored);
    }

    private static Submission select(List<Entry> entries, List<Assignment> assignments, List<String> ignored) {
        Map<String, String> files = new LinkedHashMap<>();
        Map<String, String> sources = new LinkedHashMap<>();
        Map<String, List<Copy>> copies = new LinkedHashMap<>();
        Map<String, String> framework = new LinkedHashMap<>();
        List<String> editable = new ArrayList<>();
        for (Assignment a : assignments) {
            for (Assignment.StudentFile f : a.files()) {
                editable.add(f.path());
            }
        }
        for (Entry e : entries) {
            String target = null;
            int r = 0;
            String name = e.path.substring(e.path.lastIndexOf('/') + 1);
            int depth = e.path.split("/").length - 1;
            for (String p : editable) {
                String pkgPath = p.startsWith("src/main/java/") ? p.substring("src/main/java/".length()) : p;
                String fileName = p.substring(p.lastIndexOf('/') + 1);
                if (e.path.equals(p) || e.path.endsWith("/" + p)) {
                    target = p;
                    r = 3;
                } else if (e.path.equals(pkgPath) || (e.path.endsWith("/" + pkgPath) && !e.path.contains("src/test/"))) {
                    target = p;
                    r = 2;
                } else if (name.equals(fileName) && depth <= 1) {
                    target = p;
                    r = 1;
                }
                if (target != null) {
                    break;
                }
            }
            if (target == null && e.bytes != null && e.path.endsWith(".java")) {
                // A framework file of the student's own: never graded; the grader explains a use of what only it has.
                String text = new String(e.bytes, StandardCharsets.UTF_8);
                String pkg = PackageScanner.packageOf(text);
                if (pkg.startsWith("raylab.") && !e.path.contains("src/test/")) {
                    String at = "src/main/java/" + pkg.replace('.', '/') + "/" + name;
                    if (!editable.contains(at)) {
                        framework.putIfAbsent(at, text);
                    }
                }
            }
            if (target == null) {
                ignored.add(e.path + ": " + (e.path.endsWith(".java")
                        ? "not a file of the assignments (only " + String.join(", ", editable.stream()
                                .map(x -> x.substring(x.lastIndexOf('/') + 1)).toList()) + " are graded)"
                        : "not a Java source file"));
                continue;
            }
            if (e.bytes == null) {
                ignored.add(e.path + ": larger than " + MAX_FILE + " bytes");
                continue;
            }
            String text = new String(e.bytes, StandardCharsets.UTF_8);
            String expectedPkg = target.substring("src/main/java/".length(), target.lastIndexOf('/')).replace('/', '.');
            String pkg = PackageScanner.packageOf(text);
            if (!pkg.equals(expectedPkg)) {
                ignored.add(e.path + ": declares package '" + pkg + "' but " + target + " must be in package '"
                        + expectedPkg + "'");
                continue;
            }
            copies.computeIfAbsent(target, k -> new ArrayList<>()).add(new Copy(e.path, text, r == 3));
        }
        Map<String, String> conflicts = new LinkedHashMap<>();
        copies.forEach((target, found) -> {
            String name = target.substring(target.lastIndexOf('/') + 1);
            List<Copy> atRelease = found.stream().filter(Copy::atRelease).toList();
            Copy taken = found.size() == 1 ? found.get(0) : atRelease.size() == 1 ? atRelease.get(0) : null;
            if (taken == null) {
                String why = found.size() + " copies of " + name + " (" + String.join(", ", found.stream()
                        .map(Copy::path).toList()) + ") and " + (atRelease.isEmpty() ? "none" : "more than one")
                        + " at " + target + ": neither is graded (keep one copy, at " + target + ")";
                conflicts.put(target, why);
                ignored.add(why);
                return;
            }
            for (Copy c : found) {
                if (c != taken) {
                    ignored.add(c.path + ": another copy of " + name + ", not graded (the copy at "
                            + taken.path + " is, being at " + target + ")");
                }
            }
            files.put(target, taken.text);
            sources.put(target, taken.path);
        });
                Submission s = new Submission(files, sources, ignored, conflicts);
        s.framework.putAll(framework);
        copies.forEach((target, found) -> {
            if (found.size() > 1) {
                s.duplicates.put(target, found.stream().map(c -> raylab.scene.Display.escape(c.path)).toList());
            }
        });
        return s;
    }

    /** One copy of a graded file in the submission; atRelease when at the release's path. */
    private record Copy(String path, String text, boolean atRelease) {
    }
}
