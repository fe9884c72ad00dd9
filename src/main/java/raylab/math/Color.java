package raylab.math;

/**
 * An immutable linear RGB triple: a radiance, an intensity (I, Ia) or a reflectance (ka, kd, ks).
 *
 * <p>Products of colours are componentwise: {@code kd.times(I)} is (kd_r·I_r, kd_g·I_g, kd_b·I_b).
 */
public final class Color {
    public static final Color BLACK = new Color(0, 0, 0);
    public static final Color WHITE = new Color(1, 1, 1);

    public final double r;
    public final double g;
    public final double b;

    public Color(double r, double g, double b) {
        this.r = r;
        this.g = g;
        this.b = b;
    }

    /** this + c */
    public Color plus(Color c) {
        return new Color(r + c.r, g + c.g, b + c.b);
    }

    /** Componentwise product this ∘ c. */
    public Color times(Color c) {
        return new Color(r * c.r, g * c.g, b * c.b);
    }

    /** s · this */
    public Color times(double s) {
        return new Color(r * s, g * s, b * s);
    }

    /** True when all three components are zero. */
    public boolean isBlack() {
        return r == 0 && g == 0 && b == 0;
    }

    /** True when every component is a finite number. */
    public boolean isFinite() {
        return Double.isFinite(r) && Double.isFinite(g) && Double.isFinite(b);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Color c
                && Double.compare(r, c.r) == 0
                && Double.compare(g, c.g) == 0
                && Double.compare(b, c.b) == 0;
    }

    @Override
    public int hashCode() {
        return Double.hashCode(r) * 961 + Double.hashCode(g) * 31 + Double.hashCode(b);
    }

    @Override
    public String toString() {
        return "rgb(" + Vec3.fmt(r) + ", " + Vec3.fmt(g) + ", " + Vec3.fmt(b) + ")";
    }
}
