package raylab.math;

/**
 * Named helpers for floating-point error, after pbrt: the relative error bound gamma(n), the
 * error bound of a computed hit point and the offset of a ray origin off a surface by that
 * bound, as the reference {@code Shadows.isShadowed} uses them. The course's numerics notes
 * (in the instructor's repository, beside the oracle that measures them) explain each; the
 * offsets used before this one are kept only by the study, in the instructor's repository.
 */
public final class Numerics {
    /** Unit roundoff of double precision: 2^-53. */
    public static final double MACHINE_EPSILON = Math.ulp(1.0) * 0.5;

    private Numerics() {
    }

    /**
     * gamma(n) = n·u / (1 − n·u): a bound on the relative error of n successive roundings
     * (Higham), with u the unit roundoff.
     */
    public static double gamma(int n) {
        return (n * MACHINE_EPSILON) / (1 - n * MACHINE_EPSILON);
    }

    /** Smallest offset, for hit points at the origin. */
    public static final double MIN_OFFSET = 0x1p-60;

    /**
     * The largest finite coordinate magnitude of a box (0 for an empty or unbounded box): for a
     * surface's box, a bound on the coordinates from which its hit points are computed.
     */
    public static double magnitude(BoundingBox box) {
        double m = Math.max(box.min.maxAbs(), box.max.maxAbs());
        return box.isEmpty() || !Double.isFinite(m) ? 0 : m;
    }

    // ---- The shadow-ray offset: a bound on the error of each computed hit point (pbrt-v4 style) ----

    /** Rounding steps the bound of {@link #pointError} allows for (the course's numerics notes). */
    public static final int POINT_ERROR_STEPS = 8;

    /**
     * How many times its error bound a ray origin is moved off the surface by
     * {@link #offsetRayOrigin(Vec3, double, Vec3, Vec3)}: the point's own error, the error with
     * which the next ray's intersection code locates the same surface (about as large again), and
     * room for the componentwise bound to become a distance (√3). 16·γ(8) ≈ 2^-46.
     */
    public static final double OFFSET_SAFETY = 16;

    /**
     * A bound on the rounding error of each coordinate of a computed hit point x, in the style of
     * pbrt-v4's per-hit error bounds: γ(8)·max(max|x_i|, magnitude), where magnitude bounds the
     * coordinates of the surface x was computed on ({@link #magnitude} of that one surface's
     * box, not of the scene). A hit point is a short sum of products of those coordinates
     * (sphere: c + r·n̂; triangle: b0·a + b1·b + b2·c with b0 + b1 + b2 = 1 up to rounding; box:
     * exact on the face plane), so each of its coordinates is off by at most a few rounding
     * steps of the largest coordinate involved: of x itself, or of the surface when x is small
     * on a large surface (near the middle of a huge ground triangle).
     */
    public static double pointError(Vec3 x, double magnitude) {
        return gamma(POINT_ERROR_STEPS) * Math.max(x.maxAbs(), magnitude);
    }

    /** The distance a ray origin is moved off a surface for a point error bound: OFFSET_SAFETY·error, at least MIN_OFFSET. */
    public static double offsetFor(double error) {
        return Math.max(MIN_OFFSET, OFFSET_SAFETY * error);
    }

    /**
     * pbrt-v4's OffsetRayOrigin with a per-hit bound: moves x (whose coordinates are off by at
     * most {@code error}) off the surface with unit normal n, to the side w points into, by
     * {@link #offsetFor}(error). Nothing but the point and its own bound decides the offset, so a
     * far-away object elsewhere in the scene does not change it.
     */
    public static Vec3 offsetRayOrigin(Vec3 x, double error, Vec3 n, Vec3 w) {
        double offset = offsetFor(error);
        return n.dot(w) >= 0 ? x.plus(n.times(offset)) : x.minus(n.times(offset));
    }
}
