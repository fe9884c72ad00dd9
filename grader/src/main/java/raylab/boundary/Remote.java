package raylab.boundary;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.Set;

/**
 * What a stand-in's graded method calls: the student process of this JVM. The process is
 * described by the file named in the system property {@code raylab.boundary} (a properties file:
 * {@code budget} ms per call, {@code restarts}, {@code served} class names separated by commas,
 * {@code dir}, and the command as {@code cmd.0}, {@code cmd.1}, ...) and started on the first call.
 */
public final class Remote {
    private static StudentProcess process;
    private static Speculation speculation;

    private Remote() {
    }

    /** Calls the student's method {@code cls.method} on {@code self} (null for a static method). */
    public static Object call(Object self, String cls, String method, Object[] args) {
        Speculation s = speculation;
        return s != null ? s.call(self, cls, method, args) : process().call(cls, method, self, args);
    }

    /** Batches this JVM's calls through {@code s} from now on (null: one call at a time). */
    public static synchronized void speculate(Speculation s) {
        speculation = s;
    }

    /** The student process of this JVM. */
    public static synchronized StudentProcess process() {
        if (process == null) {
            process = new StudentProcess(config());
            Runtime.getRuntime().addShutdownHook(new Thread(process::close));
        }
        return process;
    }

    /**
     * The student's own time in this JVM's student process so far
     * ({@link StudentProcess#studentTimeNanos}); 0 before it exists.
     */
    public static synchronized long studentNanos() {
        return process == null ? 0 : process.studentTimeNanos();
    }

    /** A test begins with a limit of {@code limitNanos} of the student's time ({@link StudentProcess#startTest}). */
    public static void startTest(long limitNanos) {
        process().startTest(limitNanos);
    }

    /** The CPU time of this JVM's student processes so far ({@link StudentProcess#studentCpuNanos}); 0 before one exists. */
    public static synchronized long studentCpuNanos() {
        return process == null ? 0 : process.studentCpuNanos();
    }

    /** Starts the student process now (before any test's time limit runs). */
    public static void warmUp() {
        process().ensureStarted();
    }

    /**
     * Ends this JVM's student process (if one was started) and describes the next one by
     * {@code configFile}, started now: the grader runs its visible and then its hidden tests in
     * one JVM, each group with a student process of its own, so nothing the hidden tests pass to
     * student code can reach a visible test's output.
     */
    public static synchronized void switchTo(Path configFile) {
        if (process != null) {
            process.close();
            process = null;
        }
        System.setProperty("raylab.boundary", configFile.toString());
        warmUp();
    }

    /** Uses {@code p} as this JVM's student process (tests, benchmarks). */
    public static synchronized void use(StudentProcess p) {
        process = p;
    }

    static StudentProcess.Config config() {
        String file = System.getProperty("raylab.boundary");
        if (file == null) {
            throw new IllegalStateException("no student process: the system property raylab.boundary is not set");
        }
        Properties p = new Properties();
        try (InputStream in = Files.newInputStream(Path.of(file))) {
            p.load(in);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read " + file + ": " + e.getMessage());
        }
        List<String> cmd = new ArrayList<>();
        for (int i = 0; p.getProperty("cmd." + i) != null; i++) {
            cmd.add(p.getProperty("cmd." + i));
        }
        String dir = p.getProperty("dir", "");
        return new StudentProcess.Config(cmd, dir.isEmpty() ? null : Path.of(dir),
                Set.of(p.getProperty("served", "").split(",")), Long.parseLong(p.getProperty("budget", "10000")),
                Integer.parseInt(p.getProperty("restarts", "3")));
    }

    /** Writes a configuration file for {@link #config}. */
    public static void writeConfig(Path file, StudentProcess.Config c) throws IOException {
        Properties p = new Properties();
        p.setProperty("budget", Long.toString(c.callBudgetMillis()));
        p.setProperty("restarts", Integer.toString(c.maxRestarts()));
        p.setProperty("served", String.join(",", c.served()));
        p.setProperty("dir", c.directory() == null ? "" : c.directory().toString());
        for (int i = 0; i < c.command().size(); i++) {
            p.setProperty("cmd." + i, c.command().get(i));
        }
        try (var out = Files.newOutputStream(file)) {
            p.store(out, "raylab student process");
        }
    }
}
