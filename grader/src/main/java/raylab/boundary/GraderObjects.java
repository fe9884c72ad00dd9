package raylab.boundary;

import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Parameter;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import raylab.light.PointLight;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.shading.ShadingPoint;

/**
 * How the grader's objects are described to the student process, the same for one call at a
 * time ({@link StudentProcess}) and for speculated batches ({@link Speculation}): the plain values
 * a stand-in was made from, and whether a shading point's answers want to hear its looks.
 */
final class GraderObjects {
    private GraderObjects() {
    }

    private static final Map<Class<?>, Constructor<?>> CONSTRUCTORS = new java.util.concurrent.ConcurrentHashMap<>();

    /**
     * What the object was made from: for each parameter of its widest public constructor (names
     * known through {@code -parameters}) the public field or accessor of that name, if it is a
     * plain value; null otherwise (a material, a surface: the student process gets none).
     */
    static Object[] constructorData(Object o, Class<?> as) {
        Constructor<?> k = CONSTRUCTORS.computeIfAbsent(as, c -> {
            Constructor<?> best = null;
            for (Constructor<?> x : c.getConstructors()) {
                if (best == null || x.getParameterCount() > best.getParameterCount()) {
                    best = x;
                }
            }
            return best;
        });
        if (k == null) {
            throw new IllegalArgumentException(as.getName() + " has no public constructor");
        }
        Parameter[] ps = k.getParameters();
        Object[] data = new Object[ps.length];
        List<Field> fields = null;
        int nextField = 0;
        for (int i = 0; i < ps.length; i++) {
            Object v;
            if (ps[i].isNamePresent()) {
                v = property(o, ps[i].getName());
            } else {
                // Without -parameters: the public instance fields in declaration order stand for
                // the value parameters, name() for the String one.
                if (fields == null) {
                    fields = publicFields(as);
                }
                Class<?> t = ps[i].getType();
                if (t == String.class) {
                    v = property(o, "name");
                } else if (nextField < fields.size() && wrap(t).isAssignableFrom(wrap(fields.get(nextField).getType()))) {
                    v = property(o, fields.get(nextField++).getName());
                } else {
                    v = null;
                }
            }
            data[i] = plain(v) ? v : null;
        }
        return data;
    }

    private static List<Field> publicFields(Class<?> c) {
        List<Class<?>> chain = new ArrayList<>();
        for (Class<?> x = c; x != null && x != Object.class; x = x.getSuperclass()) {
            chain.add(0, x);
        }
        List<Field> out = new ArrayList<>();
        for (Class<?> x : chain) {
            for (Field f : x.getDeclaredFields()) {
                int m = f.getModifiers();
                if (java.lang.reflect.Modifier.isPublic(m) && !java.lang.reflect.Modifier.isStatic(m)) {
                    out.add(f);
                }
            }
        }
        return out;
    }

    private static Class<?> wrap(Class<?> t) {
        return t == double.class ? Double.class : t == int.class ? Integer.class : t == boolean.class ? Boolean.class
                : t == long.class ? Long.class : t;
    }

    private static boolean plain(Object v) {
        return v instanceof Double || v instanceof Integer || v instanceof Boolean || v instanceof Long
                || v instanceof String || v instanceof Vec3 || v instanceof Color || v instanceof PointLight
                || v instanceof Ray;
    }

    private static Object property(Object o, String name) {
        try {
            Field f = o.getClass().getField(name);
            return f.get(o);
        } catch (NoSuchFieldException | IllegalAccessException e) {
            try {
                Method m = o.getClass().getMethod(name);
                return m.invoke(o);
            } catch (ReflectiveOperationException e2) {
                return null;
            }
        }
    }

    private static final Map<Class<?>, Boolean> HEARS_LOOKS = new java.util.concurrent.ConcurrentHashMap<>();
    private static final Field ANSWERS;

    static {
        Field f = null;
        try {
            f = ShadingPoint.class.getDeclaredField("answers");
            f.setAccessible(true);
        } catch (ReflectiveOperationException | RuntimeException e) {
            f = null;
        }
        ANSWERS = f;
    }

    /** Whether a shading point's answers want to hear toLight (traces): else no callback for it. */
    static boolean hearsLooks(ShadingPoint at) {
        if (ANSWERS == null) {
            return true;
        }
        try {
            Object a = ANSWERS.get(at);
            return HEARS_LOOKS.computeIfAbsent(a.getClass(), c -> {
                try {
                    return c.getMethod("lookedAt", ShadingPoint.class, PointLight.class, Vec3.class)
                            .getDeclaringClass() != ShadingPoint.Answers.class;
                } catch (NoSuchMethodException e) {
                    return true;
                }
            });
        } catch (IllegalAccessException e) {
            return true;
        }
    }
}
