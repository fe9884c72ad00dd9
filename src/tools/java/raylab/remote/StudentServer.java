package raylab.remote;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.EOFException;
import java.io.FileDescriptor;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import raylab.light.PointLight;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.shading.ShadingPoint;
import raylab.surface.Surface;

/**
 * The student process: serves the student's methods to the grader over {@link Wire} frames on
 * a channel of their own: with {@code --channel}, file descriptors {@value #CHANNEL_IN} (frames in)
 * and {@value #CHANNEL_OUT} (frames out), which the command's {@link #CHANNEL_WRAPPER} moved there
 * from standard input and output, sending the JVM's standard output (its own warnings at a thread
 * or process limit, anything written to file descriptor 1) to standard error with the rest; without
 * it, standard input and output. Its class path holds the student's classes of one milestone and the
 * public framework only; it computes results, never verdicts. What student code prints is
 * captured and sent back with each reply; a protocol error ends the process at once.
 * Arguments: {@code --student CLASS} (repeatable): the student's classes, whose stack frames an
 * exception report keeps; {@code --channel}: frames on file descriptors 3 and 4 (the JVM needs
 * {@link #CHANNEL_JVM_OPTION} to open them).
 *
 * <p>One job, kept in one file on purpose: the student side of the boundary, whose frame handlers must
 * be read together to see everything that crosses it.
 */
public final class StudentServer {
    private final DataInputStream in;
    private final OutputStream out;
    private final Set<String> studentClasses;
    private final Map<Integer, Object> handles = new HashMap<>();
    private final Map<Object, Integer> handleOf = new IdentityHashMap<>();
    private final Map<Integer, Method> methods = new HashMap<>();
    /** The grader's lights of the current call, by their numbers there. */
    private final Map<Object, Integer> lightIds = new IdentityHashMap<>();
    private int depth;
    private final Captured captured = new Captured();
    private final Wire.Out reply = new Wire.Out();
    private final Refs refs = new Refs();
    private int nextConv = 1;
    /** Output kept per reply; more is dropped with a note. */
    static final int OUTPUT_CAP = 64 * 1024;
    private boolean outputCut;
    /** The answers the grader sent with the current MULTI call, by question; null: none. */
    private Map<Wire.Key, Integer> answerOf;
    private List<byte[]> answers;
    private List<Integer> used;
    /** Answers below this index rest on the grader's predictions and are reported when used. */
    private int predicted;
    /**
     * The questions a MULTI call asked that were not answered, when the grader asked for them to
     * be sent back instead of asked one at a time; null: ask them as callbacks.
     */
    private List<byte[]> deferred;
    /** At most this many questions of one call are sent back; the grader asks again for more. */
    public static final int MAX_DEFERRED = 16;

    /** Guards the writes of frames: the serving thread's and the watchdog's last one. */
    private final Object writeLock = new Object();
    /** The thread that serves frames (and runs the student's code). */
    private volatile Thread serving;
    /** The frame being served, innermost (its reply is what the grader waits for), and whether any is. */
    private volatile int servingConv;
    private volatile boolean busy;
    /** Calls of the student's that returned and frames begun, so far (written by the serving thread only). */
    private volatile long progress;
    /** Whether the serving thread waits for the grader's answer to a callback (not the student's time). */
    private volatile boolean waiting;

    StudentServer(InputStream in, OutputStream out, Set<String> studentClasses) {
        this.in = new DataInputStream(new BufferedInputStream(in, 1 << 16));
        this.out = out;
        this.studentClasses = studentClasses;
    }

    /** The protocol's file descriptors with {@code --channel}: frames in, frames out. */
    public static final int CHANNEL_IN = 3, CHANNEL_OUT = 4;
    /**
     * Put before {@code java} in a student process's command: moves standard input and output to
     * file descriptors {@value #CHANNEL_IN} and {@value #CHANNEL_OUT}, gives the JVM /dev/null as
     * input and its standard error as output. A shell's redirections, so it works behind every
     * sandbox wrapper (they pass descriptors on).
     */
    public static final List<String> CHANNEL_WRAPPER = List.of("/bin/sh", "-c",
            "exec 3<&0 4>&1 0</dev/null 1>&2 && exec \"$@\"", "raylab-channel");
    /** The JVM option {@code --channel} needs: a FileDescriptor for a number is not public API. */
    public static final String CHANNEL_JVM_OPTION = "--add-opens=java.base/java.io=ALL-UNNAMED";

    public static void main(String[] args) throws IOException {
        Set<String> students = new HashSet<>();
        boolean channel = false;
        long stuckAfter = raylab.course.Watchdog.FLOOR.toMillis();
        for (int i = 0; i < args.length; i++) {
            if (args[i].equals("--student") && i + 1 < args.length) {
                students.add(args[++i]);
            } else if (args[i].equals("--channel")) {
                channel = true;
            } else if (args[i].equals(STUCK_AFTER) && i + 1 < args.length) {
                stuckAfter = Long.parseLong(args[++i]);
            }
        }
        OutputStream proto = new BufferedOutputStream(new FileOutputStream(channel ? descriptor(CHANNEL_OUT)
                : FileDescriptor.out), 1 << 16);
        InputStream stdin = new FileInputStream(channel ? descriptor(CHANNEL_IN) : FileDescriptor.in);
        String record = System.getProperty(RECORD);
        if (record != null && !record.isEmpty()) {
            // One file per process: the first is FILE, a later one FILE.2, FILE.3, ...
            java.io.File file = new java.io.File(record);
            for (int n = 2; !file.createNewFile(); n++) {
                file = new java.io.File(record + "." + n);
            }
            stdin = new Recording(stdin, new FileOutputStream(file));
        }
        StudentServer s = new StudentServer(stdin, proto, students);
        System.setIn(InputStream.nullInputStream());
        PrintStream capture = new PrintStream(new OutputStream() {
            @Override
            public void write(int b) {
                s.capture(new byte[] {(byte) b}, 0, 1);
            }

            @Override
            public void write(byte[] b, int off, int len) {
                s.capture(b, off, len);
            }
        }, true, StandardCharsets.UTF_8);
        System.setOut(capture);
        System.setErr(capture);
        proto.write((Wire.HELLO + "\n").getBytes(StandardCharsets.US_ASCII));
        proto.flush();
        s.serving = Thread.currentThread();
        long boundNanos = stuckAfter * 1_000_000L;
        Thread watchdog = new Thread(() -> s.watch(boundNanos), "student-watchdog");
        watchdog.setDaemon(true);
        watchdog.start();
        try {
            s.serve();
            Runtime.getRuntime().halt(0);
        } catch (Throwable e) {
            // A broken or hostile frame, or a write to a closed pipe: nothing sensible can follow.
            Runtime.getRuntime().halt(3);
        }
    }

    /**
     * Test mode: every byte the grader sends this process is also written to the file this
     * system property names, or FILE.2, FILE.3, ... by a process started after the first (the
     * differential test compares them; the autograder's documentation, "What crosses the
     * boundary"). Set only on the command line the test starts; never in a grading.
     */
    public static final String RECORD = "raylab.remote.record";

    /** Standard input, copied to a file as it is read. */
    private static final class Recording extends java.io.FilterInputStream {
        private final OutputStream copy;

        Recording(InputStream in, OutputStream copy) {
            super(in);
            this.copy = copy;
        }

        @Override
        public int read() throws IOException {
            int b = super.read();
            if (b >= 0) {
                copy.write(b);
                copy.flush();
            }
            return b;
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            int n = super.read(b, off, len);
            if (n > 0) {
                copy.write(b, off, n);
                copy.flush();
            }
            return n;
        }
    }

    /** An inherited file descriptor by its number. */
    private static FileDescriptor descriptor(int n) throws IOException {
        try {
            FileDescriptor d = new FileDescriptor();
            java.lang.reflect.Field f = FileDescriptor.class.getDeclaredField("fd");
            f.setAccessible(true);
            f.setInt(d, n);
            if (!d.valid()) {
                throw new IOException("file descriptor " + n + " is not valid");
            }
            return d;
        } catch (ReflectiveOperationException | RuntimeException e) {
            throw new IOException("cannot open the protocol channel (file descriptor " + n + "): " + e, e);
        }
    }

    private synchronized void capture(byte[] b, int off, int len) {
        int room = OUTPUT_CAP - captured.size();
        if (len > room) {
            outputCut = true;
            len = Math.max(0, room);
        }
        captured.write(b, off, len);
    }

    private synchronized String drainOutput() {
        String s = captured.toString(StandardCharsets.UTF_8);
        if (outputCut) {
            s += "\n(output cut at " + OUTPUT_CAP / 1024 + " KiB)";
        }
        captured.reset();
        outputCut = false;
        return s;
    }

    /** Serves frames until the end of standard input. */
    void serve() throws IOException {
        while (true) {
            Wire.Frame f;
            try {
                f = Wire.readFrame(in);
            } catch (EOFException e) {
                return;
            }
            dispatch(f);
        }
    }

    private void dispatch(Wire.Frame f) throws IOException {
        depth++;
        int outerConv = servingConv;
        servingConv = f.conv();
        busy = true;
        progress++;
        // A call the grader makes while answering a callback has no answers of its own.
        Map<Wire.Key, Integer> outerAnswerOf = answerOf;
        List<byte[]> outerAnswers = answers;
        List<Integer> outerUsed = used;
        List<byte[]> outerDeferred = deferred;
        int outerPredicted = predicted;
        answerOf = null;
        deferred = null;
        try {
            switch (f.type()) {
                case Wire.DEFINE -> define(f);
                case Wire.METHOD -> method(f);
                case Wire.CALL -> call(f);
                case Wire.MULTI -> multi(f);
                default -> throw new Wire.ProtocolException("unexpected frame type " + f.type());
            }
        } finally {
            answerOf = outerAnswerOf;
            answers = outerAnswers;
            used = outerUsed;
            deferred = outerDeferred;
            predicted = outerPredicted;
            servingConv = outerConv;
            if (--depth == 0) {
                busy = false;
                lightIds.clear(); // the grader's numbers hold for one call
            }
        }
    }

    private void send(byte type, int conv) throws IOException {
        synchronized (writeLock) {
            Wire.writeFrame(out, type, conv, reply);
            out.flush();
        }
    }

    /** The option that sets the watchdog's bound, in ms ({@link #watch}; default {@code Watchdog.FLOOR}). */
    public static final String STUCK_AFTER = "--stuck-after";
    /** The exception class a THROW frame names when the student's code was stuck (the message says where). */
    public static final String STUCK = "raylab.remote.StudentServer$Stuck";
    /** The exit status of a student process ended by its watchdog. */
    public static final int STUCK_EXIT = 86;

    /**
     * The student process's watchdog: when a frame is being served and no call of the student's
     * has returned while the serving thread used {@code boundNanos} of CPU time
     * ({@link raylab.course.Watchdog#threadCpuNanos}: the kernel's clock of that thread, which needs
     * no /proc, so it counts in the grader's sandbox too; only where the JVM cannot read it, 6 times
     * that of wall time; never counting the time spent waiting for the grader's answers; code that
     * waits instead of running meets the grader's wall limit, in the student's own time) and the
     * serving thread is in the student's classes, it answers the frame the grader waits
     * for with a THROW of {@link #STUCK} whose message says where ("your code has run for 2 s in
     * Lambertian.diffuse (Lambertian.java:41) without returning: an endless loop?", the student's
     * frames of the thread's stack, as {@code raylab.course.Watchdog} says it), then ends this
     * process: a loop cannot be stopped from outside, and the grader starts a new process for its
     * next call.
     */
    private void watch(long boundNanos) {
        java.util.Collection<String> files = studentClasses.stream()
                .map(c -> "src/main/java/" + c.replace('.', '/') + ".java").toList();
        java.time.Duration bound = java.time.Duration.ofNanos(boundNanos);
        long seen = -1;
        long cpu0 = 0;
        long wall0 = 0;
        while (true) {
            try {
                Thread.sleep(100);
            } catch (InterruptedException e) {
                return;
            }
            long u = progress;
            Thread t = serving;
            long cpu = t == null ? -1 : raylab.course.Watchdog.threadCpuNanos(t);
            long wall = System.nanoTime();
            if (u != seen || !busy || waiting || t == null) {
                seen = waiting || !busy ? -1 : u; // the grader's time, or none served: the clocks start again
                cpu0 = cpu;
                wall0 = wall;
                continue;
            }
            java.time.Duration idle = raylab.course.Watchdog.cpuIdle(wall - wall0, cpu < 0 ? -1 : cpu - cpu0, bound);
            if (idle == null) {
                continue;
            }
            java.util.Optional<String> where = raylab.course.Watchdog.stuck(Map.of(t, t.getStackTrace()), files, idle);
            if (where.isEmpty() || waiting || !busy) {
                continue;
            }
            synchronized (writeLock) {
                try {
                    Wire.Out o = new Wire.Out();
                    o.writeString(STUCK);
                    o.writeString(where.get());
                    o.writeInt(0);
                    o.writeString(drainOutput());
                    Wire.writeFrame(out, Wire.THROW, servingConv, o);
                    out.flush();
                } catch (IOException | RuntimeException e) {
                    // the grader is gone: nothing to tell
                }
                Runtime.getRuntime().halt(STUCK_EXIT);
            }
        }
    }

    private void define(Wire.Frame f) throws IOException {
        Wire.In in = f.in();
        int handle = in.readInt();
        String cls = in.readString();
        int n = in.readInt();
        Object[] args = readArgs(in, n);
        Object made;
        try {
            made = construct(Class.forName(cls), args);
        } catch (Throwable e) {
            replyThrow(f.conv(), unwrap(e));
            return;
        }
        Object old = handles.put(handle, made);
        if (old != null) {
            handleOf.remove(old);
        }
        handleOf.put(made, handle);
        reply.reset();
        send(Wire.ACK, f.conv());
    }

    private static Object construct(Class<?> c, Object[] args) throws Throwable {
        for (Constructor<?> k : c.getConstructors()) {
            if (k.getParameterCount() == args.length && accepts(k.getParameterTypes(), args)) {
                try {
                    return k.newInstance(args);
                } catch (InvocationTargetException e) {
                    throw e.getCause();
                }
            }
        }
        throw new NoSuchMethodException("no public constructor of " + c.getName() + " takes these " + args.length
                + " values");
    }

    private static boolean accepts(Class<?>[] types, Object[] args) {
        for (int i = 0; i < types.length; i++) {
            Class<?> t = types[i];
            Object a = args[i];
            if (t.isPrimitive()) {
                Class<?> box = t == double.class ? Double.class : t == int.class ? Integer.class
                        : t == boolean.class ? Boolean.class : t == long.class ? Long.class : Void.class;
                if (!box.isInstance(a)) {
                    return false;
                }
            } else if (a != null && !t.isInstance(a)) {
                return false;
            }
        }
        return true;
    }

    private void method(Wire.Frame f) throws IOException {
        Wire.In in = f.in();
        int id = in.readInt();
        String cls = in.readString();
        String name = in.readString();
        int arity = in.readInt();
        try {
            Method found = null;
            for (Method m : Class.forName(cls).getMethods()) {
                if (m.getName().equals(name) && m.getParameterCount() == arity) {
                    found = m;
                }
            }
            if (found == null) {
                throw new NoSuchMethodException(cls + "." + name + " with " + arity + " parameters");
            }
            methods.put(id, found);
        } catch (Throwable e) {
            replyThrow(f.conv(), unwrap(e));
            return;
        }
        reply.reset();
        send(Wire.ACK, f.conv());
    }

    private Object[] readArgs(Wire.In in, int n) throws IOException {
        if (n < 0 || n > 64) {
            throw new Wire.ProtocolException("bad argument count " + n);
        }
        Object[] args = new Object[n];
        for (int i = 0; i < n; i++) {
            args[i] = Wire.readValue(in, refs);
        }
        return args;
    }

    private Method methodOf(int id) throws IOException {
        Method m = methods.get(id);
        if (m == null) {
            throw new Wire.ProtocolException("unknown method " + id);
        }
        return m;
    }

    private void call(Wire.Frame f) throws IOException {
        Wire.In in = f.in();
        Method m = methodOf(in.readInt());
        Object target = Wire.readValue(in, refs);
        Object[] args = readArgs(in, in.readInt());
        Object result;
        try {
            result = invoke(m, target, args);
        } catch (Throwable e) {
            replyThrow(f.conv(), e);
            return;
        }
        reply.reset();
        writeResult(reply, result, args);
        reply.writeString(drainOutput());
        send(Wire.RETURN, f.conv());
    }

    /**
     * Many calls, of any methods, each with the answers the grader expects its callbacks to need
     * (predicted: a used one is reported) and the grader's own answers to questions the call asked
     * in an earlier frame: a callback whose question is among them is answered here, any other one
     * is asked, or, when the frame says so, sent back with the call instead ({@link Wire#MULTI}).
     * A call that throws is reported in its place; the others still run.
     */
    private void multi(Wire.Frame f) throws IOException {
        Wire.In in = f.in();
        int calls = in.readInt();
        if (calls < 0 || calls > in.end - in.pos) {
            throw new Wire.ProtocolException("bad call count " + calls);
        }
        Wire.Out results = depth == 1 ? multiResults : new Wire.Out();
        results.reset();
        List<Integer> usedHere = new ArrayList<>();
        List<byte[]> deferredHere = new ArrayList<>();
        // An argument sent AS_BEFORE is the previous call's at the same place: the same object, or
        // for a record a new one with the fields that one was sent with (AS_BEFORE_TESTS: but the
        // test count that follows).
        Object[] previous = new Object[0];
        for (int i = 0; i < calls; i++) {
            boolean defer = in.readBoolean();
            Method m = methodOf(in.readInt());
            Object target = Wire.readValue(in, refs);
            int n = in.readInt();
            if (n < 0 || n > 64) {
                throw new Wire.ProtocolException("bad argument count " + n);
            }
            Object[] args = new Object[n];
            Object[] sent = new Object[n];
            for (int j = 0; j < n; j++) {
                byte tag = in.peekByte();
                if (tag == Wire.AS_BEFORE || tag == Wire.AS_BEFORE_TESTS) {
                    in.readByte();
                    if (j >= previous.length || previous[j] == null) {
                        throw new Wire.ProtocolException("an argument as before with none before");
                    }
                    sent[j] = previous[j];
                    if (tag == Wire.AS_BEFORE_TESTS) {
                        if (!(previous[j] instanceof IntersectionRecord p)) {
                            throw new Wire.ProtocolException("a test count for an argument that is not a record");
                        }
                        IntersectionRecord r = Wire.copyRecord(p);
                        r.tests = in.readLong();
                        sent[j] = r;
                    }
                    args[j] = sent[j] instanceof IntersectionRecord r ? Wire.copyRecord(r) : sent[j];
                } else {
                    args[j] = Wire.readValue(in, refs);
                    sent[j] = args[j] instanceof IntersectionRecord r ? Wire.copyRecord(r) : args[j];
                }
            }
            previous = sent;
            int k = in.readInt();
            int total = in.readInt();
            if (k < 0 || total < k || total > in.end - in.pos) {
                throw new Wire.ProtocolException("bad answer count " + total);
            }
            if (total == 0) {
                answerOf = Map.of();
                answers = List.of();
            } else {
                Map<Wire.Key, Integer> of = new HashMap<>();
                List<byte[]> given = new ArrayList<>(total);
                for (int j = 0; j < total; j++) {
                    of.putIfAbsent(new Wire.Key(in.readBytes()), j);
                    given.add(in.readBytes());
                }
                answerOf = of;
                answers = given;
            }
            predicted = k;
            used = usedHere;
            used.clear();
            deferred = defer ? deferredHere : null;
            deferredHere.clear();
            int outputMark = captured.size();
            Object result = null;
            Throwable thrown = null;
            try {
                result = invoke(m, target, args);
            } catch (Throwable e) {
                thrown = e;
            }
            if (deferred != null && !deferred.isEmpty()) {
                // It asked something not answered yet (whatever it did with the Deferred it got):
                // its outcome does not count; the grader answers and sends the call again. What it
                // printed is dropped, so that the output shows each call once.
                captured.truncate(outputMark);
                results.writeByte(2);
                results.writeInt(deferred.size());
                deferred.forEach(results::writeBytes);
            } else {
                if (thrown == null) {
                    results.writeByte(0);
                    Wire.writeValue(results, result, refs);
                    for (int j = 0; j < n; j++) {
                        if (args[j] instanceof IntersectionRecord r) {
                            // A record left as it came (a miss) is one byte.
                            if (Wire.sameRecord(r, (IntersectionRecord) sent[j])) {
                                results.writeByte(Wire.AS_BEFORE);
                            } else {
                                results.writeByte(Wire.RECORD);
                                Wire.writeRecord(results, r, refs);
                            }
                        }
                    }
                } else {
                    results.writeByte(1);
                    writeThrowable(results, thrown);
                }
                results.writeInt(used.size());
                used.forEach(results::writeInt);
            }
            answerOf = null;
            deferred = null;
        }
        reply.reset();
        reply.writeInt(calls);
        reply.write(results);
        reply.writeString(drainOutput());
        send(Wire.MULTI_RETURN, f.conv());
    }

    /** The reply of a MULTI frame read at the top level, kept from frame to frame. */
    private final Wire.Out multiResults = new Wire.Out();

    private void writeResult(Wire.Out o, Object result, Object[] args) {
        Wire.writeValue(o, result, refs);
        for (Object a : args) {
            if (a instanceof IntersectionRecord r) {
                Wire.writeRecord(o, r, refs);
            }
        }
    }

    private Object invoke(Method m, Object target, Object[] args) throws Throwable {
        if (!accepts(m.getParameterTypes(), args)) {
            throw new IllegalArgumentException("the arguments do not fit " + m);
        }
        try {
            return m.invoke(target, args);
        } catch (InvocationTargetException e) {
            throw e.getCause();
        } finally {
            progress++; // a call of the student's returned
        }
    }

    private static Throwable unwrap(Throwable e) {
        return e instanceof InvocationTargetException && e.getCause() != null ? e.getCause() : e;
    }

    private void replyThrow(int conv, Throwable e) throws IOException {
        reply.reset();
        writeThrowable(reply, e);
        reply.writeString(drainOutput());
        send(Wire.THROW, conv);
    }

    /** An exception's class, message and the student's own stack frames. */
    private void writeThrowable(Wire.Out reply, Throwable e) {
        reply.writeString(e.getClass().getName());
        String msg;
        try {
            msg = e.getMessage();
        } catch (Throwable t) {
            msg = "(its getMessage threw " + t.getClass().getName() + ")";
        }
        reply.writeString(msg == null ? null : msg.length() > 2000 ? msg.substring(0, 2000) + " ..." : msg);
        List<String> frames = new ArrayList<>();
        for (StackTraceElement s : e.getStackTrace()) {
            String cls = s.getClassName();
            int dollar = cls.indexOf('$');
            String outer = dollar < 0 ? cls : cls.substring(0, dollar);
            if (studentClasses.contains(outer) && frames.size() < 20) {
                frames.add(cls.substring(cls.lastIndexOf('.') + 1) + "." + s.getMethodName() + " ("
                        + s.getFileName() + ":" + s.getLineNumber() + ")");
            }
        }
        reply.writeInt(frames.size());
        frames.forEach(reply::writeString);
    }

    /** Asks the grader's object {@code id} something; record arguments are updated from the answer. */
    Object callback(int id, byte op, Object... args) {
        try {
            Wire.Out o = new Wire.Out();
            o.writeInt(id);
            o.writeByte(op);
            o.writeInt(args.length);
            for (Object a : args) {
                Wire.writeValue(o, a, refs);
            }
            Wire.Key question = answerOf == null ? null : o.key();
            Integer given = question == null ? null : answerOf.get(question);
            if (given == null && deferred != null && Wire.deferrable(op)) {
                // Sent back with the call, which the grader sends again with the answer.
                if (deferred.size() < MAX_DEFERRED && deferred.stream().noneMatch(q -> Arrays.equals(q,
                        question.bytes()))) {
                    deferred.add(question.bytes());
                }
                throw new Deferred();
            }
            if (given != null) {
                // Answered in advance by the grader: read as the grader's reply would be.
                if (given < predicted) {
                    used.add(given);
                }
                byte[] b = answers.get(given);
                Wire.In a = new Wire.In(b, 0, b.length);
                Object v = Wire.readValue(a, refs);
                for (Object x : args) {
                    if (x instanceof IntersectionRecord r) {
                        Wire.readRecordInto(a, r, refs);
                    }
                }
                return v;
            }
            int conv = nextConv++;
            waiting = true;
            synchronized (writeLock) {
                Wire.writeFrame(out, Wire.CALLBACK, conv, o);
                out.flush();
            }
            while (true) {
                Wire.Frame f = Wire.readFrame(in);
                // The grader's time answering is not the student's (the watchdog's clocks wait).
                waiting = false;
                if (f.type() == Wire.CB_RETURN && f.conv() == conv) {
                    Object v = Wire.readValue(f.in(), refs);
                    for (Object a : args) {
                        if (a instanceof IntersectionRecord r) {
                            Wire.readRecordInto(f.in(), r, refs);
                        }
                    }
                    return v;
                } else if (f.type() == Wire.CB_THROW && f.conv() == conv) {
                    throw new GraderFailure(f.in().readString());
                } else {
                    dispatch(f);
                    waiting = true;
                }
            }
        } catch (IOException e) {
            Runtime.getRuntime().halt(3);
            throw new AssertionError(e);
        }
    }

    /**
     * Thrown through a student call that asked a question the grader has not answered yet (see
     * {@link #multi}); the call is run again once it has. Student code should not catch this.
     */
    public static final class Deferred extends Error {
        private static final long serialVersionUID = 1L;

        Deferred() {
            super("the grader answers this question with the next frame", null, false, false);
        }
    }

    /** Captured output that can be cut back to an earlier size. */
    private static final class Captured extends ByteArrayOutputStream {
        synchronized void truncate(int size) {
            count = Math.min(count, size);
        }
    }

    /** The grader could not answer a callback: student code should not catch this. */
    public static final class GraderFailure extends Error {
        private static final long serialVersionUID = 1L;

        GraderFailure(String message) {
            super(message);
        }
    }

    /** The grader's surface (the scene, a blocker), asked through callbacks. */
    final class RemoteSurface extends Surface {
        final int id;
        private final BoundingBox box;
        private final boolean convex;
        private final int count;

        RemoteSurface(int id, BoundingBox box, String name, boolean convex, int count) {
            super(null, name);
            this.id = id;
            this.box = box;
            this.convex = convex;
            this.count = count;
        }

        @Override
        public boolean intersect(IntersectionRecord outRecord, Ray ray) {
            return Boolean.TRUE.equals(callback(id, Wire.OP_INTERSECT, outRecord, ray));
        }

        @Override
        public boolean intersectsAny(Ray ray, IntersectionRecord scratch) {
            return Boolean.TRUE.equals(callback(id, Wire.OP_INTERSECTS_ANY, ray, scratch));
        }

        @Override
        public BoundingBox boundingBox() {
            return box;
        }

        @Override
        public boolean isConvex() {
            return convex;
        }

        @Override
        public int primitiveCount() {
            return count;
        }
    }

    /** The grader's material, asked through callbacks. */
    final class RemoteMaterial extends Material {
        final int id;
        private final boolean lit;
        private final boolean specular;

        RemoteMaterial(int id, String name, boolean lit, boolean specular) {
            super(name);
            this.id = id;
            this.lit = lit;
            this.specular = specular;
        }

        @Override
        public boolean isLit() {
            return lit;
        }

        @Override
        public boolean hasSpecular() {
            return specular;
        }

        @Override
        public Color ka() {
            return (Color) callback(id, Wire.OP_KA);
        }

        @Override
        public Color diffuse(Vec3 n, Vec3 l, Color intensity) {
            return (Color) callback(id, Wire.OP_DIFFUSE, n, l, intensity);
        }

        @Override
        public Color specular(Vec3 n, Vec3 l, Vec3 v, Color intensity) {
            return (Color) callback(id, Wire.OP_SPECULAR, n, l, v, intensity);
        }

        @Override
        public Color unlitColor(IntersectionRecord hit) {
            return (Color) callback(id, Wire.OP_UNLIT, hit);
        }
    }

    /** A shading point's questions, answered by the grader's shading point. */
    final class RemoteAnswers implements ShadingPoint.Answers {
        final int id;
        final boolean hearsLooks;

        RemoteAnswers(int id, boolean hearsLooks) {
            this.id = id;
            this.hearsLooks = hearsLooks;
        }

        @Override
        public Color ambient(ShadingPoint at) {
            return (Color) callback(id, Wire.OP_AMBIENT);
        }

        @Override
        public void lookedAt(ShadingPoint at, PointLight light, Vec3 l) {
            if (hearsLooks) {
                callback(id, Wire.OP_TO_LIGHT, light);
            }
        }

        @Override
        public boolean visible(ShadingPoint at, PointLight light) {
            return Boolean.TRUE.equals(callback(id, Wire.OP_VISIBLE, light));
        }

        @Override
        public Color diffuse(ShadingPoint at, PointLight light, Vec3 l) {
            return (Color) callback(id, Wire.OP_AT_DIFFUSE, light, l);
        }

        @Override
        public Color specular(ShadingPoint at, PointLight light, Vec3 l) {
            return (Color) callback(id, Wire.OP_AT_SPECULAR, light, l);
        }
    }

    /** Student side: handles for defined objects, proxies for the grader's. */
    final class Refs implements Wire.Refs {
        @Override
        public boolean encode(Wire.Out out, Object o) {
            Integer light = o instanceof PointLight ? lightIds.get(o) : null;
            if (light != null) {
                out.writeByte(Wire.LIGHT_REF);
                out.writeInt(light);
                return true;
            }
            if (o instanceof PointLight) {
                return false; // a light of the student's own: by value
            }
            Integer h = handleOf.get(o);
            if (h != null) {
                out.writeByte(Wire.HANDLE);
                out.writeInt(h);
                return true;
            }
            if (o instanceof RemoteSurface s) {
                out.writeByte(Wire.REMOTE_SURFACE);
                out.writeInt(s.id);
                return true;
            }
            if (o instanceof RemoteMaterial m) {
                out.writeByte(Wire.REMOTE_MATERIAL);
                out.writeInt(m.id);
                return true;
            }
            return false;
        }

        @Override
        public Object decode(byte tag, Wire.In in) throws IOException {
            switch (tag) {
                case Wire.HANDLE: {
                    int h = in.readInt();
                    Object o = handles.get(h);
                    if (o == null) {
                        throw new Wire.ProtocolException("unknown handle " + h);
                    }
                    return o;
                }
                case Wire.REMOTE_SURFACE: {
                    int id = in.readInt();
                    BoundingBox b = new BoundingBox(in.readVec3(), in.readVec3());
                    return new RemoteSurface(id, b, in.readString(), in.readBoolean(), in.readInt());
                }
                case Wire.LIGHT_REF: {
                    int id = in.readInt();
                    Object l = Wire.readValue(in, null);
                    if (!(l instanceof PointLight light)) {
                        throw new Wire.ProtocolException("a light reference without a light");
                    }
                    lightIds.put(light, id);
                    return light;
                }
                case Wire.REMOTE_MATERIAL:
                    return new RemoteMaterial(in.readInt(), in.readString(), in.readBoolean(), in.readBoolean());
                case Wire.SHADING_POINT: {
                    int id = in.readInt();
                    boolean looks = in.readBoolean();
                    Vec3 x = in.readVec3();
                    Vec3 n = in.readVec3();
                    Vec3 v = in.readVec3();
                    Object m = Wire.readValue(in, this);
                    if (m != null && !(m instanceof Material)) {
                        throw new Wire.ProtocolException("a shading point's material is not a material");
                    }
                    return new ShadingPoint(x, n, v, (Material) m, new RemoteAnswers(id, looks));
                }
                default:
                    throw new Wire.ProtocolException("unknown value tag " + tag);
            }
        }
    }
}
