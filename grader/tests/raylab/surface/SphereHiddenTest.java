package raylab.surface;

import static raylab.hidden.Hidden.M;
import static raylab.hidden.Hidden.assertHit;
import static raylab.hidden.Hidden.assertUntouched;
import static raylab.hidden.Hidden.copy;
import static raylab.hidden.Hidden.point;
import static raylab.hidden.Hidden.recordWith;
import static raylab.hidden.Hidden.scale;
import static raylab.hidden.Hidden.uniform;
import static raylab.hidden.Hidden.unit;
import static raylab.hidden.Hidden.within;

import java.util.SplittableRandom;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

import raylab.hidden.Calls;
import raylab.hidden.Hidden;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * Hidden tests of Sphere.intersect (grader only). Each answer is built first: a point x on the
 * sphere, then a ray through it, so the expected t, point and normal are known exactly.
 */
@Tag("sphere")
class SphereHiddenTest {
    private static final int N = 200;

    private static Sphere randomSphere(SplittableRandom r) {
        return new Sphere(point(r, 20), uniform(r, 0.2, 8), M, "sphere");
    }

    @Test
    @DisplayName("random rays from outside hit the near point (the smaller root)")
    void randomRaysFromOutsideHitTheNearPoint() {
        long seed = 0x5ee1L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Sphere s = randomSphere(r);
            Vec3 u = unit(r);
            Vec3 x = s.center.plus(u.times(s.radius));
            Vec3 d = within(r, u.negate(), 0.2).times(scale(r));
            double t = uniform(r, 0.5, 30) / d.length();
            Ray ray = new Ray(x.minus(d.times(t)), d);
            IntersectionRecord rec = new IntersectionRecord();
            boolean hit = Calls.intersect(s, rec, ray);
            assertHit("random ray from outside #" + i + " (seed " + seed + ")", s, ray, rec, hit, t, x, u,
                    "the nearer root of the quadratic is the entry point; d is not unit length");
        }
    }

    @Test
    @DisplayName("random rays from inside hit the far point (the larger root), normal outward")
    void randomRaysFromInsideHitTheFarPoint() {
        long seed = 0x1215de;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Sphere s = randomSphere(r);
            Vec3 p = s.center.plus(unit(r).times(s.radius * uniform(r, 0, 0.8)));
            Vec3 u = unit(r);
            Vec3 x = s.center.plus(u.times(s.radius));
            double k = scale(r);
            Vec3 d = x.minus(p).times(k);
            Ray ray = new Ray(p, d);
            IntersectionRecord rec = new IntersectionRecord();
            boolean hit = Calls.intersect(s, rec, ray);
            assertHit("random ray from inside #" + i + " (seed " + seed + ")", s, ray, rec, hit, 1 / k, x, u,
                    "when the origin is inside, the near root is negative: use the far root; the normal still points out");
        }
    }

    @Test
    @DisplayName("a sphere behind the ray's origin is missed")
    void sphereBehindTheOriginIsMissed() {
        long seed = 0xbe41d;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Sphere s = randomSphere(r);
            Vec3 u = unit(r);
            Vec3 p = s.center.plus(u.times(s.radius * uniform(r, 1.1, 5)));
            // Pointing away from the sphere: both roots are negative.
            Vec3 d = within(r, u, 0.3).times(scale(r));
            Ray ray = new Ray(p, d);
            IntersectionRecord rec = new IntersectionRecord();
            IntersectionRecord before = copy(rec);
            assertUntouched("sphere behind the origin #" + i + " (seed " + seed + ")", s, ray, rec,
                    Calls.intersect(s, rec, ray), before, "negative t are behind the ray's origin: both roots < tMin");
        }
    }

    @Test
    @DisplayName("rays just outside the rim miss, rays just inside it hit")
    void nearMissesAndNearGrazingHits() {
        long seed = 0x67a2eL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Sphere s = randomSphere(r);
            Vec3 d = unit(r).times(scale(r));
            Vec3 side = d.cross(unit(r)).normalize();
            // A ray whose line passes at distance 1.001 r (miss) or 0.999 r (hit) from the centre.
            boolean shouldHit = i % 2 == 0;
            double dist = s.radius * (shouldHit ? 0.999 : 1.001);
            Vec3 closest = s.center.plus(side.times(dist));
            Vec3 p = closest.minus(d.times(uniform(r, 3, 10) * s.radius / d.length()));
            Ray ray = new Ray(p, d);
            IntersectionRecord rec = new IntersectionRecord();
            boolean hit = Calls.intersect(s, rec, ray);
            if (shouldHit) {
                // The entry point: closest point moved back by sqrt(r² − dist²) along the unit direction.
                Vec3 dn = d.normalize();
                double back = Math.sqrt(s.radius * s.radius - dist * dist);
                Vec3 x = closest.minus(dn.times(back));
                double t = x.minus(p).dot(d) / d.lengthSquared();
                assertHit("grazing hit #" + i + " (seed " + seed + ")", s, ray, rec, hit, t, x,
                        x.minus(s.center).times(1 / s.radius),
                        "a ray passing just inside the silhouette has two close roots; take the nearer");
            } else {
                assertUntouched("near miss #" + i + " (seed " + seed + ")", s, ray, rec, hit,
                        new IntersectionRecord(), "negative discriminant: no real root, no hit");
            }
        }
    }

    @Test
    @DisplayName("tMin between the two roots: the hit is the exit point")
    void tMinBetweenTheRootsGivesTheExitPoint() {
        Sphere s = new Sphere(new Vec3(1, 2, -3), 2, M, "sphere");
        // Along +x through the centre: entry at x = -1 (t = 2), exit at x = 3 (t = 4); |d| = 0.5.
        Ray ray = new Ray(new Vec3(-2, 2, -3), new Vec3(0.5, 0, 0), 3.0, 100.0);
        IntersectionRecord rec = new IntersectionRecord();
        assertHit("tMin = 3 lies between the roots t = 2 and t = 10", s, ray, rec, Calls.intersect(s, rec, ray), 10,
                new Vec3(3, 2, -3), new Vec3(1, 0, 0), "the near root is below tMin: the far root is the hit");
    }

    @Test
    @DisplayName("tMax before the near root: no hit")
    void tMaxBeforeTheNearRootMisses() {
        Sphere s = new Sphere(new Vec3(1, 2, -3), 2, M, "sphere");
        Ray ray = new Ray(new Vec3(-2, 2, -3), new Vec3(0.5, 0, 0), 0.0, 1.9);
        IntersectionRecord rec = new IntersectionRecord();
        assertUntouched("tMax = 1.9 is before both roots (t = 2 and t = 10)", s, ray, rec, Calls.intersect(s, rec, ray),
                new IntersectionRecord(), "a root is a hit only when tMin ≤ t ≤ tMax");
    }

    @Test
    @DisplayName("tMax between the two roots: the hit is still the near point")
    void tMaxBetweenTheRootsStillGivesTheNearPoint() {
        Sphere s = new Sphere(new Vec3(0, 0, 0), 1, M, "sphere");
        Ray ray = new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -2), 0.0, 2.5);
        IntersectionRecord rec = new IntersectionRecord();
        assertHit("tMax = 2.5 between the roots t = 2 and t = 3", s, ray, rec, Calls.intersect(s, rec, ray), 2,
                new Vec3(0, 0, 1), new Vec3(0, 0, 1), "the near root t = 2 is in range");
    }

    @Test
    @DisplayName("a hit farther than the record's t leaves the record as it was")
    void recordIsLeftUntouchedByAFartherHit() {
        long seed = 0xfa47e4L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Sphere s = randomSphere(r);
            Vec3 u = unit(r);
            Vec3 x = s.center.plus(u.times(s.radius));
            Vec3 d = within(r, u.negate(), 0.2).times(scale(r));
            double t = uniform(r, 0.5, 30) / d.length();
            Ray ray = new Ray(x.minus(d.times(t)), d);
            // An earlier hit closer than the entry point (and than the exit point).
            IntersectionRecord rec = recordWith(t * 0.9);
            IntersectionRecord before = copy(rec);
            assertUntouched("a closer hit is already recorded #" + i + " (seed " + seed + ")", s, ray, rec,
                    Calls.intersect(s, rec, ray), before,
                    "record a hit only if t < outRecord.t; otherwise leave every field of the record as it was");
        }
    }

    @Test
    @DisplayName("a recorded hit between the two roots is kept")
    void recordWithAHitBetweenTheRootsKeepsIt() {
        Sphere s = new Sphere(new Vec3(0, 0, 0), 1, M, "sphere");
        Ray ray = new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1));
        // Entry at t = 4, exit at t = 6; an earlier hit at t = 3.5 is closer than both.
        IntersectionRecord rec = recordWith(3.5);
        IntersectionRecord before = copy(rec);
        assertUntouched("recorded hit at t = 3.5, sphere roots t = 4 and t = 6", s, ray, rec,
                Calls.intersect(s, rec, ray), before, "the far root is not closer either: no update");
    }

    @Test
    @DisplayName("a hit closer than the record's t replaces it")
    void closerHitReplacesARecordedFartherOne() {
        Sphere s = new Sphere(new Vec3(0, 0, 0), 1, M, "sphere");
        Ray ray = new Ray(new Vec3(0, 0, 5), new Vec3(0, 0, -1));
        IntersectionRecord rec = recordWith(4.5);
        assertHit("recorded hit at t = 4.5, sphere entry at t = 4", s, ray, rec, Calls.intersect(s, rec, ray), 4,
                new Vec3(0, 0, 1), new Vec3(0, 0, 1), "t = 4 < outRecord.t = 4.5: record the new hit");
    }

    @Test
    @DisplayName("very short and very long directions d: t scales with 1/‖d‖")
    void veryShortAndVeryLongDirectionsScaleT() {
        Sphere s = new Sphere(new Vec3(3, -1, 2), 0.5, M, "sphere");
        for (double k : new double[] {1e-6, 1e-3, 1, 1e3, 1e6}) {
            Ray ray = new Ray(new Vec3(3, -1, 10), new Vec3(0, 0, -k));
            IntersectionRecord rec = new IntersectionRecord();
            assertHit("direction (0, 0, " + (-k) + ")", s, ray, rec, Calls.intersect(s, rec, ray), 7.5 / k,
                    new Vec3(3, -1, 2.5), new Vec3(0, 0, 1),
                    "divide by d·d: with |d| = " + k + " the hit is at t = 7.5 / " + k);
        }
    }

    @Test
    @DisplayName("spheres far away, very large and very small")
    void farAwayLargeAndSmallSpheres() {
        for (double size : new double[] {1e-3, 1, 1e3}) {
            Vec3 c = new Vec3(100 * size, 50 * size, -200 * size);
            Sphere s = new Sphere(c, size, M, "sphere");
            Vec3 p = new Vec3(0, 0, 0);
            Vec3 toward = c.minus(p);
            Ray ray = new Ray(p, toward.times(0.37));
            IntersectionRecord rec = new IntersectionRecord();
            double dist = toward.length();
            Vec3 x = c.minus(toward.times(size / dist));
            assertHit("a sphere of radius " + size + " at distance " + dist, s, ray, rec, Calls.intersect(s, rec, ray),
                    (dist - size) / dist / 0.37, x, toward.times(-1 / dist), "scale-independent formula");
        }
    }

    @Test
    @DisplayName("exact values: t = tMin and t = tMax count, t equal to the record's t does not replace it")
    void closedRangeAndStrictRecordComparisonAtExactValues() {
        // Exactly representable: entry at t = 2 and exit at t = 4 for every correct method.
        Sphere s = new Sphere(new Vec3(0, 0, 0), 1, M, "sphere");
        Ray ray = new Ray(new Vec3(0, 0, 3), new Vec3(0, 0, -1), 0, 2);
        IntersectionRecord rec = new IntersectionRecord();
        assertHit("tMax = 2 equals the entry t = 2", s, ray, rec, Calls.intersect(s, rec, ray), 2, new Vec3(0, 0, 1),
                new Vec3(0, 0, 1), "the range is closed: tMin ≤ t ≤ tMax");
        Ray full = new Ray(new Vec3(0, 0, 3), new Vec3(0, 0, -1));
        IntersectionRecord same = recordWith(2);
        IntersectionRecord before = copy(same);
        assertUntouched("a hit at t = 2 is already recorded (outRecord.t = 2)", s, full, same,
                Calls.intersect(s, same, full), before, "update only when t < outRecord.t (strictly closer); here the far root t = 4 is farther too");
        Ray inside = new Ray(new Vec3(0, 0, 0), new Vec3(0, 0, 1));
        IntersectionRecord atExit = recordWith(1);
        IntersectionRecord before2 = copy(atExit);
        assertUntouched("from the centre, exit at t = 1, outRecord.t = 1", s, inside, atExit,
                Calls.intersect(s, atExit, inside), before2, "the far root must also be strictly closer than outRecord.t");
        Ray fromInsideAtTMin = new Ray(new Vec3(0, 0, 3), new Vec3(0, 0, -1), 4, 10);
        IntersectionRecord rec3 = new IntersectionRecord();
        assertHit("tMin = 4 equals the exit t = 4", s, fromInsideAtTMin, rec3, Calls.intersect(s, rec3, fromInsideAtTMin), 4,
                new Vec3(0, 0, -1), new Vec3(0, 0, -1), "the range is closed at tMin too");
    }

    private static Vec3 axis(int k, double s) {
        return new Vec3(k == 0 ? s : 0, k == 1 ? s : 0, k == 2 ? s : 0);
    }

    /**
     * Rays that touch the sphere at one point, with small integers and power-of-two direction
     * lengths: every formula (the quadratic's b² − a·c, the geometric method, the reference's)
     * computes a discriminant of exactly 0 here, so every correct method agrees: a touching ray
     * hits (the sphere is the closed set ‖x − c‖ = r; the two roots coincide).
     */
    @Test
    @DisplayName("rays exactly touching the sphere hit at their one point")
    void exactlyTouchingRaysHitAtTheirOnePoint() {
        long seed = 0x7a9eL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < 60; i++) {
            Vec3 c = new Vec3(r.nextInt(-10, 11), r.nextInt(-10, 11), r.nextInt(-10, 11));
            int radius = r.nextInt(1, 6);
            int touch = r.nextInt(3);
            int travel = (touch + 1 + r.nextInt(2)) % 3;
            double side = r.nextBoolean() ? 1 : -1;
            double along = r.nextBoolean() ? 1 : -1;
            int back = r.nextInt(2 * radius, 21);
            double k = Math.scalb(1.0, r.nextInt(-3, 4));
            Sphere s = new Sphere(c, radius, M, "sphere");
            Vec3 x = c.plus(axis(touch, side * radius));
            Ray ray = new Ray(x.minus(axis(travel, along * back)), axis(travel, along * k));
            IntersectionRecord rec = new IntersectionRecord();
            assertHit("ray touching the sphere #" + i + " (seed " + seed + ")", s, ray, rec, Calls.intersect(s, rec, ray),
                    back / k, x, axis(touch, side),
                    "a discriminant of exactly 0 is a hit (the ray touches the sphere): miss only when it is < 0");
        }
    }
}
