package raylab.grade;

import java.util.List;

/**
 * Everything one grading produced: per milestone its graded tests (unit tests, data cases and
 * scenes), and the files that were ignored. The report writers turn it into results.json,
 * junit.xml, report.html, PrairieLearn's results.json and the console table.
 *
 * @param milestones  graded milestones in course order
 * @param accepted    submitted files that were graded ("src/main/java/raylab/surface/Sphere.java <- Sphere.java")
 * @param ignored     submitted files that were not used, each with the reason
 * @param notes       general messages (setup problems, sandbox mode)
 * @param seconds     wall time of the grading
 */
public record GradeReport(List<Milestone> milestones, List<String> accepted, List<String> ignored,
        List<String> notes, double seconds) {

    public double score() {
        return round(milestones.stream().mapToDouble(Milestone::score).sum());
    }

    public double maxScore() {
        return round(milestones.stream().mapToDouble(Milestone::maxScore).sum());
    }

    static double round(double v) {
        return Math.round(v * 100) / 100.0; // cents: every share is a whole number of cents
    }

    /** One milestone's result. */
    public record Milestone(String id, String title, List<String> notes, List<Test> tests) {
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
     */
    public record Test(String milestone, String name, Kind kind, double maxScore, double score, boolean passed,
            String message, String output, String visibility, long millis, String file, Images images, String note) {
        public Test {
            note = note == null ? "" : note;
        }

        /** Without a note. */
        public Test(String milestone, String name, Kind kind, double maxScore, double score, boolean passed,
                String message, String output, String visibility, long millis, String file, Images images) {
            this(milestone, name, kind, maxScore, score, passed, message, output, visibility, millis, file, images, "");
        }

        /** The same with this note. */
        public Test withNote(String n) {
            return new Test(milestone, name, kind, maxScore, score, passed, message, output, visibility, millis, file,
                    images, n);
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
