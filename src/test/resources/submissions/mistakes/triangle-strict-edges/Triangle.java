// Mistake corpus (NoSilentLossTest): the inside-edge tests with the slide's > 0.
package raylab.surface;

import raylab.material.Material;
import raylab.math.BoundingBox;
import raylab.math.Vec3;
import raylab.ray.IntersectionRecord;
import raylab.ray.Ray;

/**
 * The triangle with vertices a, b, c. Its normal n = (b − a) × (c − a) / ‖(b − a) × (c − a)‖
 * points to the side from which a, b, c are seen counter-clockwise.
 */
public class Triangle extends Surface {
    public final Vec3 a;
    public final Vec3 b;
    public final Vec3 c;

    public Triangle(Vec3 a, Vec3 b, Vec3 c, Material material, String name) {
        super(material, name);
        this.a = a;
        this.b = b;
        this.c = c;
    }

    /**
     * Ray–triangle intersection (milestone {@code triangle}).
     *
     * <p>First the plane: with n = (b − a) × (c − a), the ray meets the plane (x − a)·n = 0 at
     * <pre>
     *   t = (a − p)·n / (d·n)          (no hit when d·n = 0: the ray is parallel to the plane)
     * </pre>
     * Then the point x = p + t·d is inside the triangle when it is on the inner side of all three
     * edges:
     * <pre>
     *   ((b − a) × (x − a))·n ≥ 0,   ((c − b) × (x − b))·n ≥ 0,   ((a − c) × (x − c))·n ≥ 0
     * </pre>
     * Record the hit if t is in range and closer than {@code outRecord.t}, with the unit normal
     * n / ‖n‖ (whichever side the ray comes from).
     *
     * @return true if the record was updated
     */
    @Override
    public boolean intersect(IntersectionRecord outRecord, Ray ray) {
        // The lecture: the plane (x − a)·n = 0 first, then the three inside-edge tests (≥ 0: the
        // triangle is closed, its edges belong to it).
        Vec3 n = b.minus(a).cross(c.minus(a));
        double dn = ray.d.dot(n);
        if (dn == 0) {
            return false;
        }
        double t = a.minus(ray.p).dot(n) / dn;
        if (!ray.inRange(t) || t >= outRecord.t) {
            return false;
        }
        Vec3 x = ray.evaluate(t);
        // BUG: the slide's strict > 0, so points on an edge or a vertex are outside.
        if (b.minus(a).cross(x.minus(a)).dot(n) <= 0
                || c.minus(b).cross(x.minus(b)).dot(n) <= 0
                || a.minus(c).cross(x.minus(c)).dot(n) <= 0) {
            return false;
        }
        outRecord.set(t, x, n.normalize(), this);
        return true;
    }


    @Override
    public BoundingBox boundingBox() {
        return new BoundingBox(a.min(b).min(c), a.max(b).max(c));
    }
}
