package raylab.surface;

import raylab.course.NotImplemented;
import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * An infinite plane through {@code point} with unit normal {@code normal} (an instructor's
 * extension: its scene entry is {@link PlaneType}). The fields are public and named like the
 * constructor's parameters: the grader rebuilds the student's plane from them.
 */
public class Plane extends Surface {
    public final Vec3 point;
    public final Vec3 normal;

    public Plane(Vec3 point, Vec3 normal, Material material, String name) {
        super(material, name);
        this.point = point;
        this.normal = normal.normalize();
    }

    /**
     * Ray–plane intersection (milestone {@code plane}): (p + t·d − q)·n = 0 gives
     * t = (q − p)·n / (d·n), no hit when d·n = 0. Record it if t is in the ray's range and closer
     * than {@code outRecord.t}; the normal recorded is n.
     *
     * @return true if the record was updated
     */
    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        // BEGIN SOLUTION plane
        double dn = ray.d.dot(normal);
        if (dn == 0) {
            return false;
        }
        double t = point.minus(ray.p).dot(normal) / dn;
        if (!ray.inRange(t) || t >= outRecord.t) {
            return false;
        }
        outRecord.set(t, ray.evaluate(t), normal, this);
        return true;
        // STUB
        // // TODO(plane): t = (q − p)·n / (d·n), in the ray's range and closer than outRecord.t.
        // throw new NotImplemented("plane", "Plane.intersect");
        // END SOLUTION
    }

    /** A plane has no finite bounds: a box as large as doubles allow, kept finite. */
    @Override
    public BoundingBox boundingBox() {
        double big = 1e12;
        return new BoundingBox(new Vec3(-big, -big, -big), new Vec3(big, big, big));
    }
}
