package raylab.numerics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import java.util.stream.Stream;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.FlatColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Box;

/**
 * Hard cases for the slab method, judged by the exact {@link Oracle#box}: zero direction
 * components, origins exactly on a slab plane (where (lo − p)/d = 0/0 = NaN), rays running
 * along faces and edges. The reference's policy (documented in docs/numerics.md): a slab with
 * d = 0 contains the whole line when min ≤ p ≤ max (closed), else none of it; the naive slabs
 * ({@link BoxMethods#naiveSlabs}) turn the 0/0 into a NaN and report a miss.
 */
@Tag("numerics")
class BoxNumericsTest {
    static final FlatColor M = new FlatColor(Color.WHITE, "m");
    static final Box UNIT = new Box(new Vec3(0, 0, 0), new Vec3(1, 1, 1), M, "unit box");

    static Stream<Arguments> boundaryRays() {
        return Stream.of(
                Arguments.of("along the face z = 1", new Vec3(-1, 0.5, 1), new Vec3(1, 0, 0)),
                Arguments.of("along the face y = 0, going up z", new Vec3(0.3, 0, -2), new Vec3(0, 0, 3)),
                Arguments.of("along the edge y = 1, z = 1", new Vec3(-1, 1, 1), new Vec3(2, 0, 0)),
                Arguments.of("along the edge x = 0, y = 0", new Vec3(0, 0, 5), new Vec3(0, 0, -1)),
                Arguments.of("from inside the face x = 1, along it", new Vec3(1, 0.5, 0.5), new Vec3(0, 1, 0)),
                Arguments.of("from a corner along an edge", new Vec3(0, 0, 0), new Vec3(0, 0, 1)),
                Arguments.of("along the face x = 0, tiny d", new Vec3(0, -1, 0.5), new Vec3(0, 1e-300, 0)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("boundaryRays")
    void rayAlongTheBoundaryHitsTheClosedBox(String name, Vec3 p, Vec3 d) {
        Ray ray = new Ray(p, d);
        Oracle.BoxHit o = Oracle.box(UNIT.min, UNIT.max, p, d, ray.tMin, ray.tMax);
        assertTrue(o.hit, "oracle should hit for " + name + ": " + o);
        IntersectionRecord ref = new IntersectionRecord();
        assertTrue(UNIT.intersect(ref, ray), name + ": reference misses " + ray + "; " + o);
        assertEquals(o.t.doubleValue(), ref.t, 0, name + ": " + ray);
        int axis = ref.normal.x != 0 ? 0 : ref.normal.y != 0 ? 1 : 2;
        assertTrue((o.axes & (1 << axis)) != 0 || o.axes == 0,
                name + ": normal " + ref.normal + " not of a plane through the hit; " + o);
        IntersectionRecord naive = new IntersectionRecord();
        boolean naiveHit = BoxMethods.naiveSlabs(UNIT, naive, ray);
        assertTrue(!naiveHit || Double.isNaN(naive.t),
                name + ": expected the naive slabs to fail through NaN, got " + naive);
    }

    /**
     * Random boxes and rays, with direction components set to zero and origins snapped onto
     * slab planes at random (so many rays run exactly along faces and edges): the reference
     * agrees with the oracle on every hit/miss (no margin needed: on these data its decisions
     * came out exact), its t is within 2 ulps (one subtraction, one division), its point lies
     * exactly on the plane of the face its normal names; the naive slabs get some cases wrong.
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4})
    void randomDegenerateRaysAgreeWithTheOracle(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        int naiveWrong = 0;
        int cases = 0;
        double worstUlps = 0;
        for (int i = 0; i < 10000; i++) {
            double scale = Gen.logUniform(rnd, -4, 6);
            Vec3 shift = Gen.unit(rnd).times(scale * Gen.logUniform(rnd, -1, 3));
            Vec3 lo = new Vec3(rnd.nextDouble(-1, 0), rnd.nextDouble(-1, 0), rnd.nextDouble(-1, 0))
                    .times(scale).plus(shift);
            Vec3 hi = new Vec3(rnd.nextDouble(0, 1), rnd.nextDouble(0, 1), rnd.nextDouble(0, 1))
                    .times(scale).plus(shift);
            double[] p = new double[3];
            double[] d = new double[3];
            for (int k = 0; k < 3; k++) {
                double l = lo.get(k);
                double h = hi.get(k);
                int pick = rnd.nextInt(4);
                p[k] = pick == 0 ? l : pick == 1 ? h : l + (h - l) * rnd.nextDouble(-1, 2);
                d[k] = rnd.nextInt(3) == 0 ? 0 : rnd.nextDouble(-1, 1) * scale;
            }
            if (d[0] == 0 && d[1] == 0 && d[2] == 0) {
                continue;
            }
            Vec3 pv = new Vec3(p[0], p[1], p[2]);
            Vec3 dv = new Vec3(d[0], d[1], d[2]);
            Ray ray = new Ray(pv, dv);
            Box box = new Box(lo, hi, M, "box");
            Oracle.BoxHit o = Oracle.box(lo, hi, pv, dv, ray.tMin, ray.tMax);
            IntersectionRecord ref = new IntersectionRecord();
            boolean hit = box.intersect(ref, ray);
            String what = "seed " + seed + ": " + ray + " vs box [" + lo + ", " + hi + "], " + o;
            assertEquals(o.hit, hit, what + ": reference " + ref);
            cases++;
            if (hit) {
                double ulps = Oracle.ulpError(ref.t, o.t);
                worstUlps = Math.max(worstUlps, ulps);
                assertTrue(ulps <= 2, what + ": reference t=" + ref.t + " is " + ulps + " ulps off");
                int axis = ref.normal.x != 0 ? 0 : ref.normal.y != 0 ? 1 : 2;
                double plane = ref.normal.get(axis) > 0 ? hi.get(axis) : lo.get(axis);
                assertEquals(plane, ref.point.get(axis), 0, what + ": point " + ref.point
                        + " not on the plane of its normal " + ref.normal);
                for (int k = 0; k < 3; k++) {
                    assertTrue(ref.point.get(k) >= lo.get(k) && ref.point.get(k) <= hi.get(k),
                            what + ": point " + ref.point + " outside the box");
                }
            }
            IntersectionRecord naive = new IntersectionRecord();
            boolean naiveHit = BoxMethods.naiveSlabs(box, naive, ray);
            if (naiveHit != o.hit || (naiveHit && Double.isNaN(naive.t))) {
                naiveWrong++;
            }
        }
        System.out.printf("boxes seed %d: %d rays with zero components / on-plane origins; reference"
                + " wrong 0, worst t %.2f ulps; naive slabs wrong %d%n", seed, cases, worstUlps,
                naiveWrong);
        assertTrue(naiveWrong > 0, "seed " + seed + ": the naive slabs got all " + cases
                + " cases right");
    }
}
