package raylab.course;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * What a milestone's points are made of, computed one way for {@code raylab check}, the grader,
 * the reports and the handouts' grading tables (all read {@code assignment.json} through this
 * class, so they cannot disagree).
 *
 * <p>One test is one test method ({@code @Test}, or a {@code @ParameterizedTest} with all its
 * invocations), named by its {@code @DisplayName} as the handouts cite it, in the order of its
 * source file (the order the handout teaches). A milestone's visible (hidden) points are shared
 * among its visible (hidden) tests in whole cents: every test gets the same share, and the cents
 * left over go one each to the first tests, so the shares add up exactly to the total. Data
 * cases and scenes carry their own points.
 */
public final class GradingPlan {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Pattern TEST_ANNOTATION = Pattern.compile(
            "^\\s*@(Test|ParameterizedTest|RepeatedTest|TestFactory|TestTemplate)\\b");
    private static final Pattern DISPLAY_NAME = Pattern.compile("@DisplayName\\(\\s*\"((?:[^\"\\\\]|\\\\.)*)\"\\s*\\)");
    private static final Pattern METHOD = Pattern.compile("(\\w+)\\s*\\(");

    /** What a graded item is. */
    public enum Kind {
        TEST, CASE, SCENE
    }

    /**
     * One graded item a student can run locally, or one hidden test.
     *
     * @param kind      test, data case or scene
     * @param key       "raylab.surface.SphereTest#startsInside", the case's test method, or the scene path
     * @param name      the name people see (display name, case name, scene path)
     * @param file      the test, case or scene file
     * @param cents     its points, in hundredths
     * @param tolerance a scene's tolerance (0 otherwise)
     */
    public record Item(Kind kind, String key, String name, String file, long cents, double tolerance) {
        public double points() {
            return cents / 100.0;
        }
    }

    /** A test method found in a source file: its class, name and display name. */
    public record TestMethod(String className, String method, String displayName) {
        public String key() {
            return className + "#" + method;
        }
    }

    /**
     * A milestone's plan.
     *
     * @param assignment  the milestone
     * @param visible     what the student can run locally, in handout order: visible tests, visible data
     *                    cases, scenes
     * @param hidden      the hidden tests and hidden data cases, in order
     */
    public record Plan(Assignment assignment, List<Item> visible, List<Item> hidden) {
        public long visibleCents() {
            return visible.stream().mapToLong(Item::cents).sum();
        }

        public long hiddenCents() {
            return hidden.stream().mapToLong(Item::cents).sum();
        }

        public List<Item> of(Kind k) {
            return visible.stream().filter(i -> i.kind() == k).toList();
        }

        /** "hidden tests: 6 points, graded after submission" (empty when nothing is hidden). */
        public String hiddenLine() {
            if (hidden.isEmpty()) {
                return "";
            }
            long tests = hidden.stream().filter(i -> i.kind() == Kind.TEST).count();
            long cases = hidden.stream().filter(i -> i.kind() == Kind.CASE).count();
            String what = tests > 0 && cases > 0 ? "hidden tests and data cases" : tests > 0 ? "hidden tests" : "hidden data cases";
            return what + ": " + points(hiddenCents()) + " points, graded after submission";
        }
    }

    private GradingPlan() {
    }

    /** The plan of a milestone of the project at {@code root} (hidden test files are read when present). */
    public static Plan of(Path root, Assignment a) throws IOException {
        List<Item> visible = new ArrayList<>();
        List<Item> hidden = new ArrayList<>();
        List<TestMethod> vt = new ArrayList<>();
        for (String f : a.tests().visible()) {
            vt.addAll(testMethods(root.resolve(f), className(f)));
        }
        long[] vs = share(100L * a.tests().visiblePoints(), vt.size());
        for (int i = 0; i < vt.size(); i++) {
            visible.add(new Item(Kind.TEST, vt.get(i).key(), vt.get(i).displayName(), fileOf(a.tests().visible(),
                    vt.get(i).className()), vs[i], 0));
        }
        List<TestMethod> ht = new ArrayList<>();
        for (String f : a.tests().hidden()) {
            if (Files.isRegularFile(root.resolve(f))) {
                ht.addAll(testMethods(root.resolve(f), className(f)));
            }
        }
        if (a.tests().hiddenPoints() > 0) {
            if (ht.isEmpty()) {
                // The starter: hidden tests are not there, their points are.
                hidden.add(new Item(Kind.TEST, "hidden", "hidden tests", "", 100L * a.tests().hiddenPoints(), 0));
            } else {
                double[] weights = new double[ht.size()];
                for (int i = 0; i < ht.size(); i++) {
                    weights[i] = a.tests().hiddenWeight(ht.get(i).className(), ht.get(i).method());
                }
                long[] hs = share(100L * a.tests().hiddenPoints(), weights);
                for (int i = 0; i < ht.size(); i++) {
                    hidden.add(new Item(Kind.TEST, ht.get(i).key(), ht.get(i).displayName(),
                            fileOf(a.tests().hidden(), ht.get(i).className()), hs[i], 0));
                }
            }
        }
        for (CaseInfo c : cases(root, a)) {
            Item item = new Item(Kind.CASE, c.method(), c.name(), c.file(), Math.round(c.points() * 100), 0);
            (c.visibility().equals("visible") ? visible : hidden).add(item);
        }
        for (Assignment.GradedScene s : a.scenes()) {
            visible.add(new Item(Kind.SCENE, s.scene(), s.scene(), s.scene(), 100L * s.points(), s.tolerance()));
        }
        return new Plan(a, visible, hidden);
    }

    /**
     * The graded scene that is this scene file, if a milestone of the project at {@code root}
     * grades it (for {@code render --compare}'s default tolerance); empty when there are no
     * assignments or they cannot be read.
     */
    public static java.util.Optional<Assignment.GradedScene> gradedScene(Path root, Path scene) {
        try {
            Path wanted = scene.toAbsolutePath().normalize();
            for (Assignment a : Assignments.load(root).all()) {
                for (Assignment.GradedScene g : a.scenes()) {
                    if (root.resolve(g.scene()).toAbsolutePath().normalize().equals(wanted)) {
                        return java.util.Optional.of(g);
                    }
                }
            }
        } catch (IOException | RuntimeException e) {
            // no assignments here: no grading tolerance
        }
        return java.util.Optional.empty();
    }

    /** A data case as the plan sees it. */
    public record CaseInfo(String name, double points, String visibility, String method, String file, String hint,
            JsonNode json) {
    }

    /**
     * The data cases of a milestone, numbered across its case files in order; the test method
     * names are those of the grader's generated case classes.
     */
    public static List<CaseInfo> cases(Path root, Assignment a) throws IOException {
        List<CaseInfo> out = new ArrayList<>();
        for (CaseFile f : caseFiles(root, a)) {
            for (JsonNode c : f.cases()) {
                String name = c.path("name").asText("?");
                out.add(new CaseInfo(name, c.path("points").asDouble(1),
                        c.path("visibility").asText(a.tests().hiddenVisibility()), caseMethod(out.size() + 1, name),
                        a.folder() + "/" + f.rel(), c.path("hint").asText(""), c));
            }
        }
        return out;
    }

    /**
     * One case file of a milestone, read.
     *
     * @param file  the file
     * @param rel   its path as assignment.json names it
     * @param cases its cases (the file's array, or the one object it holds), not yet checked
     */
    public record CaseFile(Path file, String rel, List<JsonNode> cases) {
    }

    /** A milestone's case files in order; a missing file or one that is not JSON is an IOException naming it. */
    public static List<CaseFile> caseFiles(Path root, Assignment a) throws IOException {
        List<CaseFile> out = new ArrayList<>();
        Path folder = root.resolve(a.folder() == null ? Path.of("assignments") : a.folder());
        for (String rel : a.cases()) {
            Path f = folder.resolve(rel);
            if (!Files.isRegularFile(f)) {
                throw new IOException(folder.resolve("assignment.json") + ": case file " + rel + " does not exist");
            }
            JsonNode n;
            try {
                n = JSON.readTree(f.toFile());
            } catch (IOException e) {
                throw new IOException(f + ": not valid JSON: " + String.valueOf(e.getMessage()).split("\n")[0]);
            }
            List<JsonNode> cases = new ArrayList<>();
            if (n.isArray()) {
                n.forEach(cases::add);
            } else {
                cases.add(n);
            }
            out.add(new CaseFile(f, rel, cases));
        }
        return out;
    }

    /** The generated test class of a milestone's data cases (the grader's name for it). */
    public static String casesClassName(String milestone) {
        StringBuilder b = new StringBuilder();
        for (String part : milestone.split("[^A-Za-z0-9]+")) {
            if (!part.isEmpty()) {
                b.append(Character.toUpperCase(part.charAt(0))).append(part.substring(1));
            }
        }
        return "raylab.cases." + b + "CasesTest";
    }

    /** Java source of a test class with one test per case, each calling raylab.cases.CaseCheck.check(json). */
    public static String casesTestSource(String milestone, List<CaseInfo> cases) {
        String cls = casesClassName(milestone);
        StringBuilder b = new StringBuilder("package raylab.cases;\n\n// Generated by raylab from the data cases of milestone ")
                .append(milestone).append(".\nclass ").append(cls.substring(cls.lastIndexOf('.') + 1)).append(" {\n");
        for (CaseInfo c : cases) {
            b.append("    @org.junit.jupiter.api.Test\n    @org.junit.jupiter.api.DisplayName(\"").append(javaString(c.name()))
                    .append("\")\n    void ").append(c.method()).append("() throws Exception {\n        CaseCheck.check(\"")
                    .append(javaString(c.json().toString())).append("\");\n    }\n\n");
        }
        return b.append("}\n").toString();
    }

    /** {@code s} as the body of a Java string literal (escapes for quotes, backslashes and non-ASCII). */
    public static String javaString(String s) {
        StringBuilder b = new StringBuilder();
        for (char ch : s.toCharArray()) {
            switch (ch) {
                case '\\' -> b.append("\\\\");
                case '"' -> b.append("\\\"");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                default -> {
                    if (ch < 32 || ch > 126) {
                        b.append(String.format(Locale.ROOT, "\\u%04x", (int) ch));
                    } else {
                        b.append(ch);
                    }
                }
            }
        }
        return b.toString();
    }

    /** The test method of the n-th case (1-based) of a milestone. */
    public static String caseMethod(int n, String name) {
        return String.format(Locale.ROOT, "case%02d_%s", n, name.replaceAll("[^A-Za-z0-9]+", "_"));
    }

    /**
     * {@code cents} shared by {@code n}: equal shares in whole cents, the remainder one cent each
     * to the first ones. The shares add up to {@code cents} exactly.
     */
    public static long[] share(long cents, int n) {
        long[] out = new long[Math.max(0, n)];
        if (n == 0) {
            return out;
        }
        long base = cents / n;
        long rest = cents - base * n;
        for (int i = 0; i < n; i++) {
            out[i] = base + (i < rest ? 1 : 0);
        }
        return out;
    }

    /**
     * Splits {@code cents} by weight in whole cents: each gets the floor of its exact share, the
     * cents left over go one each to the first (in order); equal weights give {@link #share(long, int)}.
     */
    public static long[] share(long cents, double[] weights) {
        long[] out = new long[weights.length];
        double total = 0;
        for (double w : weights) {
            total += w;
        }
        if (weights.length == 0 || !(total > 0)) {
            return out;
        }
        long given = 0;
        for (int i = 0; i < weights.length; i++) {
            // A hair above the exact share, so that 100 * 1/3 * 3 does not floor to 99.
            out[i] = (long) Math.floor(cents * (weights[i] / total) + 1e-9);
            given += out[i];
        }
        for (int i = 0; given < cents; i = (i + 1) % weights.length) {
            out[i]++;
            given++;
        }
        return out;
    }

    /** Points for people: "2", "0.47", "8.5". */
    public static String points(long cents) {
        if (cents % 100 == 0) {
            return Long.toString(cents / 100);
        }
        String s = String.format(Locale.ROOT, "%d.%02d", cents / 100, Math.abs(cents % 100));
        return s.endsWith("0") ? s.substring(0, s.length() - 1) : s;
    }

    /** A scene's tolerance for people: "0.2 %". */
    public static String percent(double tolerance) {
        String s = String.format(Locale.ROOT, "%.3f", 100 * tolerance).replaceFirst("0+$", "").replaceFirst("\\.$", "");
        return s + " %";
    }

    /** The test methods of a test source file, in source order, with their display names. */
    public static List<TestMethod> testMethods(Path source, String className) throws IOException {
        List<String> lines = Files.readAllLines(source, StandardCharsets.UTF_8);
        List<TestMethod> out = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            if (!TEST_ANNOTATION.matcher(lines.get(i)).find()) {
                continue;
            }
            String display = null;
            int j = i + 1;
            StringBuilder annotations = new StringBuilder(lines.get(i));
            for (; j < lines.size(); j++) {
                String l = lines.get(j).strip();
                if (l.startsWith("@") || l.startsWith("//") || l.isEmpty() || annotations.toString().chars()
                        .filter(ch -> ch == '(').count() > annotations.toString().chars().filter(ch -> ch == ')').count()) {
                    annotations.append(' ').append(l);
                    continue;
                }
                break;
            }
            Matcher d = DISPLAY_NAME.matcher(annotations);
            if (d.find()) {
                display = unescape(d.group(1));
            }
            if (j >= lines.size()) {
                break;
            }
            String decl = lines.get(j);
            Matcher m = METHOD.matcher(decl);
            if (!m.find()) {
                continue;
            }
            String method = m.group(1);
            out.add(new TestMethod(className, method, display == null ? method : display));
            i = j;
        }
        return out;
    }

    private static String unescape(String s) {
        return s.replace("\\\"", "\"").replace("\\\\", "\\");
    }

    /** The class of a test source path: src/test/java/raylab/surface/SphereTest.java to raylab.surface.SphereTest. */
    public static String className(String sourcePath) {
        String s = sourcePath.replace('\\', '/');
        // Visible tests live under src/test/java, the instructor's other tests under a folder "tests".
        for (String r : List.of("src/test/java/", "tests/")) {
            int k = s.indexOf(r);
            if (k >= 0) {
                s = s.substring(k + r.length());
            }
        }
        return s.replaceFirst("\\.java$", "").replace('/', '.');
    }

    private static String fileOf(List<String> files, String className) {
        for (String f : files) {
            if (className(f).equals(className)) {
                return f;
            }
        }
        return "";
    }

    /** The outer class of a (possibly nested) class name. */
    public static String outer(String className) {
        int k = className.indexOf('$');
        return k < 0 ? className : className.substring(0, k);
    }

    /** Groups test results per test method (outer class and method), in the order first seen. */
    public static Map<String, List<TestResult>> byMethod(List<TestResult> results) {
        Map<String, List<TestResult>> out = new LinkedHashMap<>();
        for (TestResult r : results) {
            out.computeIfAbsent(outer(r.className()) + "#" + r.method(), k -> new ArrayList<>()).add(r);
        }
        return out;
    }
}
