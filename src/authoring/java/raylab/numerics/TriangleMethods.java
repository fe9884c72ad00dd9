package raylab.numerics;

import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;
import raylab.surface.Triangle;

/** Ray–triangle methods to compare with the reference (watertight) {@link Triangle#intersect}. */
public final class TriangleMethods {
    private TriangleMethods() {
    }

    /**
     * The lecture's method: the plane t = (a − p)·n / (d·n) with n = (b − a) × (c − a), the point
     * x = p + t·d, then the three inside-edge tests ((b − a) × (x − a))·n ≥ 0 and so on (closed:
     * points on an edge count as inside). Each triangle computes its own x with its own rounding,
     * so a ray through an edge shared by two triangles can be judged outside both.
     */
    public static boolean lecture(Triangle tri, IntersectionRecord rec, Ray ray) {
        Vec3 a = tri.a;
        Vec3 b = tri.b;
        Vec3 c = tri.c;
        Vec3 n = b.minus(a).cross(c.minus(a));
        double dn = ray.d.dot(n);
        if (dn == 0) {
            return false;
        }
        double t = a.minus(ray.p).dot(n) / dn;
        if (!ray.inRange(t) || t >= rec.t) {
            return false;
        }
        Vec3 x = ray.evaluate(t);
        if (b.minus(a).cross(x.minus(a)).dot(n) < 0
                || c.minus(b).cross(x.minus(b)).dot(n) < 0
                || a.minus(c).cross(x.minus(c)).dot(n) < 0) {
            return false;
        }
        rec.set(t, x, n.normalize(), tri);
        return true;
    }

    /**
     * Möller and Trumbore (1997): solve p + t·d = a + u(b − a) + v(c − a) by Cramer's rule with
     * scalar triple products, accept u ≥ 0, v ≥ 0, u + v ≤ 1. Faster than the lecture's method,
     * no plane equation stored; not watertight either (u, v of a shared edge are computed
     * differently by its two triangles).
     */
    public static boolean mollerTrumbore(Triangle tri, IntersectionRecord rec, Ray ray) {
        Vec3 e1 = tri.b.minus(tri.a);
        Vec3 e2 = tri.c.minus(tri.a);
        Vec3 pvec = ray.d.cross(e2);
        double det = e1.dot(pvec);
        if (det == 0) {
            return false;
        }
        double inv = 1 / det;
        Vec3 tvec = ray.p.minus(tri.a);
        double u = tvec.dot(pvec) * inv;
        if (u < 0 || u > 1) {
            return false;
        }
        Vec3 qvec = tvec.cross(e1);
        double v = ray.d.dot(qvec) * inv;
        if (v < 0 || u + v > 1) {
            return false;
        }
        double t = e2.dot(qvec) * inv;
        if (!ray.inRange(t) || t >= rec.t) {
            return false;
        }
        rec.set(t, ray.evaluate(t), e1.cross(e2).normalize(), tri);
        return true;
    }

    /** The reference method, {@link Triangle#intersect}. */
    public static boolean reference(Triangle tri, IntersectionRecord rec, Ray ray) {
        return tri.intersect(rec, ray);
    }

    public static Intersector lecture(Triangle tri) {
        return (rec, ray) -> lecture(tri, rec, ray);
    }

    public static Intersector mollerTrumbore(Triangle tri) {
        return (rec, ray) -> mollerTrumbore(tri, rec, ray);
    }

    public static Intersector reference(Triangle tri) {
        return (rec, ray) -> reference(tri, rec, ray);
    }
}
