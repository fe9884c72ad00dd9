package raylab.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.FlatColor;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Sphere;

/** gamma(n) against exact arithmetic, and the per-hit error bound and ray origin offset of the reference. */
class NumericsTest {
    private static final MathContext MC = new MathContext(60);

    @Test
    void unitRoundoffIsTwoToTheMinus53() {
        assertEquals(Math.scalb(1.0, -53), Numerics.MACHINE_EPSILON, "u = 2^-53");
        assertEquals(1.0, 1.0 + Numerics.MACHINE_EPSILON, "1 + u rounds to 1 (ties to even)");
    }

    @Test
    void gammaMatchesExactFormula() {
        BigDecimal u = new BigDecimal(Math.scalb(1.0, -53));
        for (int n = 1; n <= 20; n++) {
            BigDecimal nu = u.multiply(BigDecimal.valueOf(n));
            double exact = nu.divide(BigDecimal.ONE.subtract(nu), MC).doubleValue();
            double g = Numerics.gamma(n);
            assertEquals(exact, g, 2 * Math.ulp(exact), "gamma(" + n + ") = n u / (1 - n u)");
            // gamma(n) bounds the error of n roundings: (1 + u)^n - 1 <= gamma(n)
            BigDecimal worst = BigDecimal.ONE.add(u).pow(n, MC).subtract(BigDecimal.ONE);
            assertTrue(worst.compareTo(new BigDecimal(g)) <= 0,
                    "(1+u)^" + n + " - 1 = " + worst + " must not exceed gamma(" + n + ") = " + g);
            assertTrue(g > n * Math.scalb(1.0, -53), "gamma(" + n + ") > n u");
        }
        assertEquals(0.0, Numerics.gamma(0), "no rounding, no error");
        assertEquals(3.330669073875472e-16, Numerics.gamma(3), 1e-30, "gamma(3) = 3u/(1-3u), about 3.33e-16");
    }

    /**
     * The per-hit error bound holds for real hit points: for seeded random triangles and spheres
     * (scales 10^-3 to 10^6, moved up to 10^7 away, hit near their middle and far from it), the
     * exact distance of the reference's computed point from the exact surface (BigDecimal, 60
     * digits) is at most √3·pointError(x, magnitude of that surface's box).
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {31, 32, 33})
    void pointErrorBoundsTheDistanceOfRealHitPointsFromTheirSurface(long seed) {
        SplittableRandom r = new SplittableRandom(seed);
        FlatColor m = new FlatColor(Color.WHITE, "m");
        double worst = 0;
        int hits = 0;
        for (int k = 0; k < 3000; k++) {
            double scale = Math.pow(10, r.nextDouble(-3, 6));
            Vec3 shift = new Vec3(r.nextDouble(-1, 1), r.nextDouble(-1, 1), r.nextDouble(-1, 1))
                    .times(r.nextBoolean() ? 0 : Math.pow(10, r.nextDouble(0, 7)));
            IntersectionRecord rec = new IntersectionRecord();
            Vec3 eye = shift.plus(new Vec3(r.nextDouble(-1, 1), 3, r.nextDouble(-1, 1)).times(scale));
            Vec3 target = shift.plus(new Vec3(r.nextDouble(-1, 1), 0, r.nextDouble(-1, 1)).times(scale * 1e-3));
            Ray ray = new Ray(eye, target.minus(eye));
            if (k % 2 == 0) {
                // A large triangle through (about) the target: x small next to its vertices.
                double big = scale * Math.pow(10, r.nextDouble(0, 4));
                Vec3 a = shift.plus(new Vec3(-big, r.nextDouble(-1e-3, 1e-3) * scale, -big));
                Vec3 b = shift.plus(new Vec3(big * 2, 0, -big));
                Vec3 c = shift.plus(new Vec3(-big, 0, big * 2));
                raylab.surface.Triangle t = new raylab.surface.Triangle(a, b, c, m, "t");
                if (!t.intersect(rec, ray)) {
                    continue;
                }
                hits++;
                double e = Numerics.pointError(rec.point, Numerics.magnitude(t.boundingBox()));
                double d = planeDistance(a, b, c, rec.point);
                worst = Math.max(worst, d / e);
                assertTrue(d <= Math.sqrt(3) * e, "seed " + seed + ", case " + k + ": triangle point " + rec.point
                        + " is " + d + " from the plane, bound " + e);
            } else {
                double radius = scale * Math.pow(10, r.nextDouble(-1, 3));
                Vec3 centre = target.minus(new Vec3(0, radius, 0));
                Sphere sp = new Sphere(centre, radius, m, "s");
                if (!sp.intersect(rec, ray)) {
                    continue;
                }
                hits++;
                double e = Numerics.pointError(rec.point, Numerics.magnitude(sp.boundingBox()));
                double d = sphereDistance(centre, radius, rec.point);
                worst = Math.max(worst, d / e);
                assertTrue(d <= Math.sqrt(3) * e, "seed " + seed + ", case " + k + ": sphere point " + rec.point
                        + " is " + d + " from the sphere, bound " + e);
            }
        }
        System.out.printf("pointError seed %d: %d hits, worst distance / bound = %.3f%n", seed, hits, worst);
        assertTrue(hits > 2000, "seed " + seed + ": too few hits to test the bound: " + hits);
    }

    private static BigDecimal[] big(Vec3 v) {
        return new BigDecimal[] {new BigDecimal(v.x), new BigDecimal(v.y), new BigDecimal(v.z)};
    }

    /** Exact distance of x from the plane through a, b, c (60 digits). */
    static double planeDistance(Vec3 a, Vec3 b, Vec3 c, Vec3 x) {
        BigDecimal[] pa = big(a);
        BigDecimal[] pb = big(b);
        BigDecimal[] pc = big(c);
        BigDecimal[] px = big(x);
        BigDecimal[] u = new BigDecimal[3];
        BigDecimal[] v = new BigDecimal[3];
        BigDecimal[] w = new BigDecimal[3];
        for (int i = 0; i < 3; i++) {
            u[i] = pb[i].subtract(pa[i]);
            v[i] = pc[i].subtract(pa[i]);
            w[i] = px[i].subtract(pa[i]);
        }
        BigDecimal[] n = {u[1].multiply(v[2]).subtract(u[2].multiply(v[1])),
            u[2].multiply(v[0]).subtract(u[0].multiply(v[2])), u[0].multiply(v[1]).subtract(u[1].multiply(v[0]))};
        BigDecimal dot = n[0].multiply(w[0]).add(n[1].multiply(w[1])).add(n[2].multiply(w[2]));
        BigDecimal len = n[0].pow(2).add(n[1].pow(2)).add(n[2].pow(2)).sqrt(MC);
        return dot.abs().divide(len, MC).doubleValue();
    }

    /** Exact | ‖x − c‖ − r | (60 digits). */
    static double sphereDistance(Vec3 c, double r, Vec3 x) {
        BigDecimal[] pc = big(c);
        BigDecimal[] px = big(x);
        BigDecimal sum = BigDecimal.ZERO;
        for (int i = 0; i < 3; i++) {
            sum = sum.add(px[i].subtract(pc[i]).pow(2));
        }
        return sum.sqrt(MC).subtract(new BigDecimal(r)).abs().doubleValue();
    }

    @Test
    void localOffsetMovesByItsBoundTowardW() {
        Vec3 x = new Vec3(3, -1000, 0.5);
        Vec3 n = new Vec3(0, 1, 0);
        double e = Numerics.pointError(x, 0);
        assertEquals(Numerics.gamma(8) * 1000, e, "the bound x itself shows: gamma(8) max|x_i|");
        assertEquals(Numerics.gamma(8) * 1e6, Numerics.pointError(x, 1e6), "a larger surface dominates");
        Vec3 up = Numerics.offsetRayOrigin(x, e, n, new Vec3(0.2, 1, 0));
        Vec3 down = Numerics.offsetRayOrigin(x, e, n, new Vec3(0.2, -1, 0));
        assertEquals(-1000 + 16 * e, up.y, Math.ulp(1000.0), "moved 16 e toward w");
        assertEquals(-1000 - 16 * e, down.y, Math.ulp(1000.0), "moved 16 e away when w points below");
        assertTrue(up.y > x.y && down.y < x.y, "the move is not lost to rounding");
        assertEquals(Numerics.MIN_OFFSET, Numerics.offsetFor(0), "at the origin: the minimum offset");
    }
}
