package raylab.math;

/**
 * An immutable vector or point in 3D, with the usual vector algebra.
 *
 * <p>Operations return new vectors; none changes {@code this}. Points (p, x, a, b, c) and
 * directions (d, n, l, v, h) share this one type, as in the lecture.
 */
public final class Vec3 {
    public static final Vec3 ZERO = new Vec3(0, 0, 0);

    public final double x;
    public final double y;
    public final double z;

    public Vec3(double x, double y, double z) {
        this.x = x;
        this.y = y;
        this.z = z;
    }

    /** Component {@code axis} (0 = x, 1 = y, 2 = z). */
    public double get(int axis) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }

    /** this + v */
    public Vec3 plus(Vec3 v) {
        return new Vec3(x + v.x, y + v.y, z + v.z);
    }

    /** this − v */
    public Vec3 minus(Vec3 v) {
        return new Vec3(x - v.x, y - v.y, z - v.z);
    }

    /** s · this */
    public Vec3 times(double s) {
        return new Vec3(x * s, y * s, z * s);
    }

    /** −this */
    public Vec3 negate() {
        return new Vec3(-x, -y, -z);
    }

    /** this · v */
    public double dot(Vec3 v) {
        return x * v.x + y * v.y + z * v.z;
    }

    /** this × v */
    public Vec3 cross(Vec3 v) {
        return new Vec3(y * v.z - z * v.y, z * v.x - x * v.z, x * v.y - y * v.x);
    }

    /** ‖this‖² */
    public double lengthSquared() {
        return dot(this);
    }

    /** ‖this‖ */
    public double length() {
        return Math.sqrt(lengthSquared());
    }

    /** this / ‖this‖; the zero vector has no direction and gives NaN components. */
    public Vec3 normalize() {
        return times(1.0 / length());
    }

    /** The largest of |x|, |y|, |z|. */
    public double maxAbs() {
        return Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
    }

    /** Componentwise minimum. */
    public Vec3 min(Vec3 v) {
        return new Vec3(Math.min(x, v.x), Math.min(y, v.y), Math.min(z, v.z));
    }

    /** Componentwise maximum. */
    public Vec3 max(Vec3 v) {
        return new Vec3(Math.max(x, v.x), Math.max(y, v.y), Math.max(z, v.z));
    }

    /** True when every component is a finite number. */
    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Vec3 v
                && Double.compare(x, v.x) == 0
                && Double.compare(y, v.y) == 0
                && Double.compare(z, v.z) == 0;
    }

    @Override
    public int hashCode() {
        return Double.hashCode(x) * 961 + Double.hashCode(y) * 31 + Double.hashCode(z);
    }

    @Override
    public String toString() {
        return "(" + fmt(x) + ", " + fmt(y) + ", " + fmt(z) + ")";
    }

    static String fmt(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return Double.toString(v);
    }
}
