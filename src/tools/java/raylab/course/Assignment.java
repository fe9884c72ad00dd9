package raylab.course;

import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.annotation.JsonIgnoreProperties;
import com.fasterxml.jackson.annotation.JsonProperty;

/**
 * One milestone, as its {@code assignments/NN-id/assignment.json} describes it (format in
 * docs/assignment-format.md).
 *
 * @param id       short name, also the JUnit tag of its tests and the solution-region id
 * @param order    position in the course (the NN of the folder)
 * @param title    title for people
 * @param points   total points of the milestone
 * @param requires milestones whose code this one's scenes also need
 * @param files    the files the student edits, with the methods to write in each
 * @param tests    the visible and hidden tests and their points
 * @param scenes   graded scenes
 * @param cases    data-driven unit cases (JSON files relative to the assignment folder)
 * @param optional whether the milestone is an optional extra
 * @param folder   the assignment folder (set by the loader, not in the file)
 */
@JsonIgnoreProperties(value = {"$schema"}, allowSetters = true)
public record Assignment(
        @JsonProperty(required = true) String id,
        @JsonProperty(required = true) int order,
        @JsonProperty(required = true) String title,
        @JsonProperty(required = true) int points,
        List<String> requires,
        @JsonProperty(required = true) List<StudentFile> files,
        @JsonProperty(required = true) Tests tests,
        List<GradedScene> scenes,
        List<String> cases,
        Boolean optional,
        Path folder) {

    public Assignment {
        requires = requires == null ? List.of() : List.copyOf(requires);
        scenes = scenes == null ? List.of() : List.copyOf(scenes);
        cases = cases == null ? List.of() : List.copyOf(cases);
        files = List.copyOf(files);
        optional = optional != null && optional; // absent means false
    }

    /** A copy that knows its folder. */
    public Assignment inFolder(Path f) {
        return new Assignment(id, order, title, points, requires, files, tests, scenes, cases, optional, f);
    }

    /** A file the student edits and the methods to write in it. */
    public record StudentFile(@JsonProperty(required = true) String path,
            @JsonProperty(required = true) List<String> methods) {
    }

    /**
     * The milestone's tests.
     *
     * @param tag              JUnit tag of the visible and hidden tests
     * @param visible          visible test files (shipped to students)
     * @param hidden           hidden test files (the instructor's; never shipped)
     * @param visiblePoints    points shared by the visible tests
     * @param hiddenPoints     points shared by the hidden tests
     * @param hiddenVisibility Gradescope visibility of hidden tests: hidden, after_due_date, ...
     * @param hiddenWeights    optional: a hidden test class's (simple name) or method's
     *                         ({@code Class.method}) weight in the split of {@code hiddenPoints};
     *                         every other hidden test method weighs 1
     */
    public record Tests(@JsonProperty(required = true) String tag,
            @JsonProperty(required = true) List<String> visible,
            List<String> hidden,
            int visiblePoints,
            int hiddenPoints,
            String hiddenVisibility,
            java.util.Map<String, Double> hiddenWeights) {
        public Tests {
            hidden = hidden == null ? List.of() : List.copyOf(hidden);
            hiddenVisibility = hiddenVisibility == null ? "after_due_date" : hiddenVisibility;
            hiddenWeights = hiddenWeights == null ? java.util.Map.of()
                    : java.util.Collections.unmodifiableMap(new java.util.LinkedHashMap<>(hiddenWeights));
        }

        /** Hidden points shared equally among the hidden test methods. */
        public Tests(String tag, List<String> visible, List<String> hidden, int visiblePoints, int hiddenPoints,
                String hiddenVisibility) {
            this(tag, visible, hidden, visiblePoints, hiddenPoints, hiddenVisibility, null);
        }

        /**
         * The weight of a hidden test method: {@code hiddenWeights} of "Class.method", else of
         * "Class" (simple names), else 1.
         */
        public double hiddenWeight(String className, String method) {
            String simple = className.substring(className.lastIndexOf('.') + 1);
            Double w = hiddenWeights.get(simple + "." + method);
            if (w == null) {
                w = hiddenWeights.get(simple);
            }
            return w == null ? 1 : w;
        }
    }

    /**
     * A scene graded by comparing its render with the reference image.
     *
     * @param scene     scene file, relative to the project root
     * @param reference reference PNG, relative to the project root
     * @param points    points for a match
     * @param tolerance fraction of pixels allowed to differ by more than 2/255
     * @param variant   how the grader varies the scene per grading (null: graded as published);
     *                  read and checked by the grader ({@code raylab.grade.VariantSpec})
     */
    public record GradedScene(@JsonProperty(required = true) String scene,
            @JsonProperty(required = true) String reference,
            int points,
            double tolerance,
            com.fasterxml.jackson.databind.JsonNode variant) {
        /** A scene graded as published. */
        public GradedScene(String scene, String reference, int points, double tolerance) {
            this(scene, reference, points, tolerance, null);
        }
    }
}
