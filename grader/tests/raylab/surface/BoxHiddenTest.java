package raylab.surface;

import static raylab.hidden.Hidden.M;
import static raylab.hidden.Hidden.assertHit;
import static raylab.hidden.Hidden.assertUntouched;
import static raylab.hidden.Hidden.copy;
import static raylab.hidden.Hidden.point;
import static raylab.hidden.Hidden.recordWith;
import static raylab.hidden.Hidden.scale;
import static raylab.hidden.Hidden.uniform;
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
 * Hidden tests of Box.intersect (grader only). Answers are built first: a point on a face (away
 * from its edges), then a ray through it.
 */
@Tag("box")
class BoxHiddenTest {
    private static final int N = 200;

    private static Box randomBox(SplittableRandom r) {
        Vec3 lo = point(r, 20);
        Vec3 size = new Vec3(uniform(r, 0.3, 6), uniform(r, 0.3, 6), uniform(r, 0.3, 6));
        return new Box(lo, lo.plus(size), M, "box");
    }

    /** A point on face (axis, side) of the box, at least 10% of the face away from its edges. */
    private static Vec3 onFace(SplittableRandom r, Box b, int axis, int side) {
        double[] c = new double[3];
        for (int k = 0; k < 3; k++) {
            double lo = b.min.get(k);
            double hi = b.max.get(k);
            c[k] = k == axis ? (side > 0 ? hi : lo) : lo + (hi - lo) * uniform(r, 0.1, 0.9);
        }
        return new Vec3(c[0], c[1], c[2]);
    }

    private static Vec3 axisVector(int axis, double s) {
        return new Vec3(axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0);
    }

    @Test
    @DisplayName("random rays from outside enter through the right face")
    void randomRaysFromOutsideEnterThroughTheRightFace() {
        long seed = 0xb0c5L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Box b = randomBox(r);
            int axis = r.nextInt(3);
            int side = r.nextBoolean() ? 1 : -1;
            Vec3 n = axisVector(axis, side);
            Vec3 x = onFace(r, b, axis, side);
            Vec3 d = within(r, n.negate(), 0.3).times(scale(r));
            double t = uniform(r, 0.5, 30) / d.length();
            Ray ray = new Ray(x.minus(d.times(t)), d);
            IntersectionRecord rec = new IntersectionRecord();
            assertHit("random ray from outside #" + i + " (seed " + seed + ")", b, ray, rec, Calls.intersect(b, rec, ray),
                    t, x, n, "t_enter = max of the slab entries, t_exit = min of the slab exits; "
                            + "swap a slab's two t values when d has a negative component");
        }
    }

    @Test
    @DisplayName("random rays from inside leave through the right face")
    void randomRaysFromInsideLeaveThroughTheRightFace() {
        long seed = 0x1b51deL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Box b = randomBox(r);
            Vec3 p = new Vec3(uniform(r, b.min.x, b.max.x), uniform(r, b.min.y, b.max.y), uniform(r, b.min.z, b.max.z));
            p = b.min.plus(p.minus(b.min).times(0.9)).plus(b.max.minus(b.min).times(0.05));
            int axis = r.nextInt(3);
            int side = r.nextBoolean() ? 1 : -1;
            Vec3 x = onFace(r, b, axis, side);
            double k = scale(r);
            Ray ray = new Ray(p, x.minus(p).times(k));
            IntersectionRecord rec = new IntersectionRecord();
            assertHit("random ray from inside #" + i + " (seed " + seed + ")", b, ray, rec, Calls.intersect(b, rec, ray),
                    1 / k, x, axisVector(axis, side),
                    "from inside, t_enter < 0: the hit is t_exit, with the normal of the face it leaves through");
        }
    }

    @Test
    @DisplayName("rays parallel to an axis (components of d equal to 0)")
    void axisParallelRays() {
        Box b = new Box(new Vec3(-1, -2, -3), new Vec3(1, 2, 3), M, "box");
        for (int axis = 0; axis < 3; axis++) {
            for (int side : new int[] {1, -1}) {
                Vec3 d = axisVector(axis, -side * 0.25);
                Vec3 offset = new Vec3(axis == 0 ? 0 : 0.3, axis == 1 ? 0 : -0.4, axis == 2 ? 0 : 0.5);
                Vec3 p = offset.plus(axisVector(axis, side * 10));
                Vec3 x = offset.plus(axisVector(axis, side * b.max.get(axis)));
                Ray ray = new Ray(p, d);
                IntersectionRecord rec = new IntersectionRecord();
                assertHit("ray along axis " + axis, b, ray, rec, Calls.intersect(b, rec, ray),
                        (10 - b.max.get(axis)) / 0.25, x, axisVector(axis, side),
                        "a zero direction component means the ray is inside that slab for all t (or never)");
                // The same ray moved outside another slab misses.
                int other = (axis + 1) % 3;
                Ray away = new Ray(p.plus(axisVector(other, 5)), d);
                IntersectionRecord rec2 = new IntersectionRecord();
                assertUntouched("ray along axis " + axis + " outside the slab of axis " + other, b, away, rec2,
                        Calls.intersect(b, rec2, away), new IntersectionRecord(),
                        "d = 0 on an axis whose slab does not contain p: no hit");
            }
        }
    }

    @Test
    @DisplayName("rays passing beside the box miss")
    void raysPassingBesideTheBoxMiss() {
        long seed = 0xbe5dL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Box b = randomBox(r);
            Vec3 size = b.max.minus(b.min);
            // A line through a point outside a corner region, aimed parallel to a face diagonal so
            // the slab intervals do not overlap.
            Vec3 q = b.max.plus(new Vec3(size.x * uniform(r, 0.2, 1), size.y * uniform(r, 0.2, 1), 0));
            Vec3 d = new Vec3(-uniform(r, 0.1, 1), uniform(r, 0.1, 1), uniform(r, -1, 1)).times(scale(r));
            double back = uniform(r, 1, 10);
            Ray ray = new Ray(q.minus(d.times(back)), d);
            // q is beyond max in x and y; moving along d lowers x while raising y: both never inside together.
            IntersectionRecord rec = new IntersectionRecord();
            assertUntouched("ray beside the box #" + i + " (seed " + seed + ")", b, ray, rec, Calls.intersect(b, rec, ray),
                    new IntersectionRecord(), "the ray misses when t_enter > t_exit");
        }
    }

    @Test
    @DisplayName("a box behind the ray's origin is missed")
    void boxBehindTheOriginIsMissed() {
        long seed = 0xbe4b0L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Box b = randomBox(r);
            int axis = r.nextInt(3);
            int side = r.nextBoolean() ? 1 : -1;
            Vec3 n = axisVector(axis, side);
            Vec3 x = onFace(r, b, axis, side);
            Vec3 d = within(r, n.negate(), 0.3).times(scale(r));
            // Start past the box and keep going: both slab-interval ends are negative.
            Vec3 size = b.max.minus(b.min);
            double beyond = (size.length() * 2 + uniform(r, 0.5, 10)) / d.length();
            Ray ray = new Ray(x.plus(d.times(beyond)), d);
            IntersectionRecord rec = new IntersectionRecord();
            assertUntouched("box behind the origin #" + i + " (seed " + seed + ")", b, ray, rec,
                    Calls.intersect(b, rec, ray), new IntersectionRecord(), "t_exit < tMin: the box is behind the ray");
        }
    }

    @Test
    @DisplayName("tMin inside the box: the hit is the exit")
    void tMinInsideTheBoxGivesTheExit() {
        Box b = new Box(new Vec3(0, 0, 0), new Vec3(2, 2, 2), M, "box");
        Ray ray = new Ray(new Vec3(-4, 1, 1), new Vec3(2, 0, 0), 2.5, 100);
        IntersectionRecord rec = new IntersectionRecord();
        assertHit("tMin = 2.5 between t_enter = 2 and t_exit = 3", b, ray, rec, Calls.intersect(b, rec, ray), 3,
                new Vec3(2, 1, 1), new Vec3(1, 0, 0), "t_enter is below tMin: record t_exit, face x = x_max");
    }

    @Test
    @DisplayName("tMax before the box: no hit")
    void tMaxBeforeTheBoxMisses() {
        Box b = new Box(new Vec3(0, 0, 0), new Vec3(2, 2, 2), M, "box");
        Ray ray = new Ray(new Vec3(-4, 1, 1), new Vec3(2, 0, 0), 0, 1.9);
        IntersectionRecord rec = new IntersectionRecord();
        assertUntouched("tMax = 1.9 before t_enter = 2", b, ray, rec, Calls.intersect(b, rec, ray),
                new IntersectionRecord(), "t_enter > tMax: no hit");
    }

    @Test
    @DisplayName("a hit farther than the record's t leaves the record as it was")
    void recordIsLeftUntouchedByAFartherHit() {
        long seed = 0xfa4b0L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Box b = randomBox(r);
            int axis = r.nextInt(3);
            int side = r.nextBoolean() ? 1 : -1;
            Vec3 n = axisVector(axis, side);
            Vec3 x = onFace(r, b, axis, side);
            Vec3 d = within(r, n.negate(), 0.3).times(scale(r));
            double t = uniform(r, 0.5, 30) / d.length();
            Ray ray = new Ray(x.minus(d.times(t)), d);
            IntersectionRecord rec = recordWith(t * 0.9);
            IntersectionRecord before = copy(rec);
            assertUntouched("a closer hit is already recorded #" + i + " (seed " + seed + ")", b, ray, rec,
                    Calls.intersect(b, rec, ray), before, "record only hits with t < outRecord.t; leave the record untouched");
        }
    }

    @Test
    @DisplayName("a hit closer than the record's t replaces it")
    void closerHitReplacesARecordedFartherOne() {
        Box b = new Box(new Vec3(0, 0, 0), new Vec3(2, 2, 2), M, "box");
        Ray ray = new Ray(new Vec3(1, 1, 7), new Vec3(0, 0, -0.5));
        IntersectionRecord rec = recordWith(11);
        assertHit("recorded hit at t = 11, box entry at t = 10", b, ray, rec, Calls.intersect(b, rec, ray), 10,
                new Vec3(1, 1, 2), new Vec3(0, 0, 1), "t = 10 < outRecord.t = 11: record the new hit");
    }

    @Test
    @DisplayName("exact values: t = tMin and t = tMax count, t equal to the record's t does not replace it")
    void closedRangeAndStrictRecordComparisonAtExactValues() {
        Box b = new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1), M, "box");
        Ray ray = new Ray(new Vec3(-5, 0.5, 0.25), new Vec3(1, 0, 0), 0, 4);
        IntersectionRecord rec = new IntersectionRecord();
        assertHit("tMax = 4 equals t_enter = 4", b, ray, rec, Calls.intersect(b, rec, ray), 4, new Vec3(-1, 0.5, 0.25),
                new Vec3(-1, 0, 0), "the range is closed: tMin ≤ t ≤ tMax");
        Ray full = new Ray(new Vec3(-5, 0.5, 0.25), new Vec3(1, 0, 0));
        IntersectionRecord same = recordWith(4);
        IntersectionRecord before = copy(same);
        assertUntouched("outRecord.t = 4 equals t_enter = 4", b, full, same, Calls.intersect(b, same, full), before,
                "update only when t < outRecord.t (strictly closer)");
        Ray inside = new Ray(new Vec3(0, 0.5, 0.25), new Vec3(1, 0, 0));
        IntersectionRecord atExit = recordWith(1);
        IntersectionRecord before2 = copy(atExit);
        assertUntouched("from inside, t_exit = 1 equals outRecord.t = 1", b, inside, atExit, Calls.intersect(b, atExit, inside),
                before2, "the exit must also be strictly closer than outRecord.t");
    }

    /** A number on the 1/8 grid: exact in binary, so a ray can lie exactly in a face's plane. */
    private static double grid(SplittableRandom r, double lo, double hi) {
        return Math.round(uniform(r, lo, hi) * 8) / 8.0;
    }

    /** A box with corners on the 1/8 grid; flat (min = max) along {@code flatAxis} unless it is −1. */
    private static Box gridBox(SplittableRandom r, int flatAxis) {
        double[] lo = new double[3];
        double[] hi = new double[3];
        for (int k = 0; k < 3; k++) {
            lo[k] = grid(r, -20, 20);
            hi[k] = k == flatAxis ? lo[k] : lo[k] + grid(r, 0.5, 6);
        }
        return new Box(new Vec3(lo[0], lo[1], lo[2]), new Vec3(hi[0], hi[1], hi[2]), M, "box");
    }

    /**
     * Rays lying exactly in the plane of a face (p on the plane, d zero along its axis), as
     * orthographic views make them: the closed box contains the face, so the ray hits the box where
     * it enters the face, on the edge with the face it enters through. Every correct method agrees
     * (the slab test that treats d = 0 apart, the inverse-direction slabs, whose NaN comparisons
     * are false); only (min − p)/d = 0/0 = NaN carried through Math.min/Math.max misses. The normal at
     * that edge may be either face's.
     */
    @Test
    @DisplayName("rays in the plane of a face hit where they enter the face")
    void raysInAFacePlaneHitTheBoxWhereTheyEnterTheFace() {
        long seed = 0xf1a7L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Box b = gridBox(r, -1);
            int plane = r.nextInt(3);
            int planeSide = r.nextBoolean() ? 1 : -1;
            int entry = (plane + 1 + r.nextInt(2)) % 3;
            int entrySide = r.nextBoolean() ? 1 : -1;
            int other = 3 - plane - entry;
            double[] x = new double[3];
            double[] d = new double[3];
            x[plane] = planeSide > 0 ? b.max.get(plane) : b.min.get(plane);
            x[entry] = entrySide > 0 ? b.max.get(entry) : b.min.get(entry);
            x[other] = b.min.get(other) + (b.max.get(other) - b.min.get(other)) * uniform(r, 0.1, 0.9);
            d[plane] = r.nextBoolean() ? 0.0 : -0.0;
            d[entry] = -entrySide * uniform(r, 0.3, 1);
            d[other] = uniform(r, -1, 1);
            Vec3 dir = new Vec3(d[0], d[1], d[2]).times(scale(r));
            Vec3 hit = new Vec3(x[0], x[1], x[2]);
            double t = uniform(r, 0.5, 30) / dir.length();
            Ray ray = new Ray(hit.minus(dir.times(t)), dir); // p lies exactly on the plane: d is 0 there
            IntersectionRecord rec = new IntersectionRecord();
            boolean returned = Calls.intersect(b, rec, ray);
            Vec3 inPlane = axisVector(plane, planeSide);
            Vec3 normal = rec.normal != null && rec.normal.minus(inPlane).length() <= 1e-6 ? inPlane
                    : axisVector(entry, entrySide);
            assertHit("ray in the plane of a face #" + i + " (seed " + seed + ")", b, ray, rec, returned, t, hit, normal,
                    "the ray lies in a face's plane: (min − p)/d is 0/0 = NaN there, and NaN makes every comparison"
                            + " false; when d is 0 along an axis, the ray is inside that slab for every t (min ≤ p ≤ max"
                            + " counts, the box is closed) or never");
        }
    }

    /**
     * A flat box (min = max along one axis, allowed by the scene format) is entered and left at one
     * t; the normal may be either face's.
     */
    @Test
    @DisplayName("flat boxes (min = max along one axis) are hit from either side")
    void flatBoxesAreHitFromEitherSide() {
        long seed = 0xf1a7b0L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            int axis = r.nextInt(3);
            Box b = gridBox(r, axis);
            int side = r.nextBoolean() ? 1 : -1;
            Vec3 n = axisVector(axis, side);
            Vec3 x = onFace(r, b, axis, side);
            Vec3 d = within(r, n.negate(), 0.3).times(scale(r));
            double t = uniform(r, 0.5, 30) / d.length();
            Ray ray = new Ray(x.minus(d.times(t)), d);
            IntersectionRecord rec = new IntersectionRecord();
            // Both faces of the flat slab are met at the same t: either outward normal is a valid
            // answer (the lecture leaves the choice open, and the renderer turns n toward the viewer).
            assertHit("flat box #" + i + " (seed " + seed + ")", b, ray, rec, Calls.intersect(b, rec, ray), t, x,
                    java.util.List.of(n, n.negate()),
                    "min = max along one axis: the ray enters and leaves that slab at the same t, so t_enter = t_exit;"
                            + " it misses only when t_enter > t_exit");
        }
    }
}
