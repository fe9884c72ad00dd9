package raylab.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradedBuild;
import raylab.course.JavaBuild;
import raylab.course.MilestoneCheck;
import raylab.course.Submission;
import raylab.scene.Display;

/**
 * {@code raylab submit-check [ZIP|FOLDER]}: lists exactly the files the grader will take, read
 * the way the grader reads a submission ({@link Submission}), and warns about everything else.
 */
@Command(name = "submit-check", mixinStandardHelpOptions = true,
        description = {"List exactly the files that will be graded, before you submit.",
            "Without an argument: your files in this project, milestone by milestone. With a zip or a folder",
            "(what you are about to upload): the files the grader takes from it, and a warning for everything else."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:at least one file will be graded", "1:no file would be graded, or a graded file is there twice",
            "2:no such file or tag, not a readable zip, or not run from the project folder"})
public final class SubmitCheckCommand implements Callable<Integer> {
    /** At most this many files that are not graded are listed. */
    static final int LISTED = 15;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "ZIP|FOLDER|TAG",
            description = "The zip file or folder you will upload, or the git tag you pushed (Classroom 50)"
                    + " (default: this project's files).")
    Path input;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        Path root = Path.of("").toAbsolutePath();
        List<Assignment> assignments;
        try {
            assignments = Assignments.load(root).all();
        } catch (IOException e) {
            throw UserError.badInput(e.getMessage());
        }
        if (input == null) {
            return project(out, root, assignments);
        }
        if (!Files.exists(input) && git(root, "rev-parse", "-q", "--verify", "refs/tags/" + input + "^{commit}") != null) {
            // A tag (Classroom 50 grades its commit): its graded files, checked as a folder.
            Path tagged = Files.createTempDirectory("raylab-tag");
            try {
                for (String f : studentFiles(assignments)) {
                    String text = git(root, "show", input + ":" + f);
                    if (text != null) {
                        Files.createDirectories(tagged.resolve(f).getParent());
                        Files.writeString(tagged.resolve(f), text, StandardCharsets.UTF_8);
                    }
                }
                out.println("The commit of the tag '" + input + "':");
                return check(out, root, assignments, tagged, input.toString());
            } finally {
                try (var walk = Files.walk(tagged)) {
                    for (Path p : walk.sorted(java.util.Comparator.reverseOrder()).toList()) {
                        Files.deleteIfExists(p);
                    }
                }
            }
        }
        if (!Files.exists(input)) {
            throw UserError.badInput(Display.path(input) + ": no such file, folder or tag");
        }
        return check(out, root, assignments, input, Display.path(input));
    }

    /** A zip, a folder or a tag's files, read as the grader reads them; {@code shown} names it. */
    private int check(PrintWriter out, Path root, List<Assignment> assignments, Path input, String shown)
            throws IOException {
        Submission s;
        try {
            s = Submission.read(input, assignments);
        } catch (IOException e) {
            throw UserError.badInput(Errors.oneLine(e.getMessage()));
        }
        out.println("The grader takes " + s.files().size() + " file" + (s.files().size() == 1 ? "" : "s") + " from "
                + shown + ":");
        for (Assignment a : assignments) {
            for (Assignment.StudentFile f : a.files()) {
                String text = s.files().get(f.path());
                out.printf("  %-8s %-46s %s%n", a.id(), f.path(), s.conflicts().containsKey(f.path())
                        ? "NOT GRADED: " + s.duplicates().get(f.path()).size() + " copies, none at this path (see below)"
                        : text == null ? "not in the submission"
                        : "from " + s.sources().get(f.path()) + stubNote(text));
            }
        }
        if (!s.ignored().isEmpty()) {
            out.println();
            out.println("WARNING: " + s.ignored().size() + " other file" + (s.ignored().size() == 1 ? " is" : "s are")
                    + " in the submission and will not be graded (upload only the files above):");
            s.ignored().stream().limit(LISTED).forEach(l -> out.println("  " + l));
            if (s.ignored().size() > LISTED) {
                out.println("  ... and " + (s.ignored().size() - LISTED) + " more");
            }
        }
        boolean breaks = !compiles(out, s.files(), studentFiles(assignments));
        breaks |= printDrift(out, drift(root, s.files(), s.files(), assignments, JavaBuild.ownClassPath()));
        if (!s.duplicates().isEmpty()) {
            out.println();
            s.duplicates().forEach((target, paths) -> out.println("REFUSED: " + paths.size() + " copies of "
                    + target.substring(target.lastIndexOf('/') + 1) + " in the submission: " + String.join(" and ", paths)
                    + (s.conflicts().containsKey(target) ? "; the grader would grade neither"
                            : "; the grader would take only " + s.sources().get(target))
                    + ". Remove all but one (at " + target + ")."));
            return Main.FAILED;
        }
        return s.files().isEmpty() || breaks ? Main.FAILED : Main.OK;
    }

    /** The project's own student files, milestone by milestone. */
    private static int project(PrintWriter out, Path root, List<Assignment> assignments) throws IOException {
        return project(out, root, assignments, List.of());
    }

    /**
     * The project's student files, each "finished" only when its milestone's visible tests and
     * data cases pass (naming those that fail); {@code first} goes before raylab's own classes
     * (a test puts a student's compiled file there).
     */
    static int project(PrintWriter out, Path root, List<Assignment> assignments, List<Path> first) throws IOException {
        out.println("Running the visible tests of every milestone ...");
        out.flush();
        Map<String, MilestoneCheck.Outcome> outcomes = new LinkedHashMap<>();
        for (MilestoneCheck.Outcome o : MilestoneCheck.run(root, assignments, 1, line -> { }, first, false)) {
            outcomes.put(o.assignment().id(), o);
        }
        out.println("The files graded, milestone by milestone (upload these; see \"Submitting\" in README.md):");
        int present = 0;
        List<String> details = new ArrayList<>();
        Map<String, String> graded = projectFiles(root, assignments);
        GradedBuild.Drift drift = drift(root, graded, graded, assignments, withFirst(first));
        Map<String, List<String>> wontCompile = wontCompile(root, assignments, assignments, drift, withFirst(first));
        for (Assignment a : assignments) {
            for (Assignment.StudentFile f : a.files()) {
                Path p = root.resolve(f.path());
                String state;
                if (Files.isRegularFile(p)) {
                    present++;
                    String stub = stubNote(Files.readString(p, StandardCharsets.UTF_8)).strip();
                    state = !stub.isEmpty() ? stub.substring(1, stub.length() - 1)
                            : wontCompile.containsKey(a.id()) ? "WILL NOT COMPILE AT THE GRADER (below): 0 points there"
                            : finished(outcomes.get(a.id()), details);
                } else {
                    state = "MISSING";
                }
                out.printf("  %-8s %-46s %s%n", a.id(), f.path(), state);
            }
        }
        details.stream().distinct().forEach(out::println);
        out.println("Nothing else is graded: the grader uses its own copy of every other file.");
        boolean breaks = printDrift(out, drift);
        tagWarnings(root, assignments).forEach(out::println);
        out.println("To check a zip before uploading it: ./raylab submit-check FILE.zip");
        return present == 0 || breaks ? Main.FAILED : Main.OK;
    }

    /** "finished (its N visible tests pass)", or what is not; the failing tests' names go to {@code details}. */
    static String finished(MilestoneCheck.Outcome o, List<String> details) {
        if (o == null) {
            return "not checked";
        }
        if (!o.problem().isEmpty()) {
            return "NOT FINISHED: " + MilestoneCheck.oneLine(o.problem(), 120);
        }
        List<String> failing = o.rows().stream().filter(r -> !r.passed()
                && r.item().kind() != raylab.course.GradingPlan.Kind.SCENE).map(r -> (r.item().kind()
                == raylab.course.GradingPlan.Kind.CASE ? "data case " : "") + "\"" + r.item().name() + "\"").toList();
        if (o.tests().isEmpty() || (o.plan() == null && o.testsPassed() < o.testCount())) {
            return "NOT FINISHED: its visible tests did not run (./raylab check " + o.assignment().id() + ")";
        }
        if (failing.isEmpty()) {
            return "finished: its " + o.testCount() + " visible tests pass";
        }
        details.add(o.assignment().id() + ": failing visible tests (./raylab check " + o.assignment().id()
                + " shows why):");
        failing.forEach(n -> details.add("  FAIL " + n));
        return "NOT FINISHED: " + failing.size() + " of " + o.testCount() + " visible tests fail (below)";
    }

    /**
     * Classroom 50 grades the commit a milestone's tag names, not the working tree: one warning
     * for each graded file whose text differs from that commit's (an edit not committed, or
     * committed after the tag was set) or that the commit does not hold (a file never added).
     * Nothing outside a git repository or for a milestone without a tag.
     */
    static List<String> tagWarnings(Path root, List<Assignment> assignments) {
        List<String> out = new ArrayList<>();
        if (!Files.exists(root.resolve(".git"))) {
            return out;
        }
        for (Assignment a : assignments) {
            String tag = a.id();
            if (git(root, "rev-parse", "-q", "--verify", "refs/tags/" + tag + "^{commit}") == null) {
                continue;
            }
            for (Assignment.StudentFile f : a.files()) {
                Path p = root.resolve(f.path());
                if (!Files.isRegularFile(p)) {
                    continue;
                }
                String tagged = git(root, "show", tag + ":" + f.path());
                String now;
                try {
                    now = Files.readString(p, StandardCharsets.UTF_8);
                } catch (IOException e) {
                    continue;
                }
                if (tagged == null) {
                    out.add("WARNING: " + f.path() + " is not in the commit of the tag '" + tag + "', which Classroom 50"
                            + " grades: git add it, commit, then move the tag (git tag -f " + tag
                            + " && git push -f origin " + tag + ")");
                } else if (!tagged.equals(now)) {
                    out.add("WARNING: " + f.path() + " differs from the commit of the tag '" + tag + "', which"
                            + " Classroom 50 grades: commit it, then move the tag (git tag -f " + tag
                            + " && git push -f origin " + tag + ")");
                }
            }
        }
        return out;
    }

    /** git's standard output, or null when it fails or is missing. */
    private static String git(Path root, String... args) {
        List<String> cmd = new ArrayList<>(List.of("git", "-C", root.toString()));
        cmd.addAll(List.of(args));
        try {
            Process p = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.DISCARD).start();
            p.getOutputStream().close();
            byte[] bytes = p.getInputStream().readAllBytes();
            return p.waitFor() == 0 ? new String(bytes, StandardCharsets.UTF_8) : null;
        } catch (IOException e) {
            return null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
    }

    /**
     * Compiles a submission's graded files as the grader does, against the framework (this
     * project's build) and prints javac's errors; false if they do not compile.
     */
    static boolean compiles(PrintWriter out, Map<String, String> files, Set<String> studentFiles) throws IOException {
        if (files.isEmpty()) {
            return true;
        }
        Path work = Files.createTempDirectory("raylab-submit-check");
        try {
            List<Path> sources = new ArrayList<>();
            for (var e : files.entrySet()) {
                Path p = work.resolve("src").resolve(e.getKey());
                Files.createDirectories(p.getParent());
                Files.writeString(p, e.getValue(), StandardCharsets.UTF_8);
                sources.add(p);
            }
            JavaBuild.Result r = JavaBuild.compile(sources, JavaBuild.ownClassPath(), work.resolve("classes"));
            if (r.success()) {
                return true;
            }
            out.println();
            out.println("DOES NOT COMPILE (as the grader builds it, so the milestone would score 0):");
            for (JavaBuild.Problem p : r.errors().stream().limit(10).toList()) {
                String file = p.file() == null ? "" : work.resolve("src").relativize(p.file()).toString().replace('\\', '/');
                out.println("  " + (file.isEmpty() ? "" : file + ":" + p.line() + ": ") + p.message());
            }
            return false;
        } finally {
            try (var walk = Files.walk(work)) {
                for (Path p : walk.sorted(java.util.Comparator.reverseOrder()).toList()) {
                    Files.deleteIfExists(p);
                }
            }
        }
    }

    /**
     * Prints what the grader builds differently (framework files changed or added, and the graded
     * files' uses of what only they have); true if a graded file would not compile at the grader.
     */
    static boolean printDrift(PrintWriter out, GradedBuild.Drift d) {
        if (d == null || d.none()) {
            return false;
        }
        out.println();
        for (String u : d.uses()) {
            out.println("WILL NOT COMPILE AT THE GRADER: " + u + ".");
        }
        for (String l : d.lines().subList(d.uses().size(), d.lines().size())) {
            out.println("NOTE: " + l + ".");
        }
        return !d.uses().isEmpty();
    }

    /**
     * Everything the grader builds differently for {@code graded} (by path: the project's files or
     * a submission's): the framework files changed or added and the uses of what only they have
     * ({@link GradedBuild#check}), and the uses of what the student added to a graded file of another
     * milestone, among {@code all} ({@link GradedBuild#acrossMilestones}). Null without a manifest.
     */
    static GradedBuild.Drift drift(Path root, Map<String, String> graded, Map<String, String> all,
            List<Assignment> assignments, List<Path> classPath) throws IOException {
        GradedBuild.Drift d = GradedBuild.check(root, graded, studentFiles(assignments), classPath);
        return d == null ? null : d.with(GradedBuild.acrossMilestones(root, graded, all, milestoneOf(assignments),
                classPath));
    }

    /**
     * The milestones of {@code selected} whose files will not compile at the grader, each with the
     * sentences that say why ({@link #drift} of its files alone, among {@code all}); empty when
     * {@code drift}, that of them all, has no such use (then nothing more is compiled).
     */
    static Map<String, List<String>> wontCompile(Path root, List<Assignment> selected, List<Assignment> all,
            GradedBuild.Drift drift, List<Path> classPath) throws IOException {
        Map<String, List<String>> out = new LinkedHashMap<>();
        if (drift == null || drift.uses().isEmpty()) {
            return out;
        }
        if (selected.size() == 1) {
            out.put(selected.get(0).id(), drift.uses());
            return out;
        }
        Map<String, String> allFiles = projectFiles(root, all);
        for (Assignment a : selected) {
            GradedBuild.Drift d = drift(root, projectFiles(root, List.of(a)), allFiles, all, classPath);
            if (d != null && !d.uses().isEmpty()) {
                out.put(a.id(), d.uses());
            }
        }
        return out;
    }

    /** Each graded file's milestone, by path. */
    static Map<String, String> milestoneOf(List<Assignment> assignments) {
        Map<String, String> out = new LinkedHashMap<>();
        assignments.forEach(a -> a.files().forEach(f -> out.put(f.path(), a.id())));
        return out;
    }

    /** The graded files of the project at {@code root}, by path, as they are now. */
    static Map<String, String> projectFiles(Path root, List<Assignment> assignments) throws IOException {
        Map<String, String> out = new LinkedHashMap<>();
        for (String f : studentFiles(assignments)) {
            if (Files.isRegularFile(root.resolve(f))) {
                out.put(f, Files.readString(root.resolve(f), StandardCharsets.UTF_8));
            }
        }
        return out;
    }

    static Set<String> studentFiles(List<Assignment> assignments) {
        Set<String> out = new java.util.LinkedHashSet<>();
        assignments.forEach(a -> a.files().forEach(f -> out.add(f.path())));
        return out;
    }

    private static List<Path> withFirst(List<Path> first) {
        List<Path> cp = new ArrayList<>(first);
        cp.addAll(JavaBuild.ownClassPath());
        return cp;
    }

    /** " (still the starter's stub: throws NotImplemented)" when the file still throws it. */
    static String stubNote(String text) {
        boolean stub = text.lines().map(String::strip).anyMatch(l -> l.startsWith("throw new NotImplemented(")
                || l.startsWith("throw new raylab.course.NotImplemented("));
        return stub ? " (still throws NotImplemented somewhere: not finished)" : "";
    }
}
