package raylab.grade;

import java.util.List;

import raylab.course.JavaBuild;

/**
 * The JVM options of a grading's processes, chosen by measuring a whole grading in Gradescope's
 * default container (0.5 CPU, 768 MB: grader/README.md, "Gradescope's default container"). In
 * such a container a JVM sizes its first heap at 1/64 of the memory (12 MB), so without these a
 * render's batches outgrow the young generation and are copied again and again, into full
 * collections; C2's compiler threads cost more than its faster code saves at half a CPU.
 */
public final class JvmOptions {
    private JvmOptions() {
    }

    /**
     * The grader's own JVM ({@code raylab grade}: the platforms' scripts, {@code grade-all} and
     * {@code grader/cgroup-check.sh} start it with these): C1 only, one collector thread, room for
     * javac and the variants' checks.
     */
    public static final List<String> GRADER = java.util.stream.Stream.concat(JavaBuild.QUICK_JVM.stream(),
            java.util.stream.Stream.of("-Xms64m", "-Xmn32m")).toList();

    /** {@link #GRADER} as one line for a shell script. */
    public static String graderLine() {
        return String.join(" ", GRADER);
    }

    /**
     * A trusted JVM (tests, stand-ins and renders of one milestone) with a heap of at most
     * {@code heapMb}: a young generation that holds a band of batched calls, and a first heap
     * that needs no full collection to grow.
     */
    public static List<String> trusted(int heapMb) {
        return List.of("-Xms" + Math.min(128, heapMb) + "m", "-Xmn" + Math.min(64, heapMb / 2) + "m");
    }

    /** A student process with a heap of at most {@code heapMb}: a young generation that holds a frame's calls. */
    public static List<String> student(int heapMb) {
        return List.of("-Xmn" + Math.min(16, heapMb / 2) + "m");
    }
}
