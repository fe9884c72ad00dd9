package raylab.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.TreeSet;


import raylab.course.Assignment;
import raylab.course.Assignments;
import raylab.course.JavaBuild;
import raylab.course.SourceRoots;

/**
 * The student's loop without Maven: after the first full build ({@code target/raylab.jar}), a
 * changed student file (one listed in an {@code assignment.json}) is compiled alone with
 * javax.tools against the built classes and put in {@code target/incremental}, which the launcher
 * puts before the jar on the class path. A change to any other source, or to pom.xml, still
 * takes the full Maven build (the launcher script does it when {@link Launch} exits with
 * {@link #FULL_BUILD}).
 *
 * <p>Which version of a file the overlay holds is written in {@code target/incremental/.stamps}
 * (size and modification time per source), so a file put back to an older time is compiled
 * again too.
 */
public final class Incremental {
    /** The exit status by which {@link Launch} asks the launcher script for a full Maven build. */
    public static final int FULL_BUILD = 100;

    /** What has to be done before running. */
    public record Plan(List<Path> compile, List<Path> needFullBuild) {
        public boolean upToDate() {
            return compile.isEmpty() && needFullBuild.isEmpty();
        }
    }

    private final Path root;
    private final Path built;
    private final Path overlay;

    /**
     * @param root    the project folder
     * @param built   the full build's output (its time says which sources it holds)
     * @param overlay where single compiled files go
     */
    public Incremental(Path root, Path built, Path overlay) {
        this.root = root.toAbsolutePath().normalize();
        this.built = built;
        this.overlay = overlay;
    }

    /** The project's layout: target/raylab.jar and target/incremental. */
    public static Incremental of(Path root) {
        return new Incremental(root, root.resolve("target/raylab.jar"), root.resolve("target/incremental"));
    }

    public Path overlay() {
        return overlay;
    }

    /** The student files of every milestone, as absolute paths (empty without assignments). */
    public List<Path> studentFiles() {
        TreeSet<Path> files = new TreeSet<>();
        try {
            for (Assignment a : Assignments.load(root).all()) {
                for (Assignment.StudentFile f : a.files()) {
                    files.add(root.resolve(f.path()).normalize());
                }
            }
        } catch (IOException | RuntimeException e) {
            // No (readable) assignments: no file is a student file, every change takes the full build.
        }
        return List.copyOf(files);
    }

    /** The sources changed since the full build or the last compile, split into student files and the rest. */
    public Plan plan() throws IOException {
        long builtAt = Files.getLastModifiedTime(built).toMillis();
        Properties stamps = readStamps();
        List<Path> student = null; // read only when something changed
        List<Path> compile = new ArrayList<>();
        List<Path> full = new ArrayList<>();
        Path pom = root.resolve("pom.xml");
        if (Files.isRegularFile(pom) && Files.getLastModifiedTime(pom).toMillis() > builtAt) {
            full.add(pom);
        }
        List<Path> sources = new ArrayList<>();
        for (String r : SourceRoots.all()) { // the lab's, and in the instructor's tree the other modules'
            if (Files.isDirectory(root.resolve(r))) {
                try (var s = Files.walk(root.resolve(r))) {
                    s.filter(Files::isRegularFile).sorted().forEach(sources::add);
                }
            }
        }
        for (Path p : sources) {
            String key = key(p);
            String stamp = stamps.getProperty(key);
            boolean changed = stamp != null ? !stamp.equals(stamp(p)) : Files.getLastModifiedTime(p).toMillis() > builtAt;
            if (!changed) {
                continue;
            }
            if (student == null) {
                student = studentFiles();
            }
            if (student.contains(p.toAbsolutePath().normalize())) {
                compile.add(p);
            } else {
                full.add(p);
            }
        }
        return new Plan(compile, full);
    }

    /** Compiles {@code sources} against the overlay and {@code classPath} into the overlay, and stamps them. */
    public JavaBuild.Result compile(List<Path> sources, List<Path> classPath) throws IOException {
        List<Path> cp = new ArrayList<>();
        cp.add(overlay);
        classPath.stream().filter(p -> !p.toAbsolutePath().normalize().equals(overlay.toAbsolutePath().normalize()))
                .forEach(cp::add);
        List<JavaBuild.Problem> errors = JavaBuild.Problem.of(JavaBuild.javac(sources, cp, overlay,
                List.of("-implicit:none", "-g")));
        if (errors.isEmpty()) {
            Properties stamps = readStamps();
            for (Path p : sources) {
                stamps.setProperty(key(p), stamp(p));
            }
            writeStamps(stamps);
            return new JavaBuild.Result(true, List.of());
        }
        return new JavaBuild.Result(false, errors);
    }

    /** Plans and, when only student files changed, compiles them: null when a full build is needed. */
    public JavaBuild.Result update(List<Path> classPath) throws IOException {
        Plan plan = plan();
        if (!plan.needFullBuild().isEmpty()) {
            return null;
        }
        return plan.compile().isEmpty() ? new JavaBuild.Result(true, List.of()) : compile(plan.compile(), classPath);
    }

    private String key(Path p) {
        return root.relativize(p.toAbsolutePath().normalize()).toString().replace('\\', '/');
    }

    private static String stamp(Path p) throws IOException {
        FileTime t = Files.getLastModifiedTime(p);
        return Files.size(p) + "@" + t.toMillis();
    }

    private Properties readStamps() throws IOException {
        Properties p = new Properties();
        Path f = overlay.resolve(".stamps");
        if (Files.isRegularFile(f)) {
            try (InputStream in = Files.newInputStream(f)) {
                p.load(in);
            }
        }
        return p;
    }

    private void writeStamps(Properties p) throws IOException {
        Path f = overlay.resolve(".stamps");
        Path tmp = overlay.resolve(".stamps.tmp");
        try (OutputStream out = Files.newOutputStream(tmp)) {
            p.store(out, "sources compiled into this folder: size@mtime");
        }
        Files.move(tmp, f, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
    }
}
