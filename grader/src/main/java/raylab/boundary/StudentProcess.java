package raylab.boundary;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;

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
 * The grader's end of the process boundary, its RPC client: calls the student's methods in the
 * student process (a {@link raylab.remote.StudentServer} behind the sandbox's command, its life
 * in {@link StudentJvm}), as {@link Batches} of calls, and answers the process's callbacks to the
 * grader's surfaces, materials and shading points. Each call has a CPU-time budget measured on
 * the student process (its own and its descendants' user and system time from
 * {@code /proc/PID/stat}); a call over it, or a crash, stops the process, the call fails with a
 * {@link StudentTimeout} or a {@link StudentException}, and the next call starts a fresh
 * process, at most {@code maxRestarts} times.
 *
 * <p>Load is never the student's: a call's wall time counts only the time its process neither
 * ran nor waited for a CPU ({@code /proc/PID/task/TID/schedstat}) and the grader was not
 * answering its questions, so that only code that sleeps or blocks runs into the wall limit
 * (3 × budget + 5 s; {@link CallClock}). The grader's own time answering one call's questions has
 * a bound of its own (its thread's CPU time, the call's budget): student code cannot make it
 * work without limit. A process killed by something other than this class (the kernel's OOM
 * killer, for memory taken elsewhere) is not the student's doing: the call is made again in a
 * fresh process, and if that is killed too, the call fails with a {@link GradingFailure}.
 *
 * <p>One RPC client kept whole on purpose: each request beside the reading of its reply, each
 * answer to a callback beside the encoding of the grader's objects it names.
 */
public final class StudentProcess implements AutoCloseable {
    /** How the student process is started: its command line, and which classes it serves. */
    public record Config(List<String> command, Path directory, Set<String> served, long callBudgetMillis,
            int maxRestarts) {
    }

    /** Milliseconds added to each answer of the grader's (-Draylab.boundary.slowGrader=MS: tests of a slow grader). */
    private static final long SLOW_GRADER_MILLIS = Long.getLong("raylab.boundary.slowGrader", 0);

    // --- The state, all of it; guarded by this object's lock. ---
    private final Config config;
    /** The student process: started, ended, its clock. */
    private final StudentJvm jvm;
    /** The calls in MULTI frames, and their counts. */
    private final Batches batches;
    /**
     * Where the student's captured output goes: {@code System.out} as it is when the output comes,
     * not when this process was made. A test JVM starts its student process before it puts its
     * capture in place ({@code TestMain}), and its standard output before that is the signed
     * channel to the grader, which a student's text must never reach.
     */
    private Consumer<String> output = s -> System.out.print(s);
    /** Run before each frame of an outermost call (a render's deadline), or null. */
    private Runnable beforeFrame;
    /** How many calls were made (batched calls counted one by one). */
    private long calls;
    /** Callbacks answered one at a time, for measurements. */
    private long liveCallbacks;
    /** The next conversation number of a frame to the student process. */
    private int nextConv = 1;
    /** How deep calls are nested (a callback's answer may call the student process again): 1, the outermost. */
    private int depth;
    /** Set by a callback's answer that failed as the student's fault: the call fails with it. */
    private RuntimeException pendingFailure;
    // Per process: served (stand-in) objects defined in it, by handle; method ids declared in it.
    private final Map<Object, Integer> handleOf = new IdentityHashMap<>();
    private final Map<Integer, Object> byHandle = new HashMap<>();
    private int nextHandle = 1;
    private final Map<String, Integer> methodIds = new HashMap<>();
    /** The ids of the methods asked for last. */
    private final RecentMethods<Integer> recentIds = new RecentMethods<>();
    // Per outermost call: the grader's lights, surfaces, materials and shading points by number.
    private final Map<Object, Integer> ephemeralOf = new IdentityHashMap<>();
    private final List<Object> ephemeral = new ArrayList<>();
    /** Per class: its served ancestor (Void: none). */
    private final Map<Class<?>, Class<?>> servedAncestors = new HashMap<>();
    /** Values as the grader sends and reads them. */
    private final Refs refs = new Refs();

    public StudentProcess(Config config) {
        this.config = config;
        this.jvm = new StudentJvm(config);
        this.batches = new Batches(new BatchLink());
    }

    /** Where the student's captured output goes (default: this JVM's {@code System.out} of the moment). */
    public void output(Consumer<String> sink) {
        this.output = sink;
    }

    /** How many calls were made (batched calls counted one by one). */
    public synchronized long calls() {
        return calls;
    }

    /** The id of the current student process (−1: none); not synchronized, for tests while a call runs. */
    long pid() {
        return jvm.pid();
    }

    /** How often a student process was started. */
    public synchronized int starts() {
        return jvm.starts();
    }

    /**
     * CPU time of every student process this object started, so far (the current one as the
     * watchdog last read it, at most a few ticks behind), in ns.
     */
    public synchronized long studentCpuNanos() {
        return jvm.clock().studentCpuNanos(jvm.running());
    }

    /**
     * The student's own time in calls so far (ns): for each call its CPU time, or its wall time
     * less the time it waited for a CPU or for the grader's answers, whichever is more; at most a
     * quarter of a second behind. What a test's time limit is measured in.
     */
    public long studentTimeNanos() {
        return jvm.clock().studentTimeNanos();
    }

    /**
     * A test begins: from now on its calls together may take {@code limitNanos} of the student's
     * time ({@link #studentTimeNanos}); the call that passes it is stopped ("... in this test").
     * 0: no limit beyond each call's.
     */
    public void startTest(long limitNanos) {
        jvm.clock().startTest(limitNanos);
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
        return s.jvm.cpuNanos();
    }

    /** Bytes of MULTI frames sent and received, for measurements. */
    public synchronized long multiBytes() {
        return batches.multiBytes();
    }

    /** Questions answered after their call came back, for measurements. */
    public synchronized long deferredQuestions() {
        return batches.deferredQuestions();
    }

    /** Callbacks answered one at a time (those not answered in advance), for measurements. */
    public synchronized long liveCallbacks() {
        return liveCallbacks;
    }

    /** Starts the student process if none is running (a failure shows at the next call). */
    public synchronized void ensureStarted() {
        if (!jvm.running()) {
            try {
                start();
            } catch (IOException | RuntimeException e) {
                jvm.dead();
            }
        }
    }

    /** A fresh student process, nothing defined in it yet. */
    private void start() throws IOException {
        handleOf.clear();
        byHandle.clear();
        methodIds.clear();
        recentIds.clear();
        jvm.start();
    }

    /**
     * Calls the student's {@code cls.name} on {@code target} (null: static) and returns its result.
     * The call goes as a batch of one call, with its questions to the grader's surfaces and
     * materials sent back and answered as in a batched render: a test's call and a render's look
     * the same inside the student's process but for their arguments (issue 35).
     */
    public synchronized Object call(String cls, String name, Object target, Object... args) {
        Object[] before = new Object[args.length];
        for (int i = 0; i < args.length; i++) {
            before[i] = args[i] instanceof IntersectionRecord r ? Wire.copyRecord(r) : args[i];
        }
        Batches.Call c = new Batches.Call(cls, name, target, before, List.of());
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

    /** Makes the calls of {@code batch} in MULTI frames ({@link Batches}), setting each one's outcome on it. */
    public synchronized void multi(List<Batches.Call> batch) {
        run(() -> {
            calls += batch.size();
            batches.run(batch);
            return null;
        });
    }

    /** The RPC client as {@link Batches} use it. */
    private final class BatchLink implements Batches.Link {
        @Override
        public void checkpoint() {
            StudentProcess.this.checkpoint();
        }

        @Override
        public int method(String cls, String name, int arity) throws IOException {
            return StudentProcess.this.method(cls, name, arity);
        }

        @Override
        public int ephemeral(Object o) {
            return StudentProcess.this.ephemeral(o);
        }

        @Override
        public Wire.Refs refs() {
            return refs;
        }

        @Override
        public Wire.Refs asStudent() {
            return asStudent;
        }

        @Override
        public Wire.In exchange(byte type, Wire.Out payload, byte replyType) throws IOException {
            return ask(type, payload, replyType).in();
        }

        @Override
        public RuntimeException throwable(Wire.In in) throws IOException {
            return StudentProcess.this.throwable(in);
        }

        @Override
        public void output(String s) {
            StudentProcess.this.output(s);
        }

        @Override
        public byte[] answerLater(byte[] question) throws IOException {
            return StudentProcess.this.answerLater(question);
        }
    }

    private void output(String s) {
        if (s != null && !s.isEmpty()) {
            output.accept(s);
        }
    }

    private interface Body<T> {
        T run() throws IOException;
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
        } catch (StudentJvm.KilledFromOutside first) {
            jvm.uncountStart();
            try {
                return attempt(body);
            } catch (StudentJvm.KilledFromOutside again) {
                jvm.uncountStart();
                throw new GradingFailure("the student process was killed twice during one call by something other than"
                        + " the grader or the student's code (" + again.getMessage() + "): the machine, probably its memory");
            }
        }
    }

    private <T> T attempt(Body<T> body) {
        boolean outer = depth == 0;
        try {
            if (!jvm.running()) {
                start();
            }
            if (outer) {
                jvm.clock().callBegins();
            }
            depth++;
            try {
                return body.run();
            } finally {
                depth--;
            }
        } catch (IOException e) {
            throw jvm.lost(e);
        } finally {
            if (outer) {
                jvm.clock().callEnds();
                ephemeral.clear();
                ephemeralOf.clear();
                pendingFailure = null;
            }
        }
    }

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
        ask(Wire.METHOD, o, Wire.ACK);
        methodIds.put(key, m);
        return m;
    }

    /** Sends {@code payload} as a frame of {@code type} in a new conversation; returns its reply of {@code reply}. */
    private Wire.Frame ask(byte type, Wire.Out payload, byte reply) throws IOException {
        int conv = nextConv++;
        Wire.writeFrame(jvm.out(), type, conv, payload);
        jvm.out().flush();
        return await(conv, reply);
    }

    /** Reads frames until the reply {@code type} to {@code conv}, answering callbacks meanwhile. */
    private Wire.Frame await(int conv, byte type) throws IOException {
        while (true) {
            Wire.Frame f = Wire.readFrame(jvm.in());
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
            jvm.dead();
            return new StudentTimeout(msg == null ? "your code did not return (an endless loop?)" : msg);
        }
        if ("raylab.course.NotImplemented".equals(cls)) {
            // The untouched stub: the framework's own exception, so messages say "TODO".
            return NotImplementedAgain.of(msg);
        }
        return new StudentException(cls, msg, frames, "");
    }

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
        long bound = jvm.clock().graderBoundNanos();
        if (jvm.clock().bill(wall0, cpu0) && jvm.running()) {
            jvm.dead();
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
            Wire.writeFrame(jvm.out(), Wire.CB_THROW, f.conv(), o);
            jvm.out().flush();
            return;
        }
        Wire.writeFrame(jvm.out(), Wire.CB_RETURN, f.conv(), answerPayload(result, a));
        jvm.out().flush();
    }

    private Object answer(Object t, byte op, Object[] a) {
        jvm.clock().answerBegins();
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
            ask(Wire.DEFINE, d, Wire.ACK);
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
        jvm.close();
    }
}
