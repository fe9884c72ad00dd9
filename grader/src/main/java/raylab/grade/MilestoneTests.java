package raylab.grade;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import raylab.course.Assignment;
import raylab.course.GradingPlan;
import raylab.course.JavaBuild;
import raylab.course.TestLauncher;
import raylab.course.TestResult;
import raylab.grade.GradeReport.Kind;

/**
 * A milestone's tests: its visible, hidden and data-case test classes (the grader's own copies)
 * run in the grader's process, a JVM of trusted code whose stand-ins call a student process in
 * its box, with the milestone's scenes rendered last in the same JVM; then their results scored
 * with the points and names of {@link GradingPlan}.
 */
final class MilestoneTests {
    private MilestoneTests() {
    }

    /**
     * What the milestone's test JVM reported.
     *
     * @param got     results by test id
     * @param notes   what the milestone's report says about the run (it did not finish)
     * @param renders the scenes it rendered after the tests, or null when it rendered none
     */
    record Ran(Map<String, TestResult> got, List<String> notes, SceneGrading.Renders renders) {
    }

    /** The milestone's test classes the grader shows (visible tests and visible data cases), in the setup's order. */
    static List<String> visibleClasses(Assignment a, GraderSetup setup) {
        return setup.testClasses.get(a.id()).stream().filter(c -> kindOf(a, c) == Kind.VISIBLE
                || c.equals(DataCases.visibleClassName(a.id()))).toList();
    }

    /**
     * Runs M's test classes in the grader's process: first the visible classes, to their end,
     * then the hidden ones with a new student process in a new box, so that nothing hidden
     * reaches student code before every visible result is reported; then, with {@code scenes},
     * M's scenes with a third student process (nothing a test passed to student code reaches a
     * picture).
     */
    static Ran run(GradingRun run, GradingRun.Milestone m, List<String> visibleClasses, List<String> hiddenClasses,
            List<TestResult> allExpected, boolean scenes) throws IOException {
        Assignment a = m.a();
        GraderSetup setup = run.setup();
        Grader.Options options = run.options();
        Map<String, TestResult> got = new LinkedHashMap<>();
        List<String> notes = new ArrayList<>();
        Set<String> visible = new HashSet<>(visibleClasses);
        Set<String> hidden = new HashSet<>(hiddenClasses);
        List<TestResult> expected = allExpected.stream().filter(e -> visible.contains(GraderSetup.outer(e.className()))
                || hidden.contains(GraderSetup.outer(e.className()))).toList();
        if (expected.isEmpty()) {
            return new Ran(got, notes, null);
        }
        List<Path> cp = new ArrayList<>();
        cp.add(setup.tests); // the grader's tests first
        cp.addAll(run.trustedClassPath(m.trusted(), scenes));
        Path dir = Files.createTempDirectory(m.dir(), "tests");
        List<Sandbox.Box> boxes = new ArrayList<>();
        try {
            List<String> classes = new ArrayList<>();
            for (int g = 0; g < 2; g++) {
                Sandbox.Box box = run.studentBox(a, m.overlay(), m.dir());
                boxes.add(box);
                Path config = dir.resolve(g == 0 ? "visible.properties" : "hidden.properties");
                raylab.boundary.Remote.writeConfig(config, run.studentConfig(a, box, m.overlay(),
                        options.limits().perTestSeconds() * 1000L, options.limits().heapMegabytes()));
                if (g == 0) {
                    classes.addAll(visibleClasses);
                } else {
                    classes.add(TestLauncher.thenBoundary(config));
                    classes.addAll(hiddenClasses);
                }
            }
            List<Path> pngs = new ArrayList<>();
            Duration sceneLimit = options.sceneLimit().multipliedBy(scenes ? a.scenes().size() : 0);
            List<String> jvm = new ArrayList<>(List.of("-Draylab.boundary=" + dir.resolve("visible.properties")));
            if (scenes) {
                Sandbox.Box box = run.studentBox(a, m.overlay(), m.dir());
                boxes.add(box);
                Path config = dir.resolve("render.properties");
                raylab.boundary.Remote.writeConfig(config, run.studentConfig(a, box, m.overlay(),
                        options.sceneLimit().toMillis(), options.sceneHeapMb()));
                Path rdir = Files.createDirectory(dir.resolve("render"));
                Path list = rdir.resolve("scenes.txt");
                Files.write(list, SceneGrading.arguments(run, a, rdir, pngs));
                classes.add(TestLauncher.thenRender(config, list, sceneLimit.toSeconds()));
                // The milestone's reference predicts the student's answers, so that calls go in batches.
                jvm.add("-Draylab.boundary.references=" + setup.references.get(a.id()).toAbsolutePath());
            }
            // One JVM for both groups and the scenes, so the milestone's time limits cover all.
            TestLauncher.Limits l = options.limits();
            TestLauncher.Limits both = new TestLauncher.Limits(Math.max(l.heapMegabytes(),
                    scenes ? options.sceneHeapMb() : 0), l.wallClock().multipliedBy(2).plus(sceneLimit)
                    .plusSeconds(scenes ? 30 : 0), l.perTestSeconds(), l.outputCapBytes());
            jvm.addAll(JvmOptions.trusted(both.heapMegabytes()));
            jvm.addAll(GradingRun.extraJvmOptions("RAYLAB_TRUSTED_JVM_OPTS"));
            TestLauncher.Run o = TestLauncher.runTrusted(cp, setup.tests, classes, both, dir, expected, jvm);
            for (TestResult r : o.results()) {
                got.put(r.id(), r);
            }
            boolean allReported = expected.stream().map(e -> got.get(e.id())).allMatch(r -> r != null
                    && r.status() != TestResult.Status.MISSING && !r.id().equals(o.cutOff()));
            SceneGrading.Renders renders = null;
            if (scenes) {
                byte[] millis = SceneGrading.readCapped(dir.resolve("render").resolve("millis.txt"), 64);
                long ms;
                try {
                    ms = Long.parseLong(new String(millis == null ? new byte[0] : millis,
                            StandardCharsets.US_ASCII).trim()) / a.scenes().size();
                } catch (NumberFormatException e) {
                    ms = 0; // stopped before the renders ended
                }
                // On this path the test JVM renders the scenes: the launcher's account of its early end.
                renders = new SceneGrading.Renders(SceneGrading.read(pngs), !o.finished() && o.timedOut(), false, ms,
                        o.finished() || o.timedOut() ? "" : o.problem());
                Path times = dir.resolve("render").resolve("times.txt");
                if (GradingRun.TIMES && Files.isRegularFile(times)) {
                    System.err.print(Files.readString(times));
                }
            }
            if (!o.finished() && !o.problem().isEmpty() && !allReported) {
                boolean visibleDone = expected.stream().filter(e -> visible.contains(GraderSetup.outer(e.className())))
                        .map(e -> got.get(e.id())).allMatch(r -> r != null && r.status() != TestResult.Status.MISSING
                                && !r.id().equals(o.cutOff()));
                // What went wrong in the hidden run is named on the hidden tests only (their visibility).
                notes.add(visibleDone ? "the hidden tests' run did not finish (see the hidden tests)"
                        : "the test run did not finish: " + o.problem());
            }
            return new Ran(got, notes, renders);
        } finally {
            for (Sandbox.Box box : boxes) {
                run.sandbox().finish(box, null);
            }
            JavaBuild.deleteTreeQuietly(dir);
        }
    }

    /** Visibility and kind of the test class. */
    static Kind kindOf(Assignment a, String className) {
        String outer = GraderSetup.outer(className);
        if (outer.equals(DataCases.className(a.id())) || outer.equals(DataCases.visibleClassName(a.id()))) {
            return Kind.CASE;
        }
        for (String v : a.tests().visible()) {
            if (GraderSetup.testClassName(v).equals(outer)) {
                return Kind.VISIBLE;
            }
        }
        return Kind.HIDDEN;
    }

    /**
     * Groups results per test method (parameterized invocations together) and scores them: the
     * points and names come from {@link GradingPlan} (display names, shares in whole cents, in
     * the order of the test files), as in {@code raylab check} and the handouts. A test whose
     * first failure is the grading's ({@link TestResult#gradingFailed()}) is {@link GradingStatus#GRADING_FAILED}.
     */
    static List<GradeReport.Test> score(Assignment a, GraderSetup setup, GradingPlan.Plan plan,
            List<TestResult> expected, Map<String, TestResult> got) {
        Map<String, List<TestResult>> groups = GradingPlan.byMethod(expected);
        Map<String, GradingPlan.Item> planned = new LinkedHashMap<>();
        List<String> order = new ArrayList<>();
        for (GradingPlan.Item i : plan.visible()) {
            planned.put(i.key(), i);
            order.add(i.key());
        }
        for (GradingPlan.Item i : plan.hidden()) {
            planned.put(i.key(), i);
            order.add(i.key());
        }
        // Shares over the groups that exist, in plan order (a test the plan does not know goes last).
        Comparator<String> byPlan = Comparator.comparingInt(k -> {
            int i = order.indexOf(k);
            return i < 0 ? Integer.MAX_VALUE : i;
        });
        List<String> keys = new ArrayList<>(groups.keySet());
        keys.sort(byPlan);
        List<String> visibleKeys = keys.stream().filter(k -> kindOf(a, groups.get(k).get(0).className()) == Kind.VISIBLE).toList();
        List<String> hiddenKeys = keys.stream().filter(k -> kindOf(a, groups.get(k).get(0).className()) == Kind.HIDDEN).toList();
        long[] vs = GradingPlan.share(100L * a.tests().visiblePoints(), visibleKeys.size());
        double[] weights = new double[hiddenKeys.size()];
        for (int i = 0; i < weights.length; i++) {
            TestResult t = groups.get(hiddenKeys.get(i)).get(0);
            weights[i] = a.tests().hiddenWeight(GradingPlan.outer(t.className()), t.method());
        }
        long[] hs = GradingPlan.share(100L * a.tests().hiddenPoints(), weights);
        Map<String, DataCases.Case> cases = new LinkedHashMap<>();
        for (DataCases.Case c : setup.cases.getOrDefault(a.id(), List.of())) {
            cases.put(c.method(), c);
        }
        List<GradeReport.Test> out = new ArrayList<>();
        for (String key : keys) {
            List<TestResult> g = groups.get(key);
            TestResult first = g.get(0);
            Kind kind = kindOf(a, first.className());
            double points;
            String visibility;
            GradingPlan.Item item = planned.get(key);
            String name = item != null ? item.name() : first.method();
            if (kind == Kind.VISIBLE) {
                points = vs[visibleKeys.indexOf(key)] / 100.0;
                visibility = "visible";
            } else if (kind == Kind.HIDDEN) {
                points = hs[hiddenKeys.indexOf(key)] / 100.0;
                visibility = a.tests().hiddenVisibility();
            } else {
                DataCases.Case c = cases.get(first.method());
                points = c == null ? 0 : Math.round(c.points() * 100) / 100.0;
                visibility = c == null ? a.tests().hiddenVisibility() : c.visibility();
                name = "data case: " + (c == null ? first.method() : c.name());
            }
            boolean passed = true;
            boolean gradingFailed = false; // the first failure is the grader's, not the student's
            String message = "";
            String output = "";
            long ms = 0;
            String note = "";
            int failedCount = 0;
            for (TestResult e : g) {
                TestResult r = got.get(e.id());
                if (r == null) {
                    r = e.with(TestResult.Status.MISSING, "no result was reported for this test");
                }
                ms += r.millis();
                note = raylab.course.Notes.add(note, r.output());
                if (!r.status().passed()) {
                    failedCount++;
                    if (passed) {
                        gradingFailed = r.gradingFailed();
                        message = gradingFailed ? GradingStatus.message(r.message())
                                : explain(r, g.size() > 1 ? r.displayName() : null);
                        output = r.output() == null ? "" : r.output();
                    }
                    passed = false;
                }
            }
            if (failedCount > 1 && g.size() > 1 && !gradingFailed) {
                message = failedCount + " of " + g.size() + " cases failed; the first: " + message;
            }
            if (kind != Kind.VISIBLE) {
                output = ""; // what hidden tests print stays hidden
            }
            String file = kind == Kind.CASE ? (cases.get(first.method()) == null ? "" : cases.get(first.method()).file())
                    : testFile(a, first.className());
            out.add(new GradeReport.Test(a.id(), name, kind, points, passed ? points : 0, passed,
                    raylab.course.Messages.plain(message), raylab.course.Notes.strip(output), visibility, ms, file, null,
                    note, gradingFailed ? GradingStatus.GRADING_FAILED : GradingStatus.GRADED));
        }
        return out;
    }

    private static String testFile(Assignment a, String className) {
        String outer = GraderSetup.outer(className);
        for (String f : a.tests().visible()) {
            if (GraderSetup.testClassName(f).equals(outer)) {
                return f;
            }
        }
        for (String f : a.tests().hidden()) {
            if (GraderSetup.testClassName(f).equals(outer)) {
                return f;
            }
        }
        return "";
    }

    private static String explain(TestResult r, String invocation) {
        String base = switch (r.status()) {
            case FAILED -> r.message();
            case TIMED_OUT -> "timed out: " + (r.message() == null || r.message().isBlank()
                    ? "the test took longer than allowed (an endless loop?)" : r.message());
            case CRASHED -> "crashed: " + r.message() + " (System.exit, running out of memory or a JVM crash; "
                    + "tests after it could not run)";
            case MISSING -> "not run: " + r.message() + ". Tests that the grader did not see pass score 0: look for "
                    + "System.exit, an exception while loading your class, an endless loop, or running out of memory";
            case ABORTED -> "aborted: " + r.message();
            case PASSED -> "";
        };
        return invocation == null ? base : "[" + invocation + "] " + base;
    }
}
