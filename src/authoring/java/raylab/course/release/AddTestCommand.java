package raylab.course.release;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import raylab.cli.UserError;
import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.GradingPlan;
import raylab.course.JavaBuild;
import raylab.course.MilestoneCheck;
import raylab.course.TestLauncher;
import raylab.course.TestResult;

/**
 * {@code raylab assignment add-test MILESTONE CLASS [--buggy FILE.java] [--points N] [--weight W]}:
 * a hidden test in one command (instructors). The test lives in {@code grader/tests/} in the
 * package of the milestone's student file; without it, the command writes a skeleton there
 * (tag, helpers {@code raylab.hidden.Calls} and {@code Hidden}, a seeded generator, a failing
 * placeholder) and stops. With it, the test is compiled and run as the grader runs it (its tag,
 * in a child JVM): it must compile, pass on the reference solution, and with {@code --buggy}
 * fail on that wrong student file; then it is listed in {@code tests.hidden}, {@code --points}
 * raise {@code hiddenPoints} (and the total), {@code --weight} sets its methods' weight in the
 * split of {@code hiddenPoints} ({@code tests.hiddenWeights}), and the handout's table follows.
 * Nothing is changed when a step fails.
 */
@Command(name = "add-test", mixinStandardHelpOptions = true,
        description = {"Write a hidden test's skeleton, or check a hidden test against the reference and grade it.",
            "The test is grader/tests/<package of the milestone's file>/CLASS.java. First run: the skeleton is written.",
            "Next runs: it must compile, carry the milestone's tag, pass on the reference solution and, with --buggy,",
            "fail on that student file; then it is added to tests.hidden of assignment.json."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:skeleton written, or checked and added", "1:the test does not compile, fails on the reference,"
                + " or passes on the buggy file (nothing changed)", "2:bad input (nothing changed)"})
public final class AddTestCommand extends AssignmentCommand.Base implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "MILESTONE", description = "The milestone id (sphere, box, ...).")
    String milestoneId;

    @Parameters(index = "1", paramLabel = "CLASS", description = "The test class's simple name, ending in HiddenTest "
            + "(e.g. SphereGrazingHiddenTest).")
    String className;

    @Option(names = "--buggy", paramLabel = "FILE.java", description = "A wrong version of the milestone's student file "
            + "(same name and package): the test must fail on it.")
    Path buggy;

    @Option(names = "--points", paramLabel = "N", description = "Raise hiddenPoints and the milestone's total by N "
            + "(default 0: the test shares the hidden points there are).")
    int points;

    @Option(names = "--weight", paramLabel = "W", description = "Each of the test's methods weighs W in the split of "
            + "hiddenPoints (default 1, as every hidden test method).")
    Double weight;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        if (!className.matches("[A-Z][A-Za-z0-9_]*HiddenTest")) {
            throw UserError.badInput("CLASS must be a Java class name ending in HiddenTest, e.g. "
                    + capital(milestoneId) + "GrazingHiddenTest; got '" + className + "'");
        }
        if (points < 0) {
            throw UserError.badInput("--points must be 0 or more, got " + points);
        }
        if (weight != null && !(weight > 0 && weight < 1e6)) {
            throw UserError.badInput("--weight must be a number > 0, got " + weight);
        }
        Assignments all = load();
        Assignment a = milestone(all, milestoneId);
        Path root = project();
        if (a.files().isEmpty()) {
            throw UserError.badInput("milestone " + a.id() + " has no student file to test");
        }
        String studentFile = a.files().get(0).path();
        String pkg = packageOf(studentFile);
        String rel = "grader/tests/" + pkg.replace('.', '/') + "/" + className + ".java";
        Path file = root.resolve(rel);
        if (buggy != null && !Files.isRegularFile(buggy)) {
            throw UserError.badInput(buggy + ": no such file");
        }
        if (!Files.isRegularFile(file)) {
            String text = skeleton(a, pkg, className);
            Files.createDirectories(file.getParent());
            Files.writeString(file, text, StandardCharsets.UTF_8);
            out.println("wrote the skeleton " + rel + " (tag \"" + a.tests().tag() + "\", helpers raylab.hidden.Calls"
                    + " and Hidden).");
            out.println("Write its checks (docs/instructors.md \"Adding a hidden test\"), then run this command again:"
                    + " it compiles the test, runs it on the reference solution" + (buggy == null ? "" : " and on " + buggy)
                    + ", and adds it to " + a.folder().toString().replace('\\', '/') + "/assignment.json.");
            return 0;
        }
        for (Assignment o : all.all()) {
            if (o != a && o.tests().hidden().contains(rel)) {
                throw UserError.badInput(rel + " is graded already, in milestone " + o.id());
            }
        }
        String fqcn = pkg + "." + className;
        Path work = Files.createTempDirectory("raylab-add-test");
        try {
            Checked checked = check(root, a, file, fqcn, buggy, work);
            out.println("checked " + rel + " as the grader runs it (tag \"" + a.tests().tag() + "\"): compiles, "
                    + checked.methods() + " test method(s) pass on the reference solution"
                    + (buggy == null ? "" : "; on " + buggy.getFileName() + " " + checked.failedOnBuggy().size()
                            + " fail: " + String.join(", ", checked.failedOnBuggy())));
        } finally {
            JavaBuild.deleteTree(work);
        }
        Path jsonFile = root.resolve(a.folder()).resolve("assignment.json");
        String json = Files.readString(jsonFile, StandardCharsets.UTF_8);
        String updated = json;
        if (!a.tests().hidden().contains(rel)) {
            updated = addHidden(updated, rel);
        }
        if (points > 0) {
            updated = withHiddenPoints(updated, a.tests().hiddenPoints() + points);
            updated = AssignmentCommand.withTotal(updated, a.points() + points);
        }
        if (weight != null) {
            updated = withWeight(updated, className, weight);
        }
        commit(a, updated, Map.of(), out);
        Assignment after = Assignments.load(root).byId(a.id()).orElseThrow();
        for (GradingPlan.Item i : GradingPlan.of(root, after).hidden()) {
            if (i.key().startsWith(fqcn + "#")) {
                out.printf(Locale.ROOT, "  hidden %-6s %s%n", GradingPlan.points(i.cents()), i.name());
            }
        }
        return 0;
    }

    /** What the check found. */
    record Checked(int methods, List<String> failedOnBuggy) {
    }

    /**
     * Compiles the test with the test helpers and runs it in a child JVM with the milestone's
     * tag, on the reference solution and, when given, on the buggy student file.
     */
    static Checked check(Path root, Assignment a, Path test, String fqcn, Path buggy, Path work) throws IOException {
        List<Path> own = JavaBuild.ownClassPath();
        List<Path> helperSources = new ArrayList<>(JavaBuild.sourcesUnder(root.resolve(MilestoneCheck.HELPERS)));
        helperSources.addAll(JavaBuild.sourcesUnder(root.resolve("grader/tests/raylab/hidden")));
        Path helpers = work.resolve("helpers");
        JavaBuild.Result h = JavaBuild.compile(helperSources, own, helpers);
        if (!h.success()) {
            throw new UserError("the test helpers do not compile: " + problem(root, h) + "; nothing was changed", 1);
        }
        Path tests = work.resolve("tests");
        List<Path> cp = new ArrayList<>(List.of(helpers));
        cp.addAll(own);
        JavaBuild.Result t = JavaBuild.compile(List.of(test), cp, tests);
        if (!t.success()) {
            throw new UserError("the test does not compile: " + problem(root, t) + "; nothing was changed", 1);
        }
        List<Path> run = new ArrayList<>(List.of(tests));
        run.addAll(cp);
        Path runDir = Files.createDirectories(work.resolve("run"));
        List<String> tags = List.of(a.tests().tag());
        List<TestResult> expected = TestLauncher.discover(run, null, tags, List.of(fqcn), runDir);
        if (expected.isEmpty()) {
            throw new UserError(root.relativize(test) + " has no test the grader would run: its class needs @Tag(\""
                    + a.tests().tag() + "\") and @Test methods; nothing was changed", 1);
        }
        Map<String, List<TestResult>> onReference = GradingPlan.byMethod(
                TestLauncher.run(run, null, tags, List.of(fqcn), TestLauncher.Limits.DEFAULT, runDir, expected).results());
        List<String> failed = new ArrayList<>();
        for (Map.Entry<String, List<TestResult>> e : onReference.entrySet()) {
            for (TestResult r : e.getValue()) {
                if (!r.status().passed()) {
                    failed.add(r.displayName() + ": " + (r.message() == null ? r.status() : r.message().strip()));
                    break;
                }
            }
        }
        if (!failed.isEmpty()) {
            throw new UserError("the test fails on the reference solution, so the grader would not grade it: "
                    + String.join("; ", failed) + "; nothing was changed", 1);
        }
        List<String> caught = new ArrayList<>();
        if (buggy != null) {
            String name = buggy.getFileName().toString();
            Assignment.StudentFile target = a.files().stream()
                    .filter(f -> Path.of(f.path()).getFileName().toString().equals(name)).findFirst()
                    .orElseThrow(() -> UserError.badInput(buggy + ": not a student file of milestone " + a.id()
                            + " (its files: " + String.join(", ", a.files().stream().map(f -> Path.of(f.path())
                                    .getFileName().toString()).toList()) + ")"));
            Path bugDir = work.resolve("buggy");
            Path copy = Files.createDirectories(work.resolve("buggy-src").resolve(Path.of(target.path()).getParent()
                    .toString())).resolve(name);
            Files.copy(buggy, copy);
            JavaBuild.Result b = JavaBuild.compile(List.of(copy), own, bugDir);
            if (!b.success()) {
                throw UserError.badInput(buggy + " does not compile: " + b.errors().get(0).line() + ": "
                        + b.errors().get(0).message());
            }
            List<Path> withBug = new ArrayList<>(List.of(bugDir));
            withBug.addAll(run);
            Map<String, List<TestResult>> onBuggy = GradingPlan.byMethod(TestLauncher.run(withBug, null, tags,
                    List.of(fqcn), TestLauncher.Limits.DEFAULT, runDir, expected).results());
            for (List<TestResult> g : onBuggy.values()) {
                if (g.stream().anyMatch(r -> !r.status().passed())) {
                    caught.add("\"" + g.get(0).displayName().replaceFirst("^\\[\\d+\\] ", "") + "\"");
                }
            }
            if (caught.isEmpty()) {
                throw new UserError("the test passes on " + buggy + " too: it does not catch that bug; nothing was changed",
                        1);
            }
        }
        return new Checked(onReference.size(), caught);
    }

    private static String problem(Path root, JavaBuild.Result r) {
        JavaBuild.Problem p = r.errors().get(0);
        String f = p.file() == null ? "" : (p.file().startsWith(root) ? root.relativize(p.file()) : p.file().getFileName())
                + ":" + p.line() + ": ";
        return f + p.message();
    }

    /** The package of a student file path (src/main/java/raylab/surface/Sphere.java: raylab.surface). */
    static String packageOf(String studentFile) {
        String p = studentFile.replaceFirst("^src/main/java/", "");
        int slash = p.lastIndexOf('/');
        return slash < 0 ? "" : p.substring(0, slash).replace('/', '.');
    }

    /** The skeleton of a hidden test: compiles, carries the tag, and fails until it is written. */
    static String skeleton(Assignment a, String pkg, String cls) {
        List<String> methods = a.files().stream().flatMap(f -> f.methods().stream()).toList();
        boolean surface = pkg.equals("raylab.surface");
        long seed = Integer.toUnsignedLong((cls + a.id()).hashCode());
        String call = surface
                ? "        // The student's method, called the way a render calls it (on a render thread):\n"
                        + "        //   IntersectionRecord rec = new IntersectionRecord();\n"
                        + "        //   boolean hit = Calls.intersect(surface, rec, ray);\n"
                : "        // Call the student's method directly, e.g. " + (methods.isEmpty() ? "" : methods.get(0)) + "(...).\n";
        return "package " + pkg + ";\n\n"
                + "import static org.junit.jupiter.api.Assertions.fail;\n\n"
                + "import java.util.SplittableRandom;\n\n"
                + "import org.junit.jupiter.api.DisplayName;\n"
                + "import org.junit.jupiter.api.Tag;\n"
                + "import org.junit.jupiter.api.Test;\n\n"
                + (surface ? "import raylab.hidden.Calls;\n" : "")
                + "import raylab.hidden.Hidden;\n"
                + (surface ? "import raylab.ray.IntersectionRecord;\n" : "")
                + "\n/**\n"
                + " * Hidden test of " + String.join(", ", methods) + " (grader only, never shipped): WHAT IT CHECKS, in\n"
                + " * the lecture's notation. Fair as every hidden test (raylab.hidden.Hidden): the answer is built\n"
                + " * first, nothing lies exactly on a boundary, every input is seeded and the seed is in every message.\n"
                + " */\n"
                + "@Tag(\"" + a.tests().tag() + "\")\n"
                + "class " + cls + " {\n"
                + "    @Test\n"
                + "    @DisplayName(\"WHAT A STUDENT READS IN THE REPORT: the case, not the method name\")\n"
                + "    void theCaseItChecks() {\n"
                + "        long seed = 0x" + Long.toHexString(seed) + "L;\n"
                + "        SplittableRandom r = Hidden.rng(seed);\n"
                + "        // Build the answer first (Hidden.unit, Hidden.point, Hidden.uniform), then the input from it.\n"
                + call
                + "        // Compare with a message that says the input, expected and actual (Hidden.assertColor, ...).\n"
                + "        fail(\"write this hidden test (seed \" + seed + \", first draw \" + r.nextDouble() + \")\");\n"
                + "    }\n"
                + "}\n";
    }

    /** The text with {@code rel} appended to tests.hidden (the array created after tests.visible if missing). */
    static String addHidden(String json, String rel) throws IOException {
        if (Pattern.compile("\"hidden\"\\s*:\\s*\\[").matcher(json).find()) {
            return AssignmentCommand.addToArray(json, "hidden", "\"" + rel + "\"");
        }
        return insertAfter(json, Pattern.compile("\"visible\"\\s*:\\s*\\[[^\\]]*\\]"), "\"hidden\": [\"" + rel + "\"]");
    }

    /** The text with tests.hiddenPoints set (added after tests.hidden if missing). */
    static String withHiddenPoints(String json, int hiddenPoints) throws IOException {
        Matcher m = Pattern.compile("\"hiddenPoints\"\\s*:\\s*\\d+").matcher(json);
        if (m.find()) {
            return json.substring(0, m.start()) + "\"hiddenPoints\": " + hiddenPoints + json.substring(m.end());
        }
        return insertAfter(json, Pattern.compile("\"hidden\"\\s*:\\s*\\[[^\\]]*\\]"), "\"hiddenPoints\": " + hiddenPoints);
    }

    /** The text with tests.hiddenWeights[cls] set (the object added after tests.hidden if missing). */
    static String withWeight(String json, String cls, double w) throws IOException {
        String value = AssignmentCommand.BigDecimalText.of(w);
        Matcher obj = Pattern.compile("\"hiddenWeights\"\\s*:\\s*\\{([^}]*)\\}").matcher(json);
        if (obj.find()) {
            Map<String, String> entries = new LinkedHashMap<>();
            Matcher e = Pattern.compile("\"([^\"]+)\"\\s*:\\s*([-0-9.eE+]+)").matcher(obj.group(1));
            while (e.find()) {
                entries.put(e.group(1), e.group(2));
            }
            entries.put(cls, value);
            List<String> parts = new ArrayList<>();
            entries.forEach((k, v) -> parts.add("\"" + k + "\": " + v));
            return json.substring(0, obj.start()) + "\"hiddenWeights\": {" + String.join(", ", parts) + "}"
                    + json.substring(obj.end());
        }
        return insertAfter(json, Pattern.compile("\"hidden\"\\s*:\\s*\\[[^\\]]*\\]"),
                "\"hiddenWeights\": {\"" + cls + "\": " + value + "}");
    }

    private static String insertAfter(String json, Pattern after, String member) throws IOException {
        Matcher m = after.matcher(json);
        if (!m.find()) {
            throw new IOException("assignment.json: no " + after.pattern().replaceAll("\\\\s\\*:.*", "").replace("\\", "")
                    + " to add " + member + " after");
        }
        return json.substring(0, m.end()) + ",\n    " + member + json.substring(m.end());
    }

    private static String capital(String s) {
        return s.isEmpty() ? s : Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }
}
