package raylab.boundary;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

/**
 * The clock of a {@link StudentProcess}'s calls and its CPU watchdog, one job with its state in
 * one place: a thread that looks at the current student process every 25 ms, measures each
 * outermost call (its CPU time from {@code /proc/PID/stat}; its wall time less the time it waited
 * for a CPU, {@code /proc/PID/task/TID/schedstat}, or for the grader's answers), sums the
 * student's own time, and kills the process of a call over its budget or a test over its limit.
 * The grader's own time answering a call's questions is billed here too, with its bound.
 */
final class CallClock implements AutoCloseable {
    private final Supplier<Process> process;
    private final long callBudgetMillis;
    private final Thread watchdog;
    /** The number of the outermost call running (−1: none), for the watchdog. */
    private volatile long callSeq = -1;
    private long callCount;
    private volatile long callStartWall;
    private volatile boolean timedOut;
    private volatile boolean starting;
    private volatile boolean closed;
    /** Wall time the grader spent answering the current call's questions (not the student's time). */
    private volatile long trustedWall;
    /** When the grader began the answer it is working on ({@link System#nanoTime}), 0: none. */
    private volatile long answering;
    /** CPU time of the grader's thread answering the current call's questions. */
    private long trustedCpu;
    /** The current process's CPU time as the watchdog last read it, and that of the processes that ended. */
    private volatile long sampledCpu;
    private long endedCpu;
    /**
     * The student's own time in calls so far, as the watchdog measured it (each call's CPU time,
     * or its wall time less the time it waited for a CPU or for the grader, whichever is more).
     */
    private volatile long studentTime;
    /** The student's time when the current test began, and the test's limit in it (0: none). */
    private volatile long testStart;
    private volatile long testLimit;
    private volatile boolean testTimedOut;

    /**
     * @param process          the student process running now (null: none)
     * @param callBudgetMillis the CPU time one call may take
     */
    CallClock(Supplier<Process> process, long callBudgetMillis) {
        this.process = process;
        this.callBudgetMillis = callBudgetMillis;
        watchdog = new Thread(this::watch, "student-process-watchdog");
        watchdog.setDaemon(true);
        watchdog.start();
    }

    /** A student process starts: its start is watched as a call, but it is not the student's time. */
    void startBegins() {
        starting = true;
        callStartWall = System.nanoTime();
        callSeq = ++callCount;
        timedOut = false;
    }

    void startEnds() {
        callSeq = -1;
        starting = false;
    }

    /** An outermost call begins: its time and the grader's time answering it start at 0. */
    void callBegins() {
        timedOut = false;
        callStartWall = System.nanoTime();
        trustedWall = 0;
        trustedCpu = 0;
        answering = 0;
        callSeq = ++callCount;
    }

    /** The outermost call ended: nothing is watched until the next. */
    void callEnds() {
        callSeq = -1;
    }

    /** Whether the watchdog stopped the current call (over its budget, or over its test's limit). */
    boolean timedOut() {
        return timedOut;
    }

    /** Whether it was the test's limit that stopped it; says so once. */
    boolean takeTestTimedOut() {
        if (!testTimedOut) {
            return false;
        }
        testTimedOut = false;
        return true;
    }

    /** The current test's limit in the student's time (ns; 0: none). */
    long testLimit() {
        return testLimit;
    }

    /** The grader begins answering a question of the current call (its time is not the student's). */
    void answerBegins() {
        if (answering == 0) {
            answering = System.nanoTime();
        }
    }

    /** The bound of the grader's CPU time answering one call's questions (ns): the call's budget, at least 1 s. */
    long graderBoundNanos() {
        return Math.max(1_000, callBudgetMillis) * 1_000_000L;
    }

    /**
     * Adds the time since {@code wall0} and this thread's CPU time since {@code cpu0} to the
     * grader's time answering the current call's questions; true when that is over
     * {@link #graderBoundNanos}.
     */
    boolean bill(long wall0, long cpu0) {
        answering = 0;
        trustedWall += System.nanoTime() - wall0;
        trustedCpu += Math.max(0, threadCpuNanos() - cpu0);
        return trustedCpu > graderBoundNanos();
    }

    /** The current process ended: its CPU time as last read is kept. */
    void processEnded() {
        endedCpu += sampledCpu;
        sampledCpu = 0;
    }

    /** CPU time of every student process so far (ns), the current one ({@code running}) as last read. */
    long studentCpuNanos(boolean running) {
        return endedCpu + (running ? sampledCpu : 0);
    }

    /** The student's own time in calls so far (ns; see {@link StudentProcess#studentTimeNanos}). */
    long studentTimeNanos() {
        return studentTime;
    }

    /** A test begins, with this limit in the student's time (ns; 0: none). */
    void startTest(long limitNanos) {
        testStart = studentTime;
        testLimit = limitNanos;
    }

    @Override
    public void close() {
        closed = true;
        watchdog.interrupt();
    }

    /**
     * This thread's CPU time in ns, or 0 in a JVM without the java.management module (a test JVM
     * started with --limit-modules: no bound on the grader's time there, which grades nothing).
     */
    static long threadCpuNanos() {
        try {
            return ThreadCpu.BEAN.getCurrentThreadCpuTime();
        } catch (LinkageError noManagement) {
            return 0;
        }
    }

    /** Loaded on first use, so that this class loads without java.management. */
    private static final class ThreadCpu {
        static final java.lang.management.ThreadMXBean BEAN = java.lang.management.ManagementFactory.getThreadMXBean();
    }

    private void watch() {
        long seen = -1;
        long baseline = 0;
        long waitedBase = 0;
        long ownBefore = 0;
        long ownNow = 0;
        while (!closed) {
            try {
                Thread.sleep(25);
            } catch (InterruptedException e) {
                return;
            }
            long call = callSeq;
            Process p = process.get();
            if (call < 0 || p == null) {
                continue;
            }
            // The CPU time at the first look at a call is its baseline (at most one tick late):
            // reading /proc at every call would cost more than the call.
            long cpu = watchedCpuNanos(p);
            sampledCpu = cpu;
            if (call != seen) {
                seen = call;
                baseline = starting ? 0 : cpu;
                waitedBase = waited;
                ownBefore += ownNow;
                ownNow = 0;
                continue;
            }
            long used = cpu - baseline;
            // Wall time too, more generously: a student process that sleeps uses no CPU. But not
            // the time it waited for a CPU (the machine's load) or for the grader's answers.
            long since = answering;
            long wall = System.nanoTime() - callStartWall - trustedWall - (since == 0 ? 0 : System.nanoTime() - since);
            long own = wall - Math.min(Math.max(0, wall), waited - waitedBase);
            if (!starting) { // a JVM's start is not the student's time
                ownNow = Math.max(ownNow, Math.max(own, used));
                studentTime = ownBefore + ownNow;
            }
            long budget = Math.max(starting ? 30_000 : 0, callBudgetMillis) * 1_000_000L;
            if (used > budget || own > 3 * budget + 5_000_000_000L) {
                timedOut = true;
                kill(p);
            } else if (testLimit > 0 && studentTime - testStart > testLimit) {
                testTimedOut = true;
                timedOut = true;
                kill(p);
            }
        }
    }

    static void kill(Process p) {
        p.descendants().forEach(ProcessHandle::destroyForcibly);
        p.destroyForcibly();
    }

    private Process watched;
    private List<Long> watchedPids = List.of();
    private long pidsListed;
    /** Time the watched processes' threads waited for a CPU, summed since the watchdog began (ns). */
    private long waited;
    private final Map<Long, Long> runDelays = new HashMap<>();
    private long delaysRead;

    /**
     * As {@link #cpuNanos}, with the process's descendants listed again only every second:
     * listing them reads every process of the machine from /proc. Every quarter second it also
     * adds to {@link #waited} how long their threads waited on a run queue since the last look.
     */
    private long watchedCpuNanos(Process p) {
        long now = System.nanoTime();
        if (p != watched || now - pidsListed > 1_000_000_000L) {
            watched = p;
            pidsListed = now;
            List<Long> pids = new ArrayList<>();
            pids.add(p.pid());
            p.descendants().forEach(d -> pids.add(d.pid()));
            watchedPids = pids;
        }
        long t = 0;
        for (long pid : watchedPids) {
            t += ticks(pid);
        }
        if (now - delaysRead > 250_000_000L) {
            delaysRead = now;
            waited += runDelaySince(watchedPids, runDelays);
        }
        return t * 10_000_000L;
    }

    /**
     * Nanoseconds the threads of {@code pids} waited on a run queue (runnable, no CPU free) since
     * {@code last} (thread id to its total at the last look, updated; a new thread counts from
     * its start). 0 where the kernel does not keep schedstat.
     */
    static long runDelaySince(List<Long> pids, Map<Long, Long> last) {
        long added = 0;
        Map<Long, Long> now = new HashMap<>();
        for (long pid : pids) {
            java.io.File[] tasks = new java.io.File("/proc/" + pid + "/task").listFiles();
            if (tasks == null) {
                continue;
            }
            for (java.io.File task : tasks) {
                try {
                    long tid = Long.parseLong(task.getName());
                    String[] f = Files.readString(task.toPath().resolve("schedstat")).trim().split(" ");
                    long delay = Long.parseLong(f[1]);
                    now.put(tid, delay);
                    added += Math.max(0, delay - last.getOrDefault(tid, 0L));
                } catch (IOException | RuntimeException e) {
                    // the thread ended, or no schedstat
                }
            }
        }
        last.clear();
        last.putAll(now);
        return added;
    }

    /** CPU time (user + system) of the process and its descendants, from /proc; 0 where unknown. */
    static long cpuNanos(Process p) {
        long ticks = ticks(p.pid());
        for (ProcessHandle d : (Iterable<ProcessHandle>) p.descendants()::iterator) {
            ticks += ticks(d.pid());
        }
        return ticks * 10_000_000L; // USER_HZ is 100 on Linux
    }

    private static long ticks(long pid) {
        try {
            String s = Files.readString(Path.of("/proc", Long.toString(pid), "stat"));
            String[] f = s.substring(s.lastIndexOf(')') + 2).split(" ");
            return Long.parseLong(f[11]) + Long.parseLong(f[12]);
        } catch (IOException | RuntimeException e) {
            return 0;
        }
    }

}
