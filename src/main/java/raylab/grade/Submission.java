package raylab.grade;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import raylab.course.Assignment;

/**
 * The files of a student's submission that the grader will use: the logic is
 * {@link raylab.course.Submission}'s (it ships in the starter, for {@code raylab submit-check});
 * this class keeps the grader's name for it.
 */
public final class Submission {
    static final long MAX_FILE = raylab.course.Submission.MAX_FILE;
    static final int MAX_ENTRIES = raylab.course.Submission.MAX_ENTRIES;
    static final long MAX_ZIP_BYTES = raylab.course.Submission.MAX_ZIP_BYTES;

    private final raylab.course.Submission intake;

    private Submission(raylab.course.Submission intake) {
        this.intake = intake;
    }

    /** Accepted files: assignment path (e.g. src/main/java/raylab/surface/Sphere.java) to text. */
    public Map<String, String> files() {
        return intake.files();
    }

    /** Where each accepted file came from in the submission. */
    public Map<String, String> sources() {
        return intake.sources();
    }

    /** Files not used, each "path: reason". */
    public List<String> ignored() {
        return intake.ignored();
    }

    /** Graded files found twice with no single copy at the release's path: path to why neither is graded. */
    public Map<String, String> conflicts() {
        return intake.conflicts();
    }

    /** The submission's own framework sources (never graded): project path to text. */
    public Map<String, String> framework() {
        return intake.framework();
    }

    /** An empty submission with one explanation (for an unreadable input). */
    static Submission unreadable(String why) {
        return new Submission(raylab.course.Submission.unreadable(why));
    }

    /** Reads a directory or a zip file. */
    public static Submission read(Path input, List<Assignment> assignments) throws IOException {
        return new Submission(raylab.course.Submission.read(input, assignments));
    }
}
