package raylab.boundary;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;

import raylab.course.JavaBuild;
import raylab.light.PointLight;
import raylab.material.Material;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.remote.StudentServer;
import raylab.remote.Wire;
import raylab.shading.ShadingPoint;
import raylab.surface.Surface;

/**
 * The grader's end of the process boundary: starts the student process (a
 * {@link raylab.remote.StudentServer} behind the sandbox's command), calls the student's methods
 * in it and answers its callbacks. Each call has a CPU-time budget measured on the student
 * process (its own and its descendants' user and system time from {@code /proc/PID/stat}); a
 * call over it, or a crash, stops the process, the call fails with a {@link StudentTimeout} or a
 * {@link StudentException}, and the next call starts a fresh process, at most
 * {@code maxRestarts} times.
 *
 * <p>Load is never the student's: a call's wall time counts only the time its process neither
 * ran nor waited for a CPU ({@code /proc/PID/task/TID/schedstat}) and the grader was not
 * answering its questions, so that only code that sleeps or blocks runs into the wall limit
 * (3 × budget + 5 s). The grader's own time answering one call's questions has a bound of its
 * own (its thread's CPU time, the call's budget): student code cannot make it work without
 * limit. A process killed by something other than this class (the kernel's OOM killer, for
 * memory taken elsewhere) is not the student's doing: the call is made again in a fresh
 * process, and if that is killed too, the call fails with a {@link GradingFailure}.
 */
public final class StudentProcess implements AutoCloseable {
    /** How the student process is started: its command line, and which classes it serves. */
    public record Config(List<String> command, Path directory, Set<String> served, long callBudgetMillis,
            int maxRestarts) {
    }

    private final Config config;
    private Consumer<String> output = System.out::print;
    private Process proc;
    private DataInputStream in;
    private OutputStream out;
    private Path stderr;
    private int starts;
    private final Map<Object, Integer> handleOf = new IdentityHashMap<>();
    private final Map<Integer, Object> byHandle = new HashMap<>();
    private int nextHandle = 1;
    private final Map<String, Integer> methodIds = new HashMap<>();
    private final Map<Object, Integer> ephemeralOf = new IdentityHashMap<>();
    private final List<Object> ephemeral = new ArrayList<>();
    private int depth;
    private int nextConv = 1;
    private final Refs refs = new Refs();
    private final Wire.Out buf = new Wire.Out();
    private RuntimeException pendingFailure;
    private long calls;
    /** Milliseconds added to each answer of the grader's (-Draylab.boundary.slowGrader=MS: tests of a slow grader). */
    private static final long SLOW_GRADER_MILLIS = Long.getLong("raylab.boundary.slowGrader", 0);
    /** The student's time in calls and the watchdog that stops a call over its budget. */
    private final CallClock clock;
    /** Run before each frame of an outermost call (a render's deadline), or null. */
    private Runnable beforeFrame;

    public StudentProcess(Config config) {
        this.config = config;
        this.clock = new CallClock(() -> proc, config.callBudgetMillis());
    }

    /** Where the student's captured output goes (default: this JVM's standard output). */
    public void output(Consumer<String> sink) {
        this.output = sink;
    }

    /** How many calls were made (batched calls counted one by one). */
    public synchronized long calls() {
        return calls;
    }

    /** The id of the current student process (−1: none); not synchronized, for tests while a call runs. */
    long pid() {
        Process p = proc;
        return p == null ? -1 : p.pid();
    }

    /** How often a student process was started. */
    public synchronized int starts() {
        return starts;
    }

    /**
     * CPU time of every student process this object started, so far (the current one as the
     * watchdog last read it, at most a few ticks behind), in ns.
     */
    public synchronized long studentCpuNanos() {
        return clock.studentCpuNanos(proc != null);
    }

    /**
     * The student's own time in calls so far (ns): for each call its CPU time, or its wall time
     * less the time it waited for a CPU or for the grader's answers, whichever is more; at most a
     * quarter of a second behind. What a test's time limit is measured in.
     */
    public long studentTimeNanos() {
        return clock.studentTimeNanos();
    }

    /**
     * A test begins: from now on its calls together may take {@code limitNanos} of the student's
     * time ({@link #studentTimeNanos}); the call that passes it is stopped ("... in this test").
     * 0: no limit beyond each call's.
     */
    public void startTest(long limitNanos) {
        clock.startTest(limitNanos);
    }

    /**
     * A check run before each frame of an outermost call is sent (null: none): what it throws
     * ends the call there, the process ready for the next. The renders check their deadline so,
     * inside a band as well as between bands.
     */
    public synchronized void beforeEachFrame(Runnable check) {
        this.beforeFrame = check;
    }

    private void checkpoint() {
        if (depth == 1 && beforeFrame != null) {
            beforeFrame.run();
        }
    }

    /** CPU time of the current student process (0 if none runs), for measurements. */
    public static long cpuNanosOf(StudentProcess s) {
        Process p = s.proc;
        return p == null ? 0 : CallClock.cpuNanos(p);
    }

    /** CPU time (user + system) of the process and its descendants, from /proc; 0 where unknown. */
    public static long cpuNanos(Process p) {
        return CallClock.cpuNanos(p);
    }

    /** Starts the student process if none is running (a failure shows at the next call). */
    public synchronized void ensureStarted() {
        if (proc == null) {
            try {
                start();
            } catch (IOException | RuntimeException e) {
                dead();
            }
        }
    }

    private void start() throws IOException {
        if (starts > config.maxRestarts()) {
            throw new StudentTimeout("your code was stopped " + starts + " times (too slow, or it crashed), so"
                    + " the grader does not run it again in this milestone");
        }
        starts++;
        handleOf.clear();
        byHandle.clear();
        methodIds.clear();
        recentIds.clear();
        stderr = Files.createTempFile("student", ".err");
        ProcessBuilder pb = new ProcessBuilder(config.command()).redirectError(stderr.toFile());
        if (config.directory() != null) {
            pb.directory(config.directory().toFile());
        }
        proc = pb.start();
        InputStream raw = proc.getInputStream();
        in = new DataInputStream(new BufferedInputStream(raw, 1 << 16));
        out = new BufferedOutputStream(proc.getOutputStream(), 1 << 16);
        // The HELLO line: anything else means the JVM did not start as a student server.
        ByteArrayOutputStream line = new ByteArrayOutputStream();
        clock.startBegins();
        try {
            for (int b; (b = in.read()) != '\n';) {
                if (b < 0 || line.size() > 200) {
                    String why = firstLine(stderr);
                    dead();
                    throw new StudentException("java.lang.Error", "the student process did not start"
                            + (why.isEmpty() ? "" : ": " + why), List.of(), "");
                }
                line.write(b);
            }
        } finally {
            clock.startEnds();
        }
        if (!line.toString(StandardCharsets.US_ASCII).equals(Wire.HELLO)) {
            dead();
            throw new StudentException("java.lang.Error", "the student process did not start", List.of(), "");
        }
    }

    private static String firstLine(Path f) {
        try {
            String s = Files.readString(f);
            int nl = s.indexOf('\n');
            return (nl < 0 ? s : s.substring(0, nl)).strip();
        } catch (IOException e) {
            return "";
        }
    }

    private void dead() {
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
     * Calls the student's {@code cls.name} on {@code target} (null: static) and returns its result.
     * The call goes as a {@link #multi} frame of one call, with its questions to the grader's
     * surfaces and materials sent back and answered as in a batched render: a test's call and a
     * render's look the same inside the student's process but for their arguments (issue 35).
     */
    public synchronized Object call(String cls, String name, Object target, Object... args) {
        Object[] before = new Object[args.length];
        for (int i = 0; i < args.length; i++) {
            before[i] = args[i] instanceof IntersectionRecord r ? Wire.copyRecord(r) : args[i];
        }
        MultiCall c = new MultiCall(cls, name, target, before, List.of());
        multi(List.of(c));
        if (c.after != null) {
            for (int i = 0; i < args.length; i++) {
                if (c.after[i] != null && args[i] instanceof IntersectionRecord r) {
                    r.copyFrom(c.after[i]);
                    r.tests = c.after[i].tests;
                }
            }
        }
        if (c.thrown != null) {
            throw c.thrown;
        }
        return c.result;
    }

    /**
     * One call of a {@link #multi} frame: the method, its target and arguments (records as they
     * are before the call; not changed by it), the callbacks it is expected to ask with their
     * answers (the grader's own, never a prediction); and after the call its result or exception
     * and the record arguments as the student's code left them.
     */
    public static final class MultiCall {
        final String cls;
        final String name;
        final Object target;
        final Object[] args;
        final List<Answered> answers;
        Object result;
        RuntimeException thrown;
        /** After the call: each record argument as the student's code left it (null for other arguments). */
        IntersectionRecord[] after;
        /** The grader's answers to questions the call sent back: [question, answer] payloads; null: none. */
        List<byte[][]> truths;
        /** Whether its questions are asked as callbacks (one of them could not be answered later). */
        boolean live;

        public MultiCall(String cls, String name, Object target, Object[] args, List<Answered> answers) {
            this.cls = cls;
            this.name = name;
            this.target = target;
            this.args = args;
            this.answers = answers;
        }

        public Object result() {
            return result;
        }

        public RuntimeException thrown() {
            return thrown;
        }

        public IntersectionRecord[] after() {
            return after;
        }
    }

    /**
     * A callback answered in advance: the grader's object asked, the operation, the arguments (a
     * record as it is before the question), the answer and the record arguments after it.
     */
    public record Answered(Object target, byte op, Object[] args, Object result, Object[] after) {
    }

    /**
     * Frames of one {@link #multi} in which questions to the grader's surfaces and materials that
     * were not answered in advance come back with the calls (answered, they go out again with the
     * calls that asked them); after them, such questions are callbacks.
     */
    static final int DEFERRED_ROUNDS = 4;

    /**
     * Many calls in one frame each way ({@link Wire#MULTI}). A question to the grader's surfaces
     * or materials that was not answered in advance comes back with its call, which is sent again
     * with the grader's answer (up to {@link #DEFERRED_ROUNDS} frames); other questions, and all
     * after those frames, are answered as they come. Each call's outcome is set on it, exactly as
     * if every question had been answered as it came: a question's answer is the grader's own,
     * whenever it is given.
     */
    public synchronized void multi(List<MultiCall> batch) {
        run(() -> {
            calls += batch.size();
            List<MultiCall> open = batch;
            for (int round = 0; !open.isEmpty(); round++) {
                open = multiRound(open, round < DEFERRED_ROUNDS);
            }
            return null;
        });
    }

    /**
     * Whether argument {@code b} of a call in a MULTI frame goes as {@link Wire#AS_BEFORE} after
     * {@code a}, the previous call's at the same place: a ray or a record equal bit for bit, or
     * the same object (a value, a light, or an object of the grader's or the student's) except a
     * shading point, which holds the answers of its own call.
     */
    private static boolean asBefore(Object a, Object b) {
        if (a == b) {
            return !(b instanceof ShadingPoint) && !(b instanceof IntersectionRecord);
        }
        return Wire.asBefore(a, b);
    }

    /** One MULTI frame each way; returns the calls sent back with questions, now answered. */
    private List<MultiCall> multiRound(List<MultiCall> batch, boolean defer) throws IOException {
        checkpoint();
        buf.reset();
        buf.writeInt(batch.size());
        Wire.Out q = new Wire.Out();
        Wire.Out a = new Wire.Out();
        Object[] previous = new Object[0];
        for (MultiCall c : batch) {
            buf.writeBoolean(defer && !c.live);
            buf.writeInt(method(c.cls, c.name, c.args.length));
            Wire.writeValue(buf, c.target, refs);
            buf.writeInt(c.args.length);
            for (int j = 0; j < c.args.length; j++) {
                // The ray of a pixel goes to every surface, and a record a surface missed to the next.
                if (j < previous.length && asBefore(previous[j], c.args[j])) {
                    buf.writeByte(Wire.AS_BEFORE);
                } else {
                    Wire.writeValue(buf, c.args[j], refs);
                }
            }
            previous = c.args;
            int truths = c.truths == null ? 0 : c.truths.size();
            // No answer given in advance is a prediction: every one is the grader's own, so none
            // is to be reported as used (grader/README.md, "What crosses the boundary").
            buf.writeInt(0);
            buf.writeInt(c.answers.size() + truths);
            for (Answered an : c.answers) {
                q.reset();
                q.writeInt(ephemeral(an.target()));
                q.writeByte(an.op());
                q.writeInt(an.args().length);
                for (Object x : an.args()) {
                    Wire.writeValue(q, x, asStudent);
                }
                buf.writeBytes(q);
                a.reset();
                Wire.writeValue(a, an.result(), refs);
                for (Object x : an.after()) {
                    if (x instanceof IntersectionRecord r) {
                        Wire.writeRecord(a, r, refs);
                    }
                }
                buf.writeBytes(a);
            }
            for (int t = 0; t < truths; t++) {
                buf.writeBytes(c.truths.get(t)[0]);
                buf.writeBytes(c.truths.get(t)[1]);
            }
        }
        int conv = nextConv++;
        Wire.writeFrame(out, Wire.MULTI, conv, buf);
        out.flush();
        Wire.Frame f = await(conv, Wire.MULTI_RETURN);
        Wire.In in = f.in();
        multiBytes += buf.size() + in.remaining();
        int n = in.readInt();
        if (n != batch.size()) {
            throw new Wire.ProtocolException("answered " + n + " of " + batch.size() + " calls");
        }
        List<MultiCall> again = new ArrayList<>();
        List<List<byte[]>> asked = new ArrayList<>();
        for (MultiCall c : batch) {
            byte status = in.readByte();
            if (status == 2) {
                int k = in.readInt();
                if (!defer || c.live || k < 1 || k > StudentServer.MAX_DEFERRED) {
                    throw new Wire.ProtocolException("questions sent back where none may be");
                }
                List<byte[]> questions = new ArrayList<>(k);
                for (int i = 0; i < k; i++) {
                    questions.add(in.readBytes());
                }
                again.add(c);
                asked.add(questions);
                continue;
            }
            if (status == 0) {
                c.result = Wire.readValue(in, refs);
                c.after = new IntersectionRecord[c.args.length];
                for (int j = 0; j < c.args.length; j++) {
                    if (c.args[j] instanceof IntersectionRecord r) {
                        byte tag = in.readByte();
                        // A record left as it was sent is that record (never changed), its
                        // material the surface's as for a record read back.
                        c.after[j] = r;
                        if (tag == Wire.RECORD) {
                            c.after[j] = Wire.copyRecord(r);
                            Wire.readRecordInto(in, c.after[j], refs);
                        } else if (tag != Wire.AS_BEFORE) {
                            throw new Wire.ProtocolException("bad record tag " + tag);
                        } else {
                            Material m = r.surface == null ? null : r.surface.material();
                            if (r.material != m) {
                                c.after[j] = Wire.copyRecord(r);
                                c.after[j].material = m;
                            }
                        }
                    }
                }
            } else if (status == 1) {
                c.thrown = throwable(in);
            } else {
                throw new Wire.ProtocolException("bad call status " + status);
            }
            // Answers are reported used only below the count of predicted ones, which is 0: a
            // report is a broken or forged reply, and nothing the reply says about itself counts.
            if (in.readInt() != 0) {
                throw new Wire.ProtocolException("reported answers used where none were predicted");
            }
        }
        output(in.readString());
        // Answered only now that the whole reply is read: an answer may itself call the student process.
        for (int i = 0; i < again.size(); i++) {
            MultiCall c = again.get(i);
            for (byte[] question : asked.get(i)) {
                byte[] answer = answerLater(question);
                deferredQuestions++;
                if (answer == null) {
                    c.live = true; // asked again as a callback, which reports what went wrong
                    continue;
                }
                if (c.truths == null) {
                    c.truths = new ArrayList<>();
                }
                if (c.truths.stream().noneMatch(t -> java.util.Arrays.equals(t[0], question))) {
                    c.truths.add(new byte[][] {question, answer});
                }
            }
        }
        return again;
    }

    private long deferredQuestions;
    private long multiBytes;

    /** Bytes of MULTI frames sent and received, for measurements. */
    public synchronized long multiBytes() {
        return multiBytes;
    }

    /** Questions answered after their call came back, for measurements. */
    public synchronized long deferredQuestions() {
        return deferredQuestions;
    }

    private void output(String s) {
        if (s != null && !s.isEmpty()) {
            output.accept(s);
        }
    }

    private void copyRecords(Wire.In in, Object[] args) throws IOException {
        for (Object a : args) {
            if (a instanceof IntersectionRecord r) {
                Wire.readRecordInto(in, r, refs);
            }
        }
    }

    private interface Body<T> {
        T run() throws IOException;
    }

    /**
     * The student process was killed, by a signal that neither the watchdog nor the student's
     * own JVM sent (the OOM killer, for memory taken elsewhere): not the student's doing.
     */
    private static final class KilledFromOutside extends StudentTimeout {
        private static final long serialVersionUID = 1L;

        KilledFromOutside(String why) {
            super(why);
        }
    }

    /**
     * Runs one call; an outermost call whose process was killed from outside is made once more
     * in a fresh process (its start not counted against the student), and if that is killed
     * too, fails with a {@link GradingFailure}.
     */
    private <T> T run(Body<T> body) {
        if (depth > 0) {
            return attempt(body);
        }
        try {
            return attempt(body);
        } catch (KilledFromOutside first) {
            starts--;
            try {
                return attempt(body);
            } catch (KilledFromOutside again) {
                starts--;
                throw new GradingFailure("the student process was killed twice during one call by something other than"
                        + " the grader or the student's code (" + again.getMessage() + "): the machine, probably its memory");
            }
        }
    }

    private <T> T attempt(Body<T> body) {
        boolean outer = depth == 0;
        try {
            if (proc == null) {
                start();
            }
            if (outer) {
                clock.callBegins();
            }
            depth++;
            try {
                return body.run();
            } finally {
                depth--;
            }
        } catch (IOException e) {
            boolean slow = clock.timedOut();
            String why = firstLine(stderr);
            Process p = proc;
            boolean outOfMemory = false;
            boolean killed = false;
            if (p != null && !slow) {
                try {
                    boolean ended = p.waitFor(2, java.util.concurrent.TimeUnit.SECONDS);
                    outOfMemory = ended && p.exitValue() == 3;
                    // 128 + SIGKILL: the sandbox's shell and unshare pass the JVM's death on as their own.
                    killed = ended && p.exitValue() == 128 + 9;
                } catch (InterruptedException ie) {
                    Thread.currentThread().interrupt();
                }
            }
            dead();
            if (killed) {
                throw new KilledFromOutside("SIGKILL" + (why.isEmpty() ? "" : ", " + why));
            }
            if (outOfMemory) {
                throw new StudentException("java.lang.OutOfMemoryError", "your code ran out of memory (look for"
                        + " something that grows with every call, such as a list kept in a static field)", List.of(), "");
            }
            if (slow && clock.takeTestTimedOut()) {
                throw new StudentTimeout("your code took longer than " + clock.testLimit() / 1e9 + " s in this test and was"
                        + " stopped (an endless loop?)");
            }
            if (slow) {
                throw new StudentTimeout("your code took longer than " + config.callBudgetMillis() / 1000.0
                        + " s of CPU time for one call and was stopped (an endless loop?)");
            }
            if (e instanceof Wire.ProtocolException) {
                throw new StudentException("java.lang.Error", "the student process sent a malformed frame ("
                        + e.getMessage() + ") and was stopped", List.of(), "");
            }
            throw new StudentException("java.lang.Error", "the student process ended during the call"
                    + (why.isEmpty() ? " (System.exit, running out of memory or a crash)" : ": " + why), List.of(), "");
        } finally {
            if (outer) {
                clock.callEnds();
                ephemeral.clear();
                ephemeralOf.clear();
                pendingFailure = null;
            }
        }
    }

    /** The ids of the methods asked for last. */
    private final RecentMethods<Integer> recentIds = new RecentMethods<>();

    private int method(String cls, String name, int arity) throws IOException {
        Integer id = recentIds.get(cls, name, arity);
        if (id == null) {
            id = methodId(cls, name, arity);
            recentIds.put(cls, name, arity, id);
        }
        return id;
    }

    private int methodId(String cls, String name, int arity) throws IOException {
        String key = cls + "#" + name + "#" + arity;
        Integer id = methodIds.get(key);
        if (id != null) {
            return id;
        }
        int m = methodIds.size() + 1;
        Wire.Out o = new Wire.Out();
        o.writeInt(m);
        o.writeString(cls);
        o.writeString(name);
        o.writeInt(arity);
        int conv = nextConv++;
        Wire.writeFrame(out, Wire.METHOD, conv, o);
        out.flush();
        await(conv, Wire.ACK);
        methodIds.put(key, m);
        return m;
    }

    /** Reads frames until the reply {@code type} to {@code conv}, answering callbacks meanwhile. */
    private Wire.Frame await(int conv, byte type) throws IOException {
        while (true) {
            Wire.Frame f = Wire.readFrame(in);
            if (f.type() == Wire.CALLBACK) {
                callback(f);
                continue;
            }
            if (f.conv() != conv) {
                throw new Wire.ProtocolException("a reply to " + f.conv() + " while waiting for " + conv);
            }
            if (f.type() == type) {
                return f;
            }
            if (f.type() == Wire.THROW) {
                throw thrown(f.in());
            }
            throw new Wire.ProtocolException("unexpected frame type " + f.type());
        }
    }

    /** An exception in a MULTI reply: class, message, frames. */
    private RuntimeException throwable(Wire.In in) throws IOException {
        return throwable(in, false);
    }

    /** A THROW frame: the exception, the output. */
    private RuntimeException thrown(Wire.In in) throws IOException {
        return throwable(in, true);
    }

    private RuntimeException throwable(Wire.In in, boolean withOutput) throws IOException {
        String cls = in.readString();
        String msg = in.readString();
        int n = in.readInt();
        if (n < 0 || n > 100) {
            throw new Wire.ProtocolException("bad frame count");
        }
        List<String> frames = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            frames.add(in.readString());
        }
        if (withOutput) {
            output(in.readString());
        }
        if (pendingFailure != null && cls.equals("raylab.remote.StudentServer$GraderFailure")) {
            RuntimeException p = pendingFailure;
            pendingFailure = null;
            return p;
        }
        if (StudentServer.STUCK.equals(cls) && withOutput) {
            // The student process's watchdog named where its code is stuck, and ended the process.
            dead();
            return new StudentTimeout(msg == null ? "your code did not return (an endless loop?)" : msg);
        }
        if ("raylab.course.NotImplemented".equals(cls)) {
            // The untouched stub: the framework's own exception, so messages say "TODO".
            return NotImplementedAgain.of(msg);
        }
        return new StudentException(cls, msg, frames, "");
    }

    /** Callbacks answered one at a time (those not answered in advance), for measurements. */
    public synchronized long liveCallbacks() {
        return liveCallbacks;
    }

    private long liveCallbacks;

    /**
     * The answer (a CB_RETURN payload) to a question a call sent back, or null if the grader's
     * object could not answer it (the call then asks it as a callback, which reports why).
     */
    private byte[] answerLater(byte[] question) throws IOException {
        Question q = question(new Wire.In(question, 0, question.length));
        if (!Wire.deferrable(q.op())) {
            throw new Wire.ProtocolException("a question sent back that must be asked");
        }
        Object result;
        long w0 = System.nanoTime();
        long c0 = CallClock.threadCpuNanos();
        try {
            result = answer(q.target(), q.op(), q.args());
        } catch (StudentTimeout e) {
            throw e; // the process is gone
        } catch (RuntimeException | Error e) {
            return null;
        } finally {
            bill(w0, c0);
        }
        return answerPayload(result, q.args()).key().bytes();
    }

    /**
     * Adds the time since {@code wall0} and this thread's CPU time since {@code cpu0} to the
     * grader's time answering the current call's questions; over the call's budget of the
     * grader's CPU time, the student process is stopped and the call fails: its questions made
     * the grader work without limit.
     */
    private void bill(long wall0, long cpu0) {
        long bound = clock.graderBoundNanos();
        if (clock.bill(wall0, cpu0) && proc != null) {
            dead();
            throw new StudentTimeout("your code asked the grader so much during one call that answering took more than "
                    + bound / 1_000_000_000.0 + " s of the grader's CPU time, and it was stopped (questions in an endless loop?)");
        }
    }

    /** A question of the student's code: the grader's object asked (null: unknown), the operation, the arguments. */
    private record Question(Object target, byte op, Object[] args) {
    }

    /** Reads a CALLBACK payload. */
    private Question question(Wire.In in) throws IOException {
        int id = in.readInt();
        byte op = in.readByte();
        int n = in.readInt();
        if (n < 0 || n > 8) {
            throw new Wire.ProtocolException("bad callback argument count");
        }
        Object[] a = new Object[n];
        for (int i = 0; i < n; i++) {
            a[i] = Wire.readValue(in, refs);
        }
        if (!in.atEnd()) {
            throw new Wire.ProtocolException("a question with bytes after its arguments");
        }
        return new Question(id > 0 && id <= ephemeral.size() ? ephemeral.get(id - 1) : null, op, a);
    }

    /** A CB_RETURN payload: the answer, then each record argument as answering left it. */
    private Wire.Out answerPayload(Object result, Object[] a) {
        Wire.Out o = new Wire.Out();
        Wire.writeValue(o, result, refs);
        for (Object x : a) {
            if (x instanceof IntersectionRecord r) {
                Wire.writeRecord(o, r, refs);
            }
        }
        return o;
    }

    private void callback(Wire.Frame f) throws IOException {
        liveCallbacks++;
        Question q = question(f.in());
        Object[] a = q.args();
        Object result;
        long w0 = System.nanoTime();
        long c0 = CallClock.threadCpuNanos();
        try {
            result = answer(q.target(), q.op(), a);
            bill(w0, c0);
        } catch (StudentTimeout e) {
            throw e; // the process is gone
        } catch (RuntimeException | Error e) {
            bill(w0, c0);
            if (e instanceof StudentException s) {
                pendingFailure = s;
            }
            Wire.Out o = new Wire.Out();
            o.writeString(e.getMessage());
            Wire.writeFrame(out, Wire.CB_THROW, f.conv(), o);
            out.flush();
            return;
        }
        Wire.writeFrame(out, Wire.CB_RETURN, f.conv(), answerPayload(result, a));
        out.flush();
    }

    private Object answer(Object t, byte op, Object[] a) {
        clock.answerBegins();
        if (SLOW_GRADER_MILLIS > 0) {
            try {
                Thread.sleep(SLOW_GRADER_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        return answerOf(t, op, a);
    }

    private static Object answerOf(Object t, byte op, Object[] a) {
        if (t == null) {
            throw new IllegalStateException("no such object of the grader (kept from an earlier call?)");
        }
        return switch (op) {
            case Wire.OP_INTERSECT -> ((Surface) t).intersect((IntersectionRecord) a[0], (Ray) a[1]);
            case Wire.OP_INTERSECTS_ANY -> ((Surface) t).intersectsAny((Ray) a[0], (IntersectionRecord) a[1]);
            case Wire.OP_KA -> ((Material) t).ka();
            case Wire.OP_DIFFUSE -> ((Material) t).diffuse((Vec3) a[0], (Vec3) a[1], (Color) a[2]);
            case Wire.OP_SPECULAR -> ((Material) t).specular((Vec3) a[0], (Vec3) a[1], (Vec3) a[2], (Color) a[3]);
            case Wire.OP_UNLIT -> ((Material) t).unlitColor((IntersectionRecord) a[0]);
            case Wire.OP_AMBIENT -> ((ShadingPoint) t).ambient();
            case Wire.OP_TO_LIGHT -> {
                ((ShadingPoint) t).toLight((PointLight) a[0]);
                yield null;
            }
            case Wire.OP_VISIBLE -> ((ShadingPoint) t).visible((PointLight) a[0]);
            case Wire.OP_AT_DIFFUSE -> ((ShadingPoint) t).diffuse((PointLight) a[0], (Vec3) a[1]);
            case Wire.OP_AT_SPECULAR -> ((ShadingPoint) t).specular((PointLight) a[0], (Vec3) a[1]);
            default -> throw new IllegalArgumentException("unknown callback " + op);
        };
    }

    private int ephemeral(Object o) {
        Integer id = ephemeralOf.get(o);
        if (id == null) {
            ephemeral.add(o);
            id = ephemeral.size();
            ephemeralOf.put(o, id);
        }
        return id;
    }

    private final Map<Class<?>, Class<?>> servedAncestors = new HashMap<>();

    private Class<?> servedAncestor(Class<?> c) {
        Class<?> r = servedAncestors.computeIfAbsent(c, k -> {
            for (Class<?> x = k; x != null; x = x.getSuperclass()) {
                if (config.served().contains(x.getName())) {
                    return x;
                }
            }
            return Void.class;
        });
        return r == Void.class ? null : r;
    }

    /** The handle of a served (stand-in) object, defined in the student process on first use. */
    private int handle(Object o, Class<?> as) {
        Integer h = handleOf.get(o);
        if (h != null) {
            return h;
        }
        int id = nextHandle++;
        try {
            Object[] data = GraderObjects.constructorData(o, as);
            Wire.Out d = new Wire.Out();
            d.writeInt(id);
            d.writeString(as.getName());
            d.writeInt(data.length);
            for (Object x : data) {
                Wire.writeValue(d, x, null);
            }
            int conv = nextConv++;
            Wire.writeFrame(out, Wire.DEFINE, conv, d);
            out.flush();
            await(conv, Wire.ACK);
        } catch (IOException e) {
            throw new DefineFailed(e);
        }
        handleOf.put(o, id);
        byHandle.put(id, o);
        return id;
    }

    /** An I/O failure while defining an object, carried out of the encoder. */
    private static final class DefineFailed extends RuntimeException {
        private static final long serialVersionUID = 1L;

        DefineFailed(IOException e) {
            super(e);
        }
    }

    /**
     * The grader's objects as the student process writes them back in a callback's question:
     * its own objects as handles, the grader's lights, surfaces and materials by number.
     */
    private final Wire.Refs asStudent = new Wire.Refs() {
        @Override
        public boolean encode(Wire.Out o, Object x) {
            Class<?> served = servedAncestor(x.getClass());
            if (served != null) {
                o.writeByte(Wire.HANDLE);
                o.writeInt(handle(x, served));
                return true;
            }
            byte tag = x instanceof PointLight ? Wire.LIGHT_REF : x instanceof Surface ? Wire.REMOTE_SURFACE
                    : x instanceof Material ? Wire.REMOTE_MATERIAL : 0;
            if (tag == 0) {
                return false;
            }
            o.writeByte(tag);
            o.writeInt(ephemeral(x));
            return true;
        }

        @Override
        public Object decode(byte tag, Wire.In in) {
            throw new UnsupportedOperationException();
        }
    };

    /** Grader side: stand-ins become handles, the grader's surfaces, materials and shading points proxies. */
    private final class Refs implements Wire.Refs {
        @Override
        public boolean encode(Wire.Out o, Object x) {
            Class<?> served = servedAncestor(x.getClass());
            if (served != null) {
                // A subclass of a served class (the reference BlinnPhong over the stand-in
                // Lambertian) is the served class there, made from the same data.
                o.writeByte(Wire.HANDLE);
                o.writeInt(handle(x, served));
                return true;
            }
            if (x instanceof PointLight l) {
                // By value, with a number: the same light comes back as the grader's own object.
                o.writeByte(Wire.LIGHT_REF);
                o.writeInt(ephemeral(l));
                Wire.writeValue(o, new PointLight(l.position, l.intensity, l.castsShadows, l.name), null);
                return true;
            }
            if (x instanceof Surface s) {
                o.writeByte(Wire.REMOTE_SURFACE);
                o.writeInt(ephemeral(s));
                var b = s.boundingBox();
                o.writeVec3(b.min);
                o.writeVec3(b.max);
                o.writeString(s.name());
                o.writeBoolean(s.isConvex());
                o.writeInt(s.primitiveCount());
                return true;
            }
            if (x instanceof Material m) {
                o.writeByte(Wire.REMOTE_MATERIAL);
                o.writeInt(ephemeral(m));
                o.writeString(m.name());
                o.writeBoolean(m.isLit());
                o.writeBoolean(m.hasSpecular());
                return true;
            }
            if (x instanceof ShadingPoint at) {
                o.writeByte(Wire.SHADING_POINT);
                o.writeInt(ephemeral(at));
                o.writeBoolean(GraderObjects.hearsLooks(at));
                o.writeVec3(at.x);
                o.writeVec3(at.n);
                o.writeVec3(at.v);
                Wire.writeValue(o, at.material, this);
                return true;
            }
            return false;
        }

        @Override
        public Object decode(byte tag, Wire.In in) throws IOException {
            int id = in.readInt();
            switch (tag) {
                case Wire.HANDLE: {
                    Object o = byHandle.get(id);
                    if (o == null) {
                        throw new Wire.ProtocolException("unknown handle " + id);
                    }
                    return o;
                }
                case Wire.REMOTE_SURFACE:
                case Wire.REMOTE_MATERIAL:
                case Wire.LIGHT_REF:
                    if (id < 1 || id > ephemeral.size()) {
                        throw new Wire.ProtocolException("unknown object " + id);
                    }
                    return ephemeral.get(id - 1);
                default:
                    throw new Wire.ProtocolException("unknown value tag " + tag);
            }
        }
    }

    @Override
    public synchronized void close() {
        clock.close();
        if (proc != null) {
            try {
                out.close();
                proc.waitFor(2, java.util.concurrent.TimeUnit.SECONDS);
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
                "-XX:+DisableAttachMechanism", "-XX:-UsePerfData", "-XX:TieredStopAtLevel=4", "-Xss4m",
                "-cp", String.join(File.pathSeparator, classPath.stream().map(Path::toString).toList()),
                "raylab.remote.StudentServer", "--channel"));
        for (String c : studentClasses) {
            cmd.add("--student");
            cmd.add(c);
        }
        return cmd;
    }
}
