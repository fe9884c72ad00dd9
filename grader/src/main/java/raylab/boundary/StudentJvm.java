package raylab.boundary;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import raylab.course.JavaBuild;
import raylab.remote.StudentServer;
import raylab.remote.Wire;

/**
 * The life of one {@link StudentProcess}'s student JVM: its command line, its start (up to the
 * HELLO line), its streams, its end, and what its end means for the call it ended. At most
 * {@code maxRestarts} fresh JVMs follow the first; the {@link CallClock} measures each of them.
 * Not thread-safe: its {@link StudentProcess} holds the lock.
 */
public final class StudentJvm {
    private final StudentProcess.Config config;
    /** The student's time in calls and the watchdog that stops a call over its budget. */
    private final CallClock clock;
    /** The running JVM (null: none), its streams and the file its standard error goes to. */
    private Process proc;
    private DataInputStream in;
    private OutputStream out;
    private Path stderr;
    /** How often a JVM was started (those killed from outside not counted). */
    private int starts;
    /**
     * Whether a JVM of this process has said HELLO. Until one has, no code of the student's has
     * run (the server loads none before it), and the run folder holds nothing the student's code
     * left: a JVM that ends before its HELLO is then the grader's command, its sandbox or the
     * machine failing, never the student's code.
     */
    private boolean greeted;
    /** Why the first JVM did not start, once it failed twice: every later start fails so too. */
    private String cannotStart;

    StudentJvm(StudentProcess.Config config) {
        this.config = config;
        this.clock = new CallClock(() -> proc, config.callBudgetMillis());
    }

    CallClock clock() {
        return clock;
    }

    boolean running() {
        return proc != null;
    }

    /** The id of the current JVM (−1: none); read without the lock, for tests while a call runs. */
    long pid() {
        Process p = proc;
        return p == null ? -1 : p.pid();
    }

    int starts() {
        return starts;
    }

    /** Replies from the student JVM. */
    DataInputStream in() {
        return in;
    }

    /** Frames to the student JVM. */
    OutputStream out() {
        return out;
    }

    /** CPU time of the current JVM (0 if none runs). */
    long cpuNanos() {
        Process p = proc;
        return p == null ? 0 : CallClock.cpuNanos(p);
    }

    /**
     * Starts a fresh JVM and reads its HELLO line; fails with a {@link StudentTimeout} when the
     * student's restarts are used up, with a {@link StudentException} when a restart does not
     * start (what the student's code left in its run folder can stop it), and with a
     * {@link GradingFailure} when no JVM of this process has started yet and two in a row do not
     * (no code of the student's has run: the command, the sandbox or the machine failed).
     */
    void start() throws IOException {
        if (cannotStart != null) {
            throw new GradingFailure(cannotStart);
        }
        try {
            startOnce();
        } catch (NotStarted first) {
            if (greeted) {
                throw first.asStudents();
            }
            starts--;
            try {
                startOnce(); // once more: a fork or a mount that failed for a moment
            } catch (NotStarted again) {
                starts--;
                cannotStart = "the student process did not start (" + (again.why.isEmpty() ? "no HELLO line" : again.why)
                        + ") before any code of the student's ran in it: the grader's command, its sandbox or the"
                        + " machine failed, not the student's code";
                throw new GradingFailure(cannotStart);
            }
        }
        greeted = true;
    }

    /** A JVM that ended or said something else before its HELLO line, and the first line of its standard error. */
    private static final class NotStarted extends IOException {
        private static final long serialVersionUID = 1L;
        final String why;

        NotStarted(String why) {
            super(why);
            this.why = why;
        }

        StudentException asStudents() {
            return new StudentException("java.lang.Error", "the student process did not start"
                    + (why.isEmpty() ? "" : ": " + why), List.of(), "");
        }
    }

    private void startOnce() throws IOException {
        if (starts > config.maxRestarts()) {
            throw new StudentTimeout("your code was stopped " + starts + " times (too slow, or it crashed), so"
                    + " the grader does not run it again in this milestone");
        }
        starts++;
        stderr = Files.createTempFile("student", ".err");
        ProcessBuilder pb = new ProcessBuilder(config.command()).redirectError(stderr.toFile());
        if (config.directory() != null) {
            pb.directory(config.directory().toFile());
        }
        try {
            proc = pb.start();
        } catch (IOException e) {
            dead();
            throw new NotStarted("it cannot be run: " + e.getMessage());
        }
        in = new DataInputStream(new BufferedInputStream(proc.getInputStream(), 1 << 16));
        out = new BufferedOutputStream(proc.getOutputStream(), 1 << 16);
        // The HELLO line: anything else means the JVM did not start as a student server.
        ByteArrayOutputStream line = new ByteArrayOutputStream();
        clock.startBegins();
        try {
            for (int b; (b = in.read()) != '\n';) {
                if (b < 0 || line.size() > 200) {
                    String why = firstLineOfStderr();
                    dead();
                    throw new NotStarted(why);
                }
                line.write(b);
            }
        } finally {
            clock.startEnds();
        }
        if (!line.toString(StandardCharsets.US_ASCII).equals(Wire.HELLO)) {
            String why = firstLineOfStderr();
            dead();
            throw new NotStarted(why);
        }
    }

    private String firstLineOfStderr() {
        if (stderr == null) {
            return "";
        }
        try {
            String s = Files.readString(stderr);
            int nl = s.indexOf('\n');
            return (nl < 0 ? s : s.substring(0, nl)).strip();
        } catch (IOException e) {
            return "";
        }
    }

    /** Stops the JVM (if one runs) and forgets it: the next call starts a fresh one. */
    void dead() {
        Process p = proc;
        proc = null;
        clock.processEnded();
        if (p != null) {
            CallClock.kill(p);
            try {
                p.waitFor();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        if (stderr != null) {
            try {
                Files.deleteIfExists(stderr);
            } catch (IOException e) {
                // a temporary file
            }
        }
    }

    /**
     * The JVM broke off a call with {@code e}: stops it and returns why, as the student reads
     * it (too slow, out of memory, a malformed frame, ended), or a {@link KilledFromOutside}.
     */
    RuntimeException lost(IOException e) {
        boolean slow = clock.timedOut();
        String why = firstLineOfStderr();
        Process p = proc;
        boolean outOfMemory = false;
        boolean killed = false;
        if (p != null && !slow) {
            try {
                boolean ended = p.waitFor(2, TimeUnit.SECONDS);
                outOfMemory = ended && p.exitValue() == 3;
                // 128 + SIGKILL: the sandbox's shell and unshare pass the JVM's death on as their own.
                killed = ended && p.exitValue() == 128 + 9;
            } catch (InterruptedException ie) {
                Thread.currentThread().interrupt();
            }
        }
        dead();
        if (killed) {
            return new KilledFromOutside("SIGKILL" + (why.isEmpty() ? "" : ", " + why));
        }
        if (outOfMemory) {
            return new StudentException("java.lang.OutOfMemoryError", "your code ran out of memory (look for"
                    + " something that grows with every call, such as a list kept in a static field)", List.of(), "");
        }
        if (slow && clock.takeTestTimedOut()) {
            return new StudentTimeout("your code took longer than " + clock.testLimit() / 1e9 + " s in this test and was"
                    + " stopped (an endless loop?)");
        }
        if (slow) {
            return new StudentTimeout("your code took longer than " + config.callBudgetMillis() / 1000.0
                    + " s of CPU time for one call and was stopped (an endless loop?)");
        }
        if (e instanceof Wire.ProtocolException) {
            return new StudentException("java.lang.Error", "the student process sent a malformed frame ("
                    + e.getMessage() + ") and was stopped", List.of(), "");
        }
        return new StudentException("java.lang.Error", "the student process ended during the call"
                + (why.isEmpty() ? " (System.exit, running out of memory or a crash)" : ": " + why), List.of(), "");
    }

    /** A JVM killed from outside is not counted against the student's restarts. */
    void uncountStart() {
        starts--;
    }

    /**
     * The student JVM was killed, by a signal that neither the watchdog nor the student's own
     * JVM sent (the OOM killer, for memory taken elsewhere): not the student's doing.
     */
    static final class KilledFromOutside extends StudentTimeout {
        private static final long serialVersionUID = 1L;

        KilledFromOutside(String why) {
            super(why);
        }
    }

    /** Ends the JVM: its input closed, two seconds to exit, then stopped; the clock's watchdog ends. */
    void close() {
        clock.close();
        if (proc != null) {
            try {
                out.close();
                proc.waitFor(2, TimeUnit.SECONDS);
            } catch (IOException | InterruptedException e) {
                // stopped below
            }
            dead();
        }
    }

    /**
     * The JVM's own command for a student process: java, the class path, StudentServer, behind
     * {@link StudentServer#CHANNEL_WRAPPER} (the protocol on a channel of its own).
     */
    public static List<String> javaCommand(List<Path> classPath, int heapMb, List<String> studentClasses) {
        List<String> cmd = new ArrayList<>(StudentServer.CHANNEL_WRAPPER);
        cmd.addAll(List.of(JavaBuild.javaExecutable(),
                StudentServer.CHANNEL_JVM_OPTION, "-Xmx" + heapMb + "m", "-XX:+ExitOnOutOfMemoryError", "-Djava.awt.headless=true",
                "-XX:+DisableAttachMechanism", "-XX:-UsePerfData", "-Xss4m"));
        cmd.addAll(JavaBuild.QUICK_JVM); // as the grader's own student process (GradingRun.studentConfig)
        cmd.addAll(List.of("-cp", String.join(File.pathSeparator, classPath.stream().map(Path::toString).toList()),
                "raylab.remote.StudentServer", "--channel"));
        for (String c : studentClasses) {
            cmd.add("--student");
            cmd.add(c);
        }
        return cmd;
    }
}
