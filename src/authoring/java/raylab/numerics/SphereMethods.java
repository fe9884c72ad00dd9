package raylab.numerics;

import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Sphere;

/**
 * Ray–sphere methods to compare with the reference {@link Sphere#intersect}.
 * Each honours the {@link raylab.surface.Surface#intersect} contract.
 */
public final class SphereMethods {
    private SphereMethods() {
    }

    /**
     * The lecture's quadratic formula evaluated as written, with f = p − c:
     * t = (−d·f ± √((d·f)² − (d·d)(f·f − r²))) / (d·d), the point p + t·d and the normal
     * (x − c)/r. Loses the discriminant to cancellation when the sphere is far away (both
     * (d·f)² and (d·d)(f·f) are about ‖f‖²‖d‖²), and the nearer root when p is just outside a
     * large sphere (−d·f and the square root nearly cancel).
     */
    public static boolean textbook(Sphere s, IntersectionRecord rec, Ray ray) {
        Vec3 f = ray.p.minus(s.center);
        double a = ray.d.dot(ray.d);
        double b = ray.d.dot(f);
        double c = f.dot(f) - s.radius * s.radius;
        double disc = b * b - a * c;
        if (disc < 0) {
            return false;
        }
        double root = Math.sqrt(disc);
        double t = (-b - root) / a;
        if (!ray.inRange(t) || t >= rec.t) {
            t = (-b + root) / a;
            if (!ray.inRange(t) || t >= rec.t) {
                return false;
            }
        }
        Vec3 x = ray.evaluate(t);
        rec.set(t, x, x.minus(s.center).times(1 / s.radius), s);
        return true;
    }

    /** The reference method, {@link Sphere#intersect}. */
    public static boolean reference(Sphere s, IntersectionRecord rec, Ray ray) {
        return s.intersect(rec, ray);
    }

    public static Intersector textbook(Sphere s) {
        return (rec, ray) -> textbook(s, rec, ray);
    }

    public static Intersector reference(Sphere s) {
        return (rec, ray) -> reference(s, rec, ray);
    }
}
