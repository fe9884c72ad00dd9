package raylab.grade;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;

/**
 * The course checks itself before students see it ({@code raylab self-check}, {@code raylab
 * bundle} and Gradescope's {@code setup.sh}): with the files a platform gets, every problem of the
 * course's side that would make a grading fail or grade wrongly, one line each.
 * <ul>
 * <li>points that do not add up, a bad variant spec ({@link Assignments#load},
 *     {@link GradedScenes#validate});</li>
 * <li>a graded scene whose variants do not keep its point (graded as published with {@link #SEEDS}
 *     grading seeds);</li>
 * <li>the grader's tests do not compile, a test fails on the reference solution (the grading of
 *     the reference fails, {@link GradeReport#failed});</li>
 * <li>the reference solution, graded as a student's submission with these files, below full
 *     marks (each item that lost points).</li>
 * </ul>
 */
public final class CourseCheck {
    /** Grading seeds whose variants must keep every graded scene's point. */
    static final long[] SEEDS = {1, 20261204, 9_007_199_254_740_991L};

    private CourseCheck() {
    }

    /**
     * Every problem, one line each (empty: the course is ready).
     *
     * @param root       the course as the platform gets it (assignments, scenes, grader tests, sources)
     * @param milestones the milestones to check (empty: all)
     * @param options    how to grade the reference (cache, sandbox, limits)
     */
    public static List<String> problems(Path root, List<String> milestones, Grader.Options options, Consumer<String> log) {
        List<String> out = new ArrayList<>();
        Assignments all;
        List<Assignment> selected = new ArrayList<>();
        try {
            all = Assignments.load(root);
            for (Assignment a : all.all()) {
                if (milestones.isEmpty() || milestones.contains(a.id())) {
                    selected.add(a);
                }
            }
            GradedScenes.validate(root, selected);
        } catch (IOException e) {
            out.add(e.getMessage());
            return out; // nothing else can be read
        }
        for (Assignment a : selected) {
            for (int i = 0; i < a.scenes().size(); i++) {
                if (a.scenes().get(i).variant() == null || a.scenes().get(i).variant().isNull()) {
                    continue;
                }
                for (long seed : SEEDS) {
                    try {
                        GradedScenes.Graded g = GradedScenes.forGrading(root, a, i, seed, false);
                        if (!g.varied()) {
                            out.add(g.note() + " (grading seed " + seed + ", " + a.folder() + "/assignment.json)");
                            break;
                        }
                    } catch (IOException | RuntimeException e) {
                        out.add(a.scenes().get(i).scene() + ": cannot be varied (grading seed " + seed + "): " + e);
                        break;
                    }
                }
            }
        }
        log.accept("self-check: grading the reference solution with the course's own files");
        Path sub = null;
        try {
            sub = Files.createTempDirectory("raylab-self-check");
            for (Assignment a : selected) {
                for (Assignment.StudentFile f : a.files()) {
                    Path from = root.resolve(f.path());
                    if (!Files.isRegularFile(from)) {
                        out.add(a.folder() + "/assignment.json: the reference " + f.path() + " is not in the course's files");
                        continue;
                    }
                    Path to = sub.resolve(f.path());
                    Files.createDirectories(to.getParent());
                    Files.writeString(to, Files.readString(from, StandardCharsets.UTF_8), StandardCharsets.UTF_8);
                }
            }
            Grader.Options o = new Grader.Options(root, selected.stream().map(Assignment::id).toList(), options.limits(),
                    options.sceneLimit(), options.sceneHeapMb(), options.cacheDir(), options.sandboxUser(),
                    options.parallel(), options.sandboxMode());
            GradeReport r = new Grader(o, log).seed(SEEDS[1]).grade(sub);
            if (r.failed()) {
                for (String cause : r.failure().split("; ")) {
                    out.add("the reference cannot be graded: " + cause);
                }
            }
            for (GradeReport.Milestone m : r.milestones()) {
                for (GradeReport.Test t : m.tests()) {
                    if (t.score() < t.maxScore()) {
                        out.add("the reference solution loses " + HtmlReport.fmt(t.maxScore() - t.score()) + " of "
                                + HtmlReport.fmt(t.maxScore()) + " points on " + m.id() + ": " + t.name() + " ("
                                + GraderSetup.firstLine(t.message()) + ")");
                    }
                }
            }
        } catch (IOException | RuntimeException e) {
            out.add("the reference cannot be graded: " + GradeCommand.describe(e));
        } finally {
            if (sub != null) {
                JavaBuild.deleteTreeQuietly(sub);
            }
        }
        return out.stream().map(GradeCommand::oneLine).distinct().toList();
    }
}
