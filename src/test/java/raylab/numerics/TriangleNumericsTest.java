package raylab.numerics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import raylab.material.FlatColor;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Triangle;

/**
 * Hard cases for ray–triangle intersection: watertightness on closed meshes, rays exactly
 * through edges and vertices, degenerate and nearly degenerate triangles, rays nearly parallel
 * to the plane. Judged by the exact {@link Oracle#triangle} where a single triangle is involved.
 */
@Tag("numerics")
class TriangleNumericsTest {
    static final FlatColor M = new FlatColor(Color.WHITE, "m");
    static final double U = Gen.U;

    interface Method {
        boolean intersect(Triangle t, IntersectionRecord rec, Ray ray);
    }

    static final Vec3[] OCTAHEDRON = {new Vec3(1, 0, 0), new Vec3(-1, 0, 0), new Vec3(0, 1, 0),
        new Vec3(0, -1, 0), new Vec3(0, 0, 1), new Vec3(0, 0, -1)};
    static final int[][] OCTAHEDRON_FACES = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
        {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    static final Vec3[] TETRAHEDRON = {new Vec3(1, 1, 1), new Vec3(1, -1, -1), new Vec3(-1, 1, -1),
        new Vec3(-1, -1, 1)};
    static final int[][] TETRAHEDRON_FACES = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    static final Vec3[] CUBE = {new Vec3(-1, -1, -1), new Vec3(1, -1, -1), new Vec3(1, 1, -1),
        new Vec3(-1, 1, -1), new Vec3(-1, -1, 1), new Vec3(1, -1, 1), new Vec3(1, 1, 1),
        new Vec3(-1, 1, 1)};
    static final int[][] CUBE_FACES = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5},
        {0, 5, 4}, {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};

    /**
     * Shoots rays from random points inside a closed mesh (randomly rotated, scaled 10^-3..10^3
     * and moved up to 10^3 of its size away from the origin) at points exactly on its edges
     * (rounded interpolations of two vertices) and at its vertices; every such ray must leave
     * the mesh through some triangle. Returns the number of rays that hit nothing.
     */
    static long escapes(long seed, int meshes, int raysPerMesh, Method method) {
        SplittableRandom rnd = new SplittableRandom(seed);
        long misses = 0;
        IntersectionRecord rec = new IntersectionRecord();
        for (int m = 0; m < meshes; m++) {
            int kind = m % 3;
            Vec3[] base = kind == 0 ? OCTAHEDRON : kind == 1 ? TETRAHEDRON : CUBE;
            int[][] faces = kind == 0 ? OCTAHEDRON_FACES : kind == 1 ? TETRAHEDRON_FACES : CUBE_FACES;
            double scale = Math.pow(10, rnd.nextInt(-3, 4));
            Vec3 center = Gen.unit(rnd).times(scale * Math.pow(10, rnd.nextInt(0, 4)));
            Vec3[] rot = Gen.rotation(rnd);
            Vec3[] v = new Vec3[base.length];
            for (int i = 0; i < v.length; i++) {
                v[i] = Gen.apply(rot, base[i]).times(scale).plus(center);
            }
            List<Triangle> tris = new ArrayList<>();
            List<int[]> edges = new ArrayList<>();
            for (int[] f : faces) {
                tris.add(new Triangle(v[f[0]], v[f[1]], v[f[2]], M, "face"));
                for (int k = 0; k < 3; k++) {
                    edges.add(new int[] {f[k], f[(k + 1) % 3]});
                }
            }
            for (int r = 0; r < raysPerMesh; r++) {
                Vec3 origin = center.plus(Gen.unit(rnd).times(scale * 0.3 * rnd.nextDouble()));
                Vec3 target;
                if (rnd.nextInt(4) == 0) {
                    target = v[rnd.nextInt(v.length)];
                } else {
                    int[] e = edges.get(rnd.nextInt(edges.size()));
                    double s = rnd.nextDouble();
                    target = v[e[0]].times(1 - s).plus(v[e[1]].times(s));
                }
                Ray ray = new Ray(origin, target.minus(origin));
                rec.reset();
                boolean hit = false;
                for (Triangle t : tris) {
                    hit |= method.intersect(t, rec, ray);
                }
                if (!hit) {
                    misses++;
                }
            }
        }
        return misses;
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 4})
    void referenceIsWatertight(long seed) {
        long misses = escapes(seed, 500, 500, TriangleMethods::reference);
        System.out.printf("watertight seed %d: reference lets %d of 250000 rays through%n", seed, misses);
        assertEquals(0, misses, "seed " + seed + ": rays from inside a closed mesh aimed at its edges"
                + " and vertices slipped through");
    }

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2})
    void lectureAndMollerTrumboreLeak(long seed) {
        long lecture = escapes(seed, 100, 500, TriangleMethods::lecture);
        long mt = escapes(seed, 100, 500, TriangleMethods::mollerTrumbore);
        System.out.printf("watertight seed %d: of 50000 rays, lecture lets %d through,"
                + " Moller-Trumbore %d%n", seed, lecture, mt);
        assertTrue(lecture > 0, "seed " + seed + ": lecture method let no ray through");
        assertTrue(mt > 0, "seed " + seed + ": Moller-Trumbore let no ray through");
    }

    /**
     * Lines through exact points of an edge or a vertex: small dyadic vertices, directions whose
     * components are 0 or ±2^k, so that the oracle finds a barycentric coordinate exactly 0 and
     * the reference's translation and shear into ray space are exact too. The closed triangle
     * must report the hit. (For other directions the shear rounds, and a lone triangle may call
     * such a ray either way; shared edges are still never missed by both triangles, which
     * {@link #referenceIsWatertight} checks.)
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {7, 8})
    void exactEdgeAndVertexHitsCount(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        int lectureMisses = 0;
        for (int i = 0; i < 5000; i++) {
            int e = rnd.nextInt(-10, 10);
            Vec3 a = intVec(rnd, 64).times(Math.scalb(1.0, e));
            Vec3 b = intVec(rnd, 64).times(Math.scalb(1.0, e));
            Vec3 c = intVec(rnd, 64).times(Math.scalb(1.0, e));
            Triangle tri = new Triangle(a, b, c, M, "t");
            Vec3 on;
            int which = rnd.nextInt(4);
            if (which == 3) {
                on = a;
            } else {
                Vec3 from = which == 0 ? a : which == 1 ? b : c;
                Vec3 to = which == 0 ? b : which == 1 ? c : a;
                on = from.plus(to.minus(from).times(rnd.nextInt(0, 9) / 8.0));
            }
            Vec3 d = new Vec3(dyadic(rnd), dyadic(rnd), dyadic(rnd)).times(Math.scalb(1.0, e));
            if (d.maxAbs() == 0) {
                continue;
            }
            Vec3 p = on.minus(d.times(4));
            Oracle.TriangleHit o = Oracle.triangle(a, b, c, p, d);
            if (!o.meetsPlane) {
                continue;
            }
            Ray ray = new Ray(p, d);
            String what = "seed " + seed + ": " + ray + " through " + on + " on triangle " + a + ", "
                    + b + ", " + c + "; " + o;
            assertTrue(o.hits(0, Double.POSITIVE_INFINITY) && o.minBarycentric() == 0, what);
            IntersectionRecord rec = new IntersectionRecord();
            assertTrue(tri.intersect(rec, ray), what + ": reference misses");
            assertEquals(4.0, rec.t, tBound(a, b, c, p, d), what);
            if (!TriangleMethods.lecture(tri, new IntersectionRecord(), ray)) {
                lectureMisses++;
            }
        }
        System.out.printf("exact edge/vertex hits seed %d: lecture method missed %d of ~5000%n",
                seed, lectureMisses);
    }

    /** 0 or ±2^k, k in −2..2. */
    static double dyadic(SplittableRandom rnd) {
        return rnd.nextInt(3) == 0 ? 0 : (rnd.nextBoolean() ? 1 : -1) * Math.scalb(1.0, rnd.nextInt(-2, 3));
    }

    /** 2^6·u·(‖a − p‖ + ‖b − p‖ + ‖c − p‖) / |d·n̂|: the t error of a backward-stable method. */
    static double tBound(Vec3 a, Vec3 b, Vec3 c, Vec3 p, Vec3 d) {
        Vec3 n = b.minus(a).cross(c.minus(a)).normalize();
        double span = a.minus(p).length() + b.minus(p).length() + c.minus(p).length();
        return 64 * U * span / Math.abs(d.dot(n));
    }

    static Vec3 intVec(SplittableRandom rnd, int bound) {
        return new Vec3(rnd.nextInt(-bound, bound + 1), rnd.nextInt(-bound, bound + 1),
                rnd.nextInt(-bound, bound + 1));
    }

    @Test
    void degenerateTrianglesAreNeverHit() {
        SplittableRandom rnd = new SplittableRandom(11);
        for (int i = 0; i < 5000; i++) {
            int e = rnd.nextInt(-20, 20);
            Vec3 a = intVec(rnd, 1000).times(Math.scalb(1.0, e));
            Vec3 step = intVec(rnd, 30).times(Math.scalb(1.0, e));
            int kind = rnd.nextInt(3);
            Vec3 b = kind == 0 ? a : a.plus(step);
            Vec3 c = kind == 1 ? b : a.plus(step.times(rnd.nextInt(-4, 5)));
            Triangle tri = new Triangle(a, b, c, M, "degenerate");
            Vec3 target = a.plus(step.times(rnd.nextDouble(-1, 2)));
            Vec3 p = target.plus(Gen.unit(rnd).times(Math.scalb(10.0, e)));
            Ray ray = new Ray(p, target.minus(p));
            IntersectionRecord rec = new IntersectionRecord();
            rec.t = 1e300;
            assertFalse(tri.intersect(rec, ray), "seed 11: zero-area triangle " + a + ", " + b + ", "
                    + c + " hit by " + ray + ": " + rec);
            assertEquals(1e300, rec.t, "record must stay untouched");
            assertNull(rec.surface, "record must stay untouched");
        }
    }

    /**
     * Slivers (height 10^-14..10^-6 of their length) and rays nearly parallel to the plane
     * (cosine 10^-12..10^-2): outside the margin (the exact point farther from every edge line
     * than the point-error bound below), the reference agrees with the oracle on hit or miss; its t is within
     * {@link #tBound} of the exact t, and its point within 2^5·u·max|vertex| + ‖d‖·tBound of the
     * exact point (a nearly parallel ray moves the plane point by 1/cos times any error).
     */
    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {21, 22})
    void slivers_and_nearlyParallelRays(long seed) {
        SplittableRandom rnd = new SplittableRandom(seed);
        int checked = 0;
        double worstT = 0;
        double worstX = 0;
        for (int i = 0; i < 5000; i++) {
            double scale = Gen.logUniform(rnd, -3, 3);
            Vec3 shift = Gen.unit(rnd).times(scale * Gen.logUniform(rnd, -1, 3));
            Vec3 a = Gen.unit(rnd).times(scale).plus(shift);
            Vec3 b = Gen.unit(rnd).times(scale).plus(shift);
            Vec3 c;
            boolean sliver = rnd.nextBoolean();
            if (sliver) {
                Vec3 mid = a.times(0.5).plus(b.times(0.5));
                c = mid.plus(Gen.unit(rnd).times(scale * Gen.logUniform(rnd, -14, -6)));
            } else {
                c = Gen.unit(rnd).times(scale).plus(shift);
            }
            Vec3 n = b.minus(a).cross(c.minus(a)).normalize();
            if (!n.isFinite()) {
                continue; // rounding made the sliver exactly degenerate
            }
            Vec3 target = a.times(0.3).plus(b.times(0.3)).plus(c.times(0.4))
                    .plus(b.minus(a).times(rnd.nextDouble(-0.3, 0.3)));
            Vec3 inPlane = n.cross(Gen.unit(rnd)).normalize();
            double cos = sliver ? rnd.nextDouble(0.1, 1) : Gen.logUniform(rnd, -12, -2);
            Vec3 dir = inPlane.times(Math.sqrt(1 - cos * cos)).plus(n.times(-cos));
            Vec3 p = target.minus(dir.times(scale * 3));
            Vec3 d = dir.times(Gen.logUniform(rnd, -2, 2));
            Oracle.TriangleHit o = Oracle.triangle(a, b, c, p, d);
            if (!o.meetsPlane) {
                continue;
            }
            double tTol = tBound(a, b, c, p, d);
            double xTol = 32 * U * Math.max(a.maxAbs(), Math.max(b.maxAbs(), c.maxAbs()))
                    + d.length() * tTol;
            // margin: the exact point must be farther than xTol from every edge line; its
            // distance to the edge opposite vertex i is |b_i|·‖(b − a) × (c − a)‖ / ‖edge‖
            double twiceArea = b.minus(a).cross(c.minus(a)).length();
            double edgeDistance = Math.min(Math.abs(o.b0.doubleValue()) / c.minus(b).length(),
                    Math.min(Math.abs(o.b1.doubleValue()) / a.minus(c).length(),
                            Math.abs(o.b2.doubleValue()) / b.minus(a).length())) * twiceArea;
            if (edgeDistance <= xTol) {
                continue; // within rounding of an edge: either answer is acceptable
            }
            Triangle tri = new Triangle(a, b, c, M, "t");
            Ray ray = new Ray(p, d);
            IntersectionRecord rec = new IntersectionRecord();
            boolean hit = tri.intersect(rec, ray);
            String what = "seed " + seed + ": " + ray + " vs triangle " + a + ", " + b + ", " + c
                    + "; " + o;
            assertEquals(o.hits(0, Double.POSITIVE_INFINITY), hit, what + "; reference " + rec);
            if (hit) {
                checked++;
                double tErr = Math.abs(rec.t - o.t.doubleValue());
                worstT = Math.max(worstT, tErr / tTol);
                assertTrue(tErr <= tTol, what + ": t=" + rec.t + " off by " + tErr + " > " + tTol);
                Vec3 exact = Oracle.point(p, d, o.t);
                double xErr = rec.point.minus(exact).maxAbs();
                worstX = Math.max(worstX, xErr / xTol);
                assertTrue(xErr <= xTol, what + ": point " + rec.point + " off by " + xErr);
            }
        }
        System.out.printf("slivers/near-parallel seed %d: %d hits checked, worst t error %.3f of"
                + " its bound, worst point error %.3f of its bound%n", seed, checked, worstT, worstX);
        assertTrue(checked > 500, "seed " + seed + ": too few hits checked: " + checked);
    }
}
