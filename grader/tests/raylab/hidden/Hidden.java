package raylab.hidden;

import static org.junit.jupiter.api.Assertions.fail;

import java.util.SplittableRandom;

import raylab.material.FlatColor;
import raylab.material.Material;
import raylab.math.Color;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Surface;

/**
 * Helpers shared by the hidden tests (grader only, never shipped): seeded random geometry with
 * known answers, and checks whose messages give the ray, the surface, expected and actual values.
 *
 * <p>Fairness rules every hidden test follows: answers are built first (a hit point chosen on the
 * surface, then a ray through it), so they do not come from any one intersection method; nothing
 * sits exactly on a boundary (edges, tangents, the ends of the t range are approached with a
 * margin); comparisons allow a relative tolerance far above the rounding error of any correct
 * method (algebraic or geometric, normalized or not).
 */
public final class Hidden {
    /** Relative tolerance for t, points and normals. */
    public static final double TOL = 1e-7;
    /** Material of the surfaces under test. */
    public static final Material M = new FlatColor(Color.WHITE, "white");

    private Hidden() {
    }

    /** A seeded generator; the seed goes into every message. */
    public static SplittableRandom rng(long seed) {
        return new SplittableRandom(seed);
    }

    public static double uniform(SplittableRandom r, double lo, double hi) {
        return lo + (hi - lo) * r.nextDouble();
    }

    /** A uniformly random unit vector. */
    public static Vec3 unit(SplittableRandom r) {
        while (true) {
            Vec3 v = new Vec3(uniform(r, -1, 1), uniform(r, -1, 1), uniform(r, -1, 1));
            double l2 = v.lengthSquared();
            if (l2 > 1e-4 && l2 <= 1) {
                return v.times(1 / Math.sqrt(l2));
            }
        }
    }

    public static Vec3 point(SplittableRandom r, double extent) {
        return new Vec3(uniform(r, -extent, extent), uniform(r, -extent, extent), uniform(r, -extent, extent));
    }

    /** A random unit vector v with v·axis ≥ minCos (a direction on the axis' side, not grazing). */
    public static Vec3 within(SplittableRandom r, Vec3 axis, double minCos) {
        while (true) {
            Vec3 v = unit(r);
            if (v.dot(axis) >= minCos) {
                return v;
            }
        }
    }

    /** A random length for d: from 1e-2 to 1e2, since d need not be a unit vector. */
    public static double scale(SplittableRandom r) {
        return Math.pow(10, uniform(r, -2, 2));
    }

    /** A record already holding a hit at t, by a sentinel surface. */
    public static IntersectionRecord recordWith(double t) {
        IntersectionRecord rec = new IntersectionRecord();
        rec.set(t, new Vec3(7, 7, 7), new Vec3(0, 1, 0), new Surface(M, "earlier hit") {
            @Override
            public boolean intersect(IntersectionRecord o, Ray ray) {
                return false;
            }

            @Override
            public raylab.math.BoundingBox boundingBox() {
                return new raylab.math.BoundingBox(Vec3.ZERO, Vec3.ZERO);
            }
        });
        return rec;
    }

    /** Checks a hit: the return value, t, point, unit outward normal and surface. */
    public static void assertHit(String what, Surface s, Ray ray, IntersectionRecord rec, boolean returned,
            double t, Vec3 point, Vec3 normal, String hint) {
        assertHit(what, s, ray, rec, returned, t, point, java.util.List.of(normal), hint);
    }

    /**
     * Checks a hit whose normal may be any of {@code normals}: where the lecture leaves the choice
     * open (a flat box, min = max, is entered through both faces at the same t), every valid
     * answer scores.
     */
    public static void assertHit(String what, Surface s, Ray ray, IntersectionRecord rec, boolean returned,
            double t, Vec3 point, java.util.List<Vec3> normals, String hint) {
        String ctx = context(what, s, ray, hint);
        if (!returned) {
            fail("expected a hit at t = " + t + " but intersect returned false" + ctx);
        }
        double scale = Math.max(1, Math.max(point.maxAbs(), ray.p.maxAbs()));
        if (!(Math.abs(rec.t - t) <= TOL * Math.max(Math.abs(t), scale / Math.max(1e-300, ray.d.length())))) {
            fail("expected t = " + t + " but the record has t = " + rec.t + ctx);
        }
        if (rec.point == null || !(rec.point.minus(point).length() <= TOL * scale)) {
            fail("expected hit point " + point + " but the record has " + rec.point + ctx);
        }
        boolean anyNormal = false;
        for (Vec3 normal : normals) {
            anyNormal |= rec.normal != null && rec.normal.minus(normal).length() <= 1e-6;
        }
        if (!anyNormal) {
            fail("expected the unit outward normal " + (normals.size() == 1 ? normals.get(0) : "one of " + normals)
                    + " but the record has " + rec.normal
                    + (rec.normal == null ? "" : " (length " + rec.normal.length() + ")") + ctx);
        }
        if (rec.surface != s) {
            fail("the record should name the surface that was hit, but names "
                    + (rec.surface == null ? "none" : raylab.testing.Check.describe(rec.surface)) + ctx);
        }
    }

    /** The lines under a message: the case, the ray and the surface in the lecture's terms, the hint. */
    static String context(String what, Surface s, Ray ray, String hint) {
        return "\n  " + what + "\n  surface:  " + describe(s) + "\n  ray:      " + raylab.testing.Check.describe(ray)
                + (hint == null ? "" : "\nHINT: " + hint);
    }

    /** Checks a miss: false returned and the record exactly as it was. */
    public static void assertUntouched(String what, Surface s, Ray ray, IntersectionRecord rec, boolean returned,
            IntersectionRecord before, String hint) {
        String ctx = context(what, s, ray, hint);
        if (returned) {
            fail("expected no hit, but intersect returned true; record: " + rec + ctx);
        }
        String changed = Double.compare(before.t, rec.t) != 0 ? "t" : before.point != rec.point ? "point"
                : before.normal != rec.normal ? "normal" : before.surface != rec.surface ? "surface" : null;
        if (changed != null) {
            fail("expected the record untouched on a miss, but its " + changed + " changed: " + rec + ctx);
        }
        // A miss is scored with a control hit through the surface's centre: a constant miss earns nothing.
        raylab.testing.Check.controlHit(s);
    }

    public static IntersectionRecord copy(IntersectionRecord r) {
        IntersectionRecord c = new IntersectionRecord();
        c.copyFrom(r);
        return c;
    }

    /** The surface as the visible tests describe it. */
    public static String describe(Surface s) {
        return raylab.testing.Check.describe(s);
    }

    /** Compares colours channel by channel with a relative tolerance. */
    public static void assertColor(String what, Color expected, Color actual, String hint) {
        double scale = Math.max(1e-12, Math.max(Math.abs(expected.r), Math.max(Math.abs(expected.g), Math.abs(expected.b))));
        if (actual == null || !(Math.abs(actual.r - expected.r) <= 1e-9 * Math.max(1, scale)
                && Math.abs(actual.g - expected.g) <= 1e-9 * Math.max(1, scale)
                && Math.abs(actual.b - expected.b) <= 1e-9 * Math.max(1, scale))) {
            fail(what + "\n  expected: " + expected + "\n  got:      " + actual + (hint == null ? "" : "\nHINT: " + hint));
        }
    }
}
