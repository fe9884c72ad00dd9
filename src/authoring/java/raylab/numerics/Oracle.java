package raylab.numerics;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;

import raylab.math.Vec3;

/**
 * Higher-precision answers to ray–shape questions, to judge the double-precision methods.
 *
 * <p>The ray's p and d and the shape's numbers are taken as exact binary values (every double is
 * an exact decimal fraction, so {@code new BigDecimal(double)} loses nothing). Sums, differences
 * and products are then exact; only divisions and square roots round, to {@link #MC} (80 decimal
 * digits, about 265 bits, against the 53 of a double). Hit-or-miss decisions are made from exact
 * signs, so they are the true answer for the given doubles, boundary cases included.
 */
public final class Oracle {
    /** Precision of the divisions and square roots: 80 significant digits. */
    public static final MathContext MC = new MathContext(80, RoundingMode.HALF_EVEN);

    private Oracle() {
    }

    static BigDecimal big(double x) {
        return new BigDecimal(x);
    }

    static BigDecimal[] big(Vec3 v) {
        return new BigDecimal[] {big(v.x), big(v.y), big(v.z)};
    }

    static BigDecimal dot(BigDecimal[] u, BigDecimal[] v) {
        return u[0].multiply(v[0]).add(u[1].multiply(v[1])).add(u[2].multiply(v[2]));
    }

    static BigDecimal[] minus(BigDecimal[] u, BigDecimal[] v) {
        return new BigDecimal[] {u[0].subtract(v[0]), u[1].subtract(v[1]), u[2].subtract(v[2])};
    }

    static BigDecimal[] cross(BigDecimal[] u, BigDecimal[] v) {
        return new BigDecimal[] {
            u[1].multiply(v[2]).subtract(u[2].multiply(v[1])),
            u[2].multiply(v[0]).subtract(u[0].multiply(v[2])),
            u[0].multiply(v[1]).subtract(u[1].multiply(v[0]))};
    }

    /** The point p + t·d, correctly rounded per coordinate (up to the 80-digit t). */
    static Vec3 evaluate(Vec3 p, Vec3 d, BigDecimal t) {
        return new Vec3(big(p.x).add(t.multiply(big(d.x))).doubleValue(),
                big(p.y).add(t.multiply(big(d.y))).doubleValue(),
                big(p.z).add(t.multiply(big(d.z))).doubleValue());
    }

    // ---------------------------------------------------------------- sphere

    /** The exact answer for the line p + t·d against the sphere ‖x − c‖ = r. */
    public static final class SphereRoots {
        /** Sign of the discriminant: −1 the line misses, 0 it is tangent, +1 it cuts through. */
        public final int discriminantSign;
        /** The roots t0 ≤ t1 (null on a miss). */
        public final BigDecimal t0;
        public final BigDecimal t1;
        /** Distance from the line to the centre, h, and the sphere's radius r. */
        public final double lineDistance;
        public final double radius;

        SphereRoots(int sign, BigDecimal t0, BigDecimal t1, double h, double r) {
            this.discriminantSign = sign;
            this.t0 = t0;
            this.t1 = t1;
            this.lineDistance = h;
            this.radius = r;
        }

        public boolean hits() {
            return discriminantSign >= 0;
        }

        /** |h − r| / r: how far, relative to the radius, the line is from grazing the sphere. */
        public double boundaryMargin() {
            return Math.abs(lineDistance - radius) / radius;
        }

        /**
         * What a closest-hit query on the ray [tMin, tMax] should find: the smallest root in
         * range, or null.
         */
        public BigDecimal firstHit(double tMin, double tMax) {
            if (!hits()) {
                return null;
            }
            if (inRange(t0, tMin, tMax)) {
                return t0;
            }
            return inRange(t1, tMin, tMax) ? t1 : null;
        }

        @Override
        public String toString() {
            return hits() ? "oracle roots t0=" + t0.doubleValue() + " t1=" + t1.doubleValue()
                    + " (h=" + lineDistance + ", r=" + radius + ")"
                    : "oracle: miss (h=" + lineDistance + ", r=" + radius + ")";
        }
    }

    static boolean inRange(BigDecimal t, double tMin, double tMax) {
        return (tMin == Double.NEGATIVE_INFINITY || t.compareTo(big(tMin)) >= 0)
                && (tMax == Double.POSITIVE_INFINITY || t.compareTo(big(tMax)) <= 0);
    }

    /** Roots of ‖p + t·d − c‖² = r², exactly signed, roots to 80 digits. */
    public static SphereRoots sphere(Vec3 center, double radius, Vec3 p, Vec3 d) {
        BigDecimal[] f = minus(big(p), big(center));
        BigDecimal[] dd = big(d);
        BigDecimal r = big(radius);
        BigDecimal a = dot(dd, dd);
        BigDecimal b = dot(f, dd); // the lecture's d·(p − c)
        BigDecimal c = dot(f, f).subtract(r.multiply(r));
        BigDecimal disc = b.multiply(b).subtract(a.multiply(c)); // exact
        // h² = ‖f‖² − (f·d)²/(d·d)
        BigDecimal h2 = dot(f, f).subtract(b.multiply(b).divide(a, MC));
        double h = h2.signum() <= 0 ? 0 : h2.sqrt(MC).doubleValue();
        int sign = disc.signum();
        if (sign < 0) {
            return new SphereRoots(sign, null, null, h, radius);
        }
        // q = −(b + sign(b)·√disc); the roots are q/a and c/q, neither cancelling.
        BigDecimal s = disc.sqrt(MC);
        BigDecimal q = b.signum() >= 0 ? b.add(s).negate() : s.subtract(b);
        BigDecimal r0 = q.divide(a, MC);
        BigDecimal r1 = q.signum() == 0 ? r0 : c.divide(q, MC);
        BigDecimal t0 = r0.min(r1);
        BigDecimal t1 = r0.max(r1);
        return new SphereRoots(sign, t0, t1, h, radius);
    }

    // ---------------------------------------------------------------- triangle

    /** The exact answer for the ray p + t·d against the closed triangle a, b, c. */
    public static final class TriangleHit {
        /** Whether the line meets the triangle's plane in one point (the triangle is not degenerate
         *  and the ray not parallel to its plane). */
        public final boolean meetsPlane;
        /** Barycentric coordinates of the line–plane point (weights of a, b, c) and its t. */
        public final BigDecimal b0;
        public final BigDecimal b1;
        public final BigDecimal b2;
        public final BigDecimal t;

        TriangleHit(boolean meets, BigDecimal b0, BigDecimal b1, BigDecimal b2, BigDecimal t) {
            this.meetsPlane = meets;
            this.b0 = b0;
            this.b1 = b1;
            this.b2 = b2;
            this.t = t;
        }

        /** Whether the line passes through the closed triangle (barycentrics all ≥ 0). */
        public boolean insideTriangle() {
            return meetsPlane && b0.signum() >= 0 && b1.signum() >= 0 && b2.signum() >= 0;
        }

        /** Whether the ray [tMin, tMax] hits the closed triangle. */
        public boolean hits(double tMin, double tMax) {
            return insideTriangle() && inRange(t, tMin, tMax);
        }

        /** The smallest barycentric coordinate: negative outside, its size is the distance to the
         *  nearest edge line as a fraction of the triangle's height over that edge. */
        public double minBarycentric() {
            return meetsPlane ? b0.min(b1).min(b2).doubleValue() : Double.NaN;
        }

        @Override
        public String toString() {
            return meetsPlane ? "oracle t=" + t.doubleValue() + " barycentrics ("
                    + b0.doubleValue() + ", " + b1.doubleValue() + ", " + b2.doubleValue() + ")"
                    : "oracle: line parallel to the plane or triangle degenerate";
        }
    }

    /** Solves p + t·d = b0·a + b1·b + b2·c, b0 + b1 + b2 = 1, by Cramer's rule with exact
     *  determinants; only the final divisions round. */
    public static TriangleHit triangle(Vec3 a, Vec3 b, Vec3 c, Vec3 p, Vec3 d) {
        BigDecimal[] A = big(a);
        BigDecimal[] e1 = minus(big(b), A);
        BigDecimal[] e2 = minus(big(c), A);
        BigDecimal[] s = minus(big(p), A);
        BigDecimal[] dd = big(d);
        BigDecimal[] n = cross(e1, e2);
        // p + t d = a + b1 e1 + b2 e2  <=>  b1 e1 + b2 e2 − t d = s
        BigDecimal det = dot(n, dd).negate(); // det[e1, e2, −d]
        if (det.signum() == 0) {
            return new TriangleHit(false, null, null, null, null);
        }
        BigDecimal[] md = new BigDecimal[] {dd[0].negate(), dd[1].negate(), dd[2].negate()};
        BigDecimal n1 = dot(s, cross(e2, md));
        BigDecimal n2 = dot(e1, cross(s, md));
        BigDecimal nt = dot(e1, cross(e2, s));
        BigDecimal n0 = det.subtract(n1).subtract(n2);
        return new TriangleHit(true, n0.divide(det, MC), n1.divide(det, MC), n2.divide(det, MC),
                nt.divide(det, MC));
    }

    /** The point p + t·d of an oracle hit, each coordinate rounded once to double. */
    public static Vec3 point(Vec3 p, Vec3 d, BigDecimal t) {
        return evaluate(p, d, t);
    }

    // ---------------------------------------------------------------- box

    /** The exact answer for the ray p + t·d against the closed box [min, max]. */
    public static final class BoxHit {
        /** Whether the ray [tMin, tMax] meets the box. */
        public final boolean hit;
        /** The t a closest-hit query should record: the entry, or the exit when p is inside. */
        public final BigDecimal t;
        /** Whether t is the entry (false: the exit); and the set of axes whose planes give t
         *  (bit 0 = x, 1 = y, 2 = z; more than one bit when the hit is on an edge or corner). */
        public final boolean entering;
        public final int axes;

        BoxHit(boolean hit, BigDecimal t, boolean entering, int axes) {
            this.hit = hit;
            this.t = t;
            this.entering = entering;
            this.axes = axes;
        }

        @Override
        public String toString() {
            return hit ? "oracle hit t=" + t.doubleValue() + (entering ? " entering" : " leaving")
                    + " through plane(s) of axes mask " + axes : "oracle: miss";
        }
    }

    /**
     * Slabs with exact arithmetic; a zero direction component means the line is inside that
     * closed slab for all t when min ≤ p ≤ max, else never.
     */
    public static BoxHit box(Vec3 min, Vec3 max, Vec3 p, Vec3 d, double tMin, double tMax) {
        BigDecimal enter = null;
        BigDecimal exit = null;
        int enterAxes = 0;
        int exitAxes = 0;
        for (int axis = 0; axis < 3; axis++) {
            double pi = p.get(axis);
            double di = d.get(axis);
            double lo = min.get(axis);
            double hi = max.get(axis);
            if (di == 0) {
                if (pi < lo || pi > hi) {
                    return new BoxHit(false, null, false, 0);
                }
                continue;
            }
            BigDecimal tLo = big(lo).subtract(big(pi)).divide(big(di), MC);
            BigDecimal tHi = big(hi).subtract(big(pi)).divide(big(di), MC);
            BigDecimal slabEnter = tLo.min(tHi);
            BigDecimal slabExit = tLo.max(tHi);
            int cmp = enter == null ? 1 : slabEnter.compareTo(enter);
            if (cmp > 0) {
                enter = slabEnter;
                enterAxes = 1 << axis;
            } else if (cmp == 0) {
                enterAxes |= 1 << axis;
            }
            cmp = exit == null ? -1 : slabExit.compareTo(exit);
            if (cmp < 0) {
                exit = slabExit;
                exitAxes = 1 << axis;
            } else if (cmp == 0) {
                exitAxes |= 1 << axis;
            }
        }
        if (enter == null || enter.compareTo(exit) > 0) {
            return new BoxHit(false, null, false, 0);
        }
        if (inRange(enter, tMin, tMax)) {
            return new BoxHit(true, enter, true, enterAxes);
        }
        if (inRange(exit, tMin, tMax)) {
            return new BoxHit(true, exit, false, exitAxes);
        }
        return new BoxHit(false, null, false, 0);
    }

    // ---------------------------------------------------------------- errors

    /** |computed − exact| / |exact| (the absolute error when exact is 0). */
    public static double relativeError(double computed, BigDecimal exact) {
        BigDecimal diff = big(computed).subtract(exact).abs();
        if (exact.signum() == 0) {
            return diff.doubleValue();
        }
        return diff.divide(exact.abs(), MC).doubleValue();
    }

    /** |computed − exact| in units of the last place of the exact value rounded to double. */
    public static double ulpError(double computed, BigDecimal exact) {
        double rounded = exact.doubleValue();
        return big(computed).subtract(exact).abs().doubleValue() / Math.ulp(rounded);
    }
}
