package raylab.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import raylab.course.Assignment;
import raylab.course.JavaBuild;
import raylab.course.MilestoneBuild;
import raylab.course.Submission;

/**
 * A milestone's first step: the student's file(s) of M compiled over the framework and the
 * reference solutions of the other milestones (those not being graded copied from the grader's
 * own code), and the class files it produced that would shadow a class below it removed.
 */
final class StudentCompile {
    private StudentCompile() {
    }

    /**
     * The student's file(s) of M compiled over the framework and the other milestones' references.
     *
     * @param overlay the student's classes
     * @param below   what they were compiled over: the other references, the framework, the libraries
     * @param errors  why it did not compile, as the student reads it (null: it compiled)
     */
    record Compiled(Path overlay, List<Path> below, String errors) {
    }

    static Compiled compile(GradingRun run, Assignment a, Submission sub, Path mdir) throws IOException {
        GraderSetup setup = run.setup();
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
        copyOtherReferences(run, a, otherRefs);
        below.add(setup.framework);
        below.addAll(setup.libraries);
        Map<String, String> files = new LinkedHashMap<>();
        for (Assignment.StudentFile f : a.files()) {
            files.put(f.path().substring("src/main/java/".length()), sub.files().get(f.path()));
        }
        long c0 = System.nanoTime();
        JavaBuild.Result compiled = MilestoneBuild.compileOverlay(files, mdir.resolve("src"), below, overlay);
        Grader.phase(a.id() + " compile", c0);
        // Children reach their boxes through this folder, but nothing else in it.
        Sandbox.workFolder(mdir);
        for (Path p : List.of(mdir.resolve("src"), overlay, otherRefs)) {
            if (Files.isDirectory(p)) {
                Sandbox.privateFolder(p);
            }
        }
        if (compiled.success()) {
            return new Compiled(overlay, below, null);
        }
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
        // A use of what the student added to a graded file of another milestone: compiled here with the
        // course's own classes of that milestone.
        Map<String, String> milestoneOf = new LinkedHashMap<>();
        run.all().forEach(o -> o.files().forEach(f -> milestoneOf.put(f.path(), o.id())));
        for (String use : raylab.course.GradedBuild.acrossAtGrader(graded, sub.files(), milestoneOf, below)) {
            msg.append("\n  ").append(use);
        }
        return new Compiled(overlay, below, msg.toString());
    }

    /** The class files of the milestones not selected that milestone {@code a}'s code may need, from the framework's code source. */
    private static void copyOtherReferences(GradingRun run, Assignment a, Path out) throws IOException {
        GraderSetup setup = run.setup();
        Files.createDirectories(out);
        List<Assignment> all = run.all();
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
    static List<String> removeShadowing(Assignment a, Path overlay, List<Path> below) throws IOException {
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

}
