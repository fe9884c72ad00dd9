package raylab.boundary;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import raylab.light.PointLight;
import raylab.material.Material;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.remote.Wire;
import raylab.shading.ShadingPoint;
import raylab.surface.Surface;

/**
 * Calls into the student process made many at a time, with results exactly as one call at a
 * time would give them (grader/README.md, "Batched renders").
 *
 * <p>A render goes in bands of pixels. In each round every open pixel of the band is traced with
 * each student call answered from the cache of the student's own answers if it is there, else
 * <em>predicted</em> by the milestone's reference (run here, in the grader's process) and noted,
 * together with the callbacks the prediction asked and their answers. The noted calls then go to
 * the student process in one {@link Wire#MULTI} frame, with those answers given in advance. A
 * pixel is done when every prediction it used equals the student's answer (result and record,
 * bit for bit): then every value its trace used is the student's own, as in a call-at-a-time
 * render. Otherwise the pixel is traced again in the next round, where the calls answered so far
 * come from the cache. A student answer computed with an answer given in advance that itself
 * rested on a prediction is not cached. After {@link #MAX_ROUNDS} rounds the remaining pixels
 * are traced one call at a time.
 */
public final class Speculation {
    /** Rounds per band before the remaining pixels are traced one call at a time. */
    public static final int MAX_ROUNDS = 8;

    private final StudentProcess process;
    private final ClassLoader predictors;
    private final Map<Wire.Key, Answer> cache = new HashMap<>();
    private final Map<Wire.Key, Guess> guessed = new HashMap<>();
    private final List<Guess> guesses = new ArrayList<>();
    private final Map<Object, Integer> stable = new IdentityHashMap<>();
    private final Map<Object, Object> predictorOf = new IdentityHashMap<>();
    private final Map<String, Method> predictorMethods = new HashMap<>();
    private final Wire.Out key = new Wire.Out();
    private Pixel pixel;
    private boolean suspended;
    private long predictions;
    private long calls;
    private long batches;

    /** A prediction waiting for the student's answer. */
    private static final class Guess {
        Wire.Key key;
        final Object self;
        final Object[] input;
        final StudentProcess.MultiCall call;
        final Object result;
        final IntersectionRecord[] after;
        final boolean[] pure;
        Answer answer;
        boolean confirmed;

        Guess(Wire.Key key, Object self, Object[] input, StudentProcess.MultiCall call, Object result,
                IntersectionRecord[] after, boolean[] pure) {
            this.key = key;
            this.self = self;
            this.input = input;
            this.call = call;
            this.result = result;
            this.after = after;
            this.pure = pure;
        }
    }

    /** The student's answer to a call: a result and the records after it, or an exception (records unchanged). */
    private record Answer(Object result, IntersectionRecord[] after, RuntimeException thrown) {
        Object apply(Object[] args) {
            if (after != null) {
                copyOut(after, args);
            }
            if (thrown != null) {
                throw again(thrown);
            }
            return result;
        }
    }

    /** The predictions one pixel's trace used in this round. */
    public static final class Pixel {
        final List<Guess> used = new ArrayList<>();
        boolean unpredictable;

        /** Whether the trace used only the student's own answers (after {@link #send}). */
        public boolean exact() {
            if (unpredictable) {
                return false;
            }
            for (Guess g : used) {
                if (!g.confirmed) {
                    return false;
                }
            }
            return true;
        }

        /** Whether a call could not be predicted: trace this pixel one call at a time. */
        public boolean unpredictable() {
            return unpredictable;
        }
    }

    /** Thrown through a trace whose call cannot be predicted: that pixel is traced one call at a time. */
    public static final class Unpredictable extends Error {
        private static final long serialVersionUID = 1L;

        Unpredictable() {
            super("a call the grader cannot predict", null, false, false);
        }
    }

    /**
     * Batches the calls to {@code process}, predicted by the reference classes in {@code references}
     * (the milestone's own: those the stand-ins stand for).
     */
    public Speculation(StudentProcess process, Path references) {
        this.process = process;
        this.predictors = loader(references);
    }

    private static ClassLoader loader(Path dir) {
        URL url;
        try {
            url = dir.toUri().toURL();
        } catch (MalformedURLException e) {
            throw new IllegalArgumentException(e);
        }
        // The reference's own classes first; everything else (the framework) from the grader's loader.
        return new URLClassLoader(new URL[] {url}, Speculation.class.getClassLoader()) {
            @Override
            protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
                synchronized (getClassLoadingLock(name)) {
                    Class<?> c = findLoadedClass(name);
                    if (c == null && Files.isRegularFile(dir.resolve(name.replace('.', '/') + ".class"))) {
                        c = findClass(name);
                    }
                    if (c == null) {
                        return super.loadClass(name, resolve);
                    }
                    if (resolve) {
                        resolveClass(c);
                    }
                    return c;
                }
            }
        };
    }

    /** Starts one pixel's trace of this round. */
    public Pixel begin() {
        pixel = new Pixel();
        return pixel;
    }

    /** Ends the current pixel's trace. */
    public void end() {
        pixel = null;
    }

    /** Forgets the answers (between bands: they are not asked again). */
    public void clear() {
        cache.clear();
        stable.clear();
    }

    /** Calls, predictions and MULTI frames so far (for measurements). */
    public String counts() {
        return "calls " + calls + ", predictions " + predictions + ", batches " + batches;
    }

    /** A stand-in's call: answered, predicted, or (outside a pixel's trace) made at once. */
    Object call(Object self, String cls, String name, Object[] args) {
        calls++;
        if (suspended || pixel == null) {
            return process.call(cls, name, self, args);
        }
        // No answers yet (the first round): no key needed, none computed.
        Wire.Key k = null;
        if (!cache.isEmpty()) {
            k = keyOf(self, cls, name, args);
            if (k == null) {
                pixel.unpredictable = true;
                throw new Unpredictable();
            }
            Answer a = cache.get(k);
            if (a != null) {
                return a.apply(args);
            }
            Guess g = guessed.get(k);
            if (g != null) {
                copyOut(g.after, args);
                pixel.used.add(g);
                return g.result;
            }
        }
        Guess g = predict(k, self, cls, name, args);
        pixel.used.add(g);
        return g.result;
    }

    private Guess predict(Wire.Key k, Object self, String cls, String name, Object[] args) {
        // The call's inputs as they are now (records copied): sent to the student, and its key.
        Object[] before = new Object[args.length];
        Object[] asked = args;
        List<StudentProcess.Answered> answers = List.of();
        List<Boolean> pure = List.of();
        for (int i = 0; i < args.length; i++) {
            Object x = args[i];
            before[i] = x instanceof IntersectionRecord r ? copy(r) : x;
            // Only a shading point's questions are answered in advance: their arguments are the
            // call's own (lights, l). A surface's would carry the reference's own rays (its
            // shadow-ray offset) into the student process, so those are asked as they come.
            if (x instanceof ShadingPoint at) {
                if (asked == args) {
                    asked = args.clone();
                    answers = new ArrayList<>();
                    pure = new ArrayList<>();
                }
                asked[i] = noting(at, answers, pure);
            }
        }
        Object result;
        try {
            Method m = predictorMethod(cls, name, args.length);
            Object target = self == null ? null : predictorFor(self, cls);
            result = m.invoke(target, asked);
            if (target != null) {
                for (Object x : args) {
                    if (x instanceof IntersectionRecord r && r.surface == target) {
                        r.surface = (Surface) self;
                    }
                }
            }
        } catch (InvocationTargetException e) {
            if (e.getCause() instanceof Unpredictable u) {
                throw u;
            }
            pixel.unpredictable = true;
            throw new Unpredictable();
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            pixel.unpredictable = true;
            throw new Unpredictable();
        }
        IntersectionRecord[] after = new IntersectionRecord[args.length];
        for (int i = 0; i < args.length; i++) {
            if (args[i] instanceof IntersectionRecord r) {
                // As a record comes back from the student process: the material is the surface's.
                r.material = r.surface == null ? null : r.surface.material();
                after[i] = copy(r);
            }
        }
        boolean[] p = new boolean[pure.size()];
        for (int i = 0; i < p.length; i++) {
            p[i] = pure.get(i);
        }
        predictions++;
        Guess g = new Guess(k, self, before, new StudentProcess.MultiCall(cls, name, self, before, answers), result,
                after, p);
        guesses.add(g);
        if (k != null) {
            guessed.put(k, g);
        }
        return g;
    }

    /**
     * Forgets this round's predictions without sending them: the trace just made with predictions
     * only is the reference solution's, kept for the graded feedback (issue 40), not checked.
     */
    public void discard() {
        guesses.clear();
        guessed.clear();
    }

    /** Whether predictions wait for the student's answers. */
    public boolean pending() {
        return !guesses.isEmpty();
    }

    /**
     * Sends the predicted calls of this round to the student process in one frame and marks each
     * prediction confirmed or not; then {@link #keep} the answers of pixels to trace again.
     */
    public void send() {
        if (guesses.isEmpty()) {
            return;
        }
        List<StudentProcess.MultiCall> batch = new ArrayList<>(guesses.size());
        for (Guess g : guesses) {
            batch.add(g.call);
        }
        suspended = true;
        try {
            batches++;
            process.multi(batch);
        } finally {
            suspended = false;
        }
        for (Guess g : guesses) {
            StudentProcess.MultiCall c = g.call;
            g.answer = new Answer(c.result(), c.after(), c.thrown());
            g.confirmed = c.thrown() == null && same(g.result, c.result()) && sameRecords(g.after, c.after());
        }
        guesses.clear();
        guessed.clear();
    }

    /**
     * Keeps the student's answers to the calls of a pixel that is traced again, except an answer
     * that used an answer given in advance which rested on a prediction.
     */
    public void keep(Pixel p) {
        for (Guess g : p.used) {
            if (g.answer == null) {
                continue;
            }
            boolean rests = false;
            for (int u : g.call.used()) {
                rests |= u < 0 || u >= g.pure.length || !g.pure[u];
            }
            if (rests) {
                continue;
            }
            if (g.key == null) {
                g.key = keyOf(g.self, g.call.cls, g.call.name, g.input);
            }
            if (g.key != null) {
                cache.put(g.key, g.answer);
            }
        }
    }

    /** Runs {@code body} with every call made at once (a pixel traced one call at a time). */
    public void oneAtATime(Runnable body) {
        boolean was = suspended;
        suspended = true;
        try {
            body.run();
        } finally {
            suspended = was;
        }
    }

    // --- keys: a call's inputs, bit for bit ---

    private Wire.Key keyOf(Object self, String cls, String name, Object[] args) {
        key.reset();
        key.writeString(cls);
        key.writeString(name);
        try {
            Wire.writeValue(key, self, keyRefs);
            key.writeInt(args.length);
            for (Object a : args) {
                Wire.writeValue(key, a, keyRefs);
            }
        } catch (IllegalArgumentException e) {
            return null;
        }
        return key.key();
    }

    private int stable(Object o) {
        return stable.computeIfAbsent(o, x -> stable.size() + 1);
    }

    /** Objects by identity (the same object in every round of a band), shading points by content. */
    private final Wire.Refs keyRefs = new Wire.Refs() {
        @Override
        public boolean encode(Wire.Out o, Object x) {
            if (x instanceof ShadingPoint at) {
                o.writeByte(Wire.SHADING_POINT);
                o.writeVec3(at.x);
                o.writeVec3(at.n);
                o.writeVec3(at.v);
                Wire.writeValue(o, at.material, this);
                o.writeBoolean(StudentProcess.hearsLooks(at));
                return true;
            }
            if (x instanceof PointLight || x instanceof Surface || x instanceof Material) {
                o.writeByte(Wire.HANDLE);
                o.writeInt(stable(x));
                return true;
            }
            return false;
        }

        @Override
        public Object decode(byte tag, Wire.In in) {
            throw new UnsupportedOperationException();
        }
    };

    // --- predictors: the milestone's reference, run here ---

    /** The predictors asked for last. */
    private final RecentMethods<Method> recentPredictors = new RecentMethods<>();

    private Method predictorMethod(String cls, String name, int arity) throws ReflectiveOperationException {
        Method m = recentPredictors.get(cls, name, arity);
        if (m == null) {
            m = findPredictorMethod(cls, name, arity);
            recentPredictors.put(cls, name, arity, m);
        }
        return m;
    }

    private Method findPredictorMethod(String cls, String name, int arity) throws ReflectiveOperationException {
        String k = cls + "#" + name + "#" + arity;
        Method m = predictorMethods.get(k);
        if (m == null) {
            Class<?> standIn = Class.forName(cls);
            Class<?> ref = Class.forName(cls, true, predictors);
            if (ref == standIn) {
                throw new ClassNotFoundException("no reference of " + cls);
            }
            for (Method x : standIn.getMethods()) {
                if (x.getName().equals(name) && x.getParameterCount() == arity) {
                    m = ref.getMethod(name, x.getParameterTypes());
                }
            }
            if (m == null) {
                throw new NoSuchMethodException(cls + "." + name);
            }
            m.setAccessible(true);
            predictorMethods.put(k, m);
        }
        return m;
    }

    private Object predictorFor(Object self, String cls) throws ReflectiveOperationException {
        Object p = predictorOf.get(self);
        if (p == null) {
            Class<?> standIn = Class.forName(cls);
            Object[] data = StudentProcess.constructorData(self, standIn);
            Class<?> ref = Class.forName(cls, true, predictors);
            for (Constructor<?> k : ref.getConstructors()) {
                if (k.getParameterCount() == data.length && fits(k.getParameterTypes(), data)) {
                    p = k.newInstance(data);
                    break;
                }
            }
            if (p == null) {
                throw new NoSuchMethodException("no constructor of the reference " + cls + " takes its data");
            }
            predictorOf.put(self, p);
        }
        return p;
    }

    private static boolean fits(Class<?>[] types, Object[] args) {
        for (int i = 0; i < types.length; i++) {
            Class<?> t = types[i];
            Object a = args[i];
            if (t.isPrimitive()) {
                if (a == null || !(t == double.class ? a instanceof Double : t == int.class ? a instanceof Integer
                        : t == boolean.class ? a instanceof Boolean : t == long.class && a instanceof Long)) {
                    return false;
                }
            } else if (a != null && !t.isInstance(a)) {
                return false;
            }
        }
        return true;
    }

    // --- noting the callbacks a prediction asks ---

    /**
     * Notes an answer: pure if no prediction was used to compute it (then it is the grader's
     * true answer, whatever the student's other answers).
     */
    private interface Asking<T> {
        T ask();
    }

    private <T> T note(List<StudentProcess.Answered> answers, List<Boolean> pure, Object target, byte op,
            Object[] args, Asking<T> asking) {
        Object[] before = new Object[args.length];
        for (int i = 0; i < args.length; i++) {
            before[i] = args[i] instanceof IntersectionRecord r ? copy(r) : args[i];
        }
        long p = predictions;
        T result = asking.ask();
        Object[] after = new Object[args.length];
        for (int i = 0; i < args.length; i++) {
            after[i] = args[i] instanceof IntersectionRecord r ? copy(r) : null;
        }
        answers.add(new StudentProcess.Answered(target, op, before, result, after));
        pure.add(p == predictions);
        return result;
    }

    private ShadingPoint noting(ShadingPoint at, List<StudentProcess.Answered> answers, List<Boolean> pure) {
        boolean looks = StudentProcess.hearsLooks(at);
        return new ShadingPoint(at.x, at.n, at.v, at.material, new ShadingPoint.Answers() {
            @Override
            public Color ambient(ShadingPoint p) {
                return note(answers, pure, at, Wire.OP_AMBIENT, new Object[0], at::ambient);
            }

            @Override
            public void lookedAt(ShadingPoint p, PointLight light, Vec3 l) {
                if (looks) {
                    note(answers, pure, at, Wire.OP_TO_LIGHT, new Object[] {light}, () -> {
                        at.toLight(light);
                        return null;
                    });
                }
            }

            @Override
            public boolean visible(ShadingPoint p, PointLight light) {
                return note(answers, pure, at, Wire.OP_VISIBLE, new Object[] {light}, () -> at.visible(light));
            }

            @Override
            public Color diffuse(ShadingPoint p, PointLight light, Vec3 l) {
                return note(answers, pure, at, Wire.OP_AT_DIFFUSE, new Object[] {light, l}, () -> at.diffuse(light, l));
            }

            @Override
            public Color specular(ShadingPoint p, PointLight light, Vec3 l) {
                return note(answers, pure, at, Wire.OP_AT_SPECULAR, new Object[] {light, l}, () -> at.specular(light, l));
            }
        });
    }

    // --- records and values, bit for bit ---

    static IntersectionRecord copy(IntersectionRecord r) {
        IntersectionRecord c = new IntersectionRecord();
        c.copyFrom(r);
        c.tests = r.tests;
        return c;
    }

    private static void copyOut(IntersectionRecord[] after, Object[] args) {
        for (int i = 0; i < args.length; i++) {
            if (after[i] != null && args[i] instanceof IntersectionRecord r) {
                r.copyFrom(after[i]);
                r.tests = after[i].tests;
            }
        }
    }

    private static RuntimeException again(RuntimeException e) {
        if (e instanceof NotImplementedAgain) {
            return NotImplementedAgain.of(e.getMessage());
        }
        if (e instanceof StudentException s && s.getClass() == StudentException.class) {
            return new StudentException(s.className(), s.studentMessage(), s.frames(), "");
        }
        return e;
    }

    private static boolean sameRecords(IntersectionRecord[] a, IntersectionRecord[] b) {
        for (int i = 0; i < a.length; i++) {
            if ((a[i] == null) != (b[i] == null)) {
                return false;
            }
            if (a[i] != null && !(bits(a[i].t) == bits(b[i].t) && same(a[i].point, b[i].point)
                    && same(a[i].normal, b[i].normal) && a[i].surface == b[i].surface
                    && a[i].material == b[i].material && a[i].primitive == b[i].primitive
                    && a[i].tests == b[i].tests)) {
                return false;
            }
        }
        return true;
    }

    private static long bits(double d) {
        return Double.doubleToRawLongBits(d);
    }

    /** Equal bit for bit (doubles, vectors, colours), or the same object. */
    static boolean same(Object a, Object b) {
        if (a == b) {
            return true;
        }
        if (a == null || b == null || a.getClass() != b.getClass()) {
            return false;
        }
        if (a instanceof Double x) {
            return bits(x) == bits((Double) b);
        }
        if (a instanceof Vec3 x) {
            Vec3 y = (Vec3) b;
            return bits(x.x) == bits(y.x) && bits(x.y) == bits(y.y) && bits(x.z) == bits(y.z);
        }
        if (a instanceof Color x) {
            Color y = (Color) b;
            return bits(x.r) == bits(y.r) && bits(x.g) == bits(y.g) && bits(x.b) == bits(y.b);
        }
        if (a instanceof Boolean || a instanceof Integer || a instanceof Long || a instanceof String) {
            return a.equals(b);
        }
        return false;
    }

    @Override
    public String toString() {
        return counts() + ", cached " + cache.size() + " " + Arrays.toString(new int[0]);
    }
}
