package raylab.course;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;

/**
 * The grader's process boundary as the test JVM ({@link TestMain}) reaches it: the student
 * process of this JVM and the trusted render of a milestone's scenes. A service: the instructor's
 * build provides it ({@code raylab.boundary}, listed in
 * {@code META-INF/services/raylab.course.BoundaryHooks}); the student starter has no provider,
 * and its test JVM runs without a boundary.
 */
public interface BoundaryHooks {
    /** Starts the student process now, before any test's time limit runs. */
    void warmUp();

    /** Ends this JVM's student process and starts the next one, described by {@code config}. */
    void switchTo(Path config);

    /** A test begins with a limit of {@code limitNanos} of the student's own time. */
    void startTest(long limitNanos);

    /** The student's own time in this JVM's student process so far; 0 before it exists. */
    long studentNanos();

    /** The CPU time of this JVM's student processes so far; 0 before one exists. */
    long studentCpuNanos();

    /**
     * Renders the scenes of {@code scenes} (lines of SCENE.json, OUT.png and NAME) with the
     * student's code, until it has used {@code cpuBudgetNanos} of the student's CPU time from
     * the first scene on ({@link Long#MAX_VALUE}: no limit); phases to {@code times}. A budget,
     * not a wall-clock deadline: the time the grader takes to start the student process on a
     * loaded machine is not the student's.
     */
    void renderAll(List<String> scenes, long cpuBudgetNanos, PrintStream times) throws IOException;

    /** This build's provider, or empty (the starter, or a provider this build cannot make). */
    static Optional<BoundaryHooks> find() {
        try {
            return ServiceLoader.load(BoundaryHooks.class, BoundaryHooks.class.getClassLoader()).findFirst();
        } catch (ServiceConfigurationError | LinkageError absent) {
            return Optional.empty();
        }
    }
}
