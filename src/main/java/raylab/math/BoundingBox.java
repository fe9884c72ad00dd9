package raylab.math;

import raylab.ray.Ray;

/**
 * An axis-aligned bounding box [min, max], used by the bounding volume hierarchy.
 *
 * <p>The empty box has min = +∞ and max = −∞, so that {@code union} with it changes nothing.
 */
public final class BoundingBox {
    public static final BoundingBox EMPTY = new BoundingBox(
            new Vec3(Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY),
            new Vec3(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY));

    public final Vec3 min;
    public final Vec3 max;

    public BoundingBox(Vec3 min, Vec3 max) {
        this.min = min;
        this.max = max;
    }

    /** The smallest box holding both boxes. */
    public BoundingBox union(BoundingBox o) {
        return new BoundingBox(min.min(o.min), max.max(o.max));
    }

    /** The smallest box holding this box and the point. */
    public BoundingBox union(Vec3 p) {
        return new BoundingBox(min.min(p), max.max(p));
    }

    public Vec3 centroid() {
        return min.plus(max).times(0.5);
    }

    public Vec3 extent() {
        return max.minus(min);
    }

    public boolean isEmpty() {
        return min.x > max.x || min.y > max.y || min.z > max.z;
    }

    /** Half the surface area (the constant factor does not matter for the surface area heuristic). */
    public double halfArea() {
        if (isEmpty()) {
            return 0;
        }
        Vec3 e = extent();
        return e.x * e.y + e.y * e.z + e.z * e.x;
    }

    /** The axis (0, 1, 2) along which the box is longest. */
    public int longestAxis() {
        Vec3 e = extent();
        return e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
    }

    /**
     * Whether the ray meets the box within [tMin, tMax], by slabs, given the reciprocal direction.
     * Conservative: the slab distances are widened by 2·gamma(3) so that rounding never loses a hit.
     */
    public boolean hit(Ray ray, double invDx, double invDy, double invDz, double tMax) {
        double t0 = ray.tMin;
        double t1 = tMax;
        double a = (min.x - ray.p.x) * invDx;
        double b = (max.x - ray.p.x) * invDx;
        if (a > b) { double s = a; a = b; b = s; }
        t0 = a > t0 ? a : t0;
        t1 = b * ROUND_UP < t1 ? b * ROUND_UP : t1;
        a = (min.y - ray.p.y) * invDy;
        b = (max.y - ray.p.y) * invDy;
        if (a > b) { double s = a; a = b; b = s; }
        t0 = a > t0 ? a : t0;
        t1 = b * ROUND_UP < t1 ? b * ROUND_UP : t1;
        a = (min.z - ray.p.z) * invDz;
        b = (max.z - ray.p.z) * invDz;
        if (a > b) { double s = a; a = b; b = s; }
        t0 = a > t0 ? a : t0;
        t1 = b * ROUND_UP < t1 ? b * ROUND_UP : t1;
        return t0 <= t1;
    }

    /** 1 + 2·gamma(3): widens exit distances to cover the rounding of the slab computation. */
    private static final double ROUND_UP = 1 + 2 * Numerics.gamma(3);

    @Override
    public String toString() {
        return "[" + min + " .. " + max + "]";
    }
}
