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
 * time would give them (grader/README.md, "Batched renders" and "What crosses the boundary").
 *
 * <p><b>The rule.</b> Nothing the student's process receives was computed by the milestone's
 * reference, or derived from it (its results, the records it left, the questions it asked):
 * only the call's own inputs, computed by the trusted framework from the student's own answers
 * and from <em>guesses</em> that do not depend on the reference (a miss, black, false: the
 * neutral answer of the method's return type, records left as they came), and the grader's own
 * answers to questions of the framework's objects that no guess went into.
 *
 * <p>A render goes in bands of pixels. In each round every open pixel of the band is traced with
 * each student call answered from the cache of the student's own answers if it is there, else
 * <em>guessed</em> and noted, together with the grader's answers, given in advance, to the
 * questions a shading point can be asked for the call's own lights. The noted calls go to the
 * student process in one {@link Wire#MULTI} frame. A pixel is done when every guess it used
 * equals the student's answer (result and record, bit for bit): then every value its trace used
 * is the student's own, as in a call-at-a-time render. Otherwise the pixel is traced again in
 * the next round, where the calls answered so far come from the cache. Every student answer is
 * an answer to inputs the grader sent, so it is cached under those inputs; nothing the student
 * process reports about itself (which answers it used) decides anything. After
 * {@link #MAX_ROUNDS} rounds the remaining pixels are traced one call at a time.
 *
 * <p>The milestone's reference runs here only to trace a band's pixels once for the reference
 * image ({@link #beginReference}); those traces note nothing and send nothing. A pixel whose
 * reference trace called no stand-in ({@link #frameworkOnly}) is the trusted framework's alone: its
 * colour is that trace's, and the rounds leave it out (they would send nothing for it).
 *
 * <p>One algorithm kept whole on purpose: the rounds, the guesses and the rule above are correct only
 * together, and a reviewer checks the rule against every line at once.
 */
public final class Speculation {
    /** Rounds per band before the remaining pixels are traced one call at a time. */
    public static final int MAX_ROUNDS = 10;

    /**
     * Test mode (the differential test, {@code BoundaryDifferentialTest}): the reference's answers
     * one ulp or one colour step off. The student's process must receive the same bytes.
     */
    static final String PERTURB = "raylab.boundary.perturb";

    private final StudentProcess process;
    private final ClassLoader predictors;
    private final boolean perturb = Boolean.getBoolean(PERTURB);
    private final Map<Wire.Key, Answer> cache = new HashMap<>();
    private final Map<Wire.Key, Guess> guessed = new HashMap<>();
    private final List<Guess> guesses = new ArrayList<>();
    private final Map<Object, Integer> stable = new IdentityHashMap<>();
    private final Map<Object, Object> predictorOf = new IdentityHashMap<>();
    private final Map<String, Method> predictorMethods = new HashMap<>();
    private final Map<String, Object> neutral = new HashMap<>();
    private final Wire.Out key = new Wire.Out();
    private Pixel pixel;
    private boolean suspended;
    private long predictions;
    private long guessesUsed;
    private long calls;
    private long batches;
    private long frameworkOnly;

    /** A guess waiting for the student's answer. */
    private static final class Guess {
        Wire.Key key;
        final Object self;
        final Object[] input;
        final Batches.Call call;
        final Object result;
        final IntersectionRecord[] after;
        Answer answer;
        boolean confirmed;

        Guess(Wire.Key key, Object self, Object[] input, Batches.Call call, Object result,
                IntersectionRecord[] after) {
            this.key = key;
            this.self = self;
            this.input = input;
            this.call = call;
            this.result = result;
            this.after = after;
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

    /** The guesses one pixel's trace used in this round. */
    public static final class Pixel {
        final List<Guess> used = new ArrayList<>();
        final boolean reference;
        boolean unpredictable;
        /** The stand-in calls this trace made (guessed, answered or predicted). */
        int calls;

        Pixel(boolean reference) {
            this.reference = reference;
        }

        /** Whether the trace used only the student's own answers (after {@link #send}). */
        public boolean exact() {
            if (unpredictable || reference) {
                return false;
            }
            for (Guess g : used) {
                if (!g.confirmed) {
                    return false;
                }
            }
            return true;
        }

        /** Whether a call could not be guessed: trace this pixel one call at a time. */
        public boolean unpredictable() {
            return unpredictable;
        }
    }

    /** Thrown through a trace whose call cannot be guessed or predicted: that pixel is traced one call at a time. */
    public static final class Unpredictable extends Error {
        private static final long serialVersionUID = 1L;

        Unpredictable() {
            super("a call the grader cannot predict", null, false, false);
        }
    }

    /**
     * Batches the calls to {@code process}; the reference classes in {@code references} (the
     * milestone's own: those the stand-ins stand for) trace the reference image.
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

    /** Starts one pixel's trace of this round: its calls are guessed, noted and sent. */
    public Pixel begin() {
        pixel = new Pixel(false);
        return pixel;
    }

    /**
     * Starts one pixel's trace by the reference alone (for the reference image): every student
     * call is answered by the milestone's reference, here; nothing is noted or sent.
     */
    public Pixel beginReference() {
        pixel = new Pixel(true);
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

    /**
     * Calls, predictions (the reference image's), guesses, MULTI frames and pixels no stand-in was
     * called for so far (for measurements).
     */
    public String counts() {
        return "calls " + calls + ", predictions " + predictions + ", guesses " + guessesUsed + ", batches " + batches
                + ", framework-only pixels " + frameworkOnly;
    }

    /**
     * Whether {@code p}, the reference's trace of a pixel, called no stand-in: then the pixel's
     * colour is the trusted framework's alone, the same in every round, and it is not traced again
     * (counted for {@link #counts}).
     */
    public boolean frameworkOnly(Pixel p) {
        if (p.reference && p.calls == 0 && !p.unpredictable) {
            frameworkOnly++;
            return true;
        }
        return false;
    }

    /** A stand-in's call: answered, guessed, predicted for the reference image, or (outside a pixel's trace) made at once. */
    Object call(Object self, String cls, String name, Object[] args) {
        calls++;
        if (suspended || pixel == null) {
            return process.call(cls, name, self, args);
        }
        pixel.calls++;
        if (pixel.reference) {
            return predict(self, cls, name, args);
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
                guessesUsed++;
                return g.result;
            }
        }
        Guess g = guess(k, self, cls, name, args);
        pixel.used.add(g);
        guessesUsed++;
        return g.result;
    }

    /**
     * Notes a call to send: its inputs as they are now (records copied), the grader's answers to
     * a shading point's questions about the call's own lights, and the neutral guess of its
     * result. Nothing here comes from the reference.
     */
    private Guess guess(Wire.Key k, Object self, String cls, String name, Object[] args) {
        Object result = neutral(cls, name, args.length);
        Object[] before = new Object[args.length];
        IntersectionRecord[] after = new IntersectionRecord[args.length];
        for (int i = 0; i < args.length; i++) {
            Object x = args[i];
            if (x instanceof IntersectionRecord r) {
                before[i] = copy(r);
                // Left as it came: a miss.
                after[i] = copy(r);
            } else {
                before[i] = x;
            }
        }
        List<Batches.Answered> answers = List.of();
        boolean complete = true;
        for (Object x : args) {
            if (x instanceof ShadingPoint at) {
                long g = guessesUsed;
                answers = answersFor(at, lightsOf(args));
                // A question whose answer rests on a guess (the student's own Lambertian under its
                // Shading) is not answered in advance: this round sends the calls it rests on and
                // holds this one back; the next round answers it from their answers, so that the
                // student's code does not ask it one round trip at a time.
                complete = g == guessesUsed;
            }
        }
        Guess g = new Guess(k, self, before, new Batches.Call(cls, name, self, before, answers), result,
                after);
        if (complete) {
            guesses.add(g);
            if (k != null) {
                guessed.put(k, g);
            }
        }
        return g;
    }

    /** The neutral guesses asked for last, each in an array of one (a void method's is null). */
    private final RecentMethods<Object[]> recentNeutral = new RecentMethods<>();

    /** The neutral guess of a method's result: false, black, zero, nothing; no reference in it. */
    private Object neutral(String cls, String name, int arity) {
        Object[] recent = recentNeutral.get(cls, name, arity);
        if (recent != null) {
            return recent[0];
        }
        Object v = neutralOf(cls, name, arity);
        recentNeutral.put(cls, name, arity, new Object[] {v});
        return v;
    }

    private Object neutralOf(String cls, String name, int arity) {
        String k = cls + "#" + name + "#" + arity;
        Object v = neutral.get(k);
        if (v == null && !neutral.containsKey(k)) {
            Class<?> type = null;
            try {
                for (Method m : Class.forName(cls).getMethods()) {
                    if (m.getName().equals(name) && m.getParameterCount() == arity) {
                        type = m.getReturnType();
                    }
                }
            } catch (ClassNotFoundException | LinkageError e) {
                type = null;
            }
            if (type == boolean.class) {
                v = Boolean.FALSE;
            } else if (type == Color.class) {
                v = Color.BLACK;
            } else if (type == double.class) {
                v = 0.0;
            } else if (type == int.class) {
                v = 0;
            } else if (type == Vec3.class) {
                v = Vec3.ZERO;
            } else if (type != void.class) {
                pixel.unpredictable = true;
                throw new Unpredictable();
            }
            neutral.put(k, v);
        }
        return v;
    }

    @SuppressWarnings("unchecked")
    private static List<PointLight> lightsOf(Object[] args) {
        for (Object x : args) {
            if (x instanceof List<?> l && l.stream().allMatch(PointLight.class::isInstance)) {
                return (List<PointLight>) l;
            }
            if (x instanceof PointLight p) {
                return List.of(p);
            }
        }
        return List.of();
    }

    /**
     * The grader's answers to the questions a shading point can be asked about the call's own
     * lights (ambient; for each light visible, and diffuse and specular in the direction
     * {@link ShadingPoint#toLight} gives), whether or not the code under test will ask them (so
     * which are given says nothing of what the reference would ask), each one only if no guess
     * went into it: then it is the framework's own answer, or rests on the student's own.
     */
    private List<Batches.Answered> answersFor(ShadingPoint at, List<PointLight> lights) {
        List<Batches.Answered> answers = new ArrayList<>();
        boolean looks = GraderObjects.hearsLooks(at);
        note(answers, at, Wire.OP_AMBIENT, new Object[0], at::ambient);
        for (PointLight light : lights) {
            Vec3 d = light.position.minus(at.x);
            Vec3 l = d.lengthSquared() == 0 ? Vec3.ZERO : d.normalize();
            if (looks) {
                note(answers, at, Wire.OP_TO_LIGHT, new Object[] {light}, () -> {
                    at.toLight(light);
                    return null;
                });
            }
            note(answers, at, Wire.OP_VISIBLE, new Object[] {light}, () -> at.visible(light));
            note(answers, at, Wire.OP_AT_DIFFUSE, new Object[] {light, l}, () -> at.diffuse(light, l));
            note(answers, at, Wire.OP_AT_SPECULAR, new Object[] {light, l}, () -> at.specular(light, l));
        }
        return answers;
    }

    /** Whether guesses wait for the student's answers. */
    public boolean pending() {
        return !guesses.isEmpty();
    }

    /**
     * Sends the guessed calls of this round to the student process in one frame and marks each
     * guess confirmed or not; then {@link #keep} the answers of pixels to trace again.
     */
    public void send() {
        if (guesses.isEmpty()) {
            return;
        }
        List<Batches.Call> batch = new ArrayList<>(guesses.size());
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
            Batches.Call c = g.call;
            g.answer = new Answer(c.result(), c.after(), c.thrown());
            g.confirmed = c.thrown() == null && same(g.result, c.result()) && sameRecords(g.after, c.after());
        }
        guesses.clear();
        guessed.clear();
    }

    /**
     * Keeps the student's answers to the calls of a pixel that is traced again: each is the
     * answer of the student's code to exactly the inputs sent, with only the grader's own answers
     * given in advance, so it is what a call with those inputs gives (what the student's process
     * says it used is not asked).
     */
    public void keep(Pixel p) {
        for (Guess g : p.used) {
            if (g.answer == null) {
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
        key.writeInt(methodNumber(cls, name, args.length));
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

    /** The methods' numbers in this render's keys: the same method, the same number. */
    private final Map<String, Integer> methodNumbers = new HashMap<>();
    private final RecentMethods<Integer> recentNumbers = new RecentMethods<>();

    private int methodNumber(String cls, String name, int arity) {
        Integer n = recentNumbers.get(cls, name, arity);
        if (n == null) {
            n = methodNumbers.computeIfAbsent(cls + "#" + name + "#" + arity, x -> methodNumbers.size() + 1);
            recentNumbers.put(cls, name, arity, n);
        }
        return n;
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
                o.writeBoolean(GraderObjects.hearsLooks(at));
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
            Object[] data = GraderObjects.constructorData(self, standIn);
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

    // --- the grader's answers given in advance ---

    private interface Asking<T> {
        T ask();
    }

    /** Notes the grader's answer to a question, unless a guess went into it. */
    private <T> void note(List<Batches.Answered> answers, Object target, byte op, Object[] args,
            Asking<T> asking) {
        long g = guessesUsed;
        boolean was = pixel.unpredictable;
        T result;
        try {
            result = asking.ask();
        } catch (Unpredictable | RuntimeException e) {
            // Not answered in advance: the student's code asks it if it needs it.
            pixel.unpredictable = was;
            return;
        }
        if (g == guessesUsed) {
            answers.add(new Batches.Answered(target, op, args, result, new Object[args.length]));
        }
    }

    // --- the reference image: the milestone's reference, run here, nothing sent ---

    private Object predict(Object self, String cls, String name, Object[] args) {
        Object result;
        try {
            Method m = predictorMethod(cls, name, args.length);
            Object target = self == null ? null : predictorFor(self, cls);
            result = m.invoke(target, args);
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
        for (Object x : args) {
            if (x instanceof IntersectionRecord r) {
                // As a record comes back from the student process: the material is the surface's.
                r.material = r.surface == null ? null : r.surface.material();
                if (perturb && r.t != Double.POSITIVE_INFINITY) {
                    r.t = Math.nextUp(r.t);
                }
            }
        }
        predictions++;
        if (perturb) {
            if (result instanceof Color c) {
                return new Color(c.r + 1 / 255.0, c.g, c.b);
            }
            if (result instanceof Double d) {
                return Math.nextUp(d);
            }
        }
        return result;
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
