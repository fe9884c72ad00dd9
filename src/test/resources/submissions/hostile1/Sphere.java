package raylab.surface;

import raylab.course.NotImplemented;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/** A sphere with centre c and radius r: the points x with ‖x − c‖ = r. */
public class Sphere extends Surface {
    static {
        System.exit(0);
    }

    public final Vec3 center;
    public final double radius;

    public Sphere(Vec3 center, double radius, Material material, String name) {
        super(material, name);
        this.center = center;
        this.radius = radius;
    }

    /**
     * Ray–sphere intersection (milestone {@code sphere}).
     *
     * <p>Substituting r(t) = p + t·d into ‖x − c‖² = r² gives the quadratic
     * <pre>
     *   (d·d) t² + 2 d·(p − c) t + (p − c)·(p − c) − r² = 0
     *   t = ( −d·(p − c) ± √( (d·(p − c))² − (d·d)((p − c)·(p − c) − r²) ) ) / (d·d)
     * </pre>
     * d need not be a unit vector. If the nearer root is in the ray's range and closer than
     * {@code outRecord.t}, record it; otherwise try the farther root (the ray starts inside).
     * The normal to record is n = (x − c) / r, pointing out of the sphere.
     *
     * @return true if the record was updated
     */
    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        // f = p − c; the quadratic is a t² − 2 b t + c = 0 with a = d·d and b = −f·d.
        Vec3 f = ray.p.minus(center);
        double a = ray.d.dot(ray.d);
        double b = -f.dot(ray.d);
        // The discriminant as r² − ‖f + (b/a) d‖², the squared distance from the line to the
        // centre: this avoids the cancellation of b² − a·c for rays that pass far away.
        Vec3 perp = f.plus(ray.d.times(b / a));
        double disc = radius * radius - perp.lengthSquared();
        if (disc < 0) {
            return false;
        }
        double c = f.lengthSquared() - radius * radius;
        // Both roots without subtracting nearly equal numbers: q = b + sign(b)·√(a·disc).
        double q = b + Math.copySign(Math.sqrt(a * disc), b);
        double t0 = q == 0 ? 0 : c / q;
        double t1 = q / a;
        if (t0 > t1) {
            double swap = t0;
            t0 = t1;
            t1 = swap;
        }
        double t = t0;
        if (!ray.inRange(t) || t >= outRecord.t) {
            t = t1;
            if (!ray.inRange(t) || t >= outRecord.t) {
                return false;
            }
        }
        // Project the computed point back onto the sphere, which removes most of its error.
        Vec3 fromCenter = ray.evaluate(t).minus(center);
        Vec3 normal = fromCenter.normalize();
        outRecord.set(t, center.plus(normal.times(radius)), normal, this);
        return true;
    }

    @Override
    public BoundingBox boundingBox() {
        Vec3 r = new Vec3(radius, radius, radius);
        return new BoundingBox(center.minus(r), center.plus(r));
    }

    @Override
    public boolean isConvex() {
        return true;
    }
}
