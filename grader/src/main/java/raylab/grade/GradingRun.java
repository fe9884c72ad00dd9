package raylab.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

import raylab.boundary.StudentProcess;
import raylab.course.Assignment;
import raylab.course.JavaBuild;
import raylab.course.TestLauncher;
import raylab.remote.StudentServer;

/**
 * The inputs of one grading that every milestone's steps share ({@link Grader#grade}): the
 * options, the grader's built setup, the sandbox, the grading's work folder and its copy of the
 * scenes (without reference images), every milestone of the course, the graded scenes' variants
 * by scene path and the reference images read before any student code ran. With them, the
 * student process's box and command line, the same for tests and scenes.
 *
 * @param options    the grading's options
 * @param setup      the grader's classes, tests and references, built once
 * @param sandbox    how student processes are isolated
 * @param work       the grading's work folder (one subfolder per milestone)
 * @param scenesCopy the grader's copy of {@code scenes/} without reference images
 * @param all        every milestone of the course, selected or not
 * @param graded     the graded scenes' variants and their references, by scene path
 * @param references reference PNG bytes by reference path (null: none)
 */
record GradingRun(Grader.Options options, GraderSetup setup, Sandbox sandbox, Path work, Path scenesCopy,
        List<Assignment> all, Map<String, GradedScenes.Graded> graded, Map<String, byte[]> references) {

    /** Phase times on standard error (environment variable RAYLAB_GRADE_TIMES; measurements only). */
    static final boolean TIMES = System.getenv("RAYLAB_GRADE_TIMES") != null;

    /**
     * The modules a student process sees: those of a test JVM that runs student code
     * ({@link TestLauncher#CHILD_MODULES}) and {@code java.management}, whose thread clock is the
     * watchdog's CPU time in the sandbox, which mounts no /proc ({@code Watchdog.threadCpuNanos}).
     * It reads this JVM only: no attach, no heap, no remote connector ({@code jdk.attach},
     * {@code jdk.management} and {@code java.management.rmi} stay out), and the process holds
     * nothing of the grader's.
     */
    static final String STUDENT_PROCESS_MODULES = TestLauncher.CHILD_MODULES + ",java.management";

    /** The instructor's project root, absolute. */
    Path root() {
        return options.root().toAbsolutePath();
    }

    /** JVM options from an environment variable, split at spaces (measurements only: flags to compare). */
    static List<String> extraJvmOptions(String variable) {
        String v = System.getenv(variable);
        return v == null || v.isBlank() ? List.of() : List.of(v.trim().split("\\s+"));
    }

    /**
     * The class path of a trusted JVM from {@code trusted}: every entry but the libraries it does
     * not need (a test JVM: JUnit and Jackson; a render JVM: all the cache holds, which leaves the
     * build's own tools out, {@code GraderSetup.toolOfTheBuild}).
     */
    List<Path> trustedClassPath(List<Path> trusted, boolean render) {
        List<Path> cp = new ArrayList<>();
        for (Path p : trusted) {
            if (!setup.libraries.contains(p) || libraryFor(p, render)) {
                cp.add(p);
            }
        }
        return cp;
    }

    private static boolean libraryFor(Path lib, boolean render) {
        return render || lib.getFileName().toString().matches("\\d+-(junit|opentest4j|apiguardian|jackson).*");
    }

    /**
     * The student process's box: the student's classes of M, the public stubs of the other
     * student files and the public framework (as the starter has it); nothing else (no
     * reference, no test, no grader class).
     */
    Sandbox.Box studentBox(Assignment a, Path overlay, Path mdir) throws IOException {
        List<String> mine = a.files().stream().map(f -> GraderSetup.classPrefix(f.path())).toList();
        return sandbox.box(mdir, List.of(overlay, setup.publicStubs, setup.publicFramework), (entry, rel) ->
                !entry.equals(setup.publicStubs) || mine.stream().noneMatch(x -> GraderSetup.isClassOf(rel, x)));
    }

    /** How the grader's process starts the student process in {@code box}, with a CPU budget per call. */
    StudentProcess.Config studentConfig(Assignment a, Sandbox.Box box, Path overlay, long budgetMillis, int heapMb)
            throws IOException {
        Set<String> students = new TreeSet<>();
        try (Stream<Path> s = Files.walk(overlay)) {
            for (Path p : (Iterable<Path>) s.filter(f -> f.toString().endsWith(".class"))::iterator) {
                String rel = overlay.relativize(p).toString().replace('\\', '/');
                students.add(GraderSetup.outer(rel.substring(0, rel.length() - 6).replace('/', '.')));
            }
        }
        List<String> cmd = new ArrayList<>(box.wrapper());
        // The protocol on file descriptors of its own: the JVM's output and the student's raw
        // writes to 1 and 2 go to the stderr file (StudentServer.CHANNEL_WRAPPER).
        cmd.addAll(StudentServer.CHANNEL_WRAPPER);
        cmd.addAll(List.of(JavaBuild.javaExecutable(),
                StudentServer.CHANNEL_JVM_OPTION, "-Xmx" + heapMb + "m",
                "-Xss4m", "-XX:+ExitOnOutOfMemoryError", "-Djava.awt.headless=true",
                "-XX:+DisableAttachMechanism", "-XX:-UsePerfData", "--limit-modules", STUDENT_PROCESS_MODULES,
                "-Dfile.encoding=UTF-8"));
        // C1 only: at 0.5 CPU, C2's compiler threads cost more than its faster code saves,
        // even in a render's hundreds of thousands of calls (grader/README.md).
        cmd.addAll(JavaBuild.QUICK_JVM);
        cmd.addAll(JvmOptions.student(heapMb));
        cmd.addAll(extraJvmOptions("RAYLAB_STUDENT_JVM_OPTS"));
        cmd.addAll(List.of("-cp", String.join(java.io.File.pathSeparator, box.classPath()),
                "raylab.remote.StudentServer", "--channel",
                // Stuck code is named after the watchdog's bound: a call of the reference takes far less.
                StudentServer.STUCK_AFTER, Long.toString(raylab.course.Watchdog.bound(0).toMillis())));
        for (String c : students) {
            cmd.add("--student");
            cmd.add(c);
        }
        return new StudentProcess.Config(cmd, box.run(), Set.copyOf(GraderSetup.servedClasses(a)), budgetMillis, 3);
    }

    /**
     * What one milestone's steps share once its code compiled.
     *
     * @param a       the milestone
     * @param dir     its work folder
     * @param overlay the student's compiled classes of it
     * @param trusted the grader's process's class path: M's stand-ins, the other milestones'
     *                references, the framework and the libraries
     */
    record Milestone(Assignment a, Path dir, Path overlay, List<Path> trusted) {
    }
}
