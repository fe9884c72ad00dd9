package raylab.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Vector algebra of Vec3 and Color, with values worked out by hand. */
class Vec3Test {
    private static final Vec3 A = new Vec3(1, 2, 3);
    private static final Vec3 B = new Vec3(4, -5, 6);

    static void assertVec(Vec3 expected, Vec3 actual, double tol, String what) {
        assertEquals(expected.x, actual.x, tol, what + ": x of " + actual + ", expected " + expected);
        assertEquals(expected.y, actual.y, tol, what + ": y of " + actual + ", expected " + expected);
        assertEquals(expected.z, actual.z, tol, what + ": z of " + actual + ", expected " + expected);
    }

    @Test
    void sumDifferenceScaleNegate() {
        assertEquals(new Vec3(5, -3, 9), A.plus(B), "a + b");
        assertEquals(new Vec3(-3, 7, -3), A.minus(B), "a - b");
        assertEquals(new Vec3(2.5, 5, 7.5), A.times(2.5), "2.5 a");
        assertEquals(new Vec3(-1, -2, -3), A.negate(), "-a");
        assertEquals(new Vec3(1, 2, 3), A, "operations must not change the operand");
    }

    @Test
    void dotAndCross() {
        assertEquals(12.0, A.dot(B), "a.b = 4 - 10 + 18");
        assertEquals(A.dot(B), B.dot(A), "dot is symmetric");
        // a x b = (2*6 - 3*(-5), 3*4 - 1*6, 1*(-5) - 2*4)
        assertEquals(new Vec3(27, 6, -13), A.cross(B), "a x b");
        assertEquals(A.cross(B).negate(), B.cross(A), "b x a = -(a x b)");
        assertEquals(0.0, A.cross(B).dot(A), "a x b is perpendicular to a");
        assertEquals(0.0, A.cross(B).dot(B), "a x b is perpendicular to b");
        assertEquals(new Vec3(0, 0, 1), new Vec3(1, 0, 0).cross(new Vec3(0, 1, 0)), "x cross y = z (right-handed)");
        assertEquals(new Vec3(1, 0, 0), new Vec3(0, 1, 0).cross(new Vec3(0, 0, 1)), "y cross z = x");
        assertEquals(Vec3.ZERO, A.cross(A.times(3)), "parallel vectors have zero cross product");
    }

    @Test
    void lengthAndNormalize() {
        Vec3 v = new Vec3(3, 4, 12);
        assertEquals(169.0, v.lengthSquared(), "|(3,4,12)|^2");
        assertEquals(13.0, v.length(), "|(3,4,12)|");
        assertVec(new Vec3(3 / 13.0, 4 / 13.0, 12 / 13.0), v.normalize(), 1e-16, "normalize (3,4,12)");
        assertEquals(1.0, new Vec3(-1e-200, 3e-200, 2e-200).times(1e190).normalize().length(), 1e-15,
                "normalized small vector has unit length");
        Vec3 zero = Vec3.ZERO.normalize();
        assertTrue(Double.isNaN(zero.x) && Double.isNaN(zero.y) && Double.isNaN(zero.z),
                "the zero vector has no direction: NaN components, got " + zero);
        assertFalse(zero.isFinite(), "normalized zero vector is not finite");
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    void identitiesOnRandomVectors(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        for (int i = 0; i < 200; i++) {
            Vec3 a = new Vec3(rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10));
            Vec3 b = new Vec3(rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10));
            Vec3 c = new Vec3(rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10), rnd.nextDouble(-10, 10));
            String ctx = "seed " + seed + ", a=" + a + ", b=" + b + ", c=" + c;
            double scale = a.length() * b.length();
            // |a x b|^2 + (a.b)^2 = |a|^2 |b|^2 (Lagrange)
            assertEquals(a.lengthSquared() * b.lengthSquared(),
                    a.cross(b).lengthSquared() + a.dot(b) * a.dot(b), 1e-12 * scale * scale, ctx);
            // a x (b x c) = b (a.c) - c (a.b)
            assertVec(b.times(a.dot(c)).minus(c.times(a.dot(b))), a.cross(b.cross(c)),
                    1e-12 * scale * c.length(), "BAC-CAB, " + ctx);
            // triple product is cyclic
            assertEquals(a.dot(b.cross(c)), b.dot(c.cross(a)), 1e-12 * scale * c.length(), ctx);
            assertEquals(1.0, a.normalize().length(), 1e-15, ctx);
            assertVec(a, a.plus(b).minus(b), 1e-13, ctx);
        }
    }

    @Test
    void componentsMinMaxAndFiniteness() {
        Vec3 v = new Vec3(-7, 2, 5);
        assertEquals(-7.0, v.get(0), "get(0)");
        assertEquals(2.0, v.get(1), "get(1)");
        assertEquals(5.0, v.get(2), "get(2)");
        assertEquals(7.0, v.maxAbs(), "max |component| of (-7, 2, 5)");
        assertEquals(new Vec3(-7, -5, 5), v.min(new Vec3(1, -5, 9)), "componentwise min");
        assertEquals(new Vec3(1, 2, 9), v.max(new Vec3(1, -5, 9)), "componentwise max");
        assertTrue(v.isFinite(), "finite vector");
        assertFalse(new Vec3(0, Double.POSITIVE_INFINITY, 0).isFinite(), "infinite y");
        assertFalse(new Vec3(0, 0, Double.NaN).isFinite(), "NaN z");
        assertEquals("(1, 2.5, -3)", new Vec3(1, 2.5, -3).toString(), "toString");
    }

    @Test
    void colorAlgebra() {
        Color kd = new Color(0.5, 0.25, 1);
        Color I = new Color(2, 4, 0.5);
        assertEquals(new Color(1, 1, 0.5), kd.times(I), "componentwise product kd o I");
        assertEquals(new Color(2.5, 4.25, 1.5), kd.plus(I), "sum");
        assertEquals(new Color(1, 0.5, 2), kd.times(2), "scale");
        assertTrue(Color.BLACK.isBlack() && new Color(0, 0, 0).isBlack(), "black");
        assertFalse(new Color(0, 1e-300, 0).isBlack(), "a tiny green is not black");
        assertFalse(new Color(Double.NaN, 0, 0).isFinite(), "NaN colour is not finite");
        assertTrue(Color.WHITE.isFinite(), "white is finite");
    }
}
