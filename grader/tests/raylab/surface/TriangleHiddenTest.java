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
 * Hidden tests of Triangle.intersect (grader only). A point is chosen by barycentric coordinates
 * (inside with a margin, or outside one edge with a margin), then a ray through it: the plane and
 * edges test and Möller–Trumbore both pass.
 */
@Tag("triangle")
class TriangleHiddenTest {
    private static final int N = 200;

    private static Triangle randomTriangle(SplittableRandom r) {
        while (true) {
            Vec3 a = point(r, 20);
            double size = uniform(r, 0.5, 10);
            Vec3 b = a.plus(unit(r).times(size));
            Vec3 c = a.plus(unit(r).times(size * uniform(r, 0.5, 1.5)));
            Vec3 n = b.minus(a).cross(c.minus(a));
            // Not too thin: the smallest angle well away from 0.
            if (n.length() > 0.3 * b.minus(a).length() * c.minus(a).length()
                    && n.length() > 0.3 * b.minus(a).length() * c.minus(b).length()) {
                return new Triangle(a, b, c, M, "triangle");
            }
        }
    }

    private static Vec3 unitNormal(Triangle tr) {
        return tr.b.minus(tr.a).cross(tr.c.minus(tr.a)).normalize();
    }

    private static Vec3 at(Triangle tr, double beta, double gamma) {
        return tr.a.times(1 - beta - gamma).plus(tr.b.times(beta)).plus(tr.c.times(gamma));
    }

    @Test
    @DisplayName("random rays through the interior, from both sides")
    void randomRaysThroughTheInteriorFromBothSides() {
        long seed = 0x7e1aL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Triangle tr = randomTriangle(r);
            Vec3 n = unitNormal(tr);
            double beta = uniform(r, 0.05, 0.9);
            double gamma = uniform(r, 0.05, 0.95 - beta);
            Vec3 x = at(tr, beta, gamma);
            Vec3 axis = i % 2 == 0 ? n.negate() : n; // from the front, then from the back
            Vec3 d = within(r, axis, 0.2).times(scale(r));
            double t = uniform(r, 0.5, 30) / d.length();
            Ray ray = new Ray(x.minus(d.times(t)), d);
            IntersectionRecord rec = new IntersectionRecord();
            assertHit("random ray through the interior #" + i + " (seed " + seed + ", from the "
                    + (i % 2 == 0 ? "front" : "back") + ")", tr, ray, rec, Calls.intersect(tr, rec, ray), t, x, n,
                    "t = (a − p)·n / (d·n); the normal is (b − a) × (c − a) normalized, whichever side the ray comes from");
        }
    }

    @Test
    @DisplayName("rays just outside each edge miss")
    void pointsJustOutsideEachEdgeMiss() {
        long seed = 0xed9eL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < 3 * N; i++) {
            Triangle tr = randomTriangle(r);
            Vec3 n = unitNormal(tr);
            double[] w = {uniform(r, 0.1, 1), uniform(r, 0.1, 1), 0};
            int edge = i % 3; // the barycentric coordinate made negative
            double s = w[0] + w[1];
            double[] bary = new double[3];
            bary[(edge + 1) % 3] = (w[0] / s) * 1.05;
            bary[(edge + 2) % 3] = (w[1] / s) * 1.05;
            bary[edge] = 1 - bary[(edge + 1) % 3] - bary[(edge + 2) % 3]; // about −0.05
            Vec3 x = at(tr, bary[1], bary[2]);
            Vec3 d = within(r, i % 2 == 0 ? n.negate() : n, 0.2).times(scale(r));
            Ray ray = new Ray(x.minus(d.times(uniform(r, 0.5, 30) / d.length())), d);
            IntersectionRecord rec = new IntersectionRecord();
            assertUntouched("plane point just outside edge " + "abc".charAt((edge + 1) % 3) + "abc".charAt((edge + 2) % 3)
                    + " #" + i + " (seed " + seed + ")", tr, ray, rec, Calls.intersect(tr, rec, ray),
                    new IntersectionRecord(), "the point must be on the inner side of all three edges");
        }
    }

    @Test
    @DisplayName("rays parallel to the plane (d·n = 0) miss")
    void raysParallelToThePlaneMiss() {
        long seed = 0x9a4aL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Triangle tr = randomTriangle(r);
            Vec3 n = unitNormal(tr);
            Vec3 inPlane = tr.b.minus(tr.a).times(uniform(r, -1, 1)).plus(tr.c.minus(tr.a).times(uniform(r, -1, 1)));
            if (inPlane.length() < 1e-3) {
                continue;
            }
            Vec3 p = at(tr, 0.3, 0.3).plus(n.times(uniform(r, 0.1, 3) * (r.nextBoolean() ? 1 : -1)))
                    .minus(inPlane.times(2));
            Ray ray = new Ray(p, inPlane);
            IntersectionRecord rec = new IntersectionRecord();
            assertUntouched("ray parallel to the plane, off the plane #" + i + " (seed " + seed + ")", tr, ray, rec,
                    Calls.intersect(tr, rec, ray), new IntersectionRecord(), "d·n = 0: the ray never meets the plane");
        }
    }

    @Test
    @DisplayName("a triangle behind the ray's origin is missed")
    void triangleBehindTheOriginIsMissed() {
        long seed = 0xbe47L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Triangle tr = randomTriangle(r);
            Vec3 n = unitNormal(tr);
            Vec3 x = at(tr, 0.3, 0.3);
            Vec3 d = within(r, n, 0.2).times(scale(r));
            Ray ray = new Ray(x.plus(d.times(uniform(r, 0.5, 30) / d.length())), d);
            IntersectionRecord rec = new IntersectionRecord();
            assertUntouched("triangle behind the origin #" + i + " (seed " + seed + ")", tr, ray, rec,
                    Calls.intersect(tr, rec, ray), new IntersectionRecord(), "t < tMin: behind the ray's origin");
        }
    }

    @Test
    @DisplayName("a hit just inside [tMin, tMax] counts, just before tMin or past tMax it does not")
    void theEndsOfTheTRange() {
        Triangle tr = new Triangle(new Vec3(-1, -1, 0), new Vec3(3, -1, 0), new Vec3(-1, 3, 0), M, "triangle");
        Vec3 p = new Vec3(0, 0, 4);
        Vec3 d = new Vec3(0, 0, -2); // hit at t = 2
        IntersectionRecord rec = new IntersectionRecord();
        Ray inside = new Ray(p, d, 1.9, 2.1);
        assertHit("t range [1.9, 2.1] around the hit t = 2", tr, inside, rec, Calls.intersect(tr, rec, inside), 2,
                new Vec3(0, 0, 0), new Vec3(0, 0, 1), "the hit is in range");
        Ray early = new Ray(p, d, 0, 1.9);
        IntersectionRecord rec2 = new IntersectionRecord();
        assertUntouched("tMax = 1.9 before the hit at t = 2", tr, early, rec2, Calls.intersect(tr, rec2, early),
                new IntersectionRecord(), "t > tMax: no hit");
        Ray late = new Ray(p, d, 2.1, 100);
        IntersectionRecord rec3 = new IntersectionRecord();
        assertUntouched("tMin = 2.1 after the hit at t = 2", tr, late, rec3, Calls.intersect(tr, rec3, late),
                new IntersectionRecord(), "t < tMin: no hit");
    }

    @Test
    @DisplayName("a hit farther than the record's t leaves the record as it was")
    void recordIsLeftUntouchedByAFartherHit() {
        long seed = 0xfa47L;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < N; i++) {
            Triangle tr = randomTriangle(r);
            Vec3 n = unitNormal(tr);
            Vec3 x = at(tr, uniform(r, 0.1, 0.4), uniform(r, 0.1, 0.4));
            Vec3 d = within(r, n.negate(), 0.2).times(scale(r));
            double t = uniform(r, 0.5, 30) / d.length();
            Ray ray = new Ray(x.minus(d.times(t)), d);
            IntersectionRecord rec = recordWith(t * 0.9);
            IntersectionRecord before = copy(rec);
            assertUntouched("a closer hit is already recorded #" + i + " (seed " + seed + ")", tr, ray, rec,
                    Calls.intersect(tr, rec, ray), before, "record only hits with t < outRecord.t");
        }
    }

    @Test
    @DisplayName("a hit closer than the record's t replaces it")
    void closerHitReplacesARecordedFartherOne() {
        Triangle tr = new Triangle(new Vec3(0, 0, -5), new Vec3(0, 4, -5), new Vec3(4, 0, -5), M, "triangle");
        Ray ray = new Ray(new Vec3(1, 1, 0), new Vec3(0, 0, -1));
        IntersectionRecord rec = recordWith(5.5);
        // (b − a) × (c − a) = (0,4,0) × (4,0,0) = (0, 0, −16): the unit normal is (0, 0, −1).
        assertHit("recorded hit at t = 5.5, triangle at t = 5", tr, ray, rec, Calls.intersect(tr, rec, ray), 5,
                new Vec3(1, 1, -5), new Vec3(0, 0, -1), "t = 5 < outRecord.t: record it; n = (b − a) × (c − a) normalized");
    }

    @Test
    @DisplayName("tiny and huge triangles")
    void tinyAndHugeTriangles() {
        for (double size : new double[] {1e-3, 1, 1e3}) {
            Triangle tr = new Triangle(new Vec3(0, 0, 0).times(size), new Vec3(2, 0, 1).times(size),
                    new Vec3(0, 2, 1).times(size), M, "triangle");
            Vec3 x = new Vec3(0.5, 0.5, 0.5).times(size);
            Vec3 d = new Vec3(0.1, -0.2, -1);
            Ray ray = new Ray(x.minus(d.times(3 * size)), d);
            IntersectionRecord rec = new IntersectionRecord();
            Vec3 n = new Vec3(2, 0, 1).cross(new Vec3(0, 2, 1)).normalize();
            assertHit("triangle of size " + size, tr, ray, rec, Calls.intersect(tr, rec, ray), 3 * size, x, n,
                    "the same method works at every scale");
        }
    }

    @Test
    @DisplayName("exact values: t = tMin and t = tMax count, t equal to the record's t does not replace it")
    void closedRangeAndStrictRecordComparisonAtExactValues() {
        Triangle tr = new Triangle(new Vec3(0, 0, 0), new Vec3(1, 0, 0), new Vec3(0, 1, 0), M, "triangle");
        Ray exact = new Ray(new Vec3(0.25, 0.25, 2), new Vec3(0, 0, -1), 2, 2);
        IntersectionRecord rec = new IntersectionRecord();
        assertHit("tMin = tMax = 2 equals the hit t = 2", tr, exact, rec, Calls.intersect(tr, rec, exact), 2,
                new Vec3(0.25, 0.25, 0), new Vec3(0, 0, 1), "the range is closed at both ends");
        Ray full = new Ray(new Vec3(0.25, 0.25, 2), new Vec3(0, 0, -1));
        IntersectionRecord same = recordWith(2);
        IntersectionRecord before = copy(same);
        assertUntouched("outRecord.t = 2 equals the hit t = 2", tr, full, same, Calls.intersect(tr, same, full), before,
                "update only when t < outRecord.t (strictly closer)");
    }

    private static Vec3 axis(int k, double s) {
        return new Vec3(k == 0 ? s : 0, k == 1 ? s : 0, k == 2 ? s : 0);
    }

    /**
     * Rays through points exactly on an edge or at a vertex, with data where no correct method
     * rounds: right triangles with legs of power-of-two length along two axes, integer corners, a
     * ray along the third axis whose length is a power of two (so the determinant of
     * Möller–Trumbore is one too, and its u, v and u + v are exact). Every edge test then computes
     * exactly 0 and every correct method agrees: the triangle is closed, such points are hits.
     */
    @Test
    @DisplayName("rays exactly through an edge or a vertex hit")
    void pointsExactlyOnAnEdgeOrAVertexAreHits() {
        long seed = 0xed9eL;
        SplittableRandom r = Hidden.rng(seed);
        double[][] onBoundary = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.25, 0.75}, {0, 0.375}, {0.125, 0}, {0.5, 0.5}};
        for (int i = 0; i < 96; i++) {
            int ax = r.nextInt(3);
            int ay = (ax + 1) % 3;
            int az = (ax + 2) % 3;
            Vec3 a = new Vec3(r.nextInt(-10, 11), r.nextInt(-10, 11), r.nextInt(-10, 11));
            Vec3 b = a.plus(axis(ax, (r.nextBoolean() ? 1 : -1) * Math.scalb(1.0, r.nextInt(-1, 4))));
            Vec3 c = a.plus(axis(ay, (r.nextBoolean() ? 1 : -1) * Math.scalb(1.0, r.nextInt(-1, 4))));
            Triangle tr = r.nextBoolean() ? new Triangle(a, b, c, M, "triangle") : new Triangle(a, c, b, M, "triangle");
            double[] bc = onBoundary[i % onBoundary.length];
            // The point a + β (b − a) + γ (c − a): β, γ ≥ 0, β + γ ≤ 1, one of them 0 or their sum 1.
            Vec3 x = a.plus(b.minus(a).times(bc[0])).plus(c.minus(a).times(bc[1]));
            double along = r.nextBoolean() ? 1 : -1;
            int back = r.nextInt(1, 21);
            double k = Math.scalb(1.0, r.nextInt(-3, 4));
            Ray ray = new Ray(x.minus(axis(az, along * back)), axis(az, along * k));
            IntersectionRecord rec = new IntersectionRecord();
            assertHit("ray through an edge or a vertex #" + i + " (seed " + seed + ", barycentric " + bc[0] + ", "
                    + bc[1] + ")", tr, ray, rec, Calls.intersect(tr, rec, ray), back / k, x, unitNormal(tr),
                    "a point on an edge belongs to the triangle: the edge tests are ≥ 0 (a barycentric coordinate of"
                            + " exactly 0 or a sum of exactly 1 is inside)");
        }
    }

    /**
     * A ray lying in the triangle's plane, through its interior, and a degenerate triangle (its
     * three corners on one line; allowed in scenes, never hit): small integers, so d·n, the
     * determinant of Möller–Trumbore and every edge test are exactly 0 for every correct method.
     */
    @Test
    @DisplayName("rays in the triangle's plane miss, and degenerate triangles are never hit")
    void raysInThePlaneAndDegenerateTrianglesMiss() {
        long seed = 0xde9eL;
        SplittableRandom r = Hidden.rng(seed);
        for (int i = 0; i < 60; i++) {
            int ax = r.nextInt(3);
            int ay = (ax + 1) % 3;
            int az = (ax + 2) % 3;
            Vec3 a = new Vec3(r.nextInt(-10, 11), r.nextInt(-10, 11), r.nextInt(-10, 11));
            Vec3 b = a.plus(axis(ax, r.nextInt(2, 9)));
            Vec3 c = a.plus(axis(ay, r.nextInt(2, 9)));
            Triangle tr = new Triangle(a, b, c, M, "triangle");
            // Through the interior point a + (b − a)/4 + (c − a)/4, along a direction in the plane.
            Vec3 x = a.plus(b.minus(a).times(0.25)).plus(c.minus(a).times(0.25));
            // Power-of-two components, so that the ratio of any two is exact too.
            double[] steps = {0, 1, 2, 4, -1, -2, -4};
            Vec3 d = axis(ax, Math.scalb(1.0, r.nextInt(0, 3))).plus(axis(ay, steps[r.nextInt(steps.length)]));
            Ray inPlane = new Ray(x.minus(d.times(r.nextInt(2, 9))), d);
            IntersectionRecord rec = new IntersectionRecord();
            assertUntouched("ray in the triangle's plane #" + i + " (seed " + seed + ")", tr, inPlane, rec,
                    Calls.intersect(tr, rec, inPlane), new IntersectionRecord(),
                    "d·n = 0: the ray is parallel to the plane (here: in it); no hit");
            Vec3 e = axis(ax, r.nextInt(1, 5)).plus(axis(ay, r.nextInt(-4, 5)));
            Triangle flat = r.nextBoolean() ? new Triangle(a, a.plus(e), a.plus(e.times(2)), M, "degenerate")
                    : new Triangle(a, a, a.plus(e), M, "degenerate");
            Vec3 onIt = a.plus(e.times(0.5));
            Ray through = new Ray(onIt.minus(axis(az, r.nextInt(1, 9))), axis(az, 1));
            IntersectionRecord rec2 = new IntersectionRecord();
            assertUntouched("degenerate triangle (corners on one line) #" + i + " (seed " + seed + ")", flat, through,
                    rec2, Calls.intersect(flat, rec2, through), new IntersectionRecord(),
                    "n = (b − a) × (c − a) = 0: a triangle without area is never hit");
        }
    }
}
