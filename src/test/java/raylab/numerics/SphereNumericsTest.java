package raylab.numerics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.FlatColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Sphere;

/**
 * Hard cases for ray–sphere intersection, judged by the exact {@link Oracle#sphere}: far-away
 * spheres hit or missed by a hair, ray origins just outside huge spheres, tangent and grazing
 * rays. Each case also shows that the lecture's formula evaluated as written
 * ({@link SphereMethods#textbook}) fails it.
 */
@Tag("numerics")
class SphereNumericsTest {
    static final FlatColor M = new FlatColor(Color.WHITE, "m");
    static final double U = Gen.U;

    /**
     * Classification margin: a case counts only if the line passes the sphere's surface by more
     * than 2^-44·‖p − c‖ (2^8 to 2^9 ulps of the distance to the centre), well beyond the
     * rounding error of any double computation with these inputs.
     */
    static final double MARGIN = 0x1p-44;

    record Counts(int cases, int referenceWrong, int textbookWrong, double referenceWorst) {
    }

    /** Rays from near the origin aimed at a sphere at distance D, passing its surface by a
     *  relative 10^-1 .. 10^-6 of r, inside or outside. */
    static Counts farAway(long seed, double distance, double radius, int n) {
        SplittableRandom rnd = new SplittableRandom(seed);
        int cases = 0;
        int refWrong = 0;
        int tbWrong = 0;
        double maxUlps = 0;
        for (int i = 0; i < n; i++) {
            Vec3 dir = Gen.unit(rnd);
            Vec3 c = dir.times(distance);
            Vec3 side = dir.cross(Gen.unit(rnd)).normalize();
            // relative gap log-uniform from just outside the margin (or 10^-6) to 10^-1
            double minGap = Math.max(1e-6, 2 * MARGIN * distance / radius);
            double miss = (rnd.nextBoolean() ? 1 : -1)
                    * Gen.logUniform(rnd, Math.log10(minGap), -1);
            Vec3 p = Gen.unit(rnd).times(rnd.nextDouble(0, 10));
            Vec3 d = c.plus(side.times(radius * (1 + miss))).minus(p)
                    .times(Gen.logUniform(rnd, -3, 3));
            Oracle.SphereRoots o = Oracle.sphere(c, radius, p, d);
            if (Math.abs(o.lineDistance - radius) <= MARGIN * c.minus(p).length()) {
                continue;
            }
            cases++;
            Sphere s = new Sphere(c, radius, M, "far");
            Ray ray = new Ray(p, d);
            IntersectionRecord ref = new IntersectionRecord();
            boolean refHit = s.intersect(ref, ray);
            boolean tbHit = SphereMethods.textbook(s, new IntersectionRecord(), ray);
            if (refHit != o.hits()) {
                refWrong++;
            }
            if (tbHit != o.hits()) {
                tbWrong++;
            }
            if (refHit && o.hits()) {
                maxUlps = Math.max(maxUlps, Math.abs(ref.t - o.t0.doubleValue())
                        / stableBound(c.minus(p).length(), radius, o.lineDistance, d.length()));
            }
        }
        return new Counts(cases, refWrong, tbWrong, maxUlps);
    }

    @ParameterizedTest(name = "D={0} r={1}")
    @CsvSource({"1e4,1", "1e4,1e-2", "1e5,1", "1e5,1e-2", "1e6,1", "1e6,1e-2", "1e7,1", "1e7,1e-2",
        "1e8,1", "1e8,1e-2"})
    void farSpheresAreClassifiedExactlyByTheReference(double distance, double radius) {
        long seed = Double.hashCode(distance) * 31L + Double.hashCode(radius);
        Counts k = farAway(seed, distance, radius, 1000);
        System.out.printf("far sphere D=%g r=%g: %d cases, misclassified: reference %d, textbook %d;"
                + " reference worst t error %.3f of the bound%n", distance, radius, k.cases,
                k.referenceWrong, k.textbookWrong, k.referenceWorst);
        assertTrue(k.cases > 900, "seed " + seed + ": too few cases outside the margin: " + k.cases);
        assertEquals(0, k.referenceWrong, "seed " + seed + ": reference hit/miss disagrees with the"
                + " exact oracle (D=" + distance + ", r=" + radius + ")");
        assertTrue(k.referenceWorst <= 1, "seed " + seed + ": reference t error "
                + k.referenceWorst + " times the bound 16u(‖f‖ + ‖f‖h/w)/‖d‖");
    }

    /** The textbook formula misclassifies far spheres once ‖f‖²·u approaches r²·(relative gap). */
    @ParameterizedTest(name = "D={0} r={1}")
    @CsvSource({"1e4,1e-2", "1e6,1", "1e6,1e-2", "1e8,1", "1e8,1e-2"})
    void textbookMisclassifiesFarSpheres(double distance, double radius) {
        long seed = Double.hashCode(distance) * 31L + Double.hashCode(radius);
        Counts k = farAway(seed, distance, radius, 1000);
        assertTrue(k.textbookWrong > 0, "seed " + seed + ": the textbook formula got all "
                + k.cases + " far-sphere cases right (D=" + distance + ", r=" + radius + ")");
        assertEquals(0, k.referenceWrong, "seed " + seed + ": the reference did not");
    }

    /** Origins a relative 10^-9 .. 10^-3 of R outside a sphere of radius R, rays going in. */
    static double[] justOutside(long seed, double bigR, int n) {
        SplittableRandom rnd = new SplittableRandom(seed);
        double refMax = 0;
        double tbMax = 0;
        for (int i = 0; i < n; i++) {
            Vec3 c = new Vec3(rnd.nextDouble(-2, 2), rnd.nextDouble(-2, 2), rnd.nextDouble(-2, 2))
                    .times(bigR);
            Vec3 u = Gen.unit(rnd);
            Vec3 p = c.plus(u.times(bigR * (1 + Gen.logUniform(rnd, -9, -3))));
            Vec3 d = u.negate().plus(Gen.unit(rnd).times(0.5)).times(Gen.logUniform(rnd, -2, 2));
            Oracle.SphereRoots o = Oracle.sphere(c, bigR, p, d);
            BigDecimal exact = o.firstHit(0, Double.POSITIVE_INFINITY);
            if (exact == null || o.t0.signum() <= 0) {
                continue; // p was rounded onto or into the sphere
            }
            Sphere s = new Sphere(c, bigR, M, "huge");
            Ray ray = new Ray(p, d);
            IntersectionRecord ref = new IntersectionRecord();
            IntersectionRecord tb = new IntersectionRecord();
            assertTrue(s.intersect(ref, ray), "seed " + seed + ": reference misses " + ray
                    + " against " + o);
            refMax = Math.max(refMax, Oracle.ulpError(ref.t, exact));
            tbMax = Math.max(tbMax, SphereMethods.textbook(s, tb, ray)
                    ? Oracle.ulpError(tb.t, exact) : Double.POSITIVE_INFINITY);
        }
        return new double[] {refMax, tbMax};
    }

    @ParameterizedTest(name = "R={0}")
    @ValueSource(doubles = {1e3, 1e4, 1e5, 1e6})
    void originJustOutsideAHugeSphere(double bigR) {
        long seed = (long) bigR + 7;
        double[] e = justOutside(seed, bigR, 1000);
        System.out.printf("just outside R=%g: max t error reference %.2f ulps, textbook %.3g ulps%n",
                bigR, e[0], e[1]);
        assertTrue(e[0] <= 4, "seed " + seed + ": reference t error " + e[0] + " ulps > 4");
        assertTrue(e[1] > 1e6, "seed " + seed + ": textbook t error only " + e[1]
                + " ulps; expected its cancellation to cost more than 10^6 ulps");
    }

    /**
     * Exactly tangent rays (data chosen so that every number is exact, the discriminant is 0):
     * the line touches the sphere at one point, a closed sphere counts that as a hit. Also rays
     * a relative 2^-30 inside and outside the tangent.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3})
    void tangentRays(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        int tbWrong = 0;
        for (int i = 0; i < 2000; i++) {
            int e = rnd.nextInt(-20, 20);
            double r = Math.scalb((double) rnd.nextInt(1, 1 << 20), e);
            Vec3 c = new Vec3(rnd.nextInt(-1000, 1000), rnd.nextInt(-1000, 1000),
                    rnd.nextInt(-1000, 1000)).times(Math.scalb(1.0, e));
            double along = Math.scalb((double) rnd.nextInt(1, 1 << 20), e + 2);
            double scaleD = Math.scalb(1.0, rnd.nextInt(-30, 30));
            int axis = rnd.nextInt(3);
            int other = (axis + 1 + rnd.nextInt(2)) % 3;
            double side = rnd.nextBoolean() ? 1 : -1;
            for (double nudge : new double[] {0, 0x1p-30, -0x1p-30}) {
                double h = r * (1 + nudge);
                Vec3 p = c.plus(unitAxis(axis).times(-along)).plus(unitAxis(other).times(side * h));
                Vec3 d = unitAxis(axis).times(scaleD);
                Oracle.SphereRoots o = Oracle.sphere(c, r, p, d);
                Sphere s = new Sphere(c, r, M, "s");
                Ray ray = new Ray(p, d);
                IntersectionRecord ref = new IntersectionRecord();
                boolean hit = s.intersect(ref, ray);
                String what = "seed " + seed + ": " + ray + " vs sphere c=" + c + " r=" + r + ", " + o;
                assertEquals(o.hits(), hit, what + ", reference hit=" + hit);
                if (hit) {
                    // At tangency t is ill-conditioned: |Δt|·|d| may reach √(error in h²).
                    double tol = Math.sqrt(8 * U) * (r + along) / scaleD;
                    double err = Math.abs(ref.t - o.t0.doubleValue());
                    assertTrue(err <= tol, what + ": t=" + ref.t + " off by " + err + " > " + tol);
                }
                if (SphereMethods.textbook(s, new IntersectionRecord(), ray) != o.hits()) {
                    tbWrong++;
                }
            }
        }
        System.out.printf("tangent rays seed %d: textbook misclassified %d of 6000%n", seed, tbWrong);
    }

    static Vec3 unitAxis(int axis) {
        return new Vec3(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0);
    }

    /**
     * Grazing rays, passing at h = r(1 − ε) with ε from 10^-12 (or just outside the margin) to
     * 10^-2, from near (D = 10 r) and far (D = 10^6 r): the reference hits, within
     * {@link #stableBound}; the textbook formula exceeds that bound for far spheres.
     */
    @ParameterizedTest(name = "D/r={0}")
    @ValueSource(doubles = {10, 1e6})
    void grazingRays(double ratio) {
        long seed = (long) ratio;
        SplittableRandom rnd = new SplittableRandom(seed);
        int tbOver = 0;
        double worst = 0;
        for (int i = 0; i < 2000; i++) {
            double r = Gen.logUniform(rnd, -2, 2);
            Vec3 dir = Gen.unit(rnd);
            Vec3 c = dir.times(ratio * r);
            Vec3 side = dir.cross(Gen.unit(rnd)).normalize();
            double minGap = Math.max(1e-12, 2 * MARGIN * ratio);
            double h = r * (1 - Gen.logUniform(rnd, Math.log10(minGap), -2));
            Vec3 d = c.plus(side.times(h)).times(Gen.logUniform(rnd, -3, 3));
            Vec3 p = Vec3.ZERO;
            Oracle.SphereRoots o = Oracle.sphere(c, r, p, d);
            if (!o.hits()) {
                continue;
            }
            double tol = stableBound(c.length(), r, o.lineDistance, d.length());
            Sphere s = new Sphere(c, r, M, "s");
            Ray ray = new Ray(p, d);
            IntersectionRecord ref = new IntersectionRecord();
            String what = "seed " + seed + ": " + ray + " vs sphere c=" + c + " r=" + r + ", " + o;
            assertTrue(s.intersect(ref, ray), what + ": reference misses");
            double err = Math.abs(ref.t - o.t0.doubleValue());
            worst = Math.max(worst, err / tol);
            assertTrue(err <= tol, what + ": reference t=" + ref.t + " off by " + err + " > " + tol);
            IntersectionRecord tb = new IntersectionRecord();
            if (!SphereMethods.textbook(s, tb, ray) || Math.abs(tb.t - o.t0.doubleValue()) > tol) {
                tbOver++;
            }
        }
        System.out.printf("grazing D/r=%g: reference worst error %.3f of the bound; textbook over"
                + " the bound (or missing) in %d of 2000%n", ratio, worst, tbOver);
        if (ratio >= 1e6) {
            assertTrue(tbOver > 0, "seed " + seed + ": textbook stayed within the bound for far"
                    + " grazing rays");
        }
    }

    /**
     * What a backward-stable method can promise for the nearer root: the line–centre distance
     * h is only known to a few u·‖f‖, which moves t by that times h/w, w = √(r² − h²) the half
     * chord; plus a few ulps of ‖f‖ for t itself. Bound: |t − t*| ≤ 16u(‖f‖ + ‖f‖h/w) / ‖d‖.
     */
    static double stableBound(double f, double r, double h, double dLength) {
        double w = Math.sqrt(Math.max(0, (r - h) * (r + h)));
        return 16 * U * (f + f * h / w) / dLength;
    }

    /** The recorded point lies on the sphere: | ‖x − c‖ − r | within a few ulps of ‖c‖ + r. */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {5, 6})
    void recordedPointIsOnTheSphere(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        for (int i = 0; i < 2000; i++) {
            double scale = Gen.logUniform(rnd, -4, 6);
            Vec3 c = Gen.unit(rnd).times(scale * Gen.logUniform(rnd, 0, 3));
            double r = scale * rnd.nextDouble(0.1, 1);
            Vec3 p = c.plus(Gen.unit(rnd).times(r * Gen.logUniform(rnd, 0.1, 4)));
            Vec3 d = c.plus(Gen.unit(rnd).times(r * 0.9)).minus(p);
            Sphere s = new Sphere(c, r, M, "s");
            IntersectionRecord rec = new IntersectionRecord();
            if (!s.intersect(rec, new Ray(p, d))) {
                continue;
            }
            double off = Math.abs(rec.point.minus(c).length() - r);
            double tol = 8 * U * (c.maxAbs() + r);
            assertTrue(off <= tol, "seed " + seed + ": point " + rec.point + " is " + off
                    + " from sphere c=" + c + " r=" + r + " (bound " + tol + ")");
            assertFalse(Double.isNaN(rec.t));
        }
    }
}
