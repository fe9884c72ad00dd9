package raylab.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import raylab.course.Messages;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Box;
import raylab.surface.Sphere;

/**
 * Hidden tests' messages read like the visible ones: the same "expected / got" lines and HINT,
 * surfaces and rays in the lecture's terms, no JUnit residue, whether they come from the hidden
 * helpers or from a plain JUnit assertion (which the grader rewrites with {@link Messages#plain}).
 */
class HiddenMessagesTest {
    /**
     * The grader-only helpers (grader/tests/raylab/hidden/Hidden.java are not on the test class
     * path), compiled here against the test class path.
     */
    static final class Hidden {
        static final raylab.material.Material M = new raylab.material.FlatColor(raylab.math.Color.WHITE, "white");
        static Class<?> cls;

        static synchronized Class<?> load() {
            if (cls == null) {
                try {
                    java.nio.file.Path out = java.nio.file.Files.createTempDirectory("hidden-helpers");
                    javax.tools.JavaCompiler javac = javax.tools.ToolProvider.getSystemJavaCompiler();
                    int rc = javac.run(null, null, null, "-d", out.toString(), "-cp", System.getProperty("java.class.path"),
                            "-sourcepath", "grader/tests", "grader/tests/raylab/hidden/Hidden.java");
                    assertEquals(0, rc, "grader/tests/raylab/hidden/Hidden.java compiles");
                    cls = new java.net.URLClassLoader(new java.net.URL[] {out.toUri().toURL()},
                            HiddenMessagesTest.class.getClassLoader()).loadClass("raylab.hidden.Hidden");
                } catch (ReflectiveOperationException | java.io.IOException e) {
                    throw new IllegalStateException(e);
                }
            }
            return cls;
        }

        static void call(String name, Class<?>[] types, Object... args) {
            try {
                load().getMethod(name, types).invoke(null, args);
            } catch (java.lang.reflect.InvocationTargetException e) {
                if (e.getCause() instanceof AssertionError a) {
                    throw a;
                }
                throw new IllegalStateException(e.getCause());
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException(e);
            }
        }

        static void assertHit(String what, raylab.surface.Surface s, Ray ray, IntersectionRecord rec, boolean returned,
                double t, Vec3 point, Vec3 normal, String hint) {
            call("assertHit", new Class<?>[] {String.class, raylab.surface.Surface.class, Ray.class, IntersectionRecord.class,
                boolean.class, double.class, Vec3.class, Vec3.class, String.class}, what, s, ray, rec, returned, t, point,
                normal, hint);
        }

        static void assertHit(String what, raylab.surface.Surface s, Ray ray, IntersectionRecord rec, boolean returned,
                double t, Vec3 point, List<Vec3> normals, String hint) {
            call("assertHit", new Class<?>[] {String.class, raylab.surface.Surface.class, Ray.class, IntersectionRecord.class,
                boolean.class, double.class, Vec3.class, List.class, String.class}, what, s, ray, rec, returned, t, point,
                normals, hint);
        }

        static void assertUntouched(String what, raylab.surface.Surface s, Ray ray, IntersectionRecord rec, boolean returned,
                IntersectionRecord before, String hint) {
            call("assertUntouched", new Class<?>[] {String.class, raylab.surface.Surface.class, Ray.class,
                IntersectionRecord.class, boolean.class, IntersectionRecord.class, String.class}, what, s, ray, rec,
                returned, before, hint);
        }

        static void assertColor(String what, raylab.math.Color expected, raylab.math.Color actual, String hint) {
            call("assertColor", new Class<?>[] {String.class, raylab.math.Color.class, raylab.math.Color.class, String.class},
                    what, expected, actual, hint);
        }
    }

    static void assertPlain(String m) {
        assertFalse(m.contains("==>") || m.contains("but was: <") || m.contains("Ray[") || m.contains("{\"type\""),
                "no JUnit residue, raw rays or JSON: " + m);
    }

    @Test
    void theHiddenHelpersWriteTheVisibleTestsFormat() {
        Sphere s = new Sphere(new Vec3(0, 0, 0), 1, Hidden.M, "unit sphere");
        Ray ray = new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1));
        IntersectionRecord rec = new IntersectionRecord();
        AssertionError e = assertThrows(AssertionError.class, () -> Hidden.assertHit("sphere #3 (seed 7)", s, ray, rec,
                false, 4, new Vec3(0, 0, 1), new Vec3(0, 0, 1), "the near root"));
        String m = e.getMessage();
        assertPlain(m);
        assertTrue(m.startsWith("expected a hit at t = 4.0 but intersect returned false"), m);
        assertTrue(m.contains("surface:  sphere 'unit sphere' centre (0, 0, 0) radius 1.0"), m);
        assertTrue(m.contains("ray:      p=(0, 0, 5) d=(0, 0, -1) t in [0.0, Infinity]"), m);
        assertTrue(m.contains("\nHINT: the near root"), m);
        IntersectionRecord before = new IntersectionRecord();
        Box b = new Box(new Vec3(0, 0, 0), new Vec3(1, 1, 1), Hidden.M, "cube");
        e = assertThrows(AssertionError.class, () -> Hidden.assertUntouched("a miss", b, ray, before, true, before, null));
        assertPlain(e.getMessage());
        e = assertThrows(AssertionError.class, () -> Hidden.assertColor("shade()", new raylab.math.Color(1, 0, 0),
                new raylab.math.Color(0, 0, 0), "ka·Ia once"));
        assertPlain(e.getMessage());
        assertTrue(e.getMessage().contains("\n  expected: ") && e.getMessage().contains("\n  got:      ")
                && e.getMessage().contains("\nHINT: ka·Ia once"), e.getMessage());
    }

    @Test
    void aFlatBoxAcceptsEitherFacesNormal() {
        Box flat = new Box(new Vec3(0, 0, 0), new Vec3(1, 0, 1), Hidden.M, "flat");
        Ray down = new Ray(new Vec3(0.5, 2, 0.5), new Vec3(0, -1, 0));
        for (Vec3 n : List.of(new Vec3(0, 1, 0), new Vec3(0, -1, 0))) {
            IntersectionRecord rec = new IntersectionRecord();
            rec.set(2, new Vec3(0.5, 0, 0.5), n, flat);
            Hidden.assertHit("flat", flat, down, rec, true, 2, new Vec3(0.5, 0, 0.5),
                    List.of(new Vec3(0, 1, 0), new Vec3(0, -1, 0)), null);
        }
        IntersectionRecord sideways = new IntersectionRecord();
        sideways.set(2, new Vec3(0.5, 0, 0.5), new Vec3(1, 0, 0), flat);
        assertThrows(AssertionError.class, () -> Hidden.assertHit("flat", flat, down, sideways, true, 2,
                new Vec3(0.5, 0, 0.5), List.of(new Vec3(0, 1, 0), new Vec3(0, -1, 0)), null));
    }

    @Test
    void junitResidueIsRewritten() {
        assertEquals("no shadow test for lights with n·l = 0",
                Messages.plain("no shadow test for lights with n·l = 0 ==> expected: <true> but was: <false>"));
        assertEquals("t of the record\n  expected: 1.5\n  got:      2.0",
                Messages.plain("t of the record ==> expected: <1.5> but was: <2.0>"));
        assertEquals("expected: 1\n  got:      2", Messages.plain("expected: <1> but was: <2>"));
        assertEquals("ray: p=(0, 0, 5) d=(0, 0, -1) t in [0.0, Infinity]",
                Messages.plain("ray: Ray[p=(0, 0, 5), d=(0, 0, -1), t in [0.0, Infinity]]"));
        assertEquals("unchanged text", Messages.plain("unchanged text"));
    }
}
