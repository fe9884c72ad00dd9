package raylab.surface;

import java.util.Random;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.Lambertian;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.Ray;
import raylab.testing.Check;

/** Milestone sphere: {@link Sphere#intersect}. Run with {@code ./mvnw test -Dgroups=sphere}. */
@Tag("sphere")
class SphereTest {
    static final Lambertian WHITE = new Lambertian(new Color(1, 1, 1), Color.BLACK, "white");
    static final Sphere UNIT = new Sphere(new Vec3(0, 0, 0), 1, WHITE, "unit sphere");

    /** From (0,0,5) along −z: the unit sphere is met at z = 1 (t = 4) and z = −1 (t = 6). */
    static final Vec3 P = new Vec3(0, 0, 5);
    static final Vec3 DOWN_Z = new Vec3(0, 0, -1);

    @Test
    @DisplayName("a ray straight at the unit sphere hits its near side at t = 4")
    void plainHit() {
        Check.hit(UNIT, new Ray(P, DOWN_Z), 4, new Vec3(0, 0, 1), new Vec3(0, 0, 1));
    }

    @Test
    @DisplayName("off-centre sphere, hit away from the pole: normal (0.6, 0.8, 0)")
    void offCentre() {
        // Centre c = (1,−2,3), radius 3. The ray runs along −x at height y = c.y + 2.4, so it
        // meets the sphere where x − c.x = √(3² − 2.4²) = 1.8: the point c + (1.8, 2.4, 0).
        // Starting at x = 11 it gets to x = 2.8 at t = 8.2; the normal is (1.8, 2.4, 0)/3.
        Sphere s = new Sphere(new Vec3(1, -2, 3), 3, WHITE, "off-centre sphere");
        Check.hit(s, new Ray(new Vec3(11, 0.4, 3), new Vec3(-1, 0, 0)),
                8.2, new Vec3(2.8, 0.4, 3), new Vec3(0.6, 0.8, 0));
    }

    @Test
    @DisplayName("a big sphere far away: t = 920")
    void farAway() {
        // Centre (0,0,−1000), radius 100; the ray from (0,60,0) along −z meets it where
        // z − (−1000) = √(100² − 60²) = 80, at z = −920: t = 920, normal (0, 60, 80)/100.
        Sphere s = new Sphere(new Vec3(0, 0, -1000), 100, WHITE, "far sphere");
        Check.hit(s, new Ray(new Vec3(0, 60, 0), DOWN_Z),
                920, new Vec3(0, 60, -920), new Vec3(0, 0.6, 0.8));
    }

    @Test
    @DisplayName("a ray that passes beside the sphere misses")
    void miss() {
        Check.miss(UNIT, new Ray(new Vec3(0, 2, 5), DOWN_Z), "the discriminant is negative here");
    }

    @Test
    @DisplayName("a ray passing just inside the rim (y = 0.999) hits")
    void nearlyTangentHit() {
        // At height y = 0.999 the sphere's surface is at z = √(1 − 0.999²) ≈ 0.0447.
        double z = Math.sqrt(1 - 0.999 * 0.999);
        Vec3 x = new Vec3(0, 0.999, z);
        Check.hit(UNIT, new Ray(new Vec3(0, 0.999, 5), DOWN_Z), 5 - z, x, x);
    }

    @Test
    @DisplayName("a ray passing just outside the rim (y = 1.001) misses")
    void nearlyTangentMiss() {
        Check.miss(UNIT, new Ray(new Vec3(0, 1.001, 5), DOWN_Z), null);
    }

    @Test
    @DisplayName("a ray starting inside hits the far side (the farther root), normal outward")
    void startsInside() {
        // From (0,0,0.5) along −z the roots are t = −0.5 (behind) and t = 1.5 (z = −1).
        Check.hit(UNIT, new Ray(new Vec3(0, 0, 0.5), DOWN_Z),
                1.5, new Vec3(0, 0, -1), new Vec3(0, 0, -1));
    }

    @Test
    @DisplayName("a sphere behind the ray's origin is not hit")
    void behind() {
        // From (0,0,5) along +z: the roots are t = −6 and t = −4, both behind the origin.
        Check.miss(UNIT, new Ray(P, new Vec3(0, 0, 1)), "both roots are negative: no hit");
    }

    @ParameterizedTest(name = "d scaled by {0}")
    @ValueSource(doubles = {0.01, 0.5, 2, 100})
    @DisplayName("d need not have length 1: scaling d by a divides t by a, same point")
    void unnormalizedDirection(double a) {
        Check.hit(UNIT, new Ray(P, DOWN_Z.times(a)), 4 / a, new Vec3(0, 0, 1), new Vec3(0, 0, 1));
    }

    @Test
    @DisplayName("tMax just above the hit: counted; just below: not (and the far root is out too)")
    void tMaxBound() {
        Check.hit(UNIT, new Ray(P, DOWN_Z, 0, 4 + 1e-6), 4, new Vec3(0, 0, 1), new Vec3(0, 0, 1));
        Check.miss(UNIT, new Ray(P, DOWN_Z, 0, 4 - 1e-6), "t = 4 > tMax does not count");
    }

    @Test
    @DisplayName("tMin just below the near hit: counted")
    void tMinBelow() {
        Check.hit(UNIT, new Ray(P, DOWN_Z, 4 - 1e-6, Double.POSITIVE_INFINITY),
                4, new Vec3(0, 0, 1), new Vec3(0, 0, 1));
    }

    @Test
    @DisplayName("tMin just past the near hit: the far side (t = 6) is the hit")
    void tMinAbove() {
        Check.hit(UNIT, new Ray(P, DOWN_Z, 4 + 1e-6, Double.POSITIVE_INFINITY),
                6, new Vec3(0, 0, -1), new Vec3(0, 0, -1));
    }

    @Test
    @DisplayName("tMin past both roots: no hit")
    void tMinPastBoth() {
        Check.miss(UNIT, new Ray(P, DOWN_Z, 6 + 1e-6, Double.POSITIVE_INFINITY), null);
    }

    @Test
    @DisplayName("a miss leaves a record that holds another hit exactly as it was")
    void missLeavesRecord() {
        Check.untouched(Check.recordWithHitAt(100), UNIT, new Ray(new Vec3(0, 2, 5), DOWN_Z), null);
    }

    @Test
    @DisplayName("a hit farther than the record's t (4 > 3) leaves the record as it was")
    void fartherHitLeavesRecord() {
        Check.untouched(Check.recordWithHitAt(3), UNIT, new Ray(P, DOWN_Z), null);
    }

    @Test
    @DisplayName("a hit closer than the record's t (4 < 5) replaces it")
    void closerHitReplacesRecord() {
        Check.hit(Check.recordWithHitAt(5), UNIT, new Ray(P, DOWN_Z),
                4, new Vec3(0, 0, 1), new Vec3(0, 0, 1), null);
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4, 5})
    @DisplayName("random spheres and rays, built so that we know where they hit")
    void random(long seed) {
        Random rnd = new Random(seed);
        for (int i = 0; i < 50; i++) {
            Vec3 c = new Vec3(rnd.nextDouble() * 20 - 10, rnd.nextDouble() * 20 - 10,
                    rnd.nextDouble() * 20 - 10);
            double r = 0.5 + rnd.nextDouble() * 4.5;
            // Pick the hit point x = c + r·u, and a direction d that enters the sphere there
            // (d·u clearly negative). The ray starts at p = x − t·d, outside: it hits x at t.
            Vec3 u = randomUnit(rnd);
            Vec3 d;
            do {
                d = randomUnit(rnd);
            } while (d.dot(u) > -0.2);
            d = d.times(0.05 + rnd.nextDouble() * 20);
            double distance = 0.1 + rnd.nextDouble() * 20;
            double t = distance / d.length();
            Vec3 x = c.plus(u.times(r));
            Sphere s = new Sphere(c, r, WHITE, "random sphere #" + i + " of seed " + seed);
            Check.hit(s, new Ray(x.minus(d.times(t)), d), t, x, u);
        }
    }

    static Vec3 randomUnit(Random rnd) {
        return new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()).normalize();
    }
}
