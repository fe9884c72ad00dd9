package raylab.surface;

import raylab.course.NotImplemented;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/** A sphere with centre c and radius r: the points x with ‖x − c‖ = r. */
public class Sphere extends Surface {
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
        // Geometric method with a unit direction u = d / |d|; t values are divided by |d| at the end.
        double dl = ray.d.length();
        Vec3 u = ray.d.times(1 / dl);
        Vec3 toCenter = center.minus(ray.p);
        double tca = toCenter.dot(u);
        double d2 = toCenter.dot(toCenter) - tca * tca;
        double r2 = radius * radius;
        if (d2 > r2) {
            return false;
        }
        double thc = Math.sqrt(r2 - d2);
        double t = (tca - thc) / dl;
        if (!ray.inRange(t) || t >= outRecord.t) {
            t = (tca + thc) / dl;
            if (!ray.inRange(t) || t >= outRecord.t) {
                return false;
            }
        }
        Vec3 x = ray.evaluate(t);
        outRecord.set(t, x, x.minus(center).times(1 / radius), this);
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
