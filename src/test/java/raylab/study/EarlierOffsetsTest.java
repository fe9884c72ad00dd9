package raylab.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.FlatColor;
import raylab.math.Color;
import raylab.math.Numerics;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Sphere;

/** The hit-point offset the study compares (2^-42·max|x_i|): its side, its scale, and that it escapes a sphere. */
class EarlierOffsetsTest {
    @Test
    void offsetGoesToTheSideOfW() {
        Vec3 x = new Vec3(1, 2, 3);
        Vec3 n = new Vec3(0, 0, 1);
        double off = EarlierOffsets.originOffset(x);
        Vec3 up = EarlierOffsets.moved(x, n, new Vec3(0.3, -0.2, 0.5), EarlierOffsets.originOffset(x));
        Vec3 down = EarlierOffsets.moved(x, n, new Vec3(0.3, -0.2, -0.5), EarlierOffsets.originOffset(x));
        assertEquals(new Vec3(1, 2, 3 + off), up, "w on the side of n: moved along +n by " + off);
        assertEquals(new Vec3(1, 2, 3 - off), down, "w against n: moved along -n by " + off);
        assertTrue(up.z > 3 && down.z < 3, "the moves actually change the coordinate: " + up + ", " + down);
    }

    @Test
    void offsetScalesWithTheSizeOfX() {
        assertEquals(Numerics.MIN_OFFSET, EarlierOffsets.originOffset(Vec3.ZERO), "at the origin: the minimum offset");
        double o1 = EarlierOffsets.originOffset(new Vec3(1, 0, 0));
        double o1000 = EarlierOffsets.originOffset(new Vec3(0, -1000, 5));
        assertEquals(Math.scalb(1.0, -42), o1, "offset at |x| = 1 is 2^-42");
        assertEquals(1000 * o1, o1000, "offset grows in proportion to the largest coordinate");
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {11, 12, 13})
    void offsetIsManyUlpsOfTheLargestCoordinate(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        for (int i = 0; i < 1000; i++) {
            double scale = Math.pow(10, rnd.nextInt(-6, 9));
            Vec3 x = new Vec3(rnd.nextDouble(-1, 1) * scale, rnd.nextDouble(-1, 1) * scale,
                    rnd.nextDouble(-1, 1) * scale);
            double off = EarlierOffsets.originOffset(x);
            double ulps = off / Math.ulp(x.maxAbs());
            assertTrue(ulps >= 1024, "seed " + seed + ": offset " + off + " at x=" + x + " is only "
                    + ulps + " ulps of the largest coordinate");
            assertTrue(off <= 1e-11 * Math.max(1e-30, x.maxAbs()) + Numerics.MIN_OFFSET,
                    "seed " + seed + ": offset " + off + " at x=" + x + " is too large");
        }
    }

    /**
     * The purpose of the offset: at any scale, a ray leaving a sphere's computed hit point
     * outward (offset along the outward normal) does not hit the sphere again.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22, 23})
    void offsetOriginEscapesTheSurfaceAtEveryScale(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        FlatColor m = new FlatColor(Color.WHITE, "m");
        IntersectionRecord rec = new IntersectionRecord();
        int checked = 0;
        for (int i = 0; i < 2000; i++) {
            double scale = Math.pow(10, rnd.nextInt(-3, 7));
            Vec3 c = new Vec3(rnd.nextDouble(-5, 5), rnd.nextDouble(-5, 5), rnd.nextDouble(-5, 5)).times(scale);
            double r = scale * rnd.nextDouble(0.1, 1);
            Sphere s = new Sphere(c, r, m, "s");
            Vec3 eye = c.plus(new Vec3(rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1))
                    .normalize().times(3 * r));
            Vec3 target = c.plus(new Vec3(rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1))
                    .times(0.5 * r));
            Ray eyeRay = new Ray(eye, target.minus(eye));
            rec.reset();
            if (!s.intersect(rec, eyeRay)) {
                continue;
            }
            checked++;
            Vec3 x = rec.point;
            Vec3 n = rec.normal;
            // leave toward a random direction on the outer side of the surface
            Vec3 w = n.plus(new Vec3(rnd.nextDouble(-0.9, 0.9), rnd.nextDouble(-0.9, 0.9),
                    rnd.nextDouble(-0.9, 0.9)));
            if (w.dot(n) <= 0.05) {
                continue;
            }
            Vec3 origin = EarlierOffsets.moved(x, n, w, EarlierOffsets.originOffset(x));
            assertNotEquals(x, origin, "the origin must move");
            Ray leaving = new Ray(origin, w);
            IntersectionRecord again = new IntersectionRecord();
            assertFalse(s.intersect(again, leaving), "seed " + seed + ": ray " + leaving
                    + " leaving sphere c=" + c + " r=" + r + " at " + x + " hits it again: " + again);
        }
        assertTrue(checked > 1000, "seed " + seed + ": too few eye rays hit (" + checked + ")");
    }
}
