package raylab.grade;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import raylab.scene.Display;

/**
 * Everything one grading produced: per milestone its graded tests (unit tests, data cases and
 * scenes), and the files that were ignored. The report writers turn it into results.json,
 * junit.xml, report.html, PrairieLearn's results.json, the gradebook and the console table, so
 * the text in it that can come from a student (failure messages, printed output, notes, file
 * names) is made safe once, here: control characters escaped, lengths bounded ({@link Display#text}).
 *
 * @param milestones  graded milestones in course order
 * @param accepted    submitted files that were graded ("src/main/java/raylab/surface/Sphere.java <- Sphere.java")
 * @param ignored     submitted files that were not used, each with the reason
 * @param notes       general messages, in the order they were written (setup problems, sandbox mode), for
 *                    the course staff
 * @param studentNotes those of the general notes a student may read, chosen where each was written: what the
 *                    submission caused; never the sandbox mode, the grader's setup, the grading seed, a variant
 *                    drawn again or not drawn, the cause of a failed grading
 * @param seconds     wall time of the grading
 * @param cause       why the grading could not run, for the course staff ({@link Grader#failed}); null: it ran
 */
public record GradeReport(List<Milestone> milestones, List<String> accepted, List<String> ignored,
        List<String> notes, List<String> studentNotes, double seconds, String cause) {
    /** Every text that may hold a student's words made safe here, once for every output ({@link Display#text}). */
    public GradeReport {
        accepted = safe(accepted);
        ignored = safe(ignored);
        notes = safe(notes);
        studentNotes = safe(studentNotes);
        cause = Display.text(cause);
    }

    /** The report of a grading that ran, every general note one a student may read. */
    public GradeReport(List<Milestone> milestones, List<String> accepted, List<String> ignored, List<String> notes,
            double seconds) {
        this(milestones, accepted, ignored, notes, notes, seconds, null);
    }

    private static List<String> safe(List<String> texts) {
        return texts.stream().map(Display::text).toList();
    }

    /** The start of the note that tells the course staff a grading, or a milestone's, could not run. */
    public static final String FAILED = "grading failed: ";

    /**
     * What a student reads, on every platform, when the grading failed: no cause (it may name the
     * instructor's paths or hidden tests), no score.
     */
    public static final String FAILED_FOR_STUDENTS = "The autograder failed while grading this submission,"
            + " so no points were decided. This is a problem of the course's autograder, not of your code: please"
            + " tell the course staff, who have the cause in their report and must fix the autograder.";

    public double score() {
        return round(milestones.stream().mapToDouble(Milestone::score).sum());
    }

    /**
     * Whether the grading decided no grade (not a score of 0): it could not run, a milestone's
     * setup could not grade it, or a part of it failed on the grader's side.
     */
    public boolean failed() {
        return failure() != null;
    }

    /**
     * Why the grading failed, for the course staff (null when it did not fail): the grading
     * could not run, a milestone's setup could not grade it, or a test or scene failed on the
     * grader's side ({@link GradingStatus#GRADING_FAILED}: the machine's load, the trusted side).
     * The other parts are graded, in the instructors' report, but a total with a part that
     * decided nothing is not the student's grade, so no grade was decided.
     */
    public String failure() {
        List<String> causes = new ArrayList<>();
        if (cause != null) {
            causes.add(cause);
        }
        for (Milestone m : milestones) {
            if (m.cause() != null) {
                causes.add(m.id() + ": " + m.cause());
            }
            // One line per cause: the parts it took down, counted, the first one named.
            Map<String, List<String>> parts = new LinkedHashMap<>();
            for (Test t : m.tests()) {
                if (t.status() == GradingStatus.GRADING_FAILED) {
                    parts.computeIfAbsent(GradingStatus.cause(t.message()), k -> new ArrayList<>()).add(t.name());
                }
            }
            parts.forEach((why, names) -> causes.add(m.id() + ": the grading of " + (names.size() == 1 ? names.get(0)
                    : names.size() + " parts (" + names.get(0) + ", ...)") + " failed on the grader's side: " + why));
        }
        return causes.isEmpty() ? null : String.join("; ", causes);
    }

    /** The start of the note that names the grading seed. */
    public static final String SEED_NOTE = "scene variants: seed ";
    /** In the note of a scene graded as published because no variant kept its point. */
    public static final String PUBLISHED_NOTE = ": graded as published: ";
    /** In the note of a scene whose variant was drawn more than once. */
    public static final String REDRAWN_NOTE = ": variant drawn ";

    public double maxScore() {
        return round(milestones.stream().mapToDouble(Milestone::maxScore).sum());
    }

    static double round(double v) {
        return Math.round(v * 100) / 100.0; // cents: every share is a whole number of cents
    }

    /**
     * One milestone's result.
     *
     * @param cause why the course's setup could not grade it, for the course staff; null: graded
     */
    public record Milestone(String id, String title, List<String> notes, List<Test> tests, String cause) {
        public Milestone {
            notes = safe(notes);
            cause = Display.text(cause);
        }

        /** A milestone that was graded. */
        public Milestone(String id, String title, List<String> notes, List<Test> tests) {
            this(id, title, notes, tests, null);
        }

        public double score() {
            return round(tests.stream().mapToDouble(Test::score).sum());
        }

        public double maxScore() {
            return round(tests.stream().mapToDouble(Test::maxScore).sum());
        }
    }

    /** What kind of graded item a test is. */
    public enum Kind {
        VISIBLE, HIDDEN, CASE, SCENE;

        public String label() {
            return name().toLowerCase(java.util.Locale.ROOT);
        }
    }

    /**
     * One graded item.
     *
     * @param milestone  milestone id
     * @param name       name for people ("SphereTest.hitsFromOutside", "scene sphere.json")
     * @param kind       visible test, hidden test, data case or scene
     * @param maxScore   its points
     * @param score      points earned (0 or maxScore)
     * @param passed     whether the grader received its pass
     * @param message    why it failed (empty when passed)
     * @param output     what it printed (capped; empty for hidden tests)
     * @param visibility Gradescope visibility: visible, hidden, after_due_date, after_published
     * @param millis     duration
     * @param file       source file of the test or scene, for reports
     * @param images     student, reference and diff images for scenes (null otherwise)
     * @param note       a zero-point note: a correct result that cost more than the render plan
     *                   needs ("your loop traced 2 shadow rays the plan could skip"), never a
     *                   reason for lost points; empty if none ({@link raylab.course.Notes})
     * @param status     whether its points were decided ({@link GradingStatus#GRADED}) or its grading
     *                   failed on the grader's side, as the grader knew it (never read from the message)
     */
    public record Test(String milestone, String name, Kind kind, double maxScore, double score, boolean passed,
            String message, String output, String visibility, long millis, String file, Images images, String note,
            GradingStatus status) {
        public Test {
            message = Display.text(message);
            output = Display.text(output);
            note = note == null ? "" : Display.text(note);
            status = status == null ? GradingStatus.GRADED : status;
        }

        /** Graded, with a note. */
        public Test(String milestone, String name, Kind kind, double maxScore, double score, boolean passed,
                String message, String output, String visibility, long millis, String file, Images images, String note) {
            this(milestone, name, kind, maxScore, score, passed, message, output, visibility, millis, file, images, note,
                    GradingStatus.GRADED);
        }

        /** Graded, without a note. */
        public Test(String milestone, String name, Kind kind, double maxScore, double score, boolean passed,
                String message, String output, String visibility, long millis, String file, Images images) {
            this(milestone, name, kind, maxScore, score, passed, message, output, visibility, millis, file, images, "");
        }

        /** The same with this note. */
        public Test withNote(String n) {
            return new Test(milestone, name, kind, maxScore, score, passed, message, output, visibility, millis, file,
                    images, n, status);
        }

        /** The same with this status. */
        public Test withStatus(GradingStatus s) {
            return new Test(milestone, name, kind, maxScore, score, passed, message, output, visibility, millis, file,
                    images, note, s);
        }
    }

    /**
     * PNG bytes of a scene's render, its reference and the diff heatmap, and the metric line; for a
     * scene that differs, its worst pixels' ray trees ({@code raylab.inspect.WorstPixels} JSON,
     * shown by {@link PixelFeedback}; "" when none).
     */
    public record Images(byte[] student, byte[] reference, byte[] diff, String metric, String pixels) {
        public Images(byte[] student, byte[] reference, byte[] diff, String metric) {
            this(student, reference, diff, metric, "");
        }
    }
}
