package raylab.grade;

import java.io.IOException;
import java.nio.file.Path;

import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

import raylab.course.Assignments;

/**
 * The grader cache the test classes share ({@code target/grader-cache} of the project root, the
 * grader's default), with the whole course built in it: a grading of some milestones uses that
 * build ({@link GraderSetup#prepare}), so a class that grades one selection after another, and
 * the classes after it in the same build, build no cache of their own (docs/testing.md, S2).
 * Building it is idempotent and safe beside another test JVM doing the same (the cache is built
 * in a temporary folder and moved into place). A grading class takes it with
 * {@code @ExtendWith(SharedGraderCache.class)}: before its tests, the build is there.
 */
public final class SharedGraderCache implements BeforeAllCallback {
    @Override
    public void beforeAll(ExtensionContext context) throws IOException {
        whole(root());
    }

    /** The project root the grading tests use (system property raylab.grade.root, else the working directory). */
    static Path root() {
        return Path.of(System.getProperty("raylab.grade.root", ".")).toAbsolutePath().normalize();
    }

    /** The shared cache folder of this root. */
    static Path folder(Path root) {
        return root.resolve("target/grader-cache");
    }

    /**
     * {@link #whole} for a class outside this package that runs {@code raylab grade} with the
     * default cache, before its gradings run side by side.
     */
    public static void build(Path root) throws IOException {
        whole(root);
    }

    /**
     * A grader cache folder of its own, ready: the whole course's build in the shared cache (made
     * there once per build if no class made it before) copied into {@code cacheRoot} (over a copy
     * a run before left there), where a grading of any milestones uses it
     * ({@link GraderSetup#prepare}). For gradings that must not share the cache (mode none
     * poisons the one it grades with; grade-all's shards keep their own) and need not test its
     * build: a build is CPU (compiling the grader's tests, running them on the reference). The
     * build and its checks are tested elsewhere ({@code CacheManifestTest}, {@code CourseCheckTest}).
     */
    static void seed(Path cacheRoot) throws IOException {
        GraderSetup built = whole(root());
        Path to = cacheRoot.resolve(built.dir.getFileName().toString());
        raylab.course.JavaBuild.deleteTreeQuietly(to);
        raylab.course.FileTrees.copy(built.dir, to);
        Sandbox.readableByAll(to);
        Sandbox.privateFolder(to);
    }

    /** The whole course's build in the shared cache: made if no grading made it before, else verified. */
    static GraderSetup whole(Path root) throws IOException {
        return GraderSetup.prepare(root, Assignments.load(root).all(), folder(root), s -> { });
    }
}
