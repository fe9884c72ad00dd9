package raylab.ray;

import raylab.math.Vec3;

/**
 * A ray r(t) = p + t·d, valid for t in the closed range [tMin, tMax].
 *
 * <p>The direction d is <em>not</em> assumed to have unit length: camera rays, shadow rays and
 * the tests all use directions of other lengths. Scaling d by a &gt; 0 gives the same ray with
 * its t values divided by a.
 */
public final class Ray {
    /** The origin p. */
    public final Vec3 p;
    /** The direction d (any non-zero length). */
    public final Vec3 d;
    /** Smallest valid t. */
    public final double tMin;
    /** Largest valid t. */
    public final double tMax;

    /** The ray p + t·d for t in [tMin, tMax]. */
    public Ray(Vec3 p, Vec3 d, double tMin, double tMax) {
        this.p = p;
        this.d = d;
        this.tMin = tMin;
        this.tMax = tMax;
    }

    /** The half line p + t·d, t in [0, +∞). */
    public Ray(Vec3 p, Vec3 d) {
        this(p, d, 0.0, Double.POSITIVE_INFINITY);
    }

    /** The point r(t) = p + t·d. */
    public Vec3 evaluate(double t) {
        return new Vec3(p.x + t * d.x, p.y + t * d.y, p.z + t * d.z);
    }

    /** Whether t lies in this ray's valid range tMin ≤ t ≤ tMax. */
    public boolean inRange(double t) {
        return t >= tMin && t <= tMax;
    }

    @Override
    public String toString() {
        return "Ray[p=" + p + ", d=" + d + ", t in [" + tMin + ", " + tMax + "]]";
    }
}
